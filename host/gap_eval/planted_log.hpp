// The benchmark's logs: a gyro log of a domain-randomised base (eq. 1 and noise drawn about the paper's unit) with
// one truth generator (truth.hpp) planted at a chosen size, as gap-eval makes them. docs/gap.md §Evaluation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"
#include "host/log/log_data.hpp"
#include "sim/model/sensor_model.hpp"

namespace driftlab::host::gap {

/// The benchmark's output period: 1 s per sample.
inline constexpr double kEvalSamplePeriodS = 1.0;

/// The benchmark's smoothing: a mean of 8 conversions per output.
inline constexpr int kEvalWindow = 8;

/// The base of log `seed`: the paper's gyro with C1 and T each scaled by a factor in [0.5, 2], its raw noise by the
/// square root of one, smoothed by a mean of `window` conversions per output; with `four_channels`, the
/// accelerometer axes too, drawn alike (the gyro's draws unchanged).
GapModel randomised_truth(std::uint64_t seed, int window = kEvalWindow, bool four_channels = false);

/// Whether `generator` replaces the converter and its log is raw-mode (sized by its rms DNL). A converter generator
/// whose log's outputs are the codes (window 1) is not: its log has no raw column.
bool raw_mode(const std::string& generator);

/// The smoothing window of `generator`'s log (TruthInfo::window; kEvalWindow for "none").
int log_window(const std::string& generator);

/// A gyro log of `truth` (smoothed as truth.smoothing says; all four channels with `four_channels`) with `added` at
/// each channel's converter input and, when given, `quantiser` as the gyro's converter. A `raw`
/// log is raw-mode, as `driftlab record` writes one: a raw_gyro column of the newest conversion's code, and sequence
/// numbers stepping by two (a SAMPLE and a RAW frame per row).
/// Rows whose frame `lost` marks (1) are left out, their sequence numbers with them.
LogData make_log(const GapModel& truth, const std::array<std::vector<double>, kChannelCount>& added,
                 const sim::Quantiser& quantiser, std::size_t samples, std::uint64_t seed, bool raw_mode,
                 const std::vector<std::uint8_t>& lost = {}, bool four_channels = false);

/// A generator acting at the converter input, sized: the signal added, its planted size and make_truth()'s scale.
struct InputSignal {
    std::vector<double> added;
    double size_counts = 0.0;  ///< the planted size [counts]
    double scale = 0.0;        ///< make_truth()'s size argument that plants it
};

/// `generator`, acting at the converter input, at `size_sd` output-noise deviations on `model`. A random
/// generator's size is its standard deviation; a deterministic one's is the RMS of the part the base's eq. 1 fit
/// cannot absorb, since only that part can be detected (a slow RC-network rise is 98-99 % absorbed, by a share that
/// varies threefold with its time constants; sizing by the peak made the detection curve non-monotone).
InputSignal input_signal(const std::string& generator, double size_sd, const GapModel& model, std::uint64_t seed,
                         std::size_t samples);

/// A log with its true model and what was planted in it.
struct Planted {
    GapModel model;
    LogData log;
    double size_counts = 0.0;       ///< the planted size [counts; a link generator's: per cent of frames lost]
    double scale = 0.0;             ///< make_truth()'s size argument that plants it
    std::vector<double> occupancy;  ///< a converter truth's: the codes of the log made with the model's converter
};

/// How a clean log is written: smoothed outputs, raw-mode (a raw column of codes beside them), outputs of one
/// conversion each (window 1: the outputs are the codes), behind the calibrated lossy link (kEvalFrameCorruption),
/// or with all four channels.
enum class CleanForm { smoothed, raw_mode, codes, lossy_link, four_channels };

/// Whether the log of `generator` (or a clean log in the form `clean`) records all four channels: a shared
/// generator's, and clean logs in the form four_channels.
bool four_channel_log(const std::string& generator, CleanForm clean = CleanForm::smoothed);

/// The calibrated link of link generators' logs and of lossy-link clean logs: each frame corrupted alone with this
/// probability (byte errors), beside which a generator's losses must stand out.
inline constexpr double kEvalFrameCorruption = 0.005;

/// The unit a log of `generator` (or a clean log in the form `clean`) is diagnosed against: the paper's, with the
/// calibrated link's byte errors towards the host for a link generator or a lossy-link clean log.
sim::SimModel eval_unit(const std::string& generator, CleanForm clean = CleanForm::smoothed);

/// A log of a domain-randomised base with `generator` planted at `size_sd` output-noise deviations (a converter
/// generator's size is its rms DNL); "none" plants nothing, in the form `clean`.
Planted plant(const std::string& generator, double size_sd, std::uint64_t seed, std::size_t samples,
              CleanForm clean = CleanForm::smoothed);

}  // namespace driftlab::host::gap
