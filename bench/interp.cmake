# interp_bench: interpreter throughput (blocks/s of a generated 1,000,000-block program,
# $FOR iterations/s). Included from bench/CMakeLists.txt when NCSIM_BENCH=ON.
add_executable(interp_bench ${CMAKE_CURRENT_SOURCE_DIR}/interp_bench.cpp)
target_link_libraries(interp_bench PRIVATE benchmark::benchmark ncsim_interp ncsim_options)
target_compile_definitions(interp_bench PRIVATE NCSIM_SOURCE_ROOT="${PROJECT_SOURCE_DIR}")
if(TARGET ncsim_bench_gen)
  target_link_libraries(interp_bench PRIVATE ncsim_bench_gen)
endif()
