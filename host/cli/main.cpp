// driftlab: the host command. Sets up the heap and the command table and maps errors to exit codes; nothing else.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/util/error.hpp"
#include "host/util/heap_policy.hpp"
#include "sim/sim_error.hpp"

namespace {

// One line per subcommand; see commands.hpp.
constexpr driftlab::host::cli::RegisterFn kCommands[] = {
    driftlab::host::cli::register_ports,     driftlab::host::cli::register_flash,
    driftlab::host::cli::register_keygen,    driftlab::host::cli::register_record,
    driftlab::host::cli::register_upload,    driftlab::host::cli::register_rekey,
    driftlab::host::cli::register_decode,    driftlab::host::cli::register_hil,
    driftlab::host::cli::register_effects,   driftlab::host::cli::register_fit,
    driftlab::host::cli::register_calibrate, driftlab::host::cli::register_whiteness,
    driftlab::host::cli::register_report,    driftlab::host::cli::register_allan,
    driftlab::host::cli::register_gap,       driftlab::host::cli::register_gap_eval,
    driftlab::host::cli::register_merge,     driftlab::host::cli::register_nav,
    driftlab::host::cli::register_nav_eval,  driftlab::host::cli::register_fleet,
};

// What a command printed before it failed (a note, a table) goes out before the error, as it happened: into one file
// or pipe the buffered standard output had been written at exit, after the error it led to.
void flush_output_so_far() {
    std::cout.flush();
    std::fflush(stdout);
}

// CLI11 names a refused option by its first long name; one with several ("--sample-period,--tau0") is named by all of
// them, as the notes name it, so that the spelling typed is in the message.
std::string naming_every_spelling(const CLI::App* command, std::string message) {
    for (const CLI::Option* opt : command->get_options()) {
        const std::vector<std::string>& names = opt->get_lnames();
        if (names.size() < 2 || message.rfind("--" + names.front() + ":", 0) != 0) continue;
        std::string all;
        for (const std::string& name : names) all += (all.empty() ? "--" : "/--") + name;
        return all + message.substr(2 + names.front().size());
    }
    return message;
}

// The message of an error that ends the command, after the output it had made; its exit code.
int report_error(const std::exception& e, int exit_code) {
    flush_output_so_far();
    std::fprintf(stderr, "driftlab: error: %s\n", e.what());
    return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
    driftlab::host::share_one_heap();
    CLI::App app{"driftlab: firmware, simulator and analysis tools for a low-cost IMU"};
    app.require_subcommand(1);
    app.set_version_flag("--version", driftlab::host::cli::kProgramVersion);
    app.formatter(driftlab::host::cli::help_formatter());  // before the subcommands, which take it when added
    for (auto reg : kCommands) reg(app);
    // The parser's refusals read like every other error, and say whose help lists the options.
    app.failure_message([](const CLI::App* a, const CLI::Error& e) {
        std::string command = "driftlab";
        std::string message = e.what();
        for (const CLI::App* sub : a->get_subcommands()) {
            command += " " + sub->get_name();
            message = naming_every_spelling(sub, message);
        }
        return "driftlab: error: " + message + "\n(" + command + " --help lists the options)\n";
    });
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // CLI11 prints the message (or the help); its own codes (105, 106, ...) would break the documented exit 2.
        return app.exit(e) == 0 ? 0 : driftlab::host::kUsageExitCode;
    } catch (const driftlab::host::Error& e) {
        return report_error(e, e.exit_code());
    } catch (const driftlab::sim::ModelFileError& e) {
        return report_error(e, driftlab::host::ConfigError::kExitCode);
    } catch (const driftlab::sim::BoardError& e) {
        return report_error(e, driftlab::host::DeviceError::kExitCode);
    } catch (const driftlab::sim::ConfigRefused& e) {
        return report_error(e, driftlab::host::kUsageExitCode);
    } catch (const std::exception& e) {
        flush_output_so_far();
        std::fprintf(stderr, "driftlab: internal error: %s\n", e.what());
        return 70;
    }
    // A full disk or a closed pipe must not pass for a written result: a script would go on with a cut JSON.
    std::cout.flush();
    const bool flushed = std::fflush(stdout) == 0;
    const int flush_errno = errno;
    if (!flushed || std::ferror(stdout) || std::cout.fail()) {
        // Only a failing final flush leaves its own errno; an earlier failed write left the stream's error flag.
        std::fprintf(stderr, "driftlab: error: writing the standard output: %s\n",
                     flushed ? "part of it was not written (a full disk?)" : std::strerror(flush_errno));
        return 4;  // the documented code for an output that cannot be written
    }
    return 0;
}
