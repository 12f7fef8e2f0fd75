// Planting a truth generator in a gyro log of a domain-randomised base; see planted_log.hpp.
#include "host/gap_eval/planted_log.hpp"

#include <algorithm>
#include <cmath>

#include "host/fit/lm_fit.hpp"
#include "host/gap/link_loss.hpp"
#include "host/gap_eval/truth.hpp"
#include "sim/model/board_outputs.hpp"
#include "sim/model/drift.hpp"
#include "sim/model/rng.hpp"
#include "sim/model/white_noise.hpp"

namespace driftlab::host::gap {
namespace {

constexpr double kMaxPeakPerSize = 300.0;   // a deterministic truth's peak, at most this many times its unabsorbed RMS
constexpr double kPaperAccelRawG = 0.0141;  // the paper's raw accelerometer noise per axis [g]
constexpr double kMismatchSpread = 0.1;     // a shared truth's loadings: each channel's DC level times 1 +- this

double output_noise_sd(const GapModel& m) {
    const double s = m.base[0].sigma_n_counts;
    return std::sqrt((s * s + 1.0 / 12.0) / m.smoothing.window);
}

// Root mean square of what the base's eq. 1 fit leaves of `signal` added to the noise-free warm-up of `model`.
double unabsorbed_rms(const GapModel& model, const std::vector<double>& t, const std::vector<double>& signal) {
    const sim::Drift drift(model.base[0].drift);
    std::vector<double> y(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) y[k] = drift.at_counts(t[k]) + signal[k];
    double sum = 0.0;
    for (double r : fit::fit_drift(t, y).residual) sum += r * r;
    return std::sqrt(sum / static_cast<double>(t.size()));
}

// Leaves out the rows `lost` marks, every column alike.
void drop_rows(LogData& log, const std::vector<std::uint8_t>& lost) {
    const auto keep = [&](auto& v) {
        std::size_t out = 0;
        for (std::size_t k = 0; k < v.size(); ++k)
            if (k >= lost.size() || !lost[k]) v[out++] = v[k];
        v.resize(out);
    };
    keep(log.t_s);
    keep(log.seq);
    for (auto& column : log.counts) keep(column);
    for (auto& [name, column] : log.optional_columns) keep(column);
}

// A shared generator's signal on each channel: the supply's relative deviation (sized so that the gyro sees
// `size_sd` of its output noise) times the channel's DC level, each off the DC level by a mismatch of its own.
std::array<std::vector<double>, kChannelCount> shared_signal(const std::string& generator, double size_sd, Planted& p,
                                                             std::uint64_t seed, std::size_t samples) {
    std::vector<double> t(samples);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k + 1) * kEvalSamplePeriodS;
    p.size_counts = size_sd * output_noise_sd(p.model);
    p.scale = p.size_counts / p.model.base[0].drift.c2_counts;  // the supply's relative standard deviation
    const std::vector<double> path = make_truth(generator, t, p.scale, seed, seed);
    sim::Rng mismatch(seed, 0x93);
    std::array<std::vector<double>, kChannelCount> added;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const double gain =
            p.model.base[c].drift.c2_counts * (1.0 + kMismatchSpread * (2.0 * mismatch.uniform() - 1.0));
        added[c] = path;
        for (double& x : added[c]) x *= gain;
    }
    return added;
}

bool lossy_link(const std::string& generator, CleanForm clean) {
    return generator == "none" ? clean == CleanForm::lossy_link : truth_info(generator).kind == TruthInfo::Kind::link;
}

}  // namespace

bool four_channel_log(const std::string& generator, CleanForm clean) {
    return generator == "none" ? clean == CleanForm::four_channels
                               : truth_info(generator).kind == TruthInfo::Kind::common;
}

sim::SimModel eval_unit(const std::string& generator, CleanForm clean) {
    sim::SimModel unit = sim::paper_model();
    if (lossy_link(generator, clean))
        unit.link.to_host.byte_error_rate =
            1.0 - std::pow(1.0 - kEvalFrameCorruption, 1.0 / static_cast<double>(sample_frame_bytes()));
    return unit;
}

GapModel randomised_truth(std::uint64_t seed, int window, bool four_channels) {
    sim::Rng rng(seed, 0x60);
    auto factor = [&] { return std::exp(std::log(0.5) + rng.uniform() * std::log(4.0)); };  // x[0.5, 2]
    GapModel m;
    m.unit = sim::paper_model();
    m.unit.effects.clear();
    m.smoothing = {kEvalSamplePeriodS, window, window, 0};
    const sim::DriftParams paper = sim::kPaperDrift[0];
    m.base[0].drift = {paper.c1_counts * factor(), paper.c2_counts, paper.tau_s * factor()};
    const double raw_counts = 0.187 * 512.0 / 90.0 * std::sqrt(factor());
    m.base[0].sigma_n_counts =
        sim::analog_sigma_for_raw_std_counts(std::max(raw_counts, sim::kMinCalibratedRawStdCounts));
    if (!four_channels) return m;
    // The accelerometer axes from a stream of their own: the gyro's draws, and so its log, stay those above.
    sim::Rng axes(seed, 0x61);
    auto axis_factor = [&] { return std::exp(std::log(0.5) + axes.uniform() * std::log(4.0)); };
    for (std::size_t c = 1; c < kChannelCount; ++c) {
        const sim::DriftParams table = sim::kPaperDrift[c];
        m.base[c].drift = {table.c1_counts * axis_factor(), table.c2_counts, table.tau_s * axis_factor()};
        const double axis_raw =
            kPaperAccelRawG * counts_per_unit(m, static_cast<Channel>(c)) * std::sqrt(axis_factor());
        m.base[c].sigma_n_counts =
            sim::analog_sigma_for_raw_std_counts(std::max(axis_raw, sim::kMinCalibratedRawStdCounts));
    }
    return m;
}

bool raw_mode(const std::string& generator) {
    return generator != "none" && truth_info(generator).kind == TruthInfo::Kind::converter &&
           truth_info(generator).window > 1;
}

int log_window(const std::string& generator) {
    return generator == "none" ? kEvalWindow : truth_info(generator).window;
}

LogData make_log(const GapModel& truth, const std::array<std::vector<double>, kChannelCount>& added,
                 const sim::Quantiser& quantiser, std::size_t samples, std::uint64_t seed, bool raw_mode,
                 const std::vector<std::uint8_t>& lost, bool four_channels) {
    LogData log;
    log.source_name = "gap-eval";
    log.t_s.resize(samples);
    for (std::size_t k = 0; k < samples; ++k) log.t_s[k] = static_cast<double>(k + 1) * kEvalSamplePeriodS;
    sim::OutputRequest req;
    req.t_s = &log.t_s;
    req.channels = {true, four_channels, four_channels, four_channels};
    req.added_counts = added;
    req.quantiser[0] = quantiser;
    sim::Outputs raw;
    if (raw_mode) req.raw_codes = &raw;
    const sim::Outputs sim = sim::simulate_outputs(truth, req, seed ^ 0xA5A5A5A5ull);
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (req.channels[c])
            log.counts[c] = sim[c];
        else
            log.counts[c].assign(samples, 512.0);
    }
    log.recorded = req.channels;
    if (raw_mode) log.optional_columns["raw_gyro"] = raw[0];
    log.seq.resize(samples);
    for (std::size_t k = 0; k < samples; ++k) log.seq[k] = raw_mode ? 2 * k : k;
    if (!lost.empty()) drop_rows(log, lost);
    log.metadata.set("sample_period_s", kEvalSamplePeriodS);
    log.metadata.set("conversions_per_output", static_cast<std::int64_t>(truth.smoothing.conversions_per_output));
    log.metadata.set("window", static_cast<std::int64_t>(truth.smoothing.window));
    log.metadata.set("fit_order", static_cast<std::int64_t>(0));
    return log;
}

InputSignal input_signal(const std::string& generator, double size_sd, const GapModel& model, std::uint64_t seed,
                         std::size_t samples) {
    InputSignal s;
    s.size_counts = size_sd * output_noise_sd(model);
    std::vector<double> t(samples);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k + 1) * kEvalSamplePeriodS;
    const std::vector<double> unit = make_truth(generator, t, 1.0, seed, seed);
    s.scale = s.size_counts;
    if (truth_info(generator).kind == TruthInfo::Kind::shape) {
        // eq. 1 is nonlinear in T, so the absorbed share depends a little on the size: one correction.
        auto scaled = [&](double g) {
            std::vector<double> v(unit);
            for (double& x : v) x *= g;
            return v;
        };
        // A shape eq. 1 absorbs almost wholly stays almost invisible: its peak is capped at kMaxPeakPerSize sizes.
        const double cap = kMaxPeakPerSize * s.size_counts;
        s.scale = std::min(cap, s.size_counts / std::max(unabsorbed_rms(model, t, unit), 1e-12));
        s.scale = std::min(cap, s.scale * s.size_counts / std::max(unabsorbed_rms(model, t, scaled(s.scale)), 1e-12));
    }
    s.added = unit;
    for (double& x : s.added) x *= s.scale;
    return s;
}

Planted plant(const std::string& generator, double size_sd, std::uint64_t seed, std::size_t samples, CleanForm clean) {
    const bool none = generator == "none";
    const bool four = four_channel_log(generator, clean);
    Planted p;
    p.model = randomised_truth(seed, none && clean == CleanForm::codes ? 1 : log_window(generator), four);
    std::array<std::vector<double>, kChannelCount> added;
    std::vector<std::uint8_t> lost;
    sim::Quantiser quantiser;
    if (generator != "none" && truth_info(generator).kind == TruthInfo::Kind::converter) {
        // Sized by the code widths the log can see: those of the codes it occupies (the same noise path through the
        // model's converter), as a deterministic shape by the part eq. 1 cannot absorb.
        p.size_counts = p.scale = size_sd * output_noise_sd(p.model);
        p.occupancy.assign(std::size_t{1} << p.model.unit.adc.bits, 0.0);
        // Held by name: a range-for over a member of the returned log would read it after its end (before C++23).
        const LogData clean_log = make_log(p.model, {}, {}, samples, seed, true);
        for (double code : clean_log.optional_columns.at("raw_gyro"))
            p.occupancy[static_cast<std::size_t>(code)] += 1.0;
        quantiser = make_converter_truth(generator, p.scale, p.occupancy, seed, seed);
    } else if (!none && truth_info(generator).kind == TruthInfo::Kind::link) {
        p.size_counts = p.scale = size_sd;  // per cent of the frames, lost in the long run
        lost = make_link_truth(generator, samples, size_sd, seed, seed);
    } else if (!none && truth_info(generator).kind == TruthInfo::Kind::common) {
        added = shared_signal(generator, size_sd, p, seed, samples);
    } else if (!none) {
        InputSignal in = input_signal(generator, size_sd, p.model, seed, samples);
        p.size_counts = in.size_counts;
        p.scale = in.scale;
        added[0] = std::move(in.added);
    }
    if (lossy_link(generator, clean)) {
        // The calibrated link's own losses under the generator's: each frame corrupted alone.
        lost.resize(samples, 0);
        sim::Rng corrupt(seed, 0x7A);
        for (auto& l : lost)
            if (corrupt.uniform() < kEvalFrameCorruption) l = 1;
    }
    p.log = make_log(p.model, added, quantiser, samples, seed,
                     raw_mode(generator) || (none && clean == CleanForm::raw_mode), lost, four);
    return p;
}

}  // namespace driftlab::host::gap
