# Tests of the verdicts, the summary, the report and the README's numbers (label `report`).
# Included at the end of reproduce/CMakeLists.txt, which defines REPRO_DIR (build/reproduce: the
# results of the configured tier), REPRO_TABLES and the CTest fixture repro_summary
# (REPRO_DIR/summary.json of that tier). The scripts import the tools' packages, so they run under
# SPRINGBLOCK_PYTHON_TOOLS (the source root on PYTHONPATH).
set(REPORT_TESTS ${CMAKE_SOURCE_DIR}/tests/report)

# Synthetic numbers only: the rules at their boundaries, known and stale deviations, claim lines,
# exit codes (0 / 1 / 77); and the schema refusing what it does not define. No simulation.
add_test(NAME report_verdict_logic COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} ${REPORT_TESTS}/test_verdicts.py)
add_test(NAME report_summary_schema COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} ${REPORT_TESTS}/test_schema.py)
set_tests_properties(report_verdict_logic report_summary_schema PROPERTIES LABELS report)

# The report built from the tier's real summary says exactly what the summary says.
add_test(NAME report_content COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} ${REPORT_TESTS}/test_report.py --data ${REPRO_DIR})
set_tests_properties(report_content PROPERTIES LABELS report FIXTURES_REQUIRED repro_summary)

# README.md's results block equals the summary. It states paper-tier numbers, so at another tier
# the check cannot confirm them and exits 77 (skipped).
add_test(NAME report_readme_numbers
         COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} -m tools.readme_results --check
                 --summary ${REPRO_DIR}/summary.json --readme ${CMAKE_SOURCE_DIR}/README.md --tables ${REPRO_TABLES})
set_tests_properties(report_readme_numbers PROPERTIES LABELS report FIXTURES_REQUIRED repro_summary
                     SKIP_RETURN_CODE 77)
