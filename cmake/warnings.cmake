# Warning sets shared by every area. Firmware and protocol code also get -Wconversion: on AVR `int` is
# 16 bits, and a silent narrowing there is a wrong sample, not a style issue.
add_library(driftlab_warnings INTERFACE)
target_compile_options(driftlab_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow)

add_library(driftlab_strict_warnings INTERFACE)
target_link_libraries(driftlab_strict_warnings INTERFACE driftlab_warnings)
target_compile_options(driftlab_strict_warnings INTERFACE -Wconversion -Wsign-conversion)
