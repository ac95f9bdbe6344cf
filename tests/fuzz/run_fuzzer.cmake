# One libFuzzer run as a ctest test (tests/fuzz/CMakeLists.txt): FUZZER for RUNS inputs from the
# committed CORPUS, deterministically (-seed=1). New inputs go to WORK, emptied first, so that the
# run depends on the binary and the committed corpus only and never writes into the repository.
# Fails on any crash, sanitizer report, leak, timeout (-timeout: one input over 25 s) or
# FUZZ_CHECK; the input that did it is kept as ARTIFACTS/<fuzzer>-crash-* (replay: FUZZER FILE).
foreach(v FUZZER RUNS CORPUS WORK ARTIFACTS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_fuzzer.cmake: -D${v}=... missing")
  endif()
endforeach()
if(NOT IS_DIRECTORY "${CORPUS}")
  message(FATAL_ERROR "run_fuzzer.cmake: no corpus ${CORPUS}")
endif()
get_filename_component(name "${FUZZER}" NAME)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}" "${ARTIFACTS}")
set(ENV{ASAN_OPTIONS} "detect_leaks=1:halt_on_error=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
execute_process(
  COMMAND "${FUZZER}" -runs=${RUNS} -seed=1 -max_len=4096 -timeout=25 -print_final_stats=1
          "-artifact_prefix=${ARTIFACTS}/${name}-" "${WORK}" "${CORPUS}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" units "${out}")
string(REGEX MATCH "stat::average_exec_per_sec: *[0-9]+" speed "${out}")
if(NOT rc EQUAL 0)
  string(LENGTH "${out}" n)
  if(n GREATER 6000)
    math(EXPR from "${n} - 6000")
    string(SUBSTRING "${out}" ${from} 6000 out)
  endif()
  message(FATAL_ERROR "${name}: FAILED (exit ${rc}); inputs in ${ARTIFACTS}\n${out}")
endif()
message(STATUS "${name}: ${RUNS} runs ok (${units}, ${speed})")
