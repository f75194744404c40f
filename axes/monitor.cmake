# axes/monitor.cmake: position control model, monitoring, couplings, modulo, homing.
# See docs/axes-monitoring.md.
target_sources(ncsim_axes PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/control.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/monitor.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/modulo.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/coupling.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/homing.cpp)
ncsim_add_test(NAME axes_monitor_tests
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/control_test.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/monitor_test.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/modulo_test.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/coupling_test.cpp
          ${CMAKE_CURRENT_SOURCE_DIR}/homing_test.cpp
  LIBS ncsim_axes)
