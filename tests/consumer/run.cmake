# Builds and runs tests/consumer, a project outside the softgl tree, in one of four ways (MODE):
#   package       against the installed package (cmake --install of this build into a private prefix)
#   subdirectory  from a parent project that adds the softgl source tree with add_subdirectory
#   raised        against the package, the consumer asking for C++17 with CMAKE_CXX_STANDARD: CMake raises it to
#                 the C++20 that softgl's targets require, and the program builds and runs
#   forced_old    the installed headers compiled by the compiler itself at -std=c++17 (as a build system other
#                 than CMake could do; CMake always raises the level): the compile must stop with softgl's
#                 one-line message, not with errors inside its templates
#   pkgconfig     against the installed package through pkg-config alone (softgl-model.pc, which requires
#                 softgl.pc): the compiler called with `pkg-config --cflags --libs softgl-model`, no CMake
# Variables: MODE, SOFTGL_BINARY_DIR, SOFTGL_SOURCE_DIR, CONSUMER_SOURCE_DIR, WORK_DIR, CXX (the compiler).
file(REMOVE_RECURSE "${WORK_DIR}")

include(${CMAKE_CURRENT_LIST_DIR}/../run_step.cmake)

set(configure_args)
if(MODE STREQUAL "subdirectory")
  set(source "${CONSUMER_SOURCE_DIR}/subdirectory")
  list(APPEND configure_args "-DSOFTGL_SOURCE_DIR=${SOFTGL_SOURCE_DIR}" -DSOFTGL_BUILD_TESTS=OFF
       -DSOFTGL_BUILD_EXAMPLES=OFF -DSOFTGL_INSTALL=OFF -DCMAKE_BUILD_TYPE=Debug)  # (what is tested is the
  # inclusion, not the code: unoptimized, the library builds in a fraction of the time)
else()
  set(source "${CONSUMER_SOURCE_DIR}")
  set(prefix "${WORK_DIR}/prefix")
  run("install" ${CMAKE_COMMAND} --install "${SOFTGL_BINARY_DIR}" --prefix "${prefix}")
  list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${prefix}")
  if(MODE STREQUAL "raised")
    list(APPEND configure_args -DCMAKE_CXX_STANDARD=17 -DCMAKE_CXX_STANDARD_REQUIRED=ON)
  endif()
endif()

if(MODE STREQUAL "pkgconfig")
  find_program(PKG_CONFIG pkg-config REQUIRED)
  set(ENV{PKG_CONFIG_PATH} "${prefix}/lib/pkgconfig:${prefix}/lib64/pkgconfig")
  file(GLOB pc_dirs "${prefix}/lib/*/pkgconfig")
  foreach(d IN LISTS pc_dirs)
    set(ENV{PKG_CONFIG_PATH} "${d}:$ENV{PKG_CONFIG_PATH}")
  endforeach()
  execute_process(COMMAND "${PKG_CONFIG}" --cflags --libs softgl-model RESULT_VARIABLE rc OUTPUT_VARIABLE flags
                  ERROR_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc)
    message(FATAL_ERROR "pkg-config --cflags --libs softgl-model failed: ${flags}")
  endif()
  if(NOT flags MATCHES "-I${prefix}/[^ ]*include" OR NOT flags MATCHES "-lsoftgl_model" OR NOT flags MATCHES "-lsoftgl( |$)")
    message(FATAL_ERROR "pkg-config gave flags that do not name the installed package: ${flags}")
  endif()
  separate_arguments(flag_list UNIX_COMMAND "${flags}")
  file(MAKE_DIRECTORY "${WORK_DIR}/build")
  run("compile" "${CXX}" "${CONSUMER_SOURCE_DIR}/main.cpp" -o "${WORK_DIR}/build/app" ${flag_list})
elseif(MODE STREQUAL "forced_old")
  execute_process(COMMAND "${CXX}" -std=c++17 "-I${prefix}/include" -c "${CONSUMER_SOURCE_DIR}/main.cpp"
                          -o "${WORK_DIR}/main.o" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  string(REGEX MATCHALL "error:" errors "${out}")
  list(LENGTH errors error_count)
  if(NOT rc OR NOT out MATCHES "softgl needs C\\+\\+20")
    message(FATAL_ERROR "a C++17 build should stop with softgl's message; got (${rc}):\n${out}")
  endif()
  # One #error and the stop: one message per translation unit, nothing from inside the templates.
  if(error_count GREATER 2)
    message(FATAL_ERROR "a C++17 build gave ${error_count} errors, expected softgl's message alone:\n${out}")
  endif()
  message(STATUS "forced C++17: stopped with softgl's message (${error_count} diagnostics)")
  return()
endif()

if(NOT MODE STREQUAL "pkgconfig")
  run("configure" ${CMAKE_COMMAND} -S "${source}" -B "${WORK_DIR}/build" ${configure_args})
  run("build" ${CMAKE_COMMAND} --build "${WORK_DIR}/build" -j 2 --target app)  # (not softgl-render: not what is tested)
endif()
execute_process(COMMAND "${WORK_DIR}/build/app" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message(STATUS "${out}")
if(rc)
  message(FATAL_ERROR "the consumer program failed (${rc}): ${out}")
endif()
if(NOT out MATCHES "C\\+\\+ level 202002")
  message(FATAL_ERROR "the consumer was not compiled as C++20: ${out}")
endif()
