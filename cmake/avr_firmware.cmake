# The native build also builds the real ATmega328P firmware, when avr-g++ is installed, so the AVR-in-the-loop
# target and its tests have an ELF: this same source tree is configured again with toolchain/avr-gcc.cmake
# into <build>/avr-fw (a separate tree, like `cmake --preset avr`). Sets DRIFTLAB_AVR_ELF to the ELF's path, or
# to "" when avr-g++ is missing (the AVR tests then skip and `driftlab hil --target avr` asks for --elf).
include(ExternalProject)

find_program(DRIFTLAB_AVR_GXX avr-g++)
if(NOT DRIFTLAB_AVR_GXX)
  message(STATUS "avr-g++ not found: the AVR firmware is not built (scripts/setup.sh installs gcc-avr)")
  set(DRIFTLAB_AVR_ELF "")
  set(DRIFTLAB_AVR_FW_DIR "")
  return()
endif()

set(_avr_fw_dir "${PROJECT_BINARY_DIR}/avr-fw")
set(DRIFTLAB_AVR_ELF "${_avr_fw_dir}/firmware/driftlab_fw.elf")
# Beside it, the MAC candidates' images (firmware/bench/mac_bench_avr.cpp) that bench/mac_bench.cpp times.
set(DRIFTLAB_AVR_FW_DIR "${_avr_fw_dir}/firmware")
ExternalProject_Add(driftlab_avr_firmware
  SOURCE_DIR "${PROJECT_SOURCE_DIR}"
  BINARY_DIR "${_avr_fw_dir}"
  CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${PROJECT_SOURCE_DIR}/toolchain/avr-gcc.cmake -DCMAKE_BUILD_TYPE=MinSizeRel
  BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --target driftlab_fw driftlab_mac_none driftlab_mac_siphash24
                driftlab_mac_blake2s driftlab_mac_sha256
  BUILD_BYPRODUCTS "${DRIFTLAB_AVR_ELF}"
  INSTALL_COMMAND ""
  # The firmware sources are not known to this tree: let the inner build decide what is out of date.
  BUILD_ALWAYS ON
  USES_TERMINAL_BUILD ON)
