# planner_bench: look-ahead throughput (segments/s through the window at N = 30/120/190),
# segment preparation and profile evaluation. Included from bench/CMakeLists.txt when
# NCSIM_BENCH=ON.
add_executable(planner_bench ${CMAKE_CURRENT_SOURCE_DIR}/planner_bench.cpp)
target_link_libraries(planner_bench PRIVATE benchmark::benchmark ncsim_planner ncsim_options)
# planner_time: machining time of the seeded 200-move reference program (docs/benchmarks.md).
add_executable(planner_time ${CMAKE_CURRENT_SOURCE_DIR}/planner_time.cpp)
target_link_libraries(planner_time PRIVATE ncsim_planner ncsim_options)
