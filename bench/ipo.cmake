# ipo_bench: machining time (`time` loop) in multiples of real time on long lines and arcs
# and on dense 0.1 mm CAM segments; the audited stepping loop for comparison
# (docs/benchmarks.md, row `ipo`). Included from bench/CMakeLists.txt when NCSIM_BENCH=ON.
add_executable(ipo_bench ${CMAKE_CURRENT_SOURCE_DIR}/ipo_bench.cpp)
target_link_libraries(ipo_bench PRIVATE benchmark::benchmark ncsim_ipo ncsim_audit ncsim_options)
# move200_bound: the 200-move table (docs/benchmarks.md): ncsim's `time` against TOPP bounds.
add_executable(move200_bound ${CMAKE_CURRENT_SOURCE_DIR}/move200_bound.cpp)
target_link_libraries(move200_bound PRIVATE ncsim_ipo ncsim_audit ncsim_options)
