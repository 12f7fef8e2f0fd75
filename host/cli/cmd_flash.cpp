// `driftlab flash`: writes the AVR firmware image (and with --key the command key) to a board through avrdude
// (host/io/avrdude).
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/io/avrdude.hpp"
#include "host/io/key_file.hpp"
#include "host/io/usb_ports.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {
namespace {

struct FlashOptions {
    io::FlashRequest request;
    std::string key_file;
    bool dry_run = false;
};

// With no --port, the only USB serial adapter present is the board; more than one needs a choice.
std::string pick_port() {
    const io::UsbPortScan scan = io::list_usb_serial_ports();
    std::vector<std::string> nodes;
    for (const io::UsbSerialPort& p : scan.ports)
        nodes.insert(nodes.end(), p.device_nodes.begin(), p.device_nodes.end());
    if (nodes.size() == 1) return nodes.front();
    if (nodes.empty())
        throw DeviceError("--port",
                          "none given and no USB serial adapter found (is the board plugged in? see `driftlab ports`)");
    std::string list;
    for (const std::string& n : nodes) list += " " + n;
    throw UsageError("no --port given and several adapters present:" + list);
}

void run_flash(FlashOptions& opts) {
    if (opts.request.hex_file.empty()) opts.request.hex_file = io::default_hex_file("/proc/self/exe");
    if (opts.request.port.empty()) opts.request.port = pick_port();
    if (!opts.key_file.empty()) opts.request.eeprom_hex_file = io::write_key_eeprom_image(opts.key_file);
    if (opts.dry_run) {
        // The same checks as a real run, so the printed command is one that can run (avrdude aside).
        io::check_image_and_port(opts.request);
        std::string line;
        for (const std::string& a : io::avrdude_arguments(opts.request))
            line += (line.empty() ? "" : " ") + io::shell_quoted(a);
        std::cout << line << "\n";
        if (!opts.key_file.empty())
            std::cerr << "note: " << opts.request.eeprom_hex_file
                      << " holds the key (owner-only); remove it once flashed\n";
        return;
    }
    const char* path = std::getenv("PATH");
    try {
        io::run_avrdude(opts.request, path != nullptr ? path : "/usr/bin:/bin");
    } catch (...) {
        if (!opts.key_file.empty()) std::filesystem::remove(opts.request.eeprom_hex_file);
        throw;
    }
    if (!opts.key_file.empty()) std::filesystem::remove(opts.request.eeprom_hex_file);
    std::cout << "flashed " << opts.request.hex_file << " to " << opts.request.port
              << (opts.key_file.empty() ? "" : " with the key of " + opts.key_file) << "\n";
}

}  // namespace

void register_flash(CLI::App& app) {
    auto opts = std::make_shared<FlashOptions>();
    CLI::App* cmd = app.add_subcommand("flash", "Write the firmware to an Arduino Uno/Nano-class board with avrdude");
    cmd->add_option("--port", opts->request.port, "Serial device of the board (default: the only USB adapter)")
        ->check(non_empty_path());
    cmd->add_option("--programmer", opts->request.programmer, "avrdude programmer id")
        ->capture_default_str()
        ->check(non_empty("an avrdude programmer id"));
    cmd->add_option("--baud", opts->request.baud, "Bootloader baud rate [bit/s]")
        ->capture_default_str()
        ->check(baud_rate());
    cmd->add_option("--part", opts->request.part, "avrdude part id")
        ->capture_default_str()
        ->check(non_empty("an avrdude part id"));
    cmd->add_option("--hex", opts->request.hex_file, "Intel HEX image (default: the AVR build's driftlab_fw.hex)")
        ->check(non_empty_path());
    cmd->add_option("--avrdude", opts->request.avrdude, "avrdude program")
        ->capture_default_str()
        ->check(non_empty_path());
    cmd->add_option("--key", opts->key_file,
                    "Also write this command key (driftlab keygen) into the board's EEPROM: needs a bootloader that "
                    "writes EEPROM, or an ISP programmer")
        ->check(non_empty_path());
    cmd->add_flag("--dry-run", opts->dry_run, "Print the avrdude command instead of running it");
    cmd->callback([opts] { run_flash(*opts); });
}

}  // namespace driftlab::host::cli
