# CTest install_consumer: install this build into a prefix inside the build tree, then configure,
# build and run tests/consumer against that prefix alone, run the installed command, and import
# the installed Python module. Usage (tests/CMakeLists.txt):
#   cmake -DBUILD_DIR= -DWORK_DIR= -DSOURCE_DIR= -DCONFIG= -DGENERATOR= -DCXX= -DCXX_FLAGS=
#         [-DPYTHON= -DPYTHON_DIR=] -P run_consumer_test.cmake
# (Arguments pass through ARGN, a list: none may hold a ';'.)
function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_consumer: ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

# Only the prefix is searched: the package registries could find the build tree instead.
step("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
     -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_CXX_COMPILER=${CXX} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
     -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
     -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF)
file(STRINGS ${WORK_DIR}/build/CMakeCache.txt found REGEX "^springblock_DIR:")
if(NOT found MATCHES "${prefix}/")
  message(FATAL_ERROR "install_consumer: the consumer found springblock outside the prefix: ${found}")
endif()
step("building the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build --config ${CONFIG})
file(GLOB_RECURSE consumer LIST_DIRECTORIES false ${WORK_DIR}/build/consumer ${WORK_DIR}/build/*/consumer)
step("running the consumer" ${consumer})
message(STATUS "consumer: ${step_output}")

step("running the installed command" ${prefix}/bin/springblock theory --json)

if(PYTHON_DIR)
  step("importing the installed Python module" ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR}
       ${PYTHON} -c "import springblock as sb\nassert sb.__file__.startswith('${prefix}/'), sb.__file__\nr = sb.run(sb.Scene(N=20, reps=1, duration='3t0'))\nassert r.mu_s.n == 1\nprint(sb.__file__, r)")
  message(STATUS "python: ${step_output}")
endif()
