// `driftlab allan FILE`: overlapping Allan (and modified Allan, overlapping Hadamard) deviations with
// confidence intervals, noise types and IEEE 952 terms, per channel; raw and drift-removed (logs, and plain rate
// files with --remove-drift; host/stats, docs/allan.md §§7-8).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/fit/allan_pipeline.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/fit/series.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/log_window.hpp"
#include "host/stats/lone_values.hpp"
#include "host/stats/rate_unit.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"
#include "host/view/allan_view.hpp"
#include "host/view/analysis_notes.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::cli {
namespace {

using nlohmann::json;

struct AllanCommandOptions {
    std::string path;
    std::vector<std::string> channels;  ///< empty or "all" = every channel / column
    std::string kind;                   ///< plain files: rate | phase (required); logs: rate only
    double tau0_s = 0.0;                ///< plain files: required; logs: default stats::grid_period_s
    std::vector<std::string> units;     ///< plain files: --unit [COLUMN:]UNIT, as report takes it
    std::string grid = "octave";
    int per_decade = 10;
    std::string deviation = "oadev";
    bool keep_drift = false;
    bool remove_drift = false;   ///< plain rate files: fit and remove eq. 1 as for logs
    bool drop_cut_line = false;  ///< logs: a cut last line is dropped (and noted), not refused
    double from_s = -INFINITY;   ///< --from/--to: rows kept, from_s <= t_s <= to_s [s since power-on]
    double to_s = INFINITY;
    std::vector<TimeWindow> excluded;  ///< --exclude: rows left out, gap slots on the grid
    bool json = false;
    std::string plot_dir;
};

std::vector<stats::Deviation> parse_deviations(const std::string& s) {
    if (s == "all") return {stats::Deviation::oadev, stats::Deviation::mdev, stats::Deviation::ohdev};
    if (s == "oadev") return {stats::Deviation::oadev};
    if (s == "mdev") return {stats::Deviation::mdev};
    if (s == "hdev") return {stats::Deviation::ohdev};  // the overlapping Hadamard estimator
    throw UsageError("--deviation: expected oadev, mdev, hdev or all, got '" + s + "'");
}

// The series of a canonical log (`log` set) or a plain file, as --kind and --remove-drift ask (which set `req`).
std::vector<fit::Series> load_series(const AllanCommandOptions& o, fit::AllanRequest& req, bool& log) {
    fit::OpenedSource source = fit::open_source(o.path);
    log = source.canonical_log;
    const ReadOptions read = fit::cut_line_options(source, o.path, o.drop_cut_line);
    std::vector<std::string> names = o.channels;
    if (names.size() == 1 && names[0] == "all") names.clear();
    std::vector<fit::Series> series;
    if (log) {
        if (!o.kind.empty() && o.kind != "rate")
            throw UsageError("--kind: a canonical log holds rate samples (counts)");
        if (!o.units.empty())
            throw UsageError("--unit: a canonical log is in counts; physical units follow the channel");
        const LogData data = parse_log(source.in, o.path, read);
        view::print_note(dropped_cut_line_note(data), o.json);
        for (const std::string& note : fit::saturation_notes(data)) view::print_note(note, o.json);
        series = fit::series_from_log(data, names);
    } else {
        if (o.kind.empty() || o.tau0_s <= 0.0) {
            throw UsageError(
                "a plain numeric file needs --kind rate|phase and --tau0 SECONDS (the input kind is "
                "never guessed)");
        }
        req.kind = o.kind == "rate" ? stats::InputKind::rate : stats::InputKind::phase;
        if (o.remove_drift && req.kind != stats::InputKind::rate)
            throw UsageError("--remove-drift: eq. 1 is a model of the rate; phase input has no drift to remove");
        // Plain files are analysed as given unless asked (published references compare against the file as is).
        req.remove_drift = o.remove_drift;
        req.kept_drift_status = req.kind == stats::InputKind::rate
                                    ? "not removed: a plain file is analysed as given; --remove-drift fits eq. 1 first"
                                    : "not removed: a plain file is analysed as given";
        series = fit::load_series(std::move(source), o.path, names, "", o.tau0_s);
    }
    return series;
}

void run(const AllanCommandOptions& o) {
    fit::AllanRequest req;
    req.deviations = parse_deviations(o.deviation);
    req.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    try {
        req.grid.grid = stats::parse_tau_grid(o.grid);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--grid: ") + e.what());
    }
    req.grid.points_per_decade = o.per_decade;
    req.remove_drift = !o.keep_drift;
    bool log = false;
    std::vector<fit::Series> series = load_series(o, req, log);
    const std::vector<std::string> selection =
        series.empty() ? std::vector<std::string>{}
                       : fit::selection_notes(series.front().t_s, o.from_s, o.to_s, o.excluded);
    for (const std::string& note : selection) view::print_note(note, o.json);
    for (fit::Series& s : series) {
        // The grid needs two samples: where --from/--to leave fewer, say where the rows were.
        fit::Series ends;
        ends.name = s.name;
        if (!s.t_s.empty()) ends.t_s = {s.t_s.front(), s.t_s.back()};
        const std::size_t rows = s.t_s.size();
        s = fit::rows_kept(std::move(s), o.from_s, o.to_s, o.excluded);  // in place: ten million rows are 160 MB
        if (s.t_s.size() < 2 && rows >= 2)
            throw DataError(o.path, 0, fit::too_few_kept(ends, s.t_s.size(), "the Allan deviation", 2));
    }
    // Phase samples are in their integral's unit (deg for deg/s); the assignment holds the deviations' (the rate's).
    const stats::UnitAssignment units = stats::parse_unit_assignment(o.units, "--unit", req.kind);
    std::vector<std::string> columns;
    for (const fit::Series& s : series) columns.push_back(s.name);
    stats::refuse_unknown_columns(units, columns, o.path);

    json out = {{"file", o.path},
                {"kind", req.kind == stats::InputKind::rate ? "rate" : "phase"},
                {"grid", o.grid},
                {"confidence", req.confidence},
                {"channels", json::object()}};
    for (const fit::Series& s : series) {
        // The report's rule, so `allan` and the report's Allan section give a log the same tau0: at the median, rows
        // in bursts had left 80 % of the grid gaps and ended the curve at 16 ms (the MPU6050 recording).
        const double tau0 = o.tau0_s > 0.0 ? o.tau0_s : stats::grid_period_s(s.t_s);
        if (!(tau0 > 0.0)) throw DataError(o.path, 0, "series '" + s.name + "': fewer than two samples");
        // The grid places each sample at its time / tau0: rows faster than tau0 would be packed onto consecutive
        // slots (their time, and a real gap after them, lost), slower ones spread over empty slots. tau0 must be the
        // rows' spacing: the median, or the mean where they come in bursts (an MPU6050 read 100 times a second in
        // bursts 2 ms apart).
        if (const auto disagreement = stats::tau0_disagreement(s.t_s, tau0))
            throw UsageError(*disagreement + (log ? "; leave --tau0 out to use the rows' spacing"
                                                  : "; give their spacing, or a table without a time column"));
        fit::AllanResult r;
        try {
            r = fit::analyse_allan(s.t_s, s.values, tau0, req);
        } catch (const std::invalid_argument& e) {
            throw DataError(o.path, 0, "series '" + s.name + "': " + e.what());
        }
        const auto unit = units.for_column(s.name);
        fit::AllanSeriesResult shown{
            s.name,
            tau0,
            s.t_s.front(),
            s.t_s.back(),
            std::move(r),
            s.channel ? stats::unit_of_channel(*s.channel) : stats::unit_of_name(unit ? unit->name : "unit"),
            {},
            stats::lone_values_warning(s.t_s, s.values, fit::code_of(s))};
        shown.packing_warning = fit::packing_caveat(shown.result, shown.result.primary().curves.front());
        if (o.json)
            out["channels"][s.name] = view::allan_json(shown);
        else
            view::print_allan_text(o.path, shown);
        if (!o.plot_dir.empty()) view::write_allan_plot(shown, o.plot_dir);
    }
    if (o.json) view::write_json(std::cout, out);
}

}  // namespace

void register_allan(CLI::App& app) {
    auto o = std::make_shared<AllanCommandOptions>();
    CLI::App* cmd = app.add_subcommand("allan",
                                       "Allan deviation (overlapping, modified, Hadamard) with confidence "
                                       "intervals, noise types and IEEE 952 terms");
    cmd->add_option("file", o->path, "Canonical log, or a plain numeric file (then --kind and --tau0)")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("--channel", o->channels, "Channels (log) or columns (plain file): NAME[,NAME] or all")
        ->delimiter(',');
    cmd->add_option("--kind", o->kind, "Plain files: rate (rate / fractional-frequency samples) or phase (integrated)")
        ->check(CLI::Validator(
            [](std::string& kind) {
                return kind == "rate" || kind == "phase" ? std::string() : "expected rate or phase, got '" + kind + "'";
            },
            ""));
    cmd->add_option("--tau0", o->tau0_s,
                    "Sample period [s]; required for plain files, logs default to the rows' median spacing (their "
                    "mean for rows in bursts, as report)")
        ->check(positive_number());
    add_unit_option(cmd, o->units, true);
    add_drop_cut_line_flag(cmd, o->drop_cut_line);
    add_time_range_options(cmd, o->from_s, o->to_s);
    add_exclude_option(
        cmd, o->excluded,
        "a corrupt row or a disturbance; its rows become gap slots on the tau grid, which the terms skip");
    cmd->add_option("--grid", o->grid, "Tau grid: octave, log, all (every m; slow for long records) or stable32")
        ->capture_default_str();
    // A whole number: the grid is 10^(k / per_decade), which puts every power of ten on it. 1000 is more than the
    // distinct m of the first three decades; --grid all is every m. CLI11 had refused 2.5 as a failed conversion.
    cmd->add_option("--per-decade", o->per_decade, "Taus per decade for --grid log, a whole number (default 10)")
        ->check(whole_number_in(1, 1000));
    cmd->add_option("--deviation", o->deviation, "oadev, mdev, hdev (overlapping Hadamard) or all")
        ->capture_default_str();
    auto* keep =
        cmd->add_flag("--keep-drift", o->keep_drift, "Logs: do not fit and remove the turn-on drift (eq. 1) first");
    cmd->add_flag(
           "--remove-drift", o->remove_drift,
           "Plain --kind rate files: fit and remove the turn-on drift (eq. 1) first, as for logs (the default there)")
        ->excludes(keep);
    cmd->add_flag("--json", o->json,
                  "Print JSON (keys: channels.<name>.{tau,adev,ci_low,ci_high,noise,n,mdev,hdev,terms,kalibr,raw})");
    cmd->add_option("--plot", o->plot_dir, "Write allan_<channel>.png/.svg into this folder")->check(non_empty_path());
    cmd->callback([o] { run(*o); });
}

}  // namespace driftlab::host::cli
