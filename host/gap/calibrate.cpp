// Base-model calibration; see calibrate.hpp.
#include "host/gap/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "host/fit/lm_fit.hpp"
#include "host/fit/start_values.hpp"
#include "host/gap/replicates.hpp"
#include "host/stats/median.hpp"
#include "host/stats/uniform_grid.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {

namespace {

constexpr int kCalibrationReplicates = 3;
constexpr int kMaxSteps = 14;                // regula falsi steps after the two bracket ends
constexpr double kRelativeTolerance = 1e-4;  // of the target spread

int metadata_int(const LogData& log, const std::string& key, int fallback, int lo, int hi) {
    if (!log.metadata.has(key)) return fallback;
    const auto v = log.metadata.get_int(key);
    if (!v || *v < lo || *v > hi)
        throw DataError(
            log.source_name, log.metadata.line_of(key),
            "metadata '" + key + "' must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(*v);
}

// Sum of the squared smoother weights (gap-method §1): order 0 -> 1/N; order 1 at the newest sample ->
// 2(2N-1)/(N(N+1)).
double kernel_power(const Smoothing& s) {
    const double n = s.window;
    return s.fit_order == 0 ? 1.0 / n : 2.0 * (2.0 * n - 1.0) / (n * (n + 1.0));
}

// The rows' times with lost frames taken out, so that a link that lost most frames keeps its period: a row k usual
// seq steps (LogData::frames_per_row) after the one before counts its spacing divided by k.
std::vector<double> times_without_lost_frames(const LogData& log) {
    if (log.seq.size() != log.t_s.size()) return log.t_s;
    const auto usual = static_cast<double>(log.frames_per_row());
    std::vector<double> t = {log.t_s.front()};
    for (std::size_t k = 1; k < log.t_s.size(); ++k) {
        const double steps = log.seq[k] > log.seq[k - 1] ? static_cast<double>(log.seq[k] - log.seq[k - 1]) : usual;
        t.push_back(t.back() + (log.t_s[k] - log.t_s[k - 1]) / std::max(steps / usual, 1.0));
    }
    return t;
}

}  // namespace

Smoothing smoothing_from_log(const LogData& log) {
    Smoothing s;
    if (log.t_s.size() < 2) throw DataError(log.source_name, 0, "needs at least two samples");
    s.sample_period_s = stats::median_spacing_s(log.t_s);
    if (log.metadata.has("sample_period_s")) {
        const auto v = log.metadata.get_double("sample_period_s");
        const std::uint64_t line = log.metadata.line_of("sample_period_s");
        if (!v || !(*v > 0.0))
            throw DataError(log.source_name, line, "metadata 'sample_period_s' must be a positive number [s]");
        // A wrong period misplaces every lag and band; bursts leave the mean alone, and lost frames are taken out.
        const std::vector<double> t = times_without_lost_frames(log);
        s.sample_period_s = *v;
        if (!stats::period_agrees(t, *v)) {
            // Polled rows come at the poll cadence on the board's clock: slower than the outputs when the board runs
            // faster than the recorder's clock (hil --pty --speed 10), each row still one output's window. Never
            // faster: a poll between two outputs repeats a row, which the recorder does not write.
            const double rows_s = stats::grid_period_s(t);
            const bool polled = log.metadata.get("mode") == "poll";
            if (!polled || !(rows_s > *v))
                throw DataError(log.source_name, line,
                                "metadata 'sample_period_s' is " + format_double(*v) + " s, but the rows are " +
                                    stats::spacing_text(t) + ", lost frames taken out" +
                                    (polled ? " (polled rows cannot come faster than the outputs)" : ""));
            s.sample_period_s = rows_s;
            s.outputs_per_row = rows_s / *v;
        }
    }
    s.conversions_per_output = metadata_int(log, "conversions_per_output", 1, 1, 64);
    s.window = metadata_int(log, "window", 1, 1, 64);
    s.fit_order = metadata_int(log, "fit_order", 0, 0, 1);
    return s;
}

std::array<bool, kChannelCount> varying_channels(const LogData& log) {
    std::array<bool, kChannelCount> out{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const auto& v = log.counts[c];
        out[c] = !v.empty() && std::any_of(v.begin(), v.end(), [&](double x) { return x != v.front(); });
    }
    return out;
}

double short_lag_spread(const std::vector<double>& residual) {
    if (residual.size() < 3) return 0.0;
    std::vector<double> d(residual.size() - 1);
    for (std::size_t i = 0; i + 1 < residual.size(); ++i) d[i] = residual[i + 1] - residual[i];
    const double med = stats::median(d);
    std::vector<double> dev(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) dev[i] = std::abs(d[i] - med);
    // +0.5 count keeps quantised differences (many exact zeros) from being clipped away.
    const double limit = 6.0 * 1.4826 * stats::median(dev) + 0.5;
    double sum = 0.0;
    std::size_t n = 0;
    for (double x : d) {
        if (std::abs(x - med) > limit) continue;
        sum += x * x;
        ++n;
    }
    return n ? std::sqrt(sum / static_cast<double>(n) / 2.0) : 0.0;
}

void match_noise(GapModel& model, const std::vector<double>& t_s, const std::array<bool, kChannelCount>& channels,
                 const std::array<double, kChannelCount>& target_spread, std::uint64_t seed) {
    const double h2 = kernel_power(model.smoothing);
    std::array<double, kChannelCount> lo{}, hi{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        // Start from the additive-quantiser reading sigma_obs^2 = (sigma_n^2 + 1/12) sum h^2, then bracket it.
        const double guess = std::sqrt(std::max(0.0, target_spread[c] * target_spread[c] / h2 - 1.0 / 12.0));
        lo[c] = 0.0;
        hi[c] = 3.0 * guess + 1.0;
    }
    auto simulated_spread = [&](const GapModel& m) {
        std::array<double, kChannelCount> out{};
        for (int r = 0; r < kCalibrationReplicates; ++r) {
            sim::OutputRequest req;
            req.t_s = &t_s;
            req.channels = channels;
            const sim::Outputs sim = sim::simulate_outputs(m, req, seed + 7919u * static_cast<std::uint64_t>(r));
            for (std::size_t c = 0; c < kChannelCount; ++c) {
                if (!channels[c]) continue;
                // The spread is taken on the same eq. 1 residual the real log gave.
                out[c] +=
                    short_lag_spread(fit::fit_drift(t_s, sim[c], start_at_model(m, static_cast<Channel>(c))).residual) /
                    kCalibrationReplicates;
            }
        }
        return out;
    };
    // Regula falsi with the Illinois modification on f(sigma) = simulated spread - target, per channel and in step
    // (one simulation serves every channel). Common random numbers keep f smooth in sigma; it converges in a few
    // simulations where bisection took sixteen.
    std::array<double, kChannelCount> f_lo{}, f_hi{};
    auto evaluate = [&](const std::array<double, kChannelCount>& sigma) {
        GapModel trial = model;
        for (std::size_t c = 0; c < kChannelCount; ++c) trial.base[c].sigma_n_counts = sigma[c];
        const auto spread = simulated_spread(trial);
        std::array<double, kChannelCount> f{};
        for (std::size_t c = 0; c < kChannelCount; ++c) f[c] = spread[c] - target_spread[c];
        return f;
    };
    f_lo = evaluate(lo);
    f_hi = evaluate(hi);
    std::array<double, kChannelCount> sigma = lo;
    std::array<bool, kChannelCount> done{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        done[c] = !channels[c] || f_lo[c] >= 0.0 || f_hi[c] <= 0.0;  // quantisation alone already spreads enough
        sigma[c] = f_lo[c] >= 0.0 ? lo[c] : hi[c];
    }
    for (int step = 0; step < kMaxSteps && !std::all_of(done.begin(), done.end(), [](bool d) { return d; }); ++step) {
        for (std::size_t c = 0; c < kChannelCount; ++c)
            if (!done[c]) sigma[c] = (lo[c] * f_hi[c] - hi[c] * f_lo[c]) / (f_hi[c] - f_lo[c]);
        const auto f = evaluate(sigma);
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            if (done[c]) continue;
            if (f[c] * f_hi[c] < 0.0) {
                lo[c] = hi[c], f_lo[c] = f_hi[c];
            } else {
                f_lo[c] *= 0.5;
            }
            hi[c] = sigma[c], f_hi[c] = f[c];
            done[c] = std::abs(f[c]) <= kRelativeTolerance * target_spread[c];
        }
    }
    for (std::size_t c = 0; c < kChannelCount; ++c)
        if (channels[c]) model.base[c].sigma_n_counts = std::max(0.0, sigma[c]);
}

std::array<bool, kChannelCount> deterministic_channels(const GapModel& model, const std::vector<double>& t_s,
                                                       const std::array<bool, kChannelCount>& channels,
                                                       std::uint64_t seed) {
    std::array<bool, kChannelCount> out{};
    sim::OutputRequest req;
    req.t_s = &t_s;
    // Noise of half a code or more moves some conversion of any log: only weaker noise needs the two simulations
    // (not the paper's gyro, calibrated near one code on its logs).
    for (std::size_t c = 0; c < kChannelCount; ++c) req.channels[c] = channels[c] && model.base[c].sigma_n_counts < 0.5;
    if (std::none_of(req.channels.begin(), req.channels.end(), [](bool b) { return b; })) return out;
    const sim::Outputs a = sim::simulate_outputs(model, req, seed), b = sim::simulate_outputs(model, req, seed + 1);
    for (std::size_t c = 0; c < kChannelCount; ++c) out[c] = req.channels[c] && a[c] == b[c];
    return out;
}

GapModel calibrate_base(const LogData& log, const sim::SimModel& unit, const std::array<bool, kChannelCount>& channels,
                        std::uint64_t seed, std::array<double, kChannelCount>* spread) {
    GapModel model;
    model.unit = unit;
    model.unit.effects.clear();
    model.smoothing = smoothing_from_log(log);
    std::array<double, kChannelCount> target{};
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!channels[c]) continue;
        const fit::FitResult f = fit::fit_drift(log.t_s, log.counts[c]);
        // A fit that ran off (no warm-up in the log: a flat or straight record) still yields a usable eq. 1: keep T
        // positive and finite, and where it had to be moved fit C1 and C2 again at the new T, so that the model
        // keeps the log's level and slope (C1 alone is the slope times T: kept with a shortened T, it was a ramp).
        const double span_s = log.t_s.back() - log.t_s.front();
        const double tau_s =
            std::isfinite(f.parameters.t_s) ? std::clamp(f.parameters.t_s, 1e-3 * span_s, 1e3 * span_s) : span_s;
        const fit::DriftParameters d =
            tau_s == f.parameters.t_s ? f.parameters : fit::amplitudes_at(log.t_s, log.counts[c], tau_s);
        model.base[c].drift = {d.c1, d.c2, tau_s};
        target[c] = short_lag_spread(f.residual);
    }
    match_noise(model, log.t_s, channels, target, seed);
    if (spread) *spread = target;
    return model;
}

}  // namespace driftlab::host::gap
