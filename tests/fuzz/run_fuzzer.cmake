# One libFuzzer run as a ctest test (tests/fuzz/CMakeLists.txt): FUZZER first replays every input
# of the committed CORPORA (the hand-made seeds of make_corpus.py and the inputs earlier campaigns
# found, minimised with -merge=1: tests/fuzz/corpus-found/), then tries NEW inputs of its own,
# deterministically (-seed=1). Inputs it finds go to WORK, emptied first, so that the run depends
# on the binary and the committed corpora only and never writes into the repository
# (tools/merge-fuzz-corpus.sh commits them). Fails on any crash, sanitizer report, leak, timeout
# (-timeout: one input over 25 s) or FUZZ_CHECK; the input that did it is kept as
# ARTIFACTS/<fuzzer>-crash-* (replay: FUZZER FILE).
foreach(v FUZZER NEW CORPORA WORK ARTIFACTS)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_fuzzer.cmake: -D${v}=... missing")
  endif()
endforeach()
set(seeds 0)
foreach(dir IN LISTS CORPORA)
  if(NOT IS_DIRECTORY "${dir}")
    message(FATAL_ERROR "run_fuzzer.cmake: no corpus ${dir}")
  endif()
  file(GLOB inputs "${dir}/*")
  list(LENGTH inputs n)
  math(EXPR seeds "${seeds} + ${n}")
endforeach()
# libFuzzer executes every corpus input before it mutates, and -runs counts both.
math(EXPR runs "${seeds} + ${NEW}")
get_filename_component(name "${FUZZER}" NAME)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}" "${ARTIFACTS}")
set(ENV{ASAN_OPTIONS} "detect_leaks=1:halt_on_error=1")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
execute_process(
  COMMAND "${FUZZER}" -runs=${runs} -seed=1 -max_len=4096 -timeout=25 -print_final_stats=1
          "-artifact_prefix=${ARTIFACTS}/${name}-" "${WORK}" ${CORPORA}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" units "${out}")
string(REGEX MATCH "stat::average_exec_per_sec: *[0-9]+" speed "${out}")
string(REGEX MATCH "INITED cov: [0-9]+ ft: [0-9]+" inited "${out}")
string(REGEX MATCH "DONE +cov: [0-9]+ ft: [0-9]+" done "${out}")
if(NOT rc EQUAL 0)
  string(LENGTH "${out}" n)
  if(n GREATER 6000)
    math(EXPR from "${n} - 6000")
    string(SUBSTRING "${out}" ${from} 6000 out)
  endif()
  message(FATAL_ERROR "${name}: FAILED (exit ${rc}); inputs in ${ARTIFACTS}\n${out}")
endif()
message(STATUS "${name}: ${seeds} corpus inputs replayed + ${NEW} new, ok (${units}, ${speed}; after the corpus ${inited}; at the end ${done})")
