// One board of a fleet; see board.hpp.
#include "host/fleet/board.hpp"

#include <optional>
#include <stdexcept>

#include "host/fit/allan_pipeline.hpp"
#include "host/fit/drift_analysis.hpp"
#include "host/fit/series.hpp"
#include "host/gap/diagnose.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/channel_name.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::fleet {
namespace {

// The longest tau the noise terms are fitted to is the record's span over this.
constexpr double kRecordPerTau = 20.0;

Estimate known(const fit::Estimate& e) { return {e.value, e.stderr_, true}; }

// Eq. 1 as `fit` reports it: C1 and T only where the record determines them, the widened errors.
void add_drift(const fit::Series& series, ChannelResult& out) {
    const fit::DriftAnalysis a = fit::analyse_drift(series);
    out.fit_status = fit::fit_status_name(a.fit.status);
    if (a.fit.status == fit::FitStatus::iteration_limit) return;  // the last iterate is no estimate
    if (a.c1_and_t_determined()) {
        out.parameters[0] = known(a.widened.c1);
        out.parameters[2] = known(a.widened.t_s);
    }
    if (a.c2_determined()) out.parameters[1] = known(a.widened.c2);
}

// N, B and K of the drift-removed overlapping ADEV (`allan`'s curve) up to a twentieth of the record, fitted without
// Q and R (kParameterCount); a term at its bound stays unknown. Longer taus hold a handful of independent averages
// from which eq. 1's removal has taken a share, and weigh in by an EDF their noise type makes too large: one board's
// N had come out 9 % low for the few longest points alone.
void add_noise(const fit::Series& series, ChannelResult& out) {
    const fit::AllanResult r =
        fit::analyse_allan(series.t_s, series.values, stats::grid_period_s(series.t_s), fit::AllanRequest{});
    const stats::AnalysedCurve& curve = r.primary().curves.front();
    const double longest = (series.t_s.back() - series.t_s.front()) / kRecordPerTau;
    std::vector<double> tau, adev, edf;
    for (std::size_t i = 0; i < curve.curve.tau_s.size() && curve.curve.tau_s[i] <= longest; ++i) {
        tau.push_back(curve.curve.tau_s[i]);
        adev.push_back(curve.curve.dev[i]);
        edf.push_back(curve.edf[i]);
    }
    stats::NoiseTermOptions options;
    options.enabled = {false, true, true, true, false};
    const stats::NoiseTermFit terms = stats::fit_noise_terms(tau, adev, edf, options);
    if (!terms.ok) return;
    using stats::NoiseTerm;
    std::size_t p = 3;
    for (const NoiseTerm k : {NoiseTerm::random_walk, NoiseTerm::bias_instability, NoiseTerm::rate_random_walk}) {
        const auto i = static_cast<std::size_t>(k);
        if (!terms.at_bound[i] && terms.value[i] > 0.0) out.parameters[p] = {terms.value[i], terms.std_error[i], true};
        ++p;
    }
}

void add_gap(const LogData& log, const sim::SimModel& unit, const BoardOptions& o, BoardResult& out) {
    gap::GapOptions options;
    options.replicates = o.replicates;
    options.seed = o.seed;
    for (const std::string& name : o.channels)
        if (const std::optional<Channel> c = channel_named(name)) options.channels[channel_index(*c)] = true;
    out.gap_run = true;
    try {
        const gap::GapResult r = gap::diagnose(log, unit, options);
        out.gap_verdict = r.verdict;
        out.gap_located = r.located.size() + r.link.located.size();
    } catch (const Error& e) {
        out.gap_error = e.what();
    }
}

}  // namespace

BoardResult analyse_board(const LogData& log, const sim::SimModel& unit, const BoardOptions& options) {
    BoardResult out;
    out.rows = log.t_s.size();
    if (!log.t_s.empty()) out.duration_s = log.t_s.back() - log.t_s.front();
    for (const fit::Series& series : fit::series_from_log(log, options.channels)) {
        ChannelResult channel;
        channel.channel = series.name;
        try {
            add_drift(series, channel);
            add_noise(series, channel);
        } catch (const Error& e) {
            channel.error = e.what();
        } catch (const std::invalid_argument& e) {
            channel.error = e.what();
        }
        out.channels.push_back(std::move(channel));
    }
    if (options.gap) add_gap(log, unit, options, out);
    return out;
}

}  // namespace driftlab::host::fleet
