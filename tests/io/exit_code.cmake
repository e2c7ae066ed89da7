# Runs EXE --scene SCENE --out OUT --threads 1 [ARGS] and prints "exit code N: <stderr>" (ctest matches it: an
# app's exit code and its message together).
execute_process(COMMAND ${EXE} --scene ${SCENE} --out ${OUT} --threads 1 ${ARGS} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
message("exit code ${rc}: ${err}")
# With -DSHOW=FILE, FILE (relative to OUT) is printed after it ("FILE: <contents>", or "FILE: missing").
if(DEFINED SHOW)
  if(EXISTS ${OUT}/${SHOW})
    file(READ ${OUT}/${SHOW} shown)
    message("${SHOW}: ${shown}")
  else()
    message("${SHOW}: missing")
  endif()
endif()
