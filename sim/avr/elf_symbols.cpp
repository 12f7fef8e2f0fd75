// ElfSymbols: ELF32 section headers -> SHT_SYMTAB + its string table (ELF specification, "Symbol Table").
#include "sim/avr/elf_symbols.hpp"

#include <cstring>
#include <fstream>
#include <iterator>

#include "sim/avr/avr_error.hpp"

namespace driftlab::sim::avr {
namespace {

constexpr std::uint32_t kShtSymtab = 2;
constexpr std::size_t kSectionHeaderBytes = 40;
constexpr std::size_t kSymbolBytes = 16;

class Reader {
public:
    Reader(const std::string& path, std::vector<std::uint8_t> bytes) : path_(path), bytes_(std::move(bytes)) {}

    std::uint32_t u32(std::size_t offset) const {
        need(offset, 4);
        return static_cast<std::uint32_t>(bytes_[offset]) | static_cast<std::uint32_t>(bytes_[offset + 1]) << 8 |
               static_cast<std::uint32_t>(bytes_[offset + 2]) << 16 |
               static_cast<std::uint32_t>(bytes_[offset + 3]) << 24;
    }
    std::uint16_t u16(std::size_t offset) const {
        need(offset, 2);
        return static_cast<std::uint16_t>(bytes_[offset] | bytes_[offset + 1] << 8);
    }
    std::uint8_t u8(std::size_t offset) const {
        need(offset, 1);
        return bytes_[offset];
    }
    std::string cstring(std::size_t offset, std::size_t end) const {
        std::string s;
        for (std::size_t i = offset; i < end && i < bytes_.size() && bytes_[i] != 0; ++i) {
            s.push_back(static_cast<char>(bytes_[i]));
        }
        return s;
    }
    [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
        throw AvrError(path_ + ": byte " + std::to_string(offset) + ": " + what);
    }

private:
    void need(std::size_t offset, std::size_t n) const {
        if (offset + n > bytes_.size()) {
            fail(offset, "file ends inside an ELF structure (" + std::to_string(bytes_.size()) + " bytes)");
        }
    }

    std::string path_;
    std::vector<std::uint8_t> bytes_;
};

}  // namespace

ElfSymbols::ElfSymbols(const std::string& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw AvrError(path + ": cannot open the firmware ELF");
    }
    const Reader r(path, std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {}));
    if (r.u32(0) != 0x464C457FU) {
        r.fail(0, "not an ELF file (expected 7F 45 4C 46)");
    }
    if (r.u8(4) != 1 || r.u8(5) != 1) {
        r.fail(4, "expected a 32-bit little-endian ELF (an AVR image)");
    }
    const std::uint32_t shoff = r.u32(32);
    const std::uint16_t shentsize = r.u16(46);
    const std::uint16_t shnum = r.u16(48);
    if (shentsize != kSectionHeaderBytes) {
        r.fail(46, "unexpected section header size " + std::to_string(shentsize));
    }
    for (std::uint16_t s = 0; s < shnum; ++s) {
        const std::size_t sh = shoff + std::size_t{s} * kSectionHeaderBytes;
        if (r.u32(sh + 4) != kShtSymtab) {
            continue;
        }
        const std::uint32_t sym_offset = r.u32(sh + 16);
        const std::uint32_t sym_bytes = r.u32(sh + 20);
        const std::uint32_t link = r.u32(sh + 24);
        if (link >= shnum) {
            r.fail(sh + 24, "symbol table links to a missing string table");
        }
        const std::size_t strtab_sh = shoff + std::size_t{link} * kSectionHeaderBytes;
        const std::uint32_t str_offset = r.u32(strtab_sh + 16);
        const std::uint32_t str_end = str_offset + r.u32(strtab_sh + 20);
        for (std::size_t e = sym_offset; e + kSymbolBytes <= std::size_t{sym_offset} + sym_bytes; e += kSymbolBytes) {
            const std::uint32_t name = r.u32(e);
            if (name == 0) {
                continue;
            }
            symbols_.push_back({r.cstring(str_offset + name, str_end), r.u32(e + 4), r.u32(e + 8)});
        }
        return;
    }
    r.fail(shoff, "no symbol table (was the ELF stripped?)");
}

std::optional<ElfSymbol> ElfSymbols::find(const std::string& name) const {
    for (const ElfSymbol& s : symbols_) {
        if (s.name == name) {
            return s;
        }
    }
    return std::nullopt;
}

ElfSymbol ElfSymbols::require(const std::string& name) const {
    if (auto s = find(name)) {
        return *s;
    }
    throw AvrError(path_ + ": symbol '" + name + "' not found; is this driftlab's ATmega328P firmware?");
}

}  // namespace driftlab::sim::avr
