# Compiles every common/src/*.cpp, and one file including every public header, with avr-g++ for the
# ATmega328P, warnings as errors. Run by ctest: cmake -DAVR_GXX=... -DCOMMON_DIR=... -DOUT_DIR=... -P this.
file(MAKE_DIRECTORY "${OUT_DIR}")
file(GLOB _headers RELATIVE "${COMMON_DIR}/include" "${COMMON_DIR}/include/driftlab/*.hpp"
     "${COMMON_DIR}/include/driftlab/proto/*.hpp")
set(_all "${OUT_DIR}/all_headers.cpp")
set(_text "")
foreach(h ${_headers})
  string(APPEND _text "#include \"${h}\"\n")
endforeach()
file(WRITE "${_all}" "${_text}")

file(GLOB _sources "${COMMON_DIR}/src/*.cpp")
foreach(src ${_sources} ${_all})
  get_filename_component(_name "${src}" NAME_WE)
  execute_process(
    COMMAND "${AVR_GXX}" -std=c++14 -mmcu=atmega328p -Os -fno-exceptions -fno-rtti -Wall -Wextra -Wconversion
            -Wsign-conversion -Werror -I "${COMMON_DIR}/include" -c "${src}" -o "${OUT_DIR}/${_name}.o"
    RESULT_VARIABLE _rc ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "avr-g++ failed on ${src}:\n${_err}")
  endif()
endforeach()
list(LENGTH _sources _count)
message(STATUS "avr-g++ compiled ${_count} sources and ${_all}")
