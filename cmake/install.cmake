# `cmake --install build --prefix P`: the library (P/lib/libspringblock.a), its public headers
# (P/include/springblock/), the command (P/bin/springblock) and a CMake package
# (P/lib/cmake/springblock/), so a consumer writes
#   find_package(springblock)  target_link_libraries(app springblock::springblock)
# The Python module installs itself (src/python/CMakeLists.txt). tests/consumer checks all this.
include(CMakePackageConfigHelpers)

# The public headers: the scene and its field table, the ensemble runner and its results, the
# results JSON, units and errors, the closed-form theory, and every project header these include,
# found by following their #include "springblock/..." lines (so a header newly included by a public
# one is installed without anyone remembering to list it). The integrator (integrate/**) is not
# among them: no public header includes it. The consumer test compiles every installed header on
# its own include path, so a missing one fails it.
set(SPRINGBLOCK_PUBLIC_ROOTS
    scene.hpp scene_fields.hpp ensemble.hpp observables.hpp io.hpp units.hpp errors.hpp theory.hpp
    scene_theory.hpp)
function(springblock_include_closure out)
  set(todo ${ARGN})
  set(seen "")
  while(todo)
    list(POP_FRONT todo header)
    if(header IN_LIST seen)
      continue()
    endif()
    list(APPEND seen ${header})
    file(STRINGS ${PROJECT_SOURCE_DIR}/src/springblock/${header} lines REGEX "^#include \"springblock/")
    foreach(line ${lines})
      string(REGEX REPLACE "^#include \"springblock/([^\"]+)\".*" "\\1" included "${line}")
      list(APPEND todo ${included})
    endforeach()
  endwhile()
  set(${out} ${seen} PARENT_SCOPE)
endfunction()
springblock_include_closure(SPRINGBLOCK_PUBLIC_HEADERS ${SPRINGBLOCK_PUBLIC_ROOTS})
if("integrate" IN_LIST SPRINGBLOCK_PUBLIC_HEADERS OR SPRINGBLOCK_PUBLIC_HEADERS MATCHES "integrate/")
  message(FATAL_ERROR "a public header includes the integrator: ${SPRINGBLOCK_PUBLIC_HEADERS}")
endif()
foreach(header ${SPRINGBLOCK_PUBLIC_HEADERS})
  get_filename_component(subdir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/springblock/${header}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/springblock/${subdir})
endforeach()

install(TARGETS springblock_core EXPORT springblockTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS springblock RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set(SPRINGBLOCK_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/springblock)
install(EXPORT springblockTargets NAMESPACE springblock:: DESTINATION ${SPRINGBLOCK_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/springblockConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/springblockConfig.cmake
                              INSTALL_DESTINATION ${SPRINGBLOCK_CMAKE_DIR})
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/springblockConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/springblockConfig.cmake ${PROJECT_BINARY_DIR}/springblockConfigVersion.cmake
        DESTINATION ${SPRINGBLOCK_CMAKE_DIR})
