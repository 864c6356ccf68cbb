# A misuse of the shader API must stop the compile with softgl's own message, and the same file without the
# misuse (its control) must compile: so the message comes from the misuse, not from a broken command.
#   cmake -DCXX=... -DINCLUDE=<softgl's include folder> -DSOURCE=<file> -DEXPECT=<regex> -P run.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../run_step.cmake)
set(flags -std=c++20 -fsyntax-only -I${INCLUDE})
run("control of ${SOURCE}" ${CXX} ${flags} ${SOURCE})
execute_process(COMMAND ${CXX} ${flags} -DSOFTGL_MISUSE ${SOURCE} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
if(NOT rc)
  message(FATAL_ERROR "the misuse in ${SOURCE} compiled")
endif()
if(NOT out MATCHES "${EXPECT}")
  message(FATAL_ERROR "the misuse in ${SOURCE} failed without the message '${EXPECT}':\n${out}")
endif()
message(STATUS "misuse in ${SOURCE}: stopped with '${EXPECT}'")
