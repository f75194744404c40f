# The tests/bad/ corpus: every bad program produces exactly the diagnostics its
# `; expect: <line>:<col> <id> [substring]` header lines state (grammar work package).
ncsim_add_test(NAME bad_programs_tests
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bad_programs_test.cpp
  LIBS ncsim_grammar)
