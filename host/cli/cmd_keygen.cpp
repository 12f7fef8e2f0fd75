// `driftlab keygen -o KEY`: a board's 128-bit command key in an owner-only file (host/io/key_file; docs/security.md).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/io/key_file.hpp"

namespace driftlab::host::cli {

void register_keygen(CLI::App& app) {
    auto out = std::make_shared<std::string>();
    CLI::App* cmd =
        app.add_subcommand("keygen", "Make a board's 128-bit command key in a file only its owner may read");
    cmd->add_option("-o,--output", *out, "Key file to create (never over an existing one)")
        ->required()
        ->check(non_empty_path());
    cmd->callback([out] {
        io::write_key_file(*out, io::new_key());
        std::cout << "wrote a 128-bit key to " << *out
                  << " (owner-only); put it on the board with `driftlab flash --key " << *out << "`\n";
    });
}

}  // namespace driftlab::host::cli
