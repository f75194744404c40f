# bench/axes.cmake: setpoint generator throughput (axes/profile*). Release build:
#   cmake -S . -B build-profile-rel -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCSIM_BENCH=ON
add_executable(axes_bench ${CMAKE_CURRENT_SOURCE_DIR}/axes_bench.cpp)
target_link_libraries(axes_bench PRIVATE benchmark::benchmark ncsim_axes ncsim_options)
# The bit-for-bit fingerprint of the plans (speed rounds that must change none, issue 36).
add_executable(axes_digest ${CMAKE_CURRENT_SOURCE_DIR}/axes_digest.cpp)
target_link_libraries(axes_digest PRIVATE ncsim_axes ncsim_options)
