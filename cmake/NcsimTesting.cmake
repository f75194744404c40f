# ncsim_add_test(NAME name SOURCES a_test.cpp ... LIBS lib ...)
# Builds one doctest executable (main from ncsim_test_main) and registers it with CTest.
# Tests live beside the code they check; this only wires them up.
function(ncsim_add_test)
  cmake_parse_arguments(T "" "NAME" "SOURCES;LIBS" ${ARGN})
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ncsim_test_main ${T_LIBS} ncsim_options)
  add_test(NAME ${T_NAME} COMMAND ${T_NAME} --no-version)
  set_tests_properties(${T_NAME} PROPERTIES
                       ENVIRONMENT "NCSIM_SOURCE_DIR=${PROJECT_SOURCE_DIR}")
endfunction()
