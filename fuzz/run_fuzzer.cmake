# Runs FUZZER with OPTIONS over a fresh SCRATCH folder (where libFuzzer writes the inputs it
# finds, so that the seed corpus in the repository stays as it is) and the seeds in SEEDS.
file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")
execute_process(COMMAND "${FUZZER}" ${OPTIONS} "${SCRATCH}" "${SEEDS}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${result})")
endif()
