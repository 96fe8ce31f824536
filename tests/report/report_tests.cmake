# Tests of the verdicts, the summary, the report and the README's numbers (label `report`).
# Included at the end of reproduce/CMakeLists.txt, which defines SPRINGBLOCK_PYTHON, REPRO_DIR
# (build/reproduce: the results of the configured tier), REPRO_CHECK, REPRO_TABLES and the CTest
# fixture repro_summary (REPRO_DIR/summary.json of that tier).
set(REPORT_TESTS ${CMAKE_SOURCE_DIR}/tests/report)
# The scripts import modules from the source tree; no __pycache__ there.
set(REPORT_ENV PYTHONDONTWRITEBYTECODE=1)

# Synthetic numbers only: the rules at their boundaries, known and stale deviations, claim lines,
# exit codes (0 / 1 / 77); and the schema refusing what it does not define. No simulation.
add_test(NAME report_verdict_logic COMMAND ${SPRINGBLOCK_PYTHON} ${REPORT_TESTS}/test_verdicts.py)
add_test(NAME report_summary_schema COMMAND ${SPRINGBLOCK_PYTHON} ${REPORT_TESTS}/test_schema.py)
set_tests_properties(report_verdict_logic report_summary_schema PROPERTIES LABELS report ENVIRONMENT ${REPORT_ENV})

# The report built from the tier's real summary says exactly what the summary says.
add_test(NAME report_content COMMAND ${SPRINGBLOCK_PYTHON} ${REPORT_TESTS}/test_report.py --data ${REPRO_DIR})
set_tests_properties(report_content PROPERTIES LABELS report FIXTURES_REQUIRED repro_summary
                     ENVIRONMENT ${REPORT_ENV})

# README.md's results block equals the summary. It states paper-tier numbers, so at another tier
# the check cannot confirm them and exits 77 (skipped).
add_test(NAME report_readme_numbers
         COMMAND ${SPRINGBLOCK_PYTHON} ${CMAKE_SOURCE_DIR}/tools/readme_results.py --check
                 --summary ${REPRO_DIR}/summary.json --readme ${CMAKE_SOURCE_DIR}/README.md --tables ${REPRO_TABLES})
set_tests_properties(report_readme_numbers PROPERTIES LABELS report FIXTURES_REQUIRED repro_summary
                     SKIP_RETURN_CODE 77 ENVIRONMENT ${REPORT_ENV})
