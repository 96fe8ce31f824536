# Whether the Python module (src/python) is built, and where `cmake --install` puts it.
#
# The module is built by default when pybind11 is found, for the interpreter SPRINGBLOCK_PYTHON
# (Debian's, which has numpy). Never in a sanitizer build: an ASan-instrumented extension cannot
# be loaded into an uninstrumented interpreter, so its tests could only fail there.
set(_springblock_python_default OFF)
if(NOT SPRINGBLOCK_SANITIZE)
  set(Python_EXECUTABLE ${SPRINGBLOCK_PYTHON})
  set(PYBIND11_FINDPYTHON ON)  # CMake's FindPython, pointed at SPRINGBLOCK_PYTHON above
  find_package(pybind11 2.6 CONFIG QUIET)
  if(pybind11_FOUND)
    set(_springblock_python_default ON)
  endif()
endif()
option(SPRINGBLOCK_BUILD_PYTHON "Build the Python module 'springblock' (needs pybind11)"
       ${_springblock_python_default})

if(SPRINGBLOCK_BUILD_PYTHON AND SPRINGBLOCK_SANITIZE)
  message(WARNING "SPRINGBLOCK_BUILD_PYTHON is ignored with SPRINGBLOCK_SANITIZE: an instrumented "
                  "module cannot be imported by an uninstrumented Python")
  set(SPRINGBLOCK_BUILD_PYTHON OFF)
elseif(SPRINGBLOCK_BUILD_PYTHON AND NOT pybind11_FOUND)
  message(FATAL_ERROR "SPRINGBLOCK_BUILD_PYTHON=ON but pybind11 was not found "
                      "(Debian: apt-get install pybind11-dev, or run tools/ensure_deps.sh)")
endif()

# The prefix-relative site directory of SPRINGBLOCK_PYTHON. Debian's default scheme maps a prefix P
# to P/local/lib/python3.X/dist-packages (so that installs into /usr land in /usr/local); the
# `local/` is dropped, so prefix /usr/local gives /usr/local/lib/python3.X/dist-packages, which
# Debian's python3 searches. Elsewhere this is the usual lib/python3.X/site-packages.
if(SPRINGBLOCK_BUILD_PYTHON AND NOT DEFINED CACHE{SPRINGBLOCK_PYTHON_INSTALL_DIR})
  execute_process(
    COMMAND ${SPRINGBLOCK_PYTHON} -c
      "import os, sysconfig; p = sysconfig.get_path('platlib', vars={'base': '/P', 'platbase': '/P'}); r = os.path.relpath(p, '/P'); print(r[len('local/'):] if r.startswith('local/') else r)"
    OUTPUT_VARIABLE _springblock_site OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  set(SPRINGBLOCK_PYTHON_INSTALL_DIR "${_springblock_site}" CACHE STRING
      "Where 'cmake --install' puts the Python module, relative to the prefix")
endif()
