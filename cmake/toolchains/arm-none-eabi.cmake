# Cross toolchain for the freestanding bob/ core on a Cortex-M4 (Debian packages gcc-arm-none-eabi
# and libnewlib-arm-none-eabi; only libgcc is linked, no C library). Used by the cortex-m preset.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
find_program(CMAKE_SIZE arm-none-eabi-size REQUIRED)
find_program(CMAKE_OBJCOPY arm-none-eabi-objcopy)

# A try_compile cannot link without a linker script: test the compiler with a static library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Freestanding: no exceptions, RTTI, thread-safe statics or atexit; each function in its own
# section so that --gc-sections drops what the firmware does not call. -fno-tree-loop-distribute-
# patterns keeps GCC from turning byte loops into memset/memcpy calls, which nothing provides.
set(CMAKE_CXX_FLAGS_INIT
    "-mcpu=cortex-m4 -mthumb -mfloat-abi=soft -ffreestanding -fno-exceptions -fno-rtti \
-fno-threadsafe-statics -fno-use-cxa-atexit -fno-asynchronous-unwind-tables \
-fno-tree-loop-distribute-patterns -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mthumb -mfloat-abi=soft -ffreestanding")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostdlib -nostartfiles -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
