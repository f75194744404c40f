# libFuzzer targets (included by tests/CMakeLists.txt only when NCSIM_FUZZ=ON; clang only).
# The compile flags (-fsanitize=fuzzer-no-link,address,undefined) come from ncsim_options;
# -fsanitize=fuzzer at link time adds libFuzzer's main. Run with tests/fuzz/run.sh SECONDS.
#   fuzz_grammar - grammar::check_program on any bytes
#   fuzz_interp  - check_program, then the interpreter and check_semantics on a bundled machine
add_executable(fuzz_grammar ${CMAKE_CURRENT_LIST_DIR}/fuzz/fuzz_grammar.cpp)
target_link_libraries(fuzz_grammar PRIVATE ncsim_grammar ncsim_core ncsim_options)
target_link_options(fuzz_grammar PRIVATE -fsanitize=fuzzer)

add_executable(fuzz_interp ${CMAKE_CURRENT_LIST_DIR}/fuzz/fuzz_interp.cpp)
target_link_libraries(fuzz_interp PRIVATE ncsim_interp ncsim_grammar ncsim_machines ncsim_core
                                          ncsim_options)
target_link_options(fuzz_interp PRIVATE -fsanitize=fuzzer)
# The bundled machines are loaded from the source tree, as the CLI does.
target_compile_definitions(fuzz_interp PRIVATE NCSIM_SOURCE_ROOT="${PROJECT_SOURCE_DIR}")
