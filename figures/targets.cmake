# Figures and the literate report. Include from the top-level CMakeLists.txt AFTER
# add_subdirectory(reproduce) (the reproduction targets must already exist):
#
#   include(figures/targets.cmake)
#
# Targets:
#   figures   every figures/<name>.py on ${CMAKE_BINARY_DIR}/reproduce -> ${CMAKE_BINARY_DIR}/figures
#             (PNG + PDF). Each figure is its own custom command depending on its script, the
#             shared modules and its target's JSON, so unchanged inputs do no work; zscores reads
#             summary.json.
#   report    tables/render_tables.py -> ${CMAKE_BINARY_DIR}/paper/tables, then
#             paper/build_report.py -> ${CMAKE_BINARY_DIR}/paper/report.{md,html}.
#             It always reruns (a few seconds); the summary it reads is a declared file.
# Hooking into the reproduction (the lead's choice), e.g.:
#   add_dependencies(reproduce-all report)   or   add_dependencies(figures reproduce-data)

set(SB_FIG_SRC ${CMAKE_SOURCE_DIR}/figures)
set(SB_FIG_OUT ${CMAKE_BINARY_DIR}/figures)
set(SB_REPRO_DIR ${CMAKE_BINARY_DIR}/reproduce)
set(SB_PAPER_OUT ${CMAKE_BINARY_DIR}/paper)
file(MAKE_DIRECTORY ${SB_FIG_OUT} ${SB_PAPER_OUT})
# The scripts are modules of the packages figures/, tables/, paper/ and tools/ (the top-level
# CMakeLists.txt says how they run).
set(SB_PY ${SPRINGBLOCK_PYTHON_TOOLS})

set(SB_FIG_COMMON ${SB_FIG_SRC}/style.py ${SB_FIG_SRC}/sweep.py ${SB_FIG_SRC}/categories.py
                  ${CMAKE_SOURCE_DIR}/tables/published_tab_pat0.tsv ${CMAKE_SOURCE_DIR}/tables/published_tab_pat1.tsv
                  ${CMAKE_SOURCE_DIR}/tables/published_tab_pat2.tsv)

# figure name -> reproduction targets whose JSON it reads
set(SB_FIG_INPUTS_fig1 fig1)
set(SB_FIG_INPUTS_fig_s1 fig_s1)
set(SB_FIG_INPUTS_fig_s2 fig_s2)
set(SB_FIG_INPUTS_fig2 fig2)
set(SB_FIG_INPUTS_fig_p1 fig_p1)
set(SB_FIG_INPUTS_fig3 fig3)
set(SB_FIG_INPUTS_fig4 fig4 tab_pat0)
set(SB_FIG_INPUTS_fig5 fig5)
set(SB_FIG_INPUTS_fig_p2 fig_p2)
set(SB_FIG_INPUTS_fig_p3 fig_p3)
set(SB_FIG_INPUTS_sensitivity sensitivity)
set(SB_FIG_INPUTS_accuracy_cost accuracy_cost)
set(SB_FIG_INPUTS_schematics "")
set(SB_FIG_INPUTS_design_map "")
set(SB_FIG_STUDIES_design_map design_map)
set(SB_FIG_INPUTS_slip_events "")
set(SB_FIG_STUDIES_slip_events slip_events)
set(SB_FIG_INPUTS_graded_friction "")
set(SB_FIG_STUDIES_graded_friction graded_friction)
set(SB_FIG_INPUTS_composite_stiffness "")
set(SB_FIG_STUDIES_composite_stiffness composite_stiffness)
set(SB_FIG_INPUTS_size_scaling "")
set(SB_FIG_STUDIES_size_scaling size_scaling)
# figure name -> other sources it imports besides figures/style.py (the fits the report shares).
set(SB_FIG_SOURCES_size_scaling ${CMAKE_SOURCE_DIR}/paper/scaling_fits.py)
# figure name -> optional studies it draws (make studies; read from the build tree if run there,
# else from the committed paper/data/<study>.json, which is what the file dependency watches).
set(SB_FIG_STUDIES_accuracy_cost rk4_refinement)
set(SB_FIG_STUDIES_layout layout)
set(SB_FIG_INPUTS_layout "")
set(SB_FIGURES fig1 fig_s1 fig_s2 fig2 fig_p1 fig3 fig4 fig5 fig_p2 fig_p3 sensitivity accuracy_cost schematics layout
               design_map slip_events graded_friction composite_stiffness size_scaling)

set(SB_FIG_PNGS "")
set(SB_FIG_DATA_TARGETS "")
foreach(fig ${SB_FIGURES})
  set(json_deps "")
  foreach(in ${SB_FIG_INPUTS_${fig}})
    # Depend on a JSON file only if a rule makes it: a target that is not (yet) defined would
    # otherwise break the build; its figure then says "not produced" instead.
    if(TARGET reproduce_${in})
      list(APPEND json_deps ${SB_REPRO_DIR}/${in}/${in}.json)
      list(APPEND SB_FIG_DATA_TARGETS reproduce_${in})
    endif()
  endforeach()
  foreach(st ${SB_FIG_STUDIES_${fig}})
    if(EXISTS ${CMAKE_SOURCE_DIR}/paper/data/${st}.json)
      list(APPEND json_deps ${CMAKE_SOURCE_DIR}/paper/data/${st}.json)
    endif()
  endforeach()
  set(png ${SB_FIG_OUT}/${fig}.png)
  add_custom_command(
    OUTPUT ${png} ${SB_FIG_OUT}/${fig}.pdf
    COMMAND ${SB_PY} -m figures.${fig} --data ${SB_REPRO_DIR} --out ${SB_FIG_OUT}
            --springblock $<TARGET_FILE:springblock_pattern>
    DEPENDS ${SB_FIG_SRC}/${fig}.py ${SB_FIG_COMMON} ${SB_FIG_SOURCES_${fig}} ${json_deps} springblock_pattern
    COMMENT "Figure ${fig}"
    VERBATIM)
  list(APPEND SB_FIG_PNGS ${png})
endforeach()

add_custom_target(figures DEPENDS ${SB_FIG_PNGS})

# zscores reads the checker's summary.json (a declared output of reproduce-summary).
if(TARGET reproduce-summary)
  add_custom_command(
    OUTPUT ${SB_FIG_OUT}/zscores.png ${SB_FIG_OUT}/zscores.pdf
    COMMAND ${SB_PY} -m figures.zscores --data ${SB_REPRO_DIR} --out ${SB_FIG_OUT}
    DEPENDS ${SB_FIG_SRC}/zscores.py ${SB_FIG_SRC}/style.py ${CMAKE_SOURCE_DIR}/tools/summary_schema.py
            ${SPRINGBLOCK_REPRODUCTION_SUMMARY}
    COMMENT "Figure zscores"
    VERBATIM)
  list(APPEND SB_FIG_PNGS ${SB_FIG_OUT}/zscores.png)
  add_custom_target(figure_zscores DEPENDS ${SB_FIG_OUT}/zscores.png)
  add_dependencies(figure_zscores reproduce-summary)
  add_dependencies(figures figure_zscores)
endif()
if(SB_FIG_DATA_TARGETS)
  list(REMOVE_DUPLICATES SB_FIG_DATA_TARGETS)
  # Order only: the file-level DEPENDS above decide whether a figure is redrawn.
  add_dependencies(figures ${SB_FIG_DATA_TARGETS})
endif()

add_custom_target(report
  COMMAND ${SB_PY} -m tables.render_tables
          --data ${SB_REPRO_DIR} --out ${SB_PAPER_OUT}/tables
  COMMAND ${SB_PY} -m paper.build_report
          --data ${SB_REPRO_DIR} --figures ${SB_FIG_OUT} --out ${SB_PAPER_OUT}
  DEPENDS ${SB_FIG_PNGS} ${CMAKE_SOURCE_DIR}/paper/build_report.py ${CMAKE_SOURCE_DIR}/paper/report_studies.py
          ${CMAKE_SOURCE_DIR}/paper/report_beyond.py
          ${CMAKE_SOURCE_DIR}/paper/choices.md
          ${CMAKE_SOURCE_DIR}/tables/render_tables.py ${CMAKE_SOURCE_DIR}/tools/summary_schema.py
  COMMENT "Reproduction report: ${SB_PAPER_OUT}/report.html"
  VERBATIM)
add_dependencies(report figures)
