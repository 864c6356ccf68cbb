# The documentation's code, compiled: installs this build into a private prefix, turns the ```cpp and ```cmake
# blocks of the Markdown files into a project (extract_snippets), builds it against the package with
# -Wall -Wextra -Wpedantic -Werror at the compiler's default language level (every installed header also compiled
# on its own), and runs each complete program in a folder of its own.
# Variables: EXTRACT (the extract_snippets program), SOFTGL_BINARY_DIR, WORK_DIR, DOCS (a list of Markdown files).
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

include(${CMAKE_CURRENT_LIST_DIR}/../run_step.cmake)

run("install" ${CMAKE_COMMAND} --install "${SOFTGL_BINARY_DIR}" --prefix "${prefix}")
run("extract" "${EXTRACT}" "${WORK_DIR}/project" "${prefix}/include" ${DOCS})
run("configure" ${CMAKE_COMMAND} -S "${WORK_DIR}/project" -B "${WORK_DIR}/build" "-DCMAKE_PREFIX_PATH=${prefix}")
run("build" ${CMAKE_COMMAND} --build "${WORK_DIR}/build" -j 2)
file(STRINGS "${WORK_DIR}/project/programs.txt" programs)
foreach(program IN LISTS programs)
  file(MAKE_DIRECTORY "${WORK_DIR}/run/${program}")
  execute_process(COMMAND "${WORK_DIR}/build/${program}" WORKING_DIRECTORY "${WORK_DIR}/run/${program}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc)
    message(FATAL_ERROR "program ${program} (see ${WORK_DIR}/project/${program}.cpp) failed (${rc}):\n${out}")
  endif()
  message(STATUS "program ${program}: ran")
endforeach()
