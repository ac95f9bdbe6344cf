# Cortex-M7 checks (docs/TARGET.md), target adcs_target_check (not in ALL), ctest label target:
#  1. compile check: every public header of include/adcs checked on its own by arm-none-eabi-g++
#     with flight flags (no exceptions, no RTTI, Eigen heap forbidden; -fsyntax-only), plus five
#     translation units that instantiate every controller/plant template with concrete sizes
#     (a header alone does not instantiate its templates; -fsyntax-only too, see 1b). Any
#     warning fails.
#  2. replays of the four paper controllers/estimators (tests/target): inputs recorded at build
#     time from host closed loops, replayed on the host and on QEMU mps2-an500 (separate CMake
#     project tests/target with cmake/arm-none-eabi.cmake, built into <build>/target), compared
#     to 1e-12, and instruction counts per step() checked deterministic.
# ctest: target_compile_check builds adcs_target_check (the fixture adcs_target_build the replay
# tests require), then target_replay_<name> and target_icount_<name>.
find_program(ADCS_ARM_CXX arm-none-eabi-g++)
set(ADCS_ARM_FLAGS
  -mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard -mthumb -O2 -std=c++17
  -fno-exceptions -fno-rtti -fno-threadsafe-statics -ffunction-sections -fdata-sections
  -DEIGEN_NO_MALLOC -Wall -Wextra -Wpedantic -Werror)

if(NOT ADCS_ARM_CXX)
  message(WARNING "arm-none-eabi-g++ not found: the Cortex-M7 check will fail; run tools/setup-deps.sh")
  add_test(NAME target_compile_check
           COMMAND ${CMAKE_COMMAND} -E echo "arm-none-eabi-g++ not found: run tools/setup-deps.sh")
  set_tests_properties(target_compile_check PROPERTIES LABELS target WILL_FAIL ON)
  return()
endif()

get_target_property(_eigen_inc Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
file(GLOB_RECURSE ADCS_PUBLIC_HEADERS CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/include
     ${PROJECT_SOURCE_DIR}/include/adcs/*.hpp)
# The folder headers (adcs/control.hpp, adcs/estimate.hpp, ...) are lists of #includes of headers
# checked alone here; only the umbrella adcs/adcs.hpp, which includes them all, is checked with
# them (CI time: the folder headers cost ~80 CPU-s and can fail only where a header they list fails).
set(_folder_headers ${ADCS_PUBLIC_HEADERS})
list(FILTER _folder_headers INCLUDE REGEX "^adcs/[a-z_]+\\.hpp$")
list(REMOVE_ITEM _folder_headers adcs/adcs.hpp)
set(_outputs)
set(_header_paths)
foreach(h IN LISTS _folder_headers)
  list(APPEND _header_paths ${PROJECT_SOURCE_DIR}/include/${h})
endforeach()
list(REMOVE_ITEM ADCS_PUBLIC_HEADERS ${_folder_headers})
set(_gen ${CMAKE_BINARY_DIR}/target_check)
# 1a. Each header alone, -fsyntax-only: self-contained, warning-free, with the M7's headers and
#     flags. No object: a header alone instantiates nothing that the units of 1b and the replay
#     ELFs do not compile to code anyway.
#     The umbrella adcs/adcs.hpp, which includes every header, is checked by arm-none-eabi-g++;
#     each header alone by clang++-14 targeting the same Cortex-M7 (--target=arm-none-eabi, same
#     -mcpu/-mfpu/-mfloat-abi, flags and warnings) with arm-none-eabi-g++'s own C++ and newlib
#     headers: self-containedness is a property of the header, and g++ instantiates every template
#     a non-template inline function calls (~190 CPU-s for the 60 headers alone, ~110 with clang;
#     docs/DECISIONS.md, "CI under 20 minutes"). Without clang++-14 every header goes to g++.
find_program(ADCS_CLANG_CXX NAMES clang++-14 clang++)
set(_clang_arm)
if(ADCS_CLANG_CXX)
  # arm-none-eabi-g++'s include search list for these flags (libstdc++, its multilib, newlib).
  execute_process(COMMAND ${ADCS_ARM_CXX} ${ADCS_ARM_FLAGS} -E -x c++ - -v INPUT_FILE /dev/null
                  OUTPUT_QUIET ERROR_VARIABLE _arm_v RESULT_VARIABLE _arm_rc)
  string(REGEX MATCH "#include <\\.\\.\\.> search starts here:\n(.*)End of search list" _m "${_arm_v}")
  string(REGEX MATCHALL "[^ \n]+" _arm_dirs "${CMAKE_MATCH_1}")
  if(_arm_rc EQUAL 0 AND _arm_dirs)
    set(_clang_arm ${ADCS_CLANG_CXX} --target=arm-none-eabi ${ADCS_ARM_FLAGS} -nostdinc++ -nostdlibinc)
    foreach(d IN LISTS _arm_dirs)
      list(APPEND _clang_arm -isystem ${d})
    endforeach()
  else()
    message(STATUS "Cortex-M7 header check: arm-none-eabi-g++'s include dirs not found, every header goes to g++")
  endif()
endif()
# The M7 compiler of every check below but the umbrella header and the replays: clang when its
# arm-none-eabi include directories were found, else arm-none-eabi-g++.
if(_clang_arm)
  set(_m7_cxx ${_clang_arm})
  set(_m7_who "clang++ --target=arm-none-eabi")
else()
  set(_m7_cxx ${ADCS_ARM_CXX} ${ADCS_ARM_FLAGS})
  set(_m7_who "arm-none-eabi-g++")
endif()
# The per-header units and stamps in target_check/one_header/: Ninja 1.11 starts ready commands in
# build.ninja's order, where CMake writes a target's custom commands sorted by output path, so
# the long ones (the umbrella header by g++, the instantiation units, the M4F float unit: 15-45 s
# each) now come before the ~55 short ones instead of after them, where they ended the build
# alone (docs/DECISIONS.md, "CI under 20 minutes").
file(MAKE_DIRECTORY ${_gen}/one_header)
# With clang, adcs/core/types.hpp (Eigen/Core and Eigen/Geometry: ~2 of the ~2.3 CPU-s of each
# check) is parsed once into a precompiled header, which the check of every header that includes
# it, directly or through other adcs headers, loads first. That is what compiling such a header
# alone does anyway: it includes types.hpp before it can name Eigen or an adcs type, and types.hpp
# defines nothing that a header's own lines before that include could use unnoticed (each header
# included on the way is checked alone too). The headers that do not reach types.hpp (status,
# failure hook and policy, ...) are checked without it, so a missing standard include is not
# masked by what Eigen includes (docs/DECISIONS.md, "CI under 20 minutes", item 23).
set(_types_h adcs/core/types.hpp)
foreach(h IN LISTS ADCS_PUBLIC_HEADERS)  # each header's adcs includes, read once
  file(STRINGS ${PROJECT_SOURCE_DIR}/include/${h} _incs REGEX "^#include \"adcs/")
  list(TRANSFORM _incs REPLACE "^#include \"([^\"]+)\".*" "\\1")
  set(_incs_of_${h} ${_incs})
endforeach()
set(_reach_types ${_types_h})
set(_changed ON)
while(_changed)
  set(_changed OFF)
  foreach(h IN LISTS ADCS_PUBLIC_HEADERS)
    if(NOT h IN_LIST _reach_types)
      foreach(i IN LISTS _incs_of_${h})
        if(i IN_LIST _reach_types)
          list(APPEND _reach_types ${h})
          set(_changed ON)
          break()
        endif()
      endforeach()
    endif()
  endforeach()
endwhile()
set(_types_pch)
if(_clang_arm)
  set(_types_pch ${_gen}/one_header/types.hpp.pch)
  add_custom_command(OUTPUT ${_types_pch}
    COMMAND ${_clang_arm} -I${PROJECT_SOURCE_DIR}/include -isystem ${_eigen_inc}
            -x c++-header ${PROJECT_SOURCE_DIR}/include/${_types_h} -o ${_types_pch}
    DEPENDS ${PROJECT_SOURCE_DIR}/include/${_types_h}
    IMPLICIT_DEPENDS CXX ${PROJECT_SOURCE_DIR}/include/${_types_h}
    COMMENT "clang++ --target=arm-none-eabi: precompiled ${_types_h} for the header checks" VERBATIM)
endif()
foreach(h IN LISTS ADCS_PUBLIC_HEADERS)
  string(REPLACE "/" "__" stem ${h})
  string(REPLACE ".hpp" "" stem ${stem})
  if(NOT h STREQUAL "adcs/adcs.hpp")
    set(stem one_header/${stem})
  endif()
  set(tu ${_gen}/${stem}.cpp)
  file(WRITE ${tu}.in "// generated: compile ${h} alone for Cortex-M7\n#include \"${h}\"\n")
  configure_file(${tu}.in ${tu} COPYONLY)
  set(stamp ${_gen}/${stem}.checked)
  if(h STREQUAL "adcs/adcs.hpp")
    set(_cxx ${ADCS_ARM_CXX} ${ADCS_ARM_FLAGS})
    set(_who "arm-none-eabi-g++")
  else()
    set(_cxx ${_m7_cxx})
    set(_who ${_m7_who})
  endif()
  set(_pch_args)
  set(_pch_dep)
  if(_types_pch AND h IN_LIST _reach_types AND NOT h STREQUAL _types_h AND NOT h STREQUAL "adcs/adcs.hpp")
    set(_pch_args -include-pch ${_types_pch})
    set(_pch_dep ${_types_pch})
  endif()
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${_cxx} ${_pch_args} -I${PROJECT_SOURCE_DIR}/include -isystem ${_eigen_inc} -fsyntax-only ${tu}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${tu} ${PROJECT_SOURCE_DIR}/include/${h} ${_pch_dep}
    IMPLICIT_DEPENDS CXX ${tu}
    COMMENT "${_who} -fsyntax-only (Cortex-M7) ${h}" VERBATIM)
  list(APPEND _outputs ${stamp})
  list(APPEND _header_paths ${PROJECT_SOURCE_DIR}/include/${h})
endforeach()
# 1b. Every flight template instantiated with concrete sizes for the M7, in five units
#     (tests/target/instantiate_*.cpp: attitude and seed 001, seeds 002, 003, 004, and the
#     27-state filter) that the cores build side by side: every member of every class and free
#     function template goes through the front end with the M7's types (32-bit int/long/size_t),
#     newlib and libstdc++, and its warnings fail the build. Compiled by clang++-14
#     --target=arm-none-eabi like the headers of 1a (same flags, arm-none-eabi-g++'s libstdc++ and
#     newlib): g++ spends ~90 % of these units in template instantiation (instantiate_seed004.cpp
#     101 s with arm-none-eabi-g++ -O2, 35 s with clang). -fsyntax-only: the code generation,
#     half of clang's time here (instantiate_seed004.cpp 41 -> 18 CPU-s, instantiate_attitude.cpp
#     41 -> 19), adds no diagnostic for this code, and M7 code is what arm-none-eabi-g++ generates
#     with -Werror for the umbrella header and the replay ELFs of part 2, i.e. every step the
#     paper systems run on the board (docs/DECISIONS.md, "CI under 20 minutes", items 8 and 19).
#     Without clang++-14 the units go to g++, also -fsyntax-only (g++ instantiates there too).
foreach(unit attitude seed002 seed003 seed004 eskf27)
  set(_inst ${PROJECT_SOURCE_DIR}/tests/target/instantiate_${unit}.cpp)
  add_custom_command(OUTPUT ${_gen}/instantiate_${unit}.ok
    COMMAND ${_m7_cxx} -I${PROJECT_SOURCE_DIR}/include -I${PROJECT_SOURCE_DIR}/src
            -isystem ${_eigen_inc} -fsyntax-only ${_inst}
    COMMAND ${CMAKE_COMMAND} -E touch ${_gen}/instantiate_${unit}.ok
    DEPENDS ${_inst} ${_header_paths}
    COMMENT "${_m7_who} -fsyntax-only (Cortex-M7) instantiate_${unit}.cpp" VERBATIM)
  list(APPEND _outputs ${_gen}/instantiate_${unit}.ok)
endforeach()
# 1c. Cortex-M4F, single precision (issue 19): the float instances compiled for an FPU without
#     double (-mfpu=fpv4-sp-d16) by arm-none-eabi-g++ with -Wdouble-promotion -Wfloat-conversion
#     (any float computation promoted to double fails the build), and ctest target_m4f_no_double
#     walks the object's call graph from the step entry points (tools/check-float-calls.py): no
#     software-double helper and no double libm function may be reachable.
set(ADCS_M4F_FLAGS
  -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb -O2 -std=c++17
  -fno-exceptions -fno-rtti -fno-threadsafe-statics -ffunction-sections -fdata-sections
  -DEIGEN_NO_MALLOC -Wall -Wextra -Wpedantic -Wdouble-promotion -Wfloat-conversion -Werror)
set(_m4f_obj ${_gen}/m4f_float_steps.o)
add_custom_command(OUTPUT ${_m4f_obj}
  COMMAND ${ADCS_ARM_CXX} ${ADCS_M4F_FLAGS} -I${PROJECT_SOURCE_DIR}/include -isystem ${_eigen_inc}
          -c ${PROJECT_SOURCE_DIR}/tests/target/m4f_float_steps.cpp -o ${_m4f_obj}
  DEPENDS ${PROJECT_SOURCE_DIR}/tests/target/m4f_float_steps.cpp ${_header_paths}
  COMMENT "arm-none-eabi-g++ (Cortex-M4F, float) m4f_float_steps.cpp" VERBATIM)
list(APPEND _outputs ${_m4f_obj})
# The same unit with every float class instantiated whole (seed 001's constructor included), by
# the clang of 1a with the M4F's -mcpu/-mfpu, -fsyntax-only: the warnings without the ~70
# arm-none-eabi-g++ CPU-s of code generation for a start-up-only design (docs/DECISIONS.md).
if(_clang_arm)
  string(REPLACE "-mcpu=cortex-m7;-mfpu=fpv5-d16" "-mcpu=cortex-m4;-mfpu=fpv4-sp-d16" _m4f_clang "${_clang_arm}")
  add_custom_command(OUTPUT ${_gen}/m4f_float_whole.ok
    COMMAND ${_m4f_clang} -fsyntax-only -Wdouble-promotion -Wfloat-conversion -DADCS_M4F_WHOLE_CLASS
            -I${PROJECT_SOURCE_DIR}/include -isystem ${_eigen_inc} ${PROJECT_SOURCE_DIR}/tests/target/m4f_float_steps.cpp
    COMMAND ${CMAKE_COMMAND} -E touch ${_gen}/m4f_float_whole.ok
    DEPENDS ${PROJECT_SOURCE_DIR}/tests/target/m4f_float_steps.cpp ${_header_paths}
    COMMENT "clang++ --target=arm-none-eabi (Cortex-M4F) -fsyntax-only m4f_float_steps.cpp, whole classes" VERBATIM)
  list(APPEND _outputs ${_gen}/m4f_float_whole.ok)
endif()
# The C interface (src/c/adcs_c*.cpp) on the M4F: the cross project's adcs_c_target
# (tests/target/CMakeLists.txt) compiles it with -Wdouble-promotion -Wfloat-conversion -Werror
# there, its static_asserts check the header's state sizes on this ABI, and
# target_m4f_c_api_no_double walks that library: its float entry points must reach no double
# routine either (a second compile of the library here, as before, cost ~22 CPU-s).
set(_m4f_c_lib ${CMAKE_BINARY_DIR}/target-m4f/libadcs_c_target.a)
find_program(ADCS_ARM_OBJDUMP arm-none-eabi-objdump)
find_package(Python3 COMPONENTS Interpreter)
if(ADCS_ARM_OBJDUMP AND Python3_Interpreter_FOUND)
  add_test(NAME target_m4f_no_double
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/check-float-calls.py ${ADCS_ARM_OBJDUMP}
                   ${_m4f_obj} adcs_m4f_adaptive_tracking_step adcs_m4f_eso_adrc_attitude_step
                   adcs_m4f_eso_adrc_attitude_init adcs_m4f_ftsmc_se3_step adcs_m4f_ftsmc_se3_init adcs_m4f_saturated_quantizer_step
                   adcs_m4f_saturated_quantizer_init adcs_m4f_ud_factorize adcs_m4f_mwgs_ud
                   adcs_m4f_agee_turner_update adcs_m4f_bierman_update adcs_m4f_sparse_propagate
                   adcs_m4f_drag_free_eskf_step adcs_m4f_saturated_esf_step adcs_m4f_saturated_esf_init
                   adcs_m4f_pid_step)
  add_test(NAME target_m4f_c_api_no_double
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/check-float-calls.py ${ADCS_ARM_OBJDUMP}
                   ${_m4f_c_lib} adcs_mrp_pd4f_init adcs_mrp_pd4f_step adcs_rw_alloc4f_init adcs_rw_alloc4f_step
                   adcs_ppcf_init adcs_ppcf_step adcs_hybrid43f_init adcs_hybrid43f_step adcs_se3_ptcf_init
                   adcs_se3_ptcf_step adcs_drag_free_adrcf_init adcs_drag_free_adrcf_step)
  set_tests_properties(target_m4f_no_double target_m4f_c_api_no_double PROPERTIES LABELS target
                       FIXTURES_REQUIRED adcs_target_build)
endif()

add_custom_target(adcs_target_check)
# Everything adcs_target_check builds on the host side: the compile checks, the gain and model
# designs, the recorded inputs, the host replays and the comparator; adcs_target_check adds the
# two nested Cortex-M builds. tools/run-tests.sh builds this with the host objects at -j 2 and
# then the nested builds one after the other (docs/DECISIONS.md, "CI under 20 minutes",
# item 26): on 2 cores, six compilers at once (two jobs here, two in each nested build) took
# twice the CPU time of two at once.
add_custom_target(adcs_target_host)
add_dependencies(adcs_target_check adcs_target_host)
add_test(NAME target_compile_check
         COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target adcs_target_check)
set_tests_properties(target_compile_check PROPERTIES LABELS target TIMEOUT 1800
                     FIXTURES_SETUP adcs_target_build)

# ---- 2. Host/target replays -----------------------------------------------------------------
set(ADCS_REPLAY_STEPS 400 CACHE STRING "Recorded steps per replay (>= 200)")
if(NOT ADCS_REPLAY_STEPS GREATER_EQUAL 200)
  message(FATAL_ERROR "ADCS_REPLAY_STEPS must be >= 200 (issue 7), got '${ADCS_REPLAY_STEPS}'")
endif()
# Every core (24 GiB on the 2-core CI machine; one seed-004 unit needs ~2 GB of RAM).
cmake_host_system_information(RESULT _ncores QUERY NUMBER_OF_LOGICAL_CORES)
set(ADCS_TARGET_BUILD_JOBS ${_ncores} CACHE STRING "Parallel jobs of the nested Cortex-M7 build")
set(ADCS_REPLAY_SYSTEMS hybrid ppc se3 dragfree attitude)
# Float Systems, replayed on the Cortex-M4F (issue 19).
set(ADCS_REPLAY_SYSTEMS_M4F attitude_f ppc_f atc_f eso_adrc_f hybrid_f se3_f se3_ftsmc_f dragfree_f)
set(_api_attitude replay::kAttitude)
set(_api_attitude_f replay::kAttitudeF)
set(_api_ppc_f replay::kPpcF)
set(_api_hybrid_f replay::kHybridF)
set(_api_se3_f replay::kSe3F)
set(_api_dragfree_f replay::kDragFreeF)
set(_api_atc_f replay::kAtcF)
set(_api_eso_adrc_f replay::kEsoAdrcF)
set(_api_se3_ftsmc_f replay::kSe3FtsmcF)
set(_api_hybrid replay::kHybrid)
set(_api_ppc replay::kPpc)
set(_api_se3 replay::kSe3)
set(_api_dragfree replay::kDragFree)
set(_tr ${PROJECT_SOURCE_DIR}/tests/target)
set(_rdir ${CMAKE_BINARY_DIR}/target_replay)
set(_rgen ${_rdir}/gen)
set(_tdir ${CMAKE_BINARY_DIR}/target)
list(GET _eigen_inc 0 _eigen_inc0)
file(MAKE_DIRECTORY ${_rgen})

# Host side: each System's core compiled once (shared by the recorder and the host replay), with
# the target's arithmetic: no FMA contraction, no SSE reordering of Eigen's sums. The recorder
# uses the same flags: EIGEN_DONT_VECTORIZE changes Eigen's alignment and inline code, which must
# not differ between translation units linked together (ODR).
add_library(adcs_replay_host_flags INTERFACE)
target_compile_options(adcs_replay_host_flags INTERFACE -ffp-contract=off)
target_compile_definitions(adcs_replay_host_flags INTERFACE EIGEN_DONT_VECTORIZE)
target_include_directories(adcs_replay_host_flags INTERFACE ${_tr} ${PROJECT_SOURCE_DIR}/src)  # scenarios/seed003_data.hpp
target_link_libraries(adcs_replay_host_flags INTERFACE adcs::adcs adcs_warnings)
# ADCS_SHORT_RUN_OPT (top-level CMakeLists.txt; tools/run-tests.sh sets -O0 for this tree): these
# programs run ADCS_REPLAY_STEPS steps once, in milliseconds, and nothing else in their
# executables runs a loop; -ffp-contract=off and no vectorisation make every optimisation level
# give the same bits (the recorded inputs and expected outputs; docs/DECISIONS.md, "CI under 20
# minutes", item 24).
target_link_libraries(adcs_replay_host_flags INTERFACE adcs_short_run_options)
# Seed 001's gain table (replay_gains_hybrid.hpp): designed on the host by design_gains.cpp, the
# ground segment, and compiled into the hybrid System on every side, which builds its law from
# it (HybridAdaptive(params, gains)) and so compiles no pole placement or Lyapunov solve: ~30 %
# of the M7 replay's arm-none-eabi-g++ time, ~45 % of a float one's on the M4F
# (docs/DECISIONS.md, "CI under 20 minutes", item 20).
# A host program built with the replays' arithmetic and run at build time to write one header
# into the generated directory (usage: program <out.hpp>).
function(adcs_replay_generator name out comment)
  add_executable(${name} EXCLUDE_FROM_ALL ${ARGN})
  target_link_libraries(${name} PRIVATE adcs_replay_host_flags)
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${_rdir})
  add_custom_command(OUTPUT ${_rgen}/${out} COMMAND ${name} ${_rgen}/${out} DEPENDS ${name}
                     COMMENT "${comment}" VERBATIM)
endfunction()
adcs_replay_generator(adcs_design_gains replay_gains_hybrid.hpp
                      "Designing seed 001's replay gains on the host (K, P)" ${_tr}/design_gains.cpp)
target_include_directories(adcs_replay_host_flags INTERFACE ${_rgen})
foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS ADCS_REPLAY_SYSTEMS_M4F)
  add_library(adcs_replay_core_${sys} OBJECT EXCLUDE_FROM_ALL ${_tr}/replay_${sys}.cpp)
  target_link_libraries(adcs_replay_core_${sys} PUBLIC adcs_replay_host_flags)
endforeach()
target_sources(adcs_replay_core_hybrid PRIVATE ${_rgen}/replay_gains_hybrid.hpp)
target_sources(adcs_replay_core_hybrid_f PRIVATE ${_rgen}/replay_gains_hybrid.hpp)
# Seed 004's discrete model (replay_model_dragfree.hpp): the 27-state ZOH and the three axis
# models, discretised on the host by design_dragfree_model.cpp, so that neither board compiles the
# matrix exponential (docs/DECISIONS.md, row "Seed 004 on the Cortex-M4F").
adcs_replay_generator(adcs_design_dragfree_model replay_model_dragfree.hpp
                      "Discretising seed 004's replay model on the host" ${_tr}/design_dragfree_model.cpp)
target_sources(adcs_replay_core_dragfree PRIVATE ${_rgen}/replay_model_dragfree.hpp)
target_sources(adcs_replay_core_dragfree_f PRIVATE ${_rgen}/replay_model_dragfree.hpp)

# The recorder closes each paper loop around the System cores and writes the input rows.
add_executable(adcs_record_inputs EXCLUDE_FROM_ALL ${_tr}/record_inputs.cpp)
target_include_directories(adcs_record_inputs PRIVATE ${PROJECT_SOURCE_DIR}/src)
target_link_libraries(adcs_record_inputs PRIVATE adcs_replay_host_flags)
set_target_properties(adcs_record_inputs PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${_rdir})
set(_inputs)
foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS ADCS_REPLAY_SYSTEMS_M4F)
  target_link_libraries(adcs_record_inputs PRIVATE adcs_replay_core_${sys})
  add_custom_command(OUTPUT ${_rgen}/replay_inputs_${sys}.hpp
    COMMAND adcs_record_inputs ${sys} ${_rgen}/replay_inputs_${sys}.hpp ${ADCS_REPLAY_STEPS}
    DEPENDS adcs_record_inputs
    COMMENT "Recording the ${sys} replay inputs (${ADCS_REPLAY_STEPS} closed-loop steps)" VERBATIM)
  list(APPEND _inputs ${_rgen}/replay_inputs_${sys}.hpp)
endforeach()
# The C example's expected results (examples/c/cfs_reference.cpp), computed with the target's
# arithmetic like the replay inputs, for the application the M7 runs (c_example_m7.elf).
enable_language(C)  # the example's plant is C (examples/c/cubesat_plant.c)
adcs_replay_generator(adcs_c_example_reference cfs_expected.h
                      "C example: the C++ components' results for the Cortex-M7 run"
                      ${PROJECT_SOURCE_DIR}/examples/c/cfs_reference.cpp ${PROJECT_SOURCE_DIR}/examples/c/cubesat_plant.c)
list(APPEND _inputs ${_rgen}/cfs_expected.h ${_rgen}/replay_gains_hybrid.hpp ${_rgen}/replay_model_dragfree.hpp)
add_custom_target(adcs_replay_inputs DEPENDS ${_inputs})

foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS ADCS_REPLAY_SYSTEMS_M4F)
  add_executable(replay_${sys}_host EXCLUDE_FROM_ALL ${_tr}/replay_main.cpp ${_rgen}/replay_inputs_${sys}.hpp)
  target_compile_definitions(replay_${sys}_host PRIVATE ADCS_REPLAY_API=${_api_${sys}}
                             "ADCS_REPLAY_INPUTS=\"replay_inputs_${sys}.hpp\"")
  target_include_directories(replay_${sys}_host PRIVATE ${_rgen})
  target_link_libraries(replay_${sys}_host PRIVATE adcs_replay_core_${sys})
  set_target_properties(replay_${sys}_host PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${_rdir})
endforeach()
add_executable(adcs_replay_compare EXCLUDE_FROM_ALL ${_tr}/replay_compare.cpp)
target_link_libraries(adcs_replay_compare PRIVATE adcs_warnings)
set_target_properties(adcs_replay_compare PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${_rdir})

# Target side: tests/target as its own CMake project with the Cortex-M7 toolchain file.
include(ExternalProject)
set(_elfs)
foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS ITEMS baseline)
  list(APPEND _elfs ${_tdir}/replay_${sys}.elf)
endforeach()
ExternalProject_Add(adcs_target_replay
  SOURCE_DIR ${_tr}
  BINARY_DIR ${_tdir}
  PREFIX ${CMAKE_BINARY_DIR}/target-ep
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/cmake/arm-none-eabi.cmake
             -DCMAKE_BUILD_TYPE=Release -DADCS_SOURCE_DIR=${PROJECT_SOURCE_DIR}
             -DADCS_EIGEN_INCLUDE_DIR=${_eigen_inc0} -DADCS_REPLAY_GEN_DIR=${_rgen}
  BUILD_COMMAND ${CMAKE_COMMAND} --build ${_tdir} -j ${ADCS_TARGET_BUILD_JOBS}
  INSTALL_COMMAND ""
  USES_TERMINAL_BUILD ON  # the console pool: never both nested builds at once (adcs_target_host)
  BUILD_ALWAYS ON
  EXCLUDE_FROM_ALL ON
  DEPENDS adcs_replay_inputs
  BUILD_BYPRODUCTS ${_elfs} ${_tdir}/c_example_m7.elf)

add_dependencies(adcs_target_check adcs_target_replay)
add_dependencies(adcs_target_host adcs_replay_inputs adcs_replay_compare)
foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS ADCS_REPLAY_SYSTEMS_M4F)
  add_dependencies(adcs_target_host replay_${sys}_host)
endforeach()

find_program(ADCS_QEMU qemu-system-arm)
foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS)
  if(NOT ADCS_QEMU)
    add_test(NAME target_replay_${sys}
             COMMAND ${CMAKE_COMMAND} -E echo "qemu-system-arm not found: run tools/setup-deps.sh")
    set_tests_properties(target_replay_${sys} PROPERTIES LABELS target WILL_FAIL ON)
    continue()
  endif()
  add_test(NAME target_replay_${sys}
           COMMAND ${CMAKE_COMMAND} -DMODE=compare -DNAME=${sys} -DHOST=$<TARGET_FILE:replay_${sys}_host>
                   -DELF=${_tdir}/replay_${sys}.elf -DQEMU=${ADCS_QEMU}
                   -DCOMPARE=$<TARGET_FILE:adcs_replay_compare> -DSTEPS=${ADCS_REPLAY_STEPS} -DTOL=1e-12
                   -DWORK=${_rdir}/${sys} -P ${_tr}/run_replay_check.cmake)
  add_test(NAME target_icount_${sys}
           COMMAND ${CMAKE_COMMAND} -DMODE=icount -DNAME=${sys} -DELF=${_tdir}/replay_${sys}.elf
                   -DQEMU=${ADCS_QEMU} -DSTEPS=${ADCS_REPLAY_STEPS} -DWORK=${_rdir}/${sys}
                   -DCOSTS_JSON=${PROJECT_SOURCE_DIR}/bench/target-costs.json
                   -P ${_tr}/run_replay_check.cmake)
  set_tests_properties(target_replay_${sys} target_icount_${sys} PROPERTIES
                       LABELS target FIXTURES_REQUIRED adcs_target_build TIMEOUT 600 COST 10)
endforeach()

# tools/target-profile.py (issue 20) on seed 004's sample, 3 steps minus 1 with the instruction mix:
# the profile must name the U-D filter's rank-one and measurement updates and the fusion (the tool
# exits non-zero otherwise).
if(ADCS_QEMU AND Python3_Interpreter_FOUND AND "dragfree" IN_LIST ADCS_REPLAY_SYSTEMS)
  add_test(NAME target_profile_dragfree
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/target-profile.py
                   ${_tdir}/replay_dragfree.elf --steps 3 --subtract 1 --mix --top 200 --expect "agee_turner_update<18"
                   --expect "EskfUd<18, 9, 9, 6, 12, double>::update_candidate" --expect "fuse_axis")
  set_tests_properties(target_profile_dragfree PROPERTIES
                       LABELS target FIXTURES_REQUIRED adcs_target_build TIMEOUT 300)
endif()

# The Cortex-M4F: the same cross project with ADCS_ARM_CPU=cortex-m4f (only the C example so far,
# tests/target/CMakeLists.txt), run under QEMU mps2-an386.
ExternalProject_Add(adcs_target_m4f
  SOURCE_DIR ${_tr}
  BINARY_DIR ${CMAKE_BINARY_DIR}/target-m4f
  PREFIX ${CMAKE_BINARY_DIR}/target-m4f-ep
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/cmake/arm-none-eabi.cmake -DADCS_ARM_CPU=cortex-m4f
             -DCMAKE_BUILD_TYPE=Release -DADCS_SOURCE_DIR=${PROJECT_SOURCE_DIR}
             -DADCS_EIGEN_INCLUDE_DIR=${_eigen_inc0} -DADCS_REPLAY_GEN_DIR=${_rgen}
  BUILD_COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR}/target-m4f -j ${ADCS_TARGET_BUILD_JOBS}
  INSTALL_COMMAND ""
  USES_TERMINAL_BUILD ON  # the console pool: never both nested builds at once (adcs_target_host)
  BUILD_ALWAYS ON
  EXCLUDE_FROM_ALL ON
  DEPENDS adcs_replay_inputs
  BUILD_BYPRODUCTS ${CMAKE_BINARY_DIR}/target-m4f/c_example_m4f.elf ${CMAKE_BINARY_DIR}/target-m4f/replay_attitude_f.elf
                   ${CMAKE_BINARY_DIR}/target-m4f/replay_ppc_f.elf ${CMAKE_BINARY_DIR}/target-m4f/replay_hybrid_f.elf
                   ${CMAKE_BINARY_DIR}/target-m4f/replay_se3_f.elf ${CMAKE_BINARY_DIR}/target-m4f/replay_dragfree_f.elf
                   ${CMAKE_BINARY_DIR}/target-m4f/replay_atc_f.elf ${CMAKE_BINARY_DIR}/target-m4f/replay_eso_adrc_f.elf
                   ${CMAKE_BINARY_DIR}/target-m4f/replay_se3_ftsmc_f.elf
                   ${CMAKE_BINARY_DIR}/target-m4f/replay_baseline.elf ${_m4f_c_lib})
add_dependencies(adcs_target_check adcs_target_m4f)
# The float replays on the M4F: host float vs QEMU mps2-an386, and the instruction counts
# (bench/target-costs.json, "systems_m4f"). Tolerance: the host core is compiled with the
# target's arithmetic (no FMA contraction, no SSE reordering), so what can differ is the float
# libm (glibc's sinf/cosf/expf/logf against newlib's, an ulp apart in places), amplified by the
# step's conditioning.
#   attitude_f 1e-6, ~16 float roundings (2^-24 ~ 6e-8): measured bit-identical.
#   ppc_f 1e-4: seed 002's step divides by the funnel ρ and differences ϑ̇ against ϑ̇_d, so one
#     rounding moves the command by up to ~2e-5 of its size (the float-vs-double step bound of
#     PpcNeuralFloat.StepMatchesDoubleOnRandomInputs, 1e-4, away from a funnel edge); measured
#     91.6 % of the values bit-identical, max 5.2e-6 (u3).
#   hybrid_f 1e-4: seed 001's step takes sinf/cosf of the four gimbal angles (the torque Jacobian)
#     and inverts X Xᵀ of the steering, whose conditioning amplifies one ulp of a libm result by up
#     to ~1e3 (the float-vs-double step bound of HybridAdaptiveFloat.StepMatchesDoubleOnRandomInputs,
#     1e-4, the same argument); measured bit-identical, 17,200 of 17,200 values.
set(_m4f_tol_attitude_f 1e-6)
set(_m4f_tol_ppc_f 1e-4)
set(_m4f_tol_hybrid_f 1e-4)
#   se3_f 1e-4: seed 003's BsPdTC takes sinf/cosf/atan2f in the SE(3) logarithm and tanhf/sqrtf
#     in the law, and forms v_e from inertial velocities of ~7.7 km/s, which amplifies one ulp of
#     an intermediate by |v|/|v_e| ~ 1e4 relative to the command's own size at worst (the
#     float-vs-double bound of Se3Float.PrescribedTimeLawMatchesDoubleOnTheSameRoundedInput, 2e-3,
#     is arithmetic against double; host float against target float differs only by libm ulps).
set(_m4f_tol_se3_f 1e-4)
#   dragfree_f 1e-4: seed 004's sample takes powf in the ADRC's fal (slope δ^(α−1) = 10 in its
#     linear zone) and expf/erfcf in Algorithm 2's truncated moments, whose results the four filters
#     carry from sample to sample; the host's float-vs-double unit tests bound the whole arithmetic
#     at 1.5e-3 (Algorithm 2's weakly observed ṙ) and 1.2e-7 (the ADRC's command), and host float
#     against target float differs only by libm ulps (6e-8) through that conditioning. Measured
#     bit-identical, 19,600 of 19,600 values.
set(_m4f_tol_dragfree_f 1e-4)
#   atc_f, eso_adrc_f, se3_ftsmc_f 1e-4, the papers' baselines and the cross pairing's law, for the
#     reasons of their papers' laws above: the ATC as the PPATC (expf of the RBF layer, sinf/cosf
#     of the Euler kinematics; PpcNeuralFloat.AdaptiveTrackingStepMatchesDouble), the ESO-based
#     ADRC through sinf/cosf of the Euler kinematics, the FTSMC as the BsPdTC (the SE(3) logarithm,
#     powf of the sliding surface, v_e from inertial velocities). Measured: see docs/TARGET.md.
set(_m4f_tol_atc_f 1e-4)
set(_m4f_tol_eso_adrc_f 1e-4)
set(_m4f_tol_se3_ftsmc_f 1e-4)
if(ADCS_QEMU)
  foreach(sys IN LISTS ADCS_REPLAY_SYSTEMS_M4F)
    add_test(NAME target_replay_m4f_${sys}
             COMMAND ${CMAKE_COMMAND} -DMODE=compare -DNAME=${sys} -DHOST=$<TARGET_FILE:replay_${sys}_host>
                     -DELF=${CMAKE_BINARY_DIR}/target-m4f/replay_${sys}.elf -DQEMU=${ADCS_QEMU} -DMACHINE=mps2-an386
                     -DCOMPARE=$<TARGET_FILE:adcs_replay_compare> -DSTEPS=${ADCS_REPLAY_STEPS} -DTOL=${_m4f_tol_${sys}}
                     -DWORK=${_rdir}/m4f_${sys} -P ${_tr}/run_replay_check.cmake)
    add_test(NAME target_icount_m4f_${sys}
             COMMAND ${CMAKE_COMMAND} -DMODE=icount -DNAME=${sys} -DELF=${CMAKE_BINARY_DIR}/target-m4f/replay_${sys}.elf
                     -DQEMU=${ADCS_QEMU} -DMACHINE=mps2-an386 -DSTEPS=${ADCS_REPLAY_STEPS} -DWORK=${_rdir}/m4f_${sys}
                     -DCOSTS_JSON=${PROJECT_SOURCE_DIR}/bench/target-costs.json -DJSON_KEY=systems_m4f
                     -P ${_tr}/run_replay_check.cmake)
    set_tests_properties(target_replay_m4f_${sys} target_icount_m4f_${sys} PROPERTIES
                         LABELS target FIXTURES_REQUIRED adcs_target_build TIMEOUT 600)
  endforeach()
endif()

# The C interface's example on the Cortex-M7 and the Cortex-M4F (examples/c/cfs_app.c over
# src/c/adcs_c.cpp, both cross-compiled): the application checks its commands against the host C++ results itself and
# exits non-zero on any difference beyond its tolerance.
if(ADCS_QEMU)
  add_test(NAME target_c_example_m7
           COMMAND ${ADCS_QEMU} -M mps2-an500 -nographic -monitor none -serial none
                   -semihosting-config enable=on,target=native -kernel ${_tdir}/c_example_m7.elf)
  add_test(NAME target_c_example_m4f
           COMMAND ${ADCS_QEMU} -M mps2-an386 -nographic -monitor none -serial none
                   -semihosting-config enable=on,target=native -kernel ${CMAKE_BINARY_DIR}/target-m4f/c_example_m4f.elf)
  set_tests_properties(target_c_example_m7 target_c_example_m4f PROPERTIES LABELS target
                       FIXTURES_REQUIRED adcs_target_build TIMEOUT 300
                       PASS_REGULAR_EXPRESSION "passed" FAIL_REGULAR_EXPRESSION "FAILED")
endif()

# The compile checks in a target of their own, defined last. Own target: the custom commands of a
# target wait (order-only) for every target it depends on, so inside adcs_target_check they
# started only after the replay chain (host cores -> recorder -> nested M7 build) and ended the
# build alone for ~80 s. Defined last: Ninja 1.11 starts the ready commands in the order of
# build.ninja, which CMake writes in the order the owning targets were defined; defined first,
# the ~60 checks (~230 CPU-s) ran before the replay chain's generated headers (design_gains ->
# replay_gains_hybrid.hpp -> recorder -> replay inputs), so the nested M7 build started at 188 s
# and the bench fixtures ended the build alone for ~40 s. Defined here, they fill the cores
# while the chain waits on a link (docs/DECISIONS.md, "CI under 20 minutes").
add_custom_target(adcs_target_compile DEPENDS ${_outputs})
add_dependencies(adcs_target_host adcs_target_compile)
# After the bench fixtures (an ordering only: the checks do not use them). bench/ is a
# subdirectory, so its units come after every top-level command in build.ninja and, left there,
# its longest unit (~110 s) started last and ended the build alone; the checks are ~60 short
# commands, which fill the cores at the end instead.
if(TARGET adcs_step_entries)
  add_dependencies(adcs_target_compile adcs_step_entries)
endif()
