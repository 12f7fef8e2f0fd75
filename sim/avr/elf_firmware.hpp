// ElfFirmware: an AVR image as simavr's elf_read_firmware loads it, with what that call allocates (flash, EEPROM,
// fuses, lock bits, the symbol table) freed when it goes out of scope: simavr has no call that frees it, and
// avr_load_firmware copies what the core keeps. LeakSanitizer found the leak. Include after <simavr/sim_elf.h>.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace driftlab::sim::avr {

struct ElfFirmware {
    elf_firmware_t f;
    ElfFirmware() { std::memset(&f, 0, sizeof f); }
    ~ElfFirmware() {
        std::free(f.flash);
        std::free(f.eeprom);
        std::free(f.fuse);
        std::free(f.lockbits);
        for (std::uint32_t i = 0; i < f.symbolcount; ++i) std::free(f.symbol[i]);
        std::free(f.symbol);
    }
    ElfFirmware(const ElfFirmware&) = delete;
    ElfFirmware& operator=(const ElfFirmware&) = delete;
};

}  // namespace driftlab::sim::avr
