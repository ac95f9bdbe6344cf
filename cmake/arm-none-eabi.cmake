# CMake toolchain file: bare-metal Cortex-M7 with double-precision FPU, hard-float ABI
# (arm-none-eabi-g++ 12.2 from Debian's gcc-arm-none-eabi, newlib-nano + semihosting).
#   cmake -S tests/target -B build/target --toolchain cmake/arm-none-eabi.cmake   (CMake >= 3.21)
#   cmake -S tests/target -B build/target -DCMAKE_TOOLCHAIN_FILE=cmake/arm-none-eabi.cmake
# Used by cmake/TargetCheck.cmake for the replay programs (docs/TARGET.md).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar CACHE FILEPATH "archiver")
set(CMAKE_RANLIB arm-none-eabi-ranlib CACHE FILEPATH "ranlib")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "size")
set(CMAKE_OBJCOPY arm-none-eabi-objcopy CACHE FILEPATH "objcopy")
# The compiler checks cannot link a program without start-up code and linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Cortex-M7, FPv5 with 16 double-precision registers (the M7's optional DP FPU), hard-float ABI.
# ADCS_ARM_CPU: cortex-m7 (default; double-precision FPU, QEMU mps2-an500) or cortex-m4f
# (single-precision FPU only, QEMU mps2-an386: issue 19's float target).
set(ADCS_ARM_CPU "cortex-m7" CACHE STRING "Target core: cortex-m7 or cortex-m4f")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ADCS_ARM_CPU)
if(ADCS_ARM_CPU STREQUAL "cortex-m7")
  set(ADCS_ARM_CPU_FLAGS "-mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard -mthumb")
elseif(ADCS_ARM_CPU STREQUAL "cortex-m4f")
  set(ADCS_ARM_CPU_FLAGS "-mcpu=cortex-m4 -mfpu=fpv4-sp-d16 -mfloat-abi=hard -mthumb")
else()
  message(FATAL_ERROR "ADCS_ARM_CPU must be cortex-m7 or cortex-m4f, got '${ADCS_ARM_CPU}'")
endif()
# Flight-code flags: no exceptions/RTTI/thread-safe statics, per-function sections for
# --gc-sections, Eigen's heap forbidden. -ffp-contract=off: no a*b+c -> VFMA.F64 fusion. GCC 12
# contracts by default in C++ even with -std=c++17 (checked: a*b+c gives vfma.f64; its ISO-mode
# "off" default applies to C only); with off it emits VMLA.F64, which rounds the product like a
# separate multiply. So the arithmetic is the host's, operation for operation (docs/TARGET.md).
string(JOIN " " CMAKE_CXX_FLAGS_INIT ${ADCS_ARM_CPU_FLAGS} -O2 -fno-exceptions -fno-rtti
            -fno-threadsafe-statics -ffunction-sections -fdata-sections -ffp-contract=off -DEIGEN_NO_MALLOC)
set(CMAKE_C_FLAGS_INIT "${ADCS_ARM_CPU_FLAGS} -O2 -ffunction-sections -fdata-sections -ffp-contract=off")
set(CMAKE_ASM_FLAGS_INIT "${ADCS_ARM_CPU_FLAGS}")
# Release stays at -O2: CMake appends its own "-O3 -DNDEBUG" to any *_RELEASE_INIT, so the cache
# entry is set here, before CMake's compiler set-up would create it.
set(CMAKE_CXX_FLAGS_RELEASE "-O2 -DNDEBUG" CACHE STRING "Release flags (Cortex-M7: -O2, not -O3)")
set(CMAKE_C_FLAGS_RELEASE "-O2 -DNDEBUG" CACHE STRING "Release flags (Cortex-M7: -O2, not -O3)")
# newlib-nano, semihosting I/O (librdimon), %f/%g in printf.
set(CMAKE_EXE_LINKER_FLAGS_INIT "--specs=nano.specs --specs=rdimon.specs -u _printf_float -Wl,--gc-sections")

# Find headers/libraries of the target only; programs (size, qemu) on the host.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
