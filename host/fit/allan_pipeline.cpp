// One series through grid placement, optional drift removal and the Allan statistics (docs/allan.md §7).
#include "host/fit/allan_pipeline.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "host/fit/lm_fit.hpp"
#include "host/stats/uniform_grid.hpp"

namespace driftlab::host::fit {
namespace {

AllanCurves analyse_curves(const stats::PhaseRecord& record, const AllanRequest& request) {
    AllanCurves out;
    std::vector<stats::Deviation> order = {stats::Deviation::oadev};
    for (stats::Deviation d : request.deviations) {
        if (d != stats::Deviation::oadev) order.push_back(d);
    }
    for (stats::Deviation d : order) {
        const auto ms = stats::analysis_factors(record, d, request.grid);
        // An empty table would read as a result; too short a record is bad input (the overlapping deviation's bound
        // is the loosest, so it decides).
        if (ms.empty() && d == stats::Deviation::oadev)
            throw std::invalid_argument(std::to_string(record.size()) +
                                        " phase samples leave no averaging time on this grid "
                                        "(the largest averaging factor is (phase samples - 1) / 4, rounded down; a "
                                        "rate series of n samples has n + 1 phase samples)");
        out.curves.push_back(stats::analyse_deviation(record, d, ms, request.confidence, request.threads));
        // Gaps can leave every factor without a term (no stretch between them holds 2m + 1 phase samples).
        if (d == stats::Deviation::oadev && out.curves.back().curve.tau_s.empty())
            throw std::invalid_argument(
                "no averaging time has a term between the gaps: the longest gap-free stretch "
                "holds " +
                std::to_string(record.longest_segment().size()) +
                " phase samples, the shortest averaging time needs 3 (is --tau0 the rows' spacing?)");
    }
    const stats::AnalysedCurve& oadev = out.curves.front();
    out.terms = stats::fit_noise_terms(oadev.curve.tau_s, oadev.curve.dev, oadev.edf);
    return out;
}

stats::PhaseRecord make_record(const std::vector<double>& v, double tau0_s, stats::InputKind kind) {
    return kind == stats::InputKind::rate ? stats::PhaseRecord::from_rate(v, tau0_s)
                                          : stats::PhaseRecord::from_phase(v, tau0_s);
}

}  // namespace

const stats::AnalysedCurve* AllanCurves::find(stats::Deviation d) const {
    for (const stats::AnalysedCurve& c : curves) {
        if (c.curve.type == d) return &c;
    }
    return nullptr;
}

std::string AllanResult::drift_status_name() const {
    return drift_fit_status ? fit_status_name(*drift_fit_status) : drift_not_fitted;
}

std::string AllanResult::drift_status_words() const {
    return drift_fit_status ? fit_status_words(*drift_fit_status) : drift_not_fitted;
}

void fit_turn_on_drift(const std::vector<double>& t_s, const std::vector<double>& values, const FitOptions& options,
                       AllanResult& out) {
    try {
        const FitResult r = fit_drift(t_s, values, options);
        out.drift_fit_status = r.status;
        // A singular fit (T far beyond the record: only the slope C1/T is seen) still gives the least-squares
        // curve, which is what is removed; only a fit that ran off is not.
        if (r.status != FitStatus::iteration_limit && std::isfinite(r.scaled_rss)) out.drift = r.parameters;
    } catch (const std::exception& e) {
        out.drift_not_fitted = e.what();
    }
}

std::optional<std::string> packing_caveat(const AllanResult& r, const stats::AnalysedCurve& curve) {
    const std::vector<double>& dev = curve.curve.dev;
    if (r.packed_samples == 0 || dev.empty()) return std::nullopt;
    const double moved_s = static_cast<double>(r.packed_most_slots) * r.tau0_s;
    const double minimum_tau_s =
        curve.curve.tau_s[static_cast<std::size_t>(std::min_element(dev.begin(), dev.end()) - dev.begin())];
    if (moved_s <= stats::kSpacingTolerance * minimum_tau_s) return std::nullopt;
    char text[400];
    std::snprintf(
        text, sizeof text,
        "%zu samples came faster than tau0 (bursts, or a record that changes its rate) and were placed up to "
        "%zu slots (%.4g s) after their time, %.0f %% of tau = %.4g s at the curve's minimum: from there on "
        "the curve reads correlated noise, which depends on when a sample was taken, and may be biased; a gap "
        "right after such a stretch is closed up",
        r.packed_samples, r.packed_most_slots, moved_s, 100.0 * moved_s / minimum_tau_s, minimum_tau_s);
    return std::string(text);
}

AllanResult analyse_allan(const std::vector<double>& t_s, const std::vector<double>& values, double tau0_s,
                          const AllanRequest& request) {
    AllanResult out;
    // The grid and each phase record live only while used (each is the series' size again: 80 MB for ten million
    // samples); the drift-removed curves grid the samples a second time.
    {
        const stats::PhaseRecord record = [&] {
            const stats::UniformSeries grid = stats::to_uniform_grid(t_s, values, tau0_s);
            out.samples = grid.values.size();
            out.gap_samples = grid.missing;
            out.packed_samples = grid.packed;
            out.packed_most_slots = grid.most_late;
            return make_record(grid.values, tau0_s, request.kind);
        }();
        out.tau0_s = tau0_s;
        out.raw = analyse_curves(record, request);
        out.longest_gap_free_s = static_cast<double>(record.longest_segment().size() - 1) * tau0_s;
    }

    if (!request.remove_drift) {
        out.drift_not_fitted = request.kept_drift_status;
        return out;
    }
    if (request.kind != stats::InputKind::rate) {
        out.drift_not_fitted = "not applicable to phase input";
        return out;
    }
    fit_turn_on_drift(t_s, values, request.drift_fit, out);
    if (!out.drift) return out;
    stats::UniformSeries grid = stats::to_uniform_grid(t_s, values, tau0_s);
    std::vector<double>& residual = grid.values;  // in place
    for (std::size_t i = 0; i < residual.size(); ++i) {
        // NaN gap slots stay NaN.
        residual[i] = residual[i] - drift_model(*out.drift, grid.t0_s + static_cast<double>(i) * tau0_s);
    }
    out.drift_removed = analyse_curves(make_record(residual, tau0_s, request.kind), request);
    return out;
}

}  // namespace driftlab::host::fit
