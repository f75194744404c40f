# programs/ and the benchmark generator:
#   bench_generator_tests - the benchmark program generator (bench/grammar_generator.*)
#   programs_tests        - every programs/*/*.nc checks clean with grammar::check_program,
#                           each program folder names its machine, the generated benchmark
#                           program checks clean
ncsim_add_test(NAME bench_generator_tests
  SOURCES ${PROJECT_SOURCE_DIR}/bench/grammar_generator_test.cpp
          ${PROJECT_SOURCE_DIR}/bench/grammar_generator.cpp
  LIBS ncsim_core)

ncsim_add_test(NAME programs_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/programs_test.cpp
          ${PROJECT_SOURCE_DIR}/bench/grammar_generator.cpp
  LIBS ncsim_grammar ncsim_core)
