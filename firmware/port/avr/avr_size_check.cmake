# Prints the firmware's flash and RAM use and fails the build when either passes its budget, 75 % of the chip's:
# the rest is the margin for the stack (RAM) and for what a later feature adds (flash). Run with -DAVR_SIZE= -DELF=
# -DFLASH_BYTES= -DRAM_BYTES= (avr_image.cmake; the chip's sizes).
execute_process(COMMAND ${AVR_SIZE} -A ${ELF} OUTPUT_VARIABLE _out RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "avr-size failed on ${ELF}")
endif()

function(_section_size name out_var)
  set(_size 0)
  if(_out MATCHES "\n${name}[ \t]+([0-9]+)")
    set(_size ${CMAKE_MATCH_1})
  endif()
  set(${out_var} ${_size} PARENT_SCOPE)
endfunction()

_section_size("\\.text" _text)
_section_size("\\.data" _data)
_section_size("\\.bss" _bss)
_section_size("\\.noinit" _noinit)
# Flash holds code plus the initial values of .data; RAM holds .data, .bss and .noinit (the stack uses the rest).
math(EXPR _flash "${_text} + ${_data}")
math(EXPR _ram "${_data} + ${_bss} + ${_noinit}")
math(EXPR _flash_pct "100 * ${_flash} / ${FLASH_BYTES}")
math(EXPR _ram_pct "100 * ${_ram} / ${RAM_BYTES}")
math(EXPR _stack "${RAM_BYTES} - ${_ram}")
message(STATUS "driftlab_fw: flash ${_flash} / ${FLASH_BYTES} bytes (${_flash_pct} %), "
               "RAM ${_ram} / ${RAM_BYTES} bytes (${_ram_pct} %, ${_stack} left for the stack)")

foreach(kind flash ram)
  string(TOUPPER ${kind} _KIND)
  set(_used ${_${kind}})
  set(_chip ${${_KIND}_BYTES})
  math(EXPR _budget "3 * ${_chip} / 4")
  if(_used GREATER _budget)
    message(FATAL_ERROR "driftlab_fw: ${kind} use ${_used} bytes exceeds its budget of ${_budget} bytes "
                        "(75 % of ${_chip})")
  endif()
endforeach()
