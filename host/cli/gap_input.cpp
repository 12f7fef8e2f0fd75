// What `driftlab gap` reads; see gap_input.hpp.
#include "host/cli/gap_input.hpp"

#include <cstdio>
#include <optional>

#include "driftlab/proto/messages.hpp"
#include "host/cli/commands.hpp"
#include "host/fit/series.hpp"
#include "host/gap/canonical_log.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap/plain_recording.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/numeric_table.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::cli {
std::array<bool, kChannelCount> channels_named(const GapInput& o) {
    std::array<bool, kChannelCount> out{};
    for (const std::string& name : o.channels) {
        const std::optional<Channel> c = channel_named(name);
        if (!c) throw UsageError("--channel: unknown channel '" + name + "' (" + channel_name_list() + ")");
        out[channel_index(*c)] = true;
    }
    return out;
}

namespace {

// Cuts `log` to the rows --from/--to keep (all without them), less those --exclude and --exclude-saturated leave out,
// and returns the note of what the range kept. Only the channels the diagnosis analyses count as saturated: a channel
// stuck at a rail is left out of it, not its rows.
std::vector<std::string> cut_to_window(const GapInput& o, LogData& log) {
    std::vector<std::string> notes = fit::selection_notes(log.t_s, o.from_s, o.to_s, {});
    if (o.windowed()) log = rows_between(log, o.from_s, o.to_s);
    std::vector<TimeWindow> windows = o.excluded;
    if (o.saturated_margin_s >= 0.0) {
        gap::GapOptions selection;
        selection.channels = channels_named(o);
        const auto saturated = saturated_stretches(log, gap::analysed_channels(log, selection), o.saturated_margin_s);
        windows.insert(windows.end(), saturated.begin(), saturated.end());
    }
    if (!windows.empty()) log = rows_outside(log, windows);
    return notes;
}

}  // namespace

LoadedRecording load_recording(const GapInput& o) {
    const sim::SimModel unit = o.model_path.empty() ? sim::paper_model() : sim::load_model_file(o.model_path);
    fit::OpenedSource source = fit::open_source(o.path);
    const ReadOptions read = fit::cut_line_options(source, o.path, o.drop_cut_line);
    if (source.canonical_log) {
        if (!o.mappings.empty() || o.tau0_s > 0.0 || o.block != 1)
            throw UsageError("--as, --tau0 and --block are for plain recordings; " + o.path + " is a canonical log");
        LoadedRecording out{
            gap::read_canonical_log(source.in, o.path, read, unit, !o.truth_path.empty() || o.motion_without_truth),
            unit,
            {},
            {}};
        out.notes = cut_to_window(o, out.log);
        if (!o.truth_path.empty()) {
            out.truth = read_truth_file(o.truth_path);
            match_truth_rows(*out.truth, out.log, o.windowed() || !out.log.cuts.empty());
        }
        return out;
    }
    if (!o.truth_path.empty())
        throw UsageError("--truth takes the ground truth of a canonical log (hil --trajectory writes both); " + o.path +
                         " is a plain recording");
    if (o.mappings.empty() || !(o.tau0_s > 0.0))
        throw UsageError(o.path +
                         " is not a canonical log: a plain recording needs --tau0 SECONDS and at least one "
                         "--as CHANNEL=COLUMN:LSB (e.g. --as gyro=col1:0.00875)");
    gap::PlainRecording how;
    for (const auto& m : o.mappings) how.columns.push_back(gap::parse_column_mapping(m));
    how.sample_period_s = o.tau0_s;
    how.block = o.block;
    LoadedRecording out{gap::log_from_table(parse_numeric_table(source.in, o.path), how), unit, {}, {}};
    out.unit = gap::unit_of_recording(unit, how, out.log);
    out.notes = cut_to_window(o, out.log);
    return out;
}

std::string rows_used(const GapInput& o, const LogData& log) {
    if (!o.windowed() && log.cuts.empty()) return "";
    char text[80];
    // Rows remain, or it was refused
    std::snprintf(text, sizeof text, " (rows from %g s to %g s", log.t_s.front(), log.t_s.back());
    std::string out = text;
    for (std::size_t i = 0; i < log.cuts.size(); ++i) {
        std::snprintf(text, sizeof text, "%s%g s to %g s", i == 0 ? ", without " : " and ", log.cuts[i].from_s,
                      log.cuts[i].to_s);
        out += text;
    }
    return out + ")";
}

void add_plain_recording_options(CLI::App* cmd, GapInput& input) {
    cmd->add_option(
        "--as", input.mappings,
        "Plain recordings: analyse COLUMN (its name, or col1... without a name line) as CHANNEL, in codes of "
        "LSB (its resolution in the column's unit: deg/s or g unless UNIT is mdps, rad/s, mg or m/s2), "
        "e.g. gyro=col1:0.00875 or gyro=gx:1.33e-4:rad/s; repeat per channel");
    cmd->add_option("--tau0", input.tau0_s,
                    "Plain recordings: the raw sample period [s] (timing from a time column, as fit finds it, "
                    "if there is one)")
        ->check(positive_number());
    cmd->add_option("--block", input.block,
                    "Plain recordings: samples averaged per output (an order-0 smoother of that "
                    "window; default 1)")
        ->check(whole_number_in(1, proto::kConversionsPerOutputMax));
}

}  // namespace driftlab::host::cli
