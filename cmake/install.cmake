# `cmake --install build --prefix P`: the library (P/lib/libspringblock.a), its public headers
# (P/include/springblock/), the command (P/bin/springblock) and a CMake package
# (P/lib/cmake/springblock/), so a consumer writes
#   find_package(springblock)  target_link_libraries(app springblock::springblock)
# The Python module installs itself (src/python/CMakeLists.txt). tests/consumer checks all this.
include(CMakePackageConfigHelpers)

# The public headers: the scene and its field table, the ensemble runner and its results, the
# results JSON, units and errors, the closed-form theory, and every project header these include.
# The integrator (integrate/**) is not among them: no public header includes it. A header added to
# this closure must be added here; the consumer test compiles every installed header on its own
# include path, so a missing one fails it.
set(SPRINGBLOCK_PUBLIC_HEADERS
    scene.hpp scene_fields.hpp ensemble.hpp observables.hpp io.hpp units.hpp errors.hpp theory.hpp
    scene_theory.hpp
    # included by the above
    model.hpp chain_force.hpp kernel_clones.hpp parameters.hpp run_control.hpp surface.hpp state.hpp
    observe/friction_observer.hpp observe/observer.hpp)
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
