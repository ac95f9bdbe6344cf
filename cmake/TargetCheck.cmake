# Cortex-M7 compile check: every public header of include/adcs compiled on its own by
# arm-none-eabi-g++ with flight flags (no exceptions, no RTTI, Eigen heap forbidden), plus one
# translation unit that instantiates every controller/plant template with concrete sizes (a
# header alone does not instantiate its templates). Any warning fails.
# Target: adcs_target_check (not in ALL); ctest test: target_compile_check (label target).
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
set(_outputs)
set(_header_paths)
set(_gen ${CMAKE_BINARY_DIR}/target_check)
foreach(h IN LISTS ADCS_PUBLIC_HEADERS)
  string(REPLACE "/" "__" stem ${h})
  string(REPLACE ".hpp" "" stem ${stem})
  set(tu ${_gen}/${stem}.cpp)
  file(WRITE ${tu}.in "// generated: compile ${h} alone for Cortex-M7\n#include \"${h}\"\n")
  configure_file(${tu}.in ${tu} COPYONLY)
  set(obj ${_gen}/${stem}.o)
  add_custom_command(OUTPUT ${obj}
    COMMAND ${ADCS_ARM_CXX} ${ADCS_ARM_FLAGS} -I${PROJECT_SOURCE_DIR}/include
            -isystem ${_eigen_inc} -c ${tu} -o ${obj}
    DEPENDS ${tu} ${PROJECT_SOURCE_DIR}/include/${h}
    IMPLICIT_DEPENDS CXX ${tu}
    COMMENT "arm-none-eabi-g++ (Cortex-M7) ${h}" VERBATIM)
  list(APPEND _outputs ${obj})
  list(APPEND _header_paths ${PROJECT_SOURCE_DIR}/include/${h})
endforeach()
set(_inst ${PROJECT_SOURCE_DIR}/tests/target/instantiate_all.cpp)
add_custom_command(OUTPUT ${_gen}/instantiate_all.o
  COMMAND ${ADCS_ARM_CXX} ${ADCS_ARM_FLAGS} -I${PROJECT_SOURCE_DIR}/include
          -isystem ${_eigen_inc} -c ${_inst} -o ${_gen}/instantiate_all.o
  DEPENDS ${_inst} ${_header_paths}
  COMMENT "arm-none-eabi-g++ (Cortex-M7) instantiate_all.cpp" VERBATIM)
list(APPEND _outputs ${_gen}/instantiate_all.o)
add_custom_target(adcs_target_check DEPENDS ${_outputs})
add_test(NAME target_compile_check
         COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target adcs_target_check)
set_tests_properties(target_compile_check PROPERTIES LABELS target TIMEOUT 1200)
