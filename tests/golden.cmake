# Golden trajectories (docs/golden.md):
#   golden.<name>        - one test per program folder programs/<name>/: `ncsim golden check` on it
#   golden.lines.<name>  - one test per line folder programs/lines/<name>/ (its channels' goldens)
#                          (the run must match programs/<name>/<name>.golden); independent, so
#                          `ctest -j` runs them in parallel. A new folder is found at the next
#                          build (CONFIGURE_DEPENDS).
#   programs_check       - `ncsim check` (syntax and semantics) passes on every program
#   golden_cli_tests     - the golden command: bless, check, deviations, exit statuses
file(GLOB ncsim_golden_programs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/programs/*/*.nc)
foreach(nc IN LISTS ncsim_golden_programs)
  get_filename_component(folder ${nc} DIRECTORY)
  get_filename_component(name ${folder} NAME)
  get_filename_component(stem ${nc} NAME_WE)
  if(name STREQUAL stem)
    add_test(NAME golden.${name} COMMAND ncsim golden check ${folder})
    set_tests_properties(golden.${name} PROPERTIES LABELS golden TIMEOUT 300)
  endif()
endforeach()

# programs/real/<name>/: programs written in the styles of shipped emitters (issue 33,
# programs/README.md "Real programs"), one golden test each too.
file(GLOB ncsim_real_programs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/programs/real/*/*.nc)
foreach(nc IN LISTS ncsim_real_programs)
  get_filename_component(folder ${nc} DIRECTORY)
  get_filename_component(name ${folder} NAME)
  get_filename_component(stem ${nc} NAME_WE)
  if(name STREQUAL stem)
    add_test(NAME golden.real.${name} COMMAND ncsim golden check ${folder})
    set_tests_properties(golden.real.${name} PROPERTIES LABELS golden TIMEOUT 300)
  endif()
endforeach()
if(ncsim_real_programs)
  add_test(NAME programs_check_real
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/golden/check_programs.sh $<TARGET_FILE:ncsim>
                   ${PROJECT_SOURCE_DIR}/programs/real)
endif()

# programs/lines/<name>/: production lines (docs/lines.md), a golden per channel
# (ch<N>_<name>.golden), all checked by one `ncsim golden check` of the line's folder.
file(GLOB ncsim_lines CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/programs/lines/*/line.toml)
foreach(toml IN LISTS ncsim_lines)
  get_filename_component(folder ${toml} DIRECTORY)
  get_filename_component(name ${folder} NAME)
  add_test(NAME golden.lines.${name} COMMAND ncsim golden check ${folder})
  set_tests_properties(golden.lines.${name} PROPERTIES LABELS golden TIMEOUT 300)
endforeach()

add_test(NAME programs_check
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/golden/check_programs.sh $<TARGET_FILE:ncsim>
                 ${PROJECT_SOURCE_DIR}/programs)
add_test(NAME golden_cli_tests
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/golden/golden_cli_test.sh $<TARGET_FILE:ncsim>)
