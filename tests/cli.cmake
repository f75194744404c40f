# End-to-end tests of the ncsim command: exit statuses and output formats (design.md §5).
add_test(NAME cli_tests
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/cli/cli_test.sh $<TARGET_FILE:ncsim>
                 ${CMAKE_CURRENT_SOURCE_DIR}/cli)
