# ctest driver of the target replay tests (cmake/TargetCheck.cmake), run as
#   cmake -DMODE=compare|icount -DNAME=<system> ... -P run_replay_check.cmake
#
# MODE=compare (test target_replay_<name>): runs the host replay (HOST) and the Cortex-M7 replay
#   (ELF) under QEMU mps2-an500, requires exit status 0 from both, then replay_compare (COMPARE):
#   STEPS step lines each, exact statuses/counters, and every value within TOL relative to
#   max(|host value|, the column's stated scale). TOL = 1e-12 because:
#     - both sides are compiled with -ffp-contract=off (no FMA fusion: GCC would fuse a*b+c into
#       VFMA.F64 on the M7 otherwise) and the host with -DEIGEN_DONT_VECTORIZE (SSE2 would change
#       Eigen's summation order), so +, -, *, / and sqrt - IEEE-754 correctly rounded on both -
#       give identical results in identical order;
#     - what may still differ is the C library: newlib's and glibc's sin, cos, exp, log, pow,
#       tanh, erfc, ... are not correctly rounded and may differ in the last ulp (~1.1e-16
#       relative). A replay runs a few hundred steps through filters and adaptive laws whose
#       states carry such differences on, amplified by the conditioning of what follows; 1e-12
#       leaves about four orders of magnitude above one ulp for that. Measured: <= 6.7e-14.
#   Round-off-level changes stay below it too (the hybrid replay built with GCC's default FMA
#   contraction: 1.4e-13; with -ffast-math: 3.6e-14): the tolerance is not what detects them -
#   the printed bit-identical fraction is (98.5-100 % with the flags above). It fails on a
#   different computation: another branch or status (compared exactly), a parameter, input or
#   state that differs, single-precision arithmetic (~1e-8).
#   The result (max relative difference, bit-identical or not) is printed either way.
# MODE=icount (test target_icount_<name>): runs the ELF in cost mode under -icount shift=0, then
#   again for its first 40 steps only (argument steps=40), and requires the second output to
#   equal the first's header and first 40 step lines (instruction counts are deterministic; a
#   whole second run cost as much as the first: 27.7 s of QEMU alone for the drag-free System,
#   the 40-step run 3.3 s), STEPS
#   step lines with an icount field, and - when COSTS_JSON has this system - max icount per step
#   <= 2x the committed value (a loose regression gate; tools/target-costs.py refreshes the JSON).
foreach(v MODE NAME ELF QEMU STEPS WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_replay_check.cmake: -D${v}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY ${WORK})
# MACHINE: the QEMU board (mps2-an500: Cortex-M7; mps2-an386: Cortex-M4F). JSON_KEY: the section
# of COSTS_JSON holding this board's systems (systems, systems_m4f).
if(NOT DEFINED MACHINE)
  set(MACHINE mps2-an500)
endif()
if(NOT DEFINED JSON_KEY)
  set(JSON_KEY systems)
endif()
set(_qemu ${QEMU} -M ${MACHINE} -nographic -monitor none -serial none
          -semihosting-config enable=on,target=native)

if(MODE STREQUAL "compare")
  execute_process(COMMAND ${HOST} OUTPUT_FILE ${WORK}/host.txt RESULT_VARIABLE rc_host TIMEOUT 120)
  if(NOT rc_host EQUAL 0)
    message(FATAL_ERROR "host replay ${HOST} exited with '${rc_host}' (output: ${WORK}/host.txt)")
  endif()
  execute_process(COMMAND ${_qemu} -kernel ${ELF} OUTPUT_FILE ${WORK}/target.txt
                  ERROR_VARIABLE err RESULT_VARIABLE rc_target TIMEOUT 120)
  if(NOT rc_target EQUAL 0)
    message(FATAL_ERROR "QEMU replay ${ELF} exited with '${rc_target}' ${err} (output: ${WORK}/target.txt)")
  endif()
  execute_process(COMMAND ${COMPARE} ${WORK}/host.txt ${WORK}/target.txt ${STEPS} ${TOL}
                  RESULT_VARIABLE rc_cmp)
  if(NOT rc_cmp EQUAL 0)
    message(FATAL_ERROR "host and target replays of ${NAME} differ (see above; files in ${WORK})")
  endif()

elseif(MODE STREQUAL "icount")
  set(_prefix_steps 40)
  foreach(run 1 2)
    set(_args cost)
    if(run EQUAL 2)
      set(_args "cost steps=${_prefix_steps}")
    endif()
    execute_process(COMMAND ${_qemu} -icount shift=0 -kernel ${ELF} -append ${_args}
                    OUTPUT_FILE ${WORK}/cost${run}.txt ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 300)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "QEMU cost run ${run} of ${ELF} exited with '${rc}' ${err} (output: ${WORK}/cost${run}.txt)")
    endif()
  endforeach()
  file(READ ${WORK}/cost1.txt a)
  # The second run's lines are the first's up to its step K - 1, but for the step counts in the
  # first ("steps=") and last ("# done steps=") lines.
  file(STRINGS ${WORK}/cost1.txt a_lines)
  file(STRINGS ${WORK}/cost2.txt b_lines)
  list(LENGTH b_lines nb)
  list(LENGTH a_lines na)
  if(nb LESS 3 OR na LESS nb)
    message(FATAL_ERROR "${NAME}: the prefix run has ${nb} lines, the full run ${na} (${WORK}/cost2.txt)")
  endif()
  math(EXPR last "${nb} - 2")
  foreach(i RANGE 0 ${last})
    list(GET a_lines ${i} la)
    list(GET b_lines ${i} lb)
    if(i EQUAL 0)
      string(REGEX REPLACE " steps=[0-9]+" "" la "${la}")
      string(REGEX REPLACE " steps=[0-9]+" "" lb "${lb}")
    endif()
    if(NOT la STREQUAL lb)
      message(FATAL_ERROR "two -icount runs of ${NAME} differ at line ${i}: instruction counts are not "
                          "deterministic (diff ${WORK}/cost1.txt ${WORK}/cost2.txt)")
    endif()
  endforeach()
  list(GET b_lines -1 lb)
  if(NOT lb STREQUAL "# done steps=${_prefix_steps}")
    message(FATAL_ERROR "${NAME}: the prefix run ended with '${lb}' (${WORK}/cost2.txt)")
  endif()
  string(REGEX MATCHALL " icount=[0-9]+" counts "${a}")
  list(LENGTH counts n)
  if(NOT n EQUAL STEPS)
    message(FATAL_ERROR "${NAME}: ${n} measured steps, expected ${STEPS} (${WORK}/cost1.txt)")
  endif()
  set(max 0)
  foreach(c IN LISTS counts)
    string(REGEX REPLACE " icount=" "" c "${c}")
    if(c GREATER max)
      set(max ${c})
    endif()
  endforeach()
  message(STATUS "${NAME}: ${n} steps, identical counts in the first ${_prefix_steps} of two runs, max ${max} instructions per step")
  if(DEFINED COSTS_JSON AND EXISTS ${COSTS_JSON})
    file(READ ${COSTS_JSON} json)
    string(JSON committed ERROR_VARIABLE jerr GET "${json}" ${JSON_KEY} ${NAME} instructions_per_step max)
    if(NOT jerr AND committed GREATER 0)
      math(EXPR limit "2 * ${committed}")
      if(max GREATER limit)
        message(FATAL_ERROR "${NAME}: max ${max} instructions per step > 2 x ${committed} "
                            "(bench/target-costs.json); if intended, rerun tools/target-costs.py")
      endif()
      message(STATUS "${NAME}: within 2 x the committed max (${committed})")
    endif()
  endif()
else()
  message(FATAL_ERROR "MODE must be compare or icount")
endif()
