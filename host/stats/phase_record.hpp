// PhaseRecord: the one internal form every Allan-family statistic works on (docs/allan.md §2).
//
// Input kind is explicit, never guessed: `from_rate` takes rate / fractional-frequency samples y_k (a gyro's
// deg/s or counts), `from_phase` takes phase / integrated samples x_k (angle, time error). Rate samples become
// phase by x_0 = 0, x_{k+1} = x_k + (y_k - mean(y)) tau0, summed in extended precision: subtracting the mean first
// keeps a large static offset (a 10-bit ADC at mid-scale) from eating the mantissa, and changes no deviation.
//
// Scale: the phase is stored divided by a power of two that brings its largest magnitude near 1, so that squared
// differences neither underflow (rates of 1e-170, or a tau0 of 1e-300) nor overflow (1e200); a power of two
// changes no bit of a difference, and compute_deviation multiplies the result back.
//
// Gaps: a NaN sample (or one masked by the caller) breaks the record. A rate sample y_k covers the phase
// interval [k, k+1]; a phase sample x_k covers the intervals on both sides of it. The record keeps the maximal
// runs of phase samples with no broken interval between them ("segments"); a statistic's term is used only when
// it lies inside one segment, so no term ever bridges a gap.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace driftlab::host::stats {

/// What the input samples are. Deviations are of the rate (fractional frequency) in both cases.
enum class InputKind : std::uint8_t {
    rate,   ///< rate / fractional-frequency samples, one per tau0 [data unit]
    phase,  ///< phase / integrated samples, one per tau0 [data unit * s]
};

/// A run of phase samples [begin, end) with no gap inside.
struct Segment {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t size() const { return end - begin; }
};

/// Phase samples on a uniform grid plus the gap-free segments they form.
class PhaseRecord {
public:
    /// Builds the record from rate samples. `mask` (optional, same length) marks samples to treat as gaps;
    /// NaN samples are gaps too. Throws std::invalid_argument when tau0_s <= 0 or a mask length differs.
    static PhaseRecord from_rate(std::span<const double> rate, double tau0_s, std::span<const std::uint8_t> mask = {});

    /// Builds the record from phase samples [data unit * s]; NaN or masked samples are gaps.
    static PhaseRecord from_phase(std::span<const double> phase, double tau0_s,
                                  std::span<const std::uint8_t> mask = {});

    /// Phase samples divided by 2^scale_exponent() [data unit * s]. Samples inside a gap hold a finite
    /// placeholder that no term reads.
    const std::vector<double>& scaled_phase() const { return phase_; }
    /// The phase is scaled_phase() * 2^scale_exponent().
    int scale_exponent() const { return scale_exponent_; }
    std::size_t size() const { return phase_.size(); }
    double tau0_s() const { return tau0_s_; }
    InputKind kind() const { return kind_; }
    /// Gap-free runs, in order. One segment spanning everything when there is no gap.
    const std::vector<Segment>& segments() const { return segments_; }
    bool has_gaps() const { return segments_.size() != 1 || segments_.front().size() != phase_.size(); }
    /// Input samples that were NaN or masked.
    std::size_t gap_samples() const { return gap_samples_; }
    /// Longest segment: the contiguous stretch noise identification works on.
    Segment longest_segment() const;

private:
    PhaseRecord() = default;
    // usable[k]: phase sample k exists; linked[k]: nothing breaks the interval between samples k and k+1.
    void build_segments(const std::vector<std::uint8_t>& usable, const std::vector<std::uint8_t>& linked);
    // Stores the n phase samples divided by the power of two that brings their largest magnitude near 1. `visit(each)`
    // calls each(k, x_k) for k = 0..n-1 in order, the same values every time: it runs twice (the scale, then the
    // samples) rather than hold n long doubles (160 MB for ten million samples).
    template <class Visit>
    void store_scaled(std::size_t n, const Visit& visit);

    std::vector<double> phase_;
    std::vector<Segment> segments_;
    int scale_exponent_ = 0;
    double tau0_s_ = 1.0;
    InputKind kind_ = InputKind::rate;
    std::size_t gap_samples_ = 0;
};

}  // namespace driftlab::host::stats
