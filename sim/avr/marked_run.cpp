// A self-marking AVR image in simavr (marked_run.hpp).
#include "sim/avr/marked_run.hpp"

#include <simavr/sim_avr.h>
#include <simavr/sim_elf.h>
#include <simavr/sim_io.h>

#include "sim/avr/avr_error.hpp"
#include "sim/avr/elf_firmware.hpp"

namespace driftlab::sim::avr {
namespace {

constexpr avr_io_addr_t kGpior0 = 0x3E;  // GPIOR0 in data space (I/O 0x1E)
constexpr std::uint8_t kDone = 0xFF;

struct Marks {
    MarkedRun* out;
    std::uint8_t open = 0;
    std::uint64_t opened_at = 0;
    bool done = false;
};

void on_gpior0(avr_t* avr, avr_io_addr_t, std::uint8_t value, void* param) {
    Marks& m = *static_cast<Marks*>(param);
    if (value == kDone) {
        m.done = true;
    } else if (value == 0 && m.open != 0) {
        m.out->span_cycles[m.open] += avr->cycle - m.opened_at;
        m.open = 0;
    } else if (value != 0) {
        m.open = value;
        m.opened_at = avr->cycle;
    }
}

}  // namespace

MarkedRun run_marked(const std::string& elf_path, std::uint64_t max_cycles) {
    ElfFirmware elf;
    if (elf_read_firmware(elf_path.c_str(), &elf.f) != 0) throw AvrError(elf_path + ": simavr cannot load this ELF");
    avr_t* avr = avr_make_mcu_by_name("atmega328p");
    if (avr == nullptr) throw AvrError("simavr has no ATmega328P model");
    avr_init(avr);
    avr->log = LOG_ERROR;
    avr_load_firmware(avr, &elf.f);
    avr->frequency = 16000000;
    MarkedRun out;
    out.flash_bytes = elf.f.flashsize;
    out.ram_bytes = elf.f.datasize + elf.f.bsssize;
    Marks marks{&out};
    avr_register_io_write(avr, kGpior0, on_gpior0, &marks);
    int state = cpu_Running;
    while (!marks.done && avr->cycle < max_cycles && state != cpu_Done && state != cpu_Crashed) state = avr_run(avr);
    avr_terminate(avr);
    if (!marks.done)
        throw AvrError(elf_path + ": did not finish its marked work in " + std::to_string(max_cycles) + " cycles");
    return out;
}

}  // namespace driftlab::sim::avr
