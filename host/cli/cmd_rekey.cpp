// `driftlab rekey --port DEV --key OLD --new-key NEW`: the board takes a new command key, sent sealed under its
// current one (KEY_SET; docs/security.md "Keys").
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/io/board_client.hpp"
#include "host/io/key_file.hpp"
#include "host/io/serial_port.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::cli {
namespace {

struct RekeyOptions {
    std::string port;
    int baud = 115200;
    std::string key_file;
    std::string new_key_file;
};

void run(const RekeyOptions& o) {
    const io::CommandKey current = io::read_key_file(o.key_file);
    const io::CommandKey next = io::read_key_file(o.new_key_file);
    if (current == next) throw UsageError("--new-key " + o.new_key_file + " holds the key --key already gives");
    io::SerialPort port(o.port, o.baud);
    io::BoardClient client(port);
    client.set_key(current);
    const io::HelloResult hello = client.hello();
    if (!hello.ok) throw DeviceError(o.port, hello.problem);
    if (const std::string problem = client.key_change(next); !problem.empty()) throw DeviceError(o.port, problem);
    std::cout << o.port << ": the board now obeys the key of " << o.new_key_file << "; " << o.key_file
              << " no longer works\n";
}

}  // namespace

void register_rekey(CLI::App& app) {
    auto opts = std::make_shared<RekeyOptions>();
    CLI::App* cmd = app.add_subcommand("rekey", "Give a board a new command key, sent sealed under its current one");
    cmd->add_option("--port", opts->port, "Serial device of the board")->required()->check(non_empty_path());
    cmd->add_option("--baud", opts->baud, "Serial baud rate [bit/s]")->capture_default_str()->check(baud_rate());
    cmd->add_option("--key", opts->key_file, "The board's current key file")->required()->check(non_empty_path());
    cmd->add_option("--new-key", opts->new_key_file, "The new key file (driftlab keygen)")
        ->required()
        ->check(non_empty_path());
    cmd->callback([opts] { run(*opts); });
}

}  // namespace driftlab::host::cli
