// AvrError: why an AVR-in-the-loop run cannot start or go on (missing or malformed ELF, wrong chip, firmware
// layout the harness does not recognise). The message names the file and what was expected (docs/avr-in-the-loop.md).
#pragma once

#include <stdexcept>
#include <string>

namespace driftlab::sim::avr {

class AvrError : public std::runtime_error {
public:
    explicit AvrError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace driftlab::sim::avr
