# axes/profile.cmake: the PTP setpoint generator (7-phase profile, online changes, velocity
# motion, position compensation). See docs/axes-profile.md.
target_sources(ncsim_axes PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/profile.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_builder.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_general.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_velocity.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_optimal.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_classify.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_outside.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/phase_sync.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_compensation.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/profile_generator.cpp
)

ncsim_add_test(NAME axes_profile_tests
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_figures_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_property_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_online_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_start_state_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_optimal_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_turn_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_reference_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_duration_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_duration_gap_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_classify_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_outside_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_synchronized_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/profile_moving_target_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/phase_sync_test.cpp
  LIBS ncsim_axes)

# The shape-free LP reference (profile_lp_reference.hpp) needs GLPK (Debian libglpk-dev,
# installed by scripts/deps.sh); linked into this test only.
find_path(GLPK_INCLUDE_DIR glpk.h)
find_library(GLPK_LIBRARY glpk)
if(GLPK_INCLUDE_DIR AND GLPK_LIBRARY)
  ncsim_add_test(NAME axes_profile_lp_tests
    SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/profile_lp_reference_test.cpp
    LIBS ncsim_axes ${GLPK_LIBRARY})
  target_include_directories(axes_profile_lp_tests SYSTEM PRIVATE ${GLPK_INCLUDE_DIR})
else()
  message(FATAL_ERROR "GLPK not found (glpk.h, libglpk): run scripts/deps.sh (libglpk-dev)")
endif()
