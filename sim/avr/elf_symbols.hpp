// ElfSymbols: the symbol table of an AVR ELF (name, address, size), read without libelf. simavr's own loader
// keeps names and addresses of code only; the cycle budget needs sizes (ISR and function extents) and data
// symbols (end of .bss for the stack paint, the ISR state for the trigger tick). ELF32 little-endian only.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace driftlab::sim::avr {

struct ElfSymbol {
    std::string name;          ///< as in the file (C++ names mangled)
    std::uint32_t address;     ///< st_value: byte address in flash, or 0x800000 + RAM address for data
    std::uint32_t size_bytes;  ///< st_size [bytes]
};

class ElfSymbols {
public:
    /// Reads `path`; throws AvrError naming the file and byte offset when it is not an ELF32 LE file with a
    /// symbol table.
    explicit ElfSymbols(const std::string& path);

    /// The symbol called exactly `name`, if any.
    std::optional<ElfSymbol> find(const std::string& name) const;
    /// Like find(), but throws AvrError naming the file when the symbol is missing.
    ElfSymbol require(const std::string& name) const;

    const std::vector<ElfSymbol>& all() const { return symbols_; }

private:
    std::string path_;
    std::vector<ElfSymbol> symbols_;
};

/// Data symbols of an AVR ELF live at 0x800000 + RAM address (avr-ld's data memory region).
inline constexpr std::uint32_t kAvrDataOffset = 0x800000;

}  // namespace driftlab::sim::avr
