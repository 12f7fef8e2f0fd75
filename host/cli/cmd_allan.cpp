// `driftlab allan FILE`: overlapping Allan (and modified Allan, overlapping Hadamard) deviations with
// confidence intervals, noise types and IEEE 952 terms, per channel; raw and drift-removed (logs, and plain rate
// files with --remove-drift; host/stats, docs/allan.md §§7-8).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/fit/allan_pipeline.hpp"
#include "host/fit/series.hpp"
#include "host/log/log_reader.hpp"
#include "host/log/log_window.hpp"
#include "host/report/gnuplot.hpp"
#include "host/report/json_out.hpp"
#include "host/stats/lone_values.hpp"
#include "host/stats/rate_unit.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"

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

json curve_json(const stats::AnalysedCurve& c, const char* dev_key) {
    json j;
    j["tau"] = report::json_array(c.curve.tau_s);
    j[dev_key] = report::json_array(c.curve.dev);
    j["ci_low"] = report::json_array(c.ci_low);
    j["ci_high"] = report::json_array(c.ci_high);
    j["noise"] = c.alpha;
    j["noise_identified"] = c.alpha_identified;
    j["n"] = c.curve.n;
    j["n_skipped"] = c.curve.n_skipped;
    j["edf"] = report::json_array(c.edf);
    return j;
}

json terms_json(const stats::NoiseTermFit& t, const stats::SampleUnit& u) {
    if (!t.ok) return nullptr;
    const std::string& U = u.name;
    const char* units[stats::kNoiseTermCount] = {"*s", "/sqrt(Hz)", "", "/sqrt(s)", "/s"};
    json j = {{"unit", U},
              {"model", "AVAR = 3Q^2/tau^2 + N^2/tau + (2 ln2/pi) B^2 + K^2 tau/3 + R^2 tau^2/2"},
              {"bias_instability_factor", stats::kBiasInstabilityFactor}};
    for (std::size_t k = 0; k < stats::kNoiseTermCount; ++k) {
        // A term pinned at 0 keeps its value 0 for readers of `value`; the null error and the bound say it is
        // not a measured zero.
        json term = {{"value", report::json_number(t.value[k])},
                     {"std_error", t.at_bound[k] ? json(nullptr) : report::json_number(t.std_error[k])},
                     {"unit", U + units[k]}};
        if (t.at_bound[k]) term["upper_bound"] = report::json_number(t.upper_bound[k]);
        j[stats::kNoiseTermSymbols[k]] = term;
    }
    // An unresolved term's NamedValue::value is NaN: null here, never a 0 to paste into a filter's configuration.
    json phys = json::object();
    for (const auto& nv : stats::physical_terms(t, u.quantity, u.si_per_unit))
        phys[nv.key] = report::json_number(nv.value);
    j["physical"] = phys;
    return j;
}

json version_json(const fit::AllanCurves& v, const stats::SampleUnit& u) {
    json j = curve_json(v.curves.front(), "adev");
    if (const auto* m = v.find(stats::Deviation::mdev)) j["mdev"] = curve_json(*m, "dev");
    if (const auto* h = v.find(stats::Deviation::ohdev)) j["hdev"] = curve_json(*h, "dev");
    j["terms"] = terms_json(v.terms, u);
    json k = json::object();
    for (const auto& nv : stats::kalibr_densities(v.terms, u.quantity, u.si_per_unit))
        k[nv.key] = report::json_number(nv.value);
    j["kalibr"] = k.empty() ? json(nullptr) : k;
    return j;
}

void print_named(const char* prefix, const stats::NamedValue& nv) {
    const int width = 26 - static_cast<int>(std::string(prefix).size());
    if (nv.resolved)
        std::printf("      %s%-*s %.5g\n", prefix, width, nv.key.c_str(), nv.value);
    else
        std::printf("      %s%-*s not resolved (<= %.5g)\n", prefix, width, nv.key.c_str(), nv.upper_bound);
}

// The table's n hides what the gaps cost: from the first tau where they skip more than 20 % of the terms, say so
// and why the curve may end early (JSON has n_skipped per tau).
void print_skipped_note(const stats::DeviationCurve& c, double longest_gap_free_s) {
    constexpr double kNotable = 0.2;
    const auto share = [&](std::size_t i) {
        const auto all = static_cast<double>(c.n[i] + c.n_skipped[i]);
        return all > 0.0 ? static_cast<double>(c.n_skipped[i]) / all : 0.0;
    };
    std::size_t first = 0;
    while (first < c.m.size() && share(first) <= kNotable) ++first;
    if (first == c.m.size()) return;
    std::size_t most = first;
    for (std::size_t i = first; i < c.m.size(); ++i)
        if (share(i) > share(most)) most = i;
    std::printf(
        "    note: gaps skip more than 20 %% of the terms from tau = %.5g s on (%.0f %% at tau = %.5g s); the longest "
        "gap-free stretch is %.5g s, and a term spans 2 tau (3 tau for mdev and hdev)\n",
        c.tau_s[first], 100.0 * share(most), c.tau_s[most], longest_gap_free_s);
}

void print_version(const char* title, const fit::AllanCurves& v, const stats::SampleUnit& u,
                   double longest_gap_free_s) {
    std::printf("  %s\n", title);
    for (const auto& c : v.curves) {
        std::printf("    %-6s %12s %10s %5s %12s %12s %12s\n", std::string(stats::deviation_name(c.curve.type)).c_str(),
                    "tau [s]", "n", "alpha", "low", "dev", "high");
        for (std::size_t i = 0; i < c.curve.m.size(); ++i) {
            std::printf("    %-6s %12.5g %10lld %5d %12.5g %12.5g %12.5g\n", "", c.curve.tau_s[i],
                        static_cast<long long>(c.curve.n[i]), c.alpha[i], c.ci_low[i], c.curve.dev[i], c.ci_high[i]);
        }
        print_skipped_note(c.curve, longest_gap_free_s);
    }
    if (!v.terms.ok) return;
    const char* units[stats::kNoiseTermCount] = {"*s", "/sqrt(Hz)", " (ADEV floor = 0.664 B)", "/sqrt(s)", "/s"};
    const char* bound_units[stats::kNoiseTermCount] = {"*s", "/sqrt(Hz)", ", the ADEV minimum / 0.664", "/sqrt(s)",
                                                       "/s"};
    std::printf("    IEEE 952 terms [%s]:", u.name.c_str());
    for (std::size_t k = 0; k < stats::kNoiseTermCount; ++k) {
        if (v.terms.at_bound[k])
            std::printf(" %s not resolved (<= %.4g%s)", stats::kNoiseTermSymbols[k], v.terms.upper_bound[k],
                        bound_units[k]);
        else
            std::printf(" %s = %.4g%s", stats::kNoiseTermSymbols[k], v.terms.value[k], units[k]);
        std::printf("%s", k + 1 < stats::kNoiseTermCount ? "," : "\n");
    }
    for (const auto& nv : stats::physical_terms(v.terms, u.quantity, u.si_per_unit)) print_named("", nv);
    for (const auto& nv : stats::kalibr_densities(v.terms, u.quantity, u.si_per_unit)) print_named("kalibr ", nv);
}

report::Plot allan_plot(const std::string& name, const fit::AllanResult& r, const stats::SampleUnit& u) {
    report::Plot p;
    p.title = "Allan deviation: " + name;
    p.x_label = "tau [s]";
    p.y_label = "overlapping ADEV [" + u.name + "]";
    p.log_x = p.log_y = true;
    const fit::AllanCurves& main = r.primary();
    const stats::AnalysedCurve& c = main.curves.front();
    report::PlotSeries band{r.drift_removed ? "drift removed (68 % CI)" : "ADEV (68 % CI)",
                            c.curve.tau_s,
                            c.curve.dev,
                            c.ci_low,
                            c.ci_high,
                            report::SeriesStyle::error_bars,
                            false,
                            "#1f77b4",
                            1.5};
    p.series.push_back(band);
    if (r.drift_removed) {
        const auto& raw = r.raw.curves.front();
        p.series.push_back({"raw (with drift)",
                            raw.curve.tau_s,
                            raw.curve.dev,
                            {},
                            {},
                            report::SeriesStyle::lines,
                            false,
                            "#7f7f7f",
                            1.5});
    }
    if (main.terms.ok) {
        p.series.push_back({"IEEE 952 fit",
                            c.curve.tau_s,
                            main.terms.model_adev,
                            {},
                            {},
                            report::SeriesStyle::lines,
                            false,
                            "#d62728",
                            2.0});
        for (std::size_t k = 0; k < stats::kNoiseTermCount; ++k) {
            if (main.terms.value[k] <= 0.0) continue;
            std::array<double, stats::kNoiseTermCount> only{};
            only[k] = main.terms.value[k];
            std::vector<double> y;
            for (double t : c.curve.tau_s) y.push_back(std::sqrt(stats::noise_term_avar(only, t)));
            p.series.push_back({std::string(stats::kNoiseTermSymbols[k]) + " term",
                                c.curve.tau_s,
                                y,
                                {},
                                {},
                                report::SeriesStyle::lines,
                                true,
                                "",
                                1.0});
        }
    }
    return p;
}

void run(const AllanCommandOptions& o) {
    fit::AllanRequest req;
    req.deviations = parse_deviations(o.deviation);
    try {
        req.grid.grid = stats::parse_tau_grid(o.grid);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--grid: ") + e.what());
    }
    req.grid.points_per_decade = o.per_decade;
    req.remove_drift = !o.keep_drift;
    fit::OpenedSource source = fit::open_source(o.path);
    const bool log = source.canonical_log;
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
        print_note(dropped_cut_line_note(data), o.json);
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
    const std::vector<std::string> selection =
        series.empty() ? std::vector<std::string>{}
                       : fit::selection_notes(series.front().t_s, o.from_s, o.to_s, o.excluded);
    for (const std::string& note : selection) print_note(note, o.json);
    for (fit::Series& s : series) {
        fit::Series kept = fit::rows_kept(s, o.from_s, o.to_s, o.excluded);
        // The grid needs two samples: where --from/--to leave fewer, say where the rows are.
        if (kept.t_s.size() < 2 && s.t_s.size() >= 2)
            throw DataError(o.path, 0, fit::too_few_kept(s, kept.t_s.size(), "the Allan deviation", 2));
        s = std::move(kept);
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
        const stats::SampleUnit u =
            s.channel ? stats::unit_of_channel(*s.channel) : stats::unit_of_name(unit ? unit->name : "unit");
        const std::optional<std::string> packing = fit::packing_caveat(r, r.primary().curves.front());
        const std::optional<std::string> lone = stats::lone_values_warning(s.t_s, s.values, fit::code_of(s));
        if (o.json) {
            json c = version_json(r.primary(), u);
            c["tau0_s"] = tau0;
            c["samples"] = r.samples;
            c["t_first_s"] = s.t_s.front();  // as fit gives them: the rows --from/--to kept
            c["t_last_s"] = s.t_s.back();
            c["gap_samples"] = r.gap_samples;
            c["packed_samples"] = r.packed_samples;
            c["packed_most_slots"] = r.packed_most_slots;
            c["packing_warning"] = packing ? json(*packing) : json(nullptr);
            c["lone_values_warning"] = lone ? json(*lone) : json(nullptr);
            c["drift_removed"] = r.drift_removed.has_value();
            c["drift_status"] = r.drift_status_name();
            if (r.drift) c["drift"] = {{"C1", r.drift->c1}, {"C2", r.drift->c2}, {"T_s", r.drift->t_s}};
            if (r.drift_removed) c["raw"] = version_json(r.raw, u);
            out["channels"][s.name] = c;
        } else {
            std::printf("%s: %s, tau0 = %.6g s, %zu samples, %zu gap samples, drift: %s\n", o.path.c_str(),
                        s.name.c_str(), tau0, r.samples, r.gap_samples,
                        r.drift_removed ? "removed (eq. 1)" : r.drift_status_words().c_str());
            if (lone) std::printf("  warning: %s\n", lone->c_str());
            if (packing) std::printf("  warning: %s\n", packing->c_str());
            if (r.drift_removed) print_version("drift removed", *r.drift_removed, u, r.longest_gap_free_s);
            print_version(r.drift_removed ? "raw" : "as given", r.raw, u, r.longest_gap_free_s);
        }
        if (!o.plot_dir.empty()) report::render_plot(allan_plot(s.name, r, u), o.plot_dir, "allan_" + s.name);
    }
    if (o.json) report::write_json(std::cout, out);
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
