# axes/config.cmake: the one mapping from a loaded machine's axis parameters onto the axis
# core's configurations (generator, position control, monitors). See docs/machines.md
# "From a machine to its axes".
target_sources(ncsim_axes PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/axis_config.cpp)
target_link_libraries(ncsim_axes PUBLIC ncsim_machines)
ncsim_add_test(NAME axes_config_tests
  SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/axis_config_test.cpp
  LIBS ncsim_axes ncsim_machines)
