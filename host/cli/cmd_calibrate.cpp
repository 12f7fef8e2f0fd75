// `driftlab calibrate LOG -o CAL.json`: eq. 1 fitted to every channel of a board's log, written as the calibration the
// board applies (host/cal; docs/calibration.md).
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "host/cal/cal_file.hpp"
#include "host/cal/calibration.hpp"
#include "host/cli/commands.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "host/util/output_file.hpp"
#include "host/view/calibration_view.hpp"

namespace driftlab::host::cli {
namespace {

struct CalibrateOptions {
    fit::FileAnalysisRequest request;
    std::string out;
    std::optional<std::uint16_t> id;
    std::vector<std::string> zero{"gyro"};
    bool json = false;
    bool overwrite = false;
};

std::array<bool, kChannelCount> zero_mask(const std::vector<std::string>& names) {
    std::array<bool, kChannelCount> mask{};
    if (names.size() == 1 && names[0] == "none") return mask;
    for (const std::string& n : names) {
        const std::optional<Channel> c = channel_named(n);
        if (!c) throw UsageError("--zero: '" + n + "' is not a channel (" + channel_name_list() + ", or none)");
        mask[channel_index(*c)] = true;
    }
    return mask;
}

void run(const CalibrateOptions& o) {
    refuse_writing_over_input(o.out, "-o", o.request.path, "log");
    refuse_replacing(o.out, "calibration", "-o", o.overwrite);
    const std::array<bool, kChannelCount> zero = zero_mask(o.zero);
    check_output_file(o.out, "calibration");
    const fit::FileAnalysis file = fit::analyse_file(o.request);
    const cal::Calibration calibration = cal::from_fit(file, zero, o.id);
    cal::write_calibration(o.out, calibration);
    if (o.json)
        std::cout << cal::calibration_json(calibration);
    else
        view::print_calibration(std::cout, calibration, o.out);
}

}  // namespace

void register_calibrate(CLI::App& app) {
    auto opts = std::make_shared<CalibrateOptions>();
    CLI::App* cmd = app.add_subcommand(
        "calibrate", "Fit eq. 1 to every channel of a log from power-on and write the calibration a board applies");
    cmd->add_option("log", opts->request.path, "Canonical log of an uncompensated board, recorded from power-on")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("-o,--output", opts->out, "Calibration file to write (CAL.json)")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("--id", opts->id, "Calibration id 1..65535 the board reports (default: from the model's bytes)")
        ->check(whole_number_in(1, 65535));
    cmd->add_option("--zero", opts->zero,
                    "Channels the board refers to mid-scale as well as removing their transient, or 'none' "
                    "(default gyro: its zero-rate code)")
        ->delimiter(',');
    add_time_range_options(cmd, opts->request.options.t_min_s, opts->request.options.t_max_s);
    add_drop_cut_line_flag(cmd, opts->request.drop_cut_line);
    cmd->add_flag("--json", opts->json, "Print the calibration file's JSON instead of the table");
    cmd->add_flag("--overwrite", opts->overwrite, "Replace an existing calibration file");
    cmd->callback([opts] { run(*opts); });
}

}  // namespace driftlab::host::cli
