// `driftlab upload --port DEV --cal CAL.json`: the calibration into a board, read back and confirmed by the board
// (host/io/calibration_upload; docs/calibration.md).
#include <iostream>
#include <memory>
#include <string>

#include "host/cal/cal_file.hpp"
#include "host/cal/calibration.hpp"
#include "host/cli/commands.hpp"
#include "host/io/calibration_upload.hpp"
#include "host/io/key_file.hpp"
#include "host/io/serial_port.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {
namespace {

struct UploadOptions {
    std::string port;
    int baud = 115200;
    std::string cal_path;
    bool clear = false;
    std::string key_file;
};

std::array<proto::CalPayload, kChannelCount> cleared() {
    std::array<proto::CalPayload, kChannelCount> out{};
    for (std::uint8_t c = 0; c < kChannelCount; ++c) out[c].channel = c;
    return out;
}

void run(const UploadOptions& o) {
    if (o.clear == !o.cal_path.empty()) throw UsageError("give either --cal CAL.json or --clear");
    const std::array<proto::CalPayload, kChannelCount> entries =
        o.clear ? cleared() : cal::to_payloads(cal::read_calibration(o.cal_path), o.cal_path);
    io::SerialPort port(o.port, o.baud);
    io::BoardClient client(port);
    if (!o.key_file.empty()) client.set_key(io::read_key_file(o.key_file));
    const io::UploadResult r = io::upload_calibration(client, entries);
    if (!r.ok) throw DeviceError(o.port, r.problem);
    if (o.clear)
        std::cout << o.port << ": calibration cleared; the board outputs what it measures\n";
    else
        std::cout << o.port << ": calibration " << entries[0].cal_id << " stored, read back and in use\n";
}

}  // namespace

void register_upload(CLI::App& app) {
    auto opts = std::make_shared<UploadOptions>();
    CLI::App* cmd = app.add_subcommand(
        "upload", "Store a calibration in a board's EEPROM, read it back and check the board uses it");
    cmd->add_option("--port", opts->port, "Serial device of the board")->required()->check(non_empty_path());
    cmd->add_option("--baud", opts->baud, "Serial baud rate [bit/s]")->capture_default_str()->check(baud_rate());
    cmd->add_option("--cal", opts->cal_path, "Calibration file written by `driftlab calibrate`")
        ->check(non_empty_path());
    cmd->add_flag("--clear", opts->clear, "Clear the board's calibration: outputs as measured");
    cmd->add_option("--key", opts->key_file,
                    "The board's command key (driftlab keygen; needed once `flash --key` gave it one)")
        ->check(non_empty_path());
    cmd->callback([opts] { run(*opts); });
}

}  // namespace driftlab::host::cli
