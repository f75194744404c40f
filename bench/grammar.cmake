# Grammar benchmark fragment (included by bench/CMakeLists.txt when NCSIM_BENCH=ON).
#   gen_program   - writes the generated benchmark program (.nc ISG and .ngc RS274/NGC)
#   grammar_bench - blocks/s of grammar::check_program on an in-memory generated program
# The side-by-side run against LinuxCNC's rs274 is bench/check_vs_rs274.sh.
add_library(ncsim_bench_gen STATIC ${CMAKE_CURRENT_LIST_DIR}/grammar_generator.cpp)
target_include_directories(ncsim_bench_gen PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(ncsim_bench_gen PUBLIC ncsim_options)

add_executable(gen_program ${CMAKE_CURRENT_LIST_DIR}/gen_program.cpp)
target_link_libraries(gen_program PRIVATE ncsim_bench_gen CLI11::CLI11 ncsim_options)

add_executable(grammar_bench ${CMAKE_CURRENT_LIST_DIR}/grammar_bench.cpp)
target_link_libraries(grammar_bench PRIVATE ncsim_bench_gen ncsim_grammar benchmark::benchmark
                                            ncsim_options)
