# Issue 36: the independent trajectory checker (tests/checker/README.md). Python 3 with numpy
# (Debian's python3-numpy, scripts/deps.sh); Debian's /usr/bin/python3 first, since another
# python3 on PATH (pyenv) may lack numpy.
find_program(NCSIM_CHECKER_PYTHON NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
find_program(NCSIM_CHECKER_PYTHON NAMES python3)
set(_checker ${CMAKE_CURRENT_SOURCE_DIR}/checker)
# The CI set: 150 seeded random programs on random portal_3x variants, the checker against the
# machine lists and the audit; the seeds of expected_seeds.txt must show exactly their listed
# findings (issue 36 items 5, 6 and F1), every other seed none (about 1 min on 2 cores).
add_test(NAME checker_random
         COMMAND ${NCSIM_CHECKER_PYTHON} ${_checker}/run_set.py --ncsim $<TARGET_FILE:ncsim>
                 --seeds 1..150 --jobs 2 --expect ${_checker}/expected_seeds.txt)
set_tests_properties(checker_random PROPERTIES TIMEOUT 900 LABELS checker)
# Issue 36's reproductions (tests/checker/known/): each must show exactly the findings of
# known/expected.txt; a fixed item makes this test fail until its line is removed.
add_test(NAME checker_known
         COMMAND ${NCSIM_CHECKER_PYTHON} ${_checker}/run_set.py --ncsim $<TARGET_FILE:ncsim>
                 --known --jobs 2 --expect ${_checker}/known/expected.txt)
set_tests_properties(checker_known PROPERTIES TIMEOUT 300 LABELS checker)
# The same cases with no expectations: every item is fixed (issue 36 items 1, 2, 5, 6; item 1 in
# session 36), so each case must be clean.
add_test(NAME checker_known_strict
         COMMAND ${NCSIM_CHECKER_PYTHON} ${_checker}/run_set.py --ncsim $<TARGET_FILE:ncsim>
                 --known --jobs 2 --quiet)
set_tests_properties(checker_known_strict PROPERTIES TIMEOUT 300 LABELS checker)
# The checker itself on synthetic trajectories with known answers (no ncsim).
add_test(NAME checker_selftest COMMAND ${NCSIM_CHECKER_PYTHON} ${_checker}/selftest.py)
set_tests_properties(checker_selftest PROPERTIES LABELS checker)
# The time-optimal bound tool of issue 36 (bench/bound.py, independent of ncsim's code) on
# answers known in closed form.
add_test(NAME bound_selftest COMMAND ${NCSIM_CHECKER_PYTHON}
                                     ${CMAKE_SOURCE_DIR}/bench/bound_test.py)
set_tests_properties(bound_selftest PROPERTIES LABELS checker)
