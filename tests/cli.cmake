# End-to-end tests of the ncsim command: exit statuses and output formats (design.md §5).
add_test(NAME cli_tests
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/cli_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
# Seeded random override / feed-hold scenarios over random programs (issue 13): audit clean,
# the program completes, time equals run, reruns identical (tests/cli/random_scenarios.sh).
add_test(NAME cli_random_scenarios
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/random_scenarios.sh $<TARGET_FILE:ncsim>
                 ${PROJECT_SOURCE_DIR} 12 13)
# --- line: time per workpiece, synchro_lag, sweep, tune-delay (docs/conveyor.md)
add_test(NAME cli_line_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/line_test.sh $<TARGET_FILE:ncsim>)
# Issue 36 items 7, 8: under conveyor tracking X.v is the derivative of X, and synchro_lag on a
# fluctuating belt ripples by the manual's residual (docs/conveyor.md F-8)
add_test(NAME cli_conveyor_ff_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/conveyor_ff_test.sh $<TARGET_FILE:ncsim>)
# --- workspace: an error while synchronised keeps the synchronisation (docs/conveyor.md)
add_test(NAME cli_sync_error_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/sync_error_test.sh $<TARGET_FILE:ncsim>)
# Issue 12's 200-move program in six variants: audit clean, within [TOPP bound, the table]
# (docs/benchmarks.md "The 200-move table").
add_test(NAME cli_move200_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/move200_test.sh $<TARGET_FILE:ncsim>)
# --- planner (issue 12): --cycle-us, `run -o` written whole or not at all, the CSV's numbers
add_test(NAME cli_run_output_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_output_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
# --- planner (issue 12): P-CHAN-00071, the channel's start slope, end to end
add_test(NAME cli_start_slope_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/start_slope_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
# --- planner (issue 12): the channel list's P-CHAN-00009 and ncsim's channel keys, end to end
add_test(NAME cli_channel_keys_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/channel_keys_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
# Issue 33: cycle calls, --cycles, --missing-cycles, M values and zero offsets end to end.
add_test(NAME cli_cycles_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/cycles_test.sh $<TARGET_FILE:ncsim>)
# --- issue 34: inputs that are no regular files, outputs that are not replaced, signals and
# closed pipes (tests/cli/robust_files_test.sh)
add_test(NAME cli_robust_files_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/robust_files_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
set_tests_properties(cli_robust_files_test PROPERTIES TIMEOUT 600)
# --- tool radius compensation (issue 33 item 6): check's positioned errors, trace (docs/trc.md)
add_test(NAME cli_trc_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/trc_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
# Issue 34's critical motion defects (items 1-7, 11, 12, 19, 22): every run ends, positioned
# errors, check and time agree, no NaN in the outputs.
add_test(NAME cli_robust_motion_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/robust_motion_test.sh $<TARGET_FILE:ncsim>)
# Issue 34's property over seeded hostile programs and scenarios: every run ends with a
# documented status, JSON parses, no NaN or infinity in any output, no temporary file left.
add_test(NAME cli_hostile_property_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/hostile_property_test.sh $<TARGET_FILE:ncsim>
                 ${PROJECT_SOURCE_DIR} 40 34)
set_tests_properties(cli_hostile_property_test PROPERTIES TIMEOUT 900)
# --- issue 37: production lines, several channels in one run (docs/lines.md)
add_test(NAME cli_production_line_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/production_line_test.sh $<TARGET_FILE:ncsim>)
# ncsim line sweep: answers known by construction, the binding constraint, determinism
add_test(NAME cli_line_sweep_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/line_sweep_test.sh $<TARGET_FILE:ncsim>)
# one test per bundled line programs/lines/<name>/line.toml: check, time, run, reruns identical
file(GLOB ncsim_lines CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/programs/lines/*/line.toml)
foreach(line IN LISTS ncsim_lines)
  get_filename_component(folder ${line} DIRECTORY)
  get_filename_component(name ${folder} NAME)
  add_test(NAME line.${name}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/line_example.sh $<TARGET_FILE:ncsim>
                   ${folder})
endforeach()
# --- issue 37 step 5: studies (docs/study.md): local runs identical whatever the threads and
# the order, positioned errors; and the same study through a single-node Slurm the test brings
# up itself (munge, slurmctld, slurmd), byte for byte the local table.
add_test(NAME cli_study_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/study_test.sh $<TARGET_FILE:ncsim>)
add_test(NAME cli_study_slurm_test
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/study_slurm_test.sh $<TARGET_FILE:ncsim>)
set_tests_properties(cli_study_slurm_test PROPERTIES TIMEOUT 600 SKIP_RETURN_CODE 77)
