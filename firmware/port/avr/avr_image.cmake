# driftlab_fw.elf/.hex for the ATmega328P, its flash/RAM report, and the `flash` target (avrdude).
# Included from firmware/CMakeLists.txt when cross-compiling (DRIFTLAB_AVR).

# ATmega328P budgets [bytes]: 32 KiB flash (the Arduino bootloader takes 0.5 KiB of it), 2 KiB SRAM.
set(DRIFTLAB_AVR_FLASH_BYTES 32768 CACHE STRING "Flash available to the firmware [bytes]")
set(DRIFTLAB_AVR_RAM_BYTES 2048 CACHE STRING "SRAM of the MCU [bytes]")

set(DRIFTLAB_AVRDUDE_PORT "/dev/ttyACM0" CACHE STRING "Serial port of the board for `flash`")
set(DRIFTLAB_AVRDUDE_PROGRAMMER "arduino" CACHE STRING "avrdude -c programmer (arduino = Optiboot over serial)")
set(DRIFTLAB_AVRDUDE_BAUD "115200" CACHE STRING "avrdude -b bootloader baud rate (old Nano bootloaders: 57600)")
set(DRIFTLAB_AVRDUDE_PART "m328p" CACHE STRING "avrdude -p part")

# simavr's avr_mcu_section.h sits under <simavr/avr/>; -idirafter keeps avr-libc's own <avr/...> headers first.
find_path(DRIFTLAB_SIMAVR_SECTION_DIR avr/avr_mcu_section.h PATHS /usr/include/simavr /usr/local/include/simavr
          NO_CMAKE_FIND_ROOT_PATH)
if(NOT DRIFTLAB_SIMAVR_SECTION_DIR)
  message(FATAL_ERROR "avr_mcu_section.h not found: install libsimavr-dev (scripts/setup.sh)")
endif()

set(_avr_dir "${CMAKE_CURRENT_SOURCE_DIR}/port/avr")
add_executable(driftlab_fw "${_avr_dir}/main_avr.cpp" "${_avr_dir}/hal_avr.cpp" "${_avr_dir}/isr_avr.cpp"
                           "${_avr_dir}/mcu_tag_avr.c")
set_target_properties(driftlab_fw PROPERTIES SUFFIX ".elf")
target_compile_options(driftlab_fw PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions -fno-rtti>)
# The tag macros end in a ';' of their own, which -Wpedantic reports; the file is simavr's idiom, not ours.
set_source_files_properties("${_avr_dir}/mcu_tag_avr.c" PROPERTIES
                            COMPILE_OPTIONS "-idirafter;${DRIFTLAB_SIMAVR_SECTION_DIR};-Wno-pedantic")
target_link_libraries(driftlab_fw PRIVATE driftlab_fw_core driftlab_strict_warnings)
# The .mmcu tag is referenced by nothing; keep it through --gc-sections.
target_link_options(driftlab_fw PRIVATE -Wl,--undefined=_mmcu)

add_custom_command(TARGET driftlab_fw POST_BUILD
  COMMAND ${AVR_OBJCOPY} -O ihex -j .text -j .data $<TARGET_FILE:driftlab_fw> driftlab_fw.hex
  COMMAND ${CMAKE_COMMAND} -DAVR_SIZE=${AVR_SIZE} -DELF=$<TARGET_FILE:driftlab_fw>
          -DFLASH_BYTES=${DRIFTLAB_AVR_FLASH_BYTES} -DRAM_BYTES=${DRIFTLAB_AVR_RAM_BYTES}
          -P "${_avr_dir}/avr_size_check.cmake"
  BYPRODUCTS driftlab_fw.hex
  WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}"
  COMMENT "driftlab_fw.hex and flash/RAM use"
  VERBATIM)

# The MAC candidates, one image each (and a baseline without), for bench/mac_bench.cpp to time in simavr and size.
set(_mac_names none siphash24 blake2s sha256)
foreach(i RANGE 3)
  list(GET _mac_names ${i} _mac)
  add_executable(driftlab_mac_${_mac} "${CMAKE_CURRENT_SOURCE_DIR}/bench/mac_bench_avr.cpp")
  set_target_properties(driftlab_mac_${_mac} PROPERTIES SUFFIX ".elf")
  target_compile_definitions(driftlab_mac_${_mac} PRIVATE DRIFTLAB_MAC=${i})
  target_compile_options(driftlab_mac_${_mac} PRIVATE -fno-exceptions -fno-rtti)
  target_link_libraries(driftlab_mac_${_mac} PRIVATE driftlab_proto driftlab_strict_warnings)
endforeach()

find_program(AVRDUDE avrdude)
add_custom_target(flash
  COMMAND ${AVRDUDE} -c ${DRIFTLAB_AVRDUDE_PROGRAMMER} -p ${DRIFTLAB_AVRDUDE_PART} -P ${DRIFTLAB_AVRDUDE_PORT}
          -b ${DRIFTLAB_AVRDUDE_BAUD} -D -U flash:w:driftlab_fw.hex:i
  WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}"
  COMMENT "Flashing driftlab_fw.hex to ${DRIFTLAB_AVRDUDE_PART} on ${DRIFTLAB_AVRDUDE_PORT}"
  VERBATIM USES_TERMINAL)
add_dependencies(flash driftlab_fw)
