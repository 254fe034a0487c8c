# cortex-m4f.cmake - CMake toolchain file of tests/check_consumer.sh: GCC for a
# bare-metal Cortex-M4F (CPU flags of port/cortex-m/cortex-m.mk). Only
# libraries are built with it (no startup code, no linker script), so CMake's
# own compiler checks build static libraries instead of programs.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -ffunction-sections -fdata-sections")
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
