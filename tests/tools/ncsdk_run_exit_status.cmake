# The built ncsdk_run executable's exit status on a shipped scenario (0), the same scenario with one
# wrong expectation (1, the check named on stderr) and a bad input (2, the JSON pointer named).
# cmake -DRUN=<ncsdk_run> -DSCENARIOS=<docs/scenarios> -DOUT=<scratch folder> -P this file
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

function(expect_status status what)
  execute_process(COMMAND ${RUN} ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL status)
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${status}\n${err}")
  endif()
  set(stderr_text "${err}" PARENT_SCOPE)
endfunction()

expect_status(0 "shipped scenario" ${SCENARIOS}/axes/seed_axis.json ${SCENARIOS}/dynamics_1_1.json
              --out ${OUT}/ok)

file(READ ${SCENARIOS}/dynamics_1_1.json timeline)
string(REPLACE "\"field\": \"SetPos\", \"value\": 1000" "\"field\": \"SetPos\", \"value\": 999"
       wrong "${timeline}")
if(wrong STREQUAL timeline)
  message(FATAL_ERROR "the end-position check of dynamics_1_1.json was not found")
endif()
file(WRITE ${OUT}/wrong.json "${wrong}")
expect_status(1 "wrong expectation" ${SCENARIOS}/axes/seed_axis.json ${OUT}/wrong.json
              --out ${OUT}/wrong)
if(NOT stderr_text MATCHES "check /expect/1 failed")
  message(FATAL_ERROR "the failed check is not named: ${stderr_text}")
endif()

string(REPLACE "\"MC_MoveAbsolute\"" "\"MC_MoveAbsolut\"" bad "${timeline}")
file(WRITE ${OUT}/bad.json "${bad}")
expect_status(2 "bad input" ${SCENARIOS}/axes/seed_axis.json ${OUT}/bad.json --out ${OUT}/bad)
if(NOT stderr_text MATCHES "/timeline/1/type: unknown block type 'MC_MoveAbsolut'")
  message(FATAL_ERROR "the bad input's pointer is not named: ${stderr_text}")
endif()
if(EXISTS ${OUT}/bad)
  message(FATAL_ERROR "a bad input wrote output")
endif()
