# Configures and builds driftlab_fw.elf with toolchain/avr-gcc.cmake into BUILD_DIR; the build itself fails when
# the image exceeds its flash or RAM budget (firmware/port/avr/avr_size_check.cmake). Then checks that the ELF
# and the HEX exist and the ELF carries simavr's .mmcu tag.
# Run with -DSOURCE_DIR= -DBUILD_DIR= -DGENERATOR=.
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BUILD_DIR} -G ${GENERATOR}
          -DCMAKE_TOOLCHAIN_FILE=${SOURCE_DIR}/toolchain/avr-gcc.cmake -DCMAKE_BUILD_TYPE=MinSizeRel
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "AVR configure failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target driftlab_fw
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "AVR build failed:\n${out}\n${err}")
endif()
foreach(file driftlab_fw.elf driftlab_fw.hex)
  if(NOT EXISTS ${BUILD_DIR}/firmware/${file})
    message(FATAL_ERROR "AVR build produced no firmware/${file}")
  endif()
endforeach()
file(READ ${BUILD_DIR}/firmware/driftlab_fw.elf elf_hex HEX LIMIT 200000)
# ".mmcu" as hex: the section name must be in the ELF's string table.
string(FIND "${elf_hex}" "2e6d6d6375" mmcu_at)
if(mmcu_at EQUAL -1)
  message(FATAL_ERROR "driftlab_fw.elf has no .mmcu section (simavr could not identify the chip)")
endif()
message(STATUS "AVR image built: ${out}")
