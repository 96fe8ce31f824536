# The documentation site (`make docs`) and the browser checks of the site and the report.
# Included by the top-level CMakeLists.txt after the reproduction and its report targets. The site
# runs the built command and imports the built module (tools/docs/sphinx_run.py, autodoc), so it
# exists only where the module is built (not in a sanitizer build).
if(NOT SPRINGBLOCK_BUILD_PYTHON)
  return()
endif()

set(DOCS_OUT ${PROJECT_BINARY_DIR}/docs)
set(BROWSER_OUT ${PROJECT_BINARY_DIR}/browser)
set(DOCS_BUILD_COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} -m tools.docs.build --exe $<TARGET_FILE:springblock>
    --python-dir ${PROJECT_BINARY_DIR}/python --out ${DOCS_OUT})

# build/docs/html: Sphinx with warnings as errors, then every internal link, anchor and image
# checked. Always a whole rebuild: the pages show the outputs of the command as built now.
add_custom_target(docs COMMAND ${DOCS_BUILD_COMMAND} DEPENDS springblock springblock_python
                  COMMENT "Documentation: ${DOCS_OUT}/html/index.html" USES_TERMINAL VERBATIM)

# `make test` builds the site the same way and fails on a Sphinx warning, a broken internal link
# or a missing image.
add_test(NAME docs_build COMMAND ${DOCS_BUILD_COMMAND})
set_tests_properties(docs_build PROPERTIES LABELS docs FIXTURES_SETUP docs_site TIMEOUT 900)

# The browser check can fail: on tiny pages with a missing image, a console error and broken links.
add_test(NAME browser_check_selftest
         COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} ${CMAKE_CURRENT_LIST_DIR}/test_check_browser.py)
set_tests_properties(browser_check_selftest PROPERTIES LABELS "browser" TIMEOUT 300)

# The site's index in headless Chromium, its screenshot kept in build/browser/, then every other page.
add_test(NAME browser_docs
         COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} -m tools.docs.check_browser ${DOCS_OUT}/html/index.html
                 --screenshot ${BROWSER_OUT}/docs_index.png --site ${DOCS_OUT}/html)
set_tests_properties(browser_docs PROPERTIES LABELS "docs;browser" FIXTURES_REQUIRED docs_site TIMEOUT 300)

# The report of the configured tier, as `make reproduce-all` writes it (figures and report drawn from
# the reproduction fixtures' results), then opened in Chromium scrolled to its first table. The
# figures are independent targets, drawn in parallel on the cores the reproduction lock holds.
if(SPRINGBLOCK_BUILD_REPRODUCE)
  cmake_host_system_information(RESULT report_jobs QUERY NUMBER_OF_LOGICAL_CORES)
  add_test(NAME report_html
           COMMAND ${CMAKE_COMMAND} --build ${PROJECT_BINARY_DIR} --target report --parallel ${report_jobs})
  set_tests_properties(report_html PROPERTIES LABELS report FIXTURES_SETUP report_html
                       FIXTURES_REQUIRED repro_summary RESOURCE_LOCK reproduction_cores TIMEOUT 1500)
  add_test(NAME browser_report
           COMMAND ${SPRINGBLOCK_PYTHON_TOOLS} -m tools.docs.check_browser ${PROJECT_BINARY_DIR}/paper/report.html
                   --show table --screenshot ${BROWSER_OUT}/report_first_table.png)
  set_tests_properties(browser_report PROPERTIES LABELS "report;browser" FIXTURES_REQUIRED report_html TIMEOUT 300)
endif()
