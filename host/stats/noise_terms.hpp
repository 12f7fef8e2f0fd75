// IEEE Std 952-1997 (Annex C) noise terms from an Allan variance curve, and the continuous-time noise densities
// Kalibr's IMU model expects (docs/allan.md §6).
//
// Model, for a rate in data unit U and tau in s:
//   AVAR(tau) = 3 Q^2 / tau^2 + N^2 / tau + (2 ln 2 / pi) B^2 + K^2 tau / 3 + R^2 tau^2 / 2
//   Q quantisation [U s]  N random walk of the integral (ARW/VRW) [U / sqrt(Hz)]  B bias instability [U]
//   K rate random walk [U / sqrt(s)]  R rate ramp [U / s]
// B is the flicker floor divided by sqrt(2 ln 2 / pi) = 0.664: the flat ADEV minimum is 0.664 B.
// Fit: non-negative weighted least squares on AVAR, weights edf / (2 AVAR_model^2) (var of a chi-square
// variance estimate with `edf` degrees of freedom), iterated so the weights follow the model, not the noisy data.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace driftlab::host::stats {

/// Index of each term in NoiseTermFit arrays.
enum class NoiseTerm : std::uint8_t {
    quantisation = 0,
    random_walk = 1,
    bias_instability = 2,
    rate_random_walk = 3,
    ramp = 4
};
inline constexpr std::size_t kNoiseTermCount = 5;
/// Short names used in JSON: Q, N, B, K, R.
inline constexpr std::array<const char*, kNoiseTermCount> kNoiseTermSymbols = {"Q", "N", "B", "K", "R"};

/// sqrt(2 ln 2 / pi): ADEV of the bias-instability term is this times B.
inline constexpr double kBiasInstabilityFactor = 0.664282470267960;

struct NoiseTermOptions {
    std::array<bool, kNoiseTermCount> enabled = {true, true, true, true, true};
    int reweight_iterations = 3;
};

struct NoiseTermFit {
    /// Coefficients in data units: Q [U s], N [U s^0.5], B [U], K [U s^-0.5], R [U s^-1]; 0 when not present.
    std::array<double, kNoiseTermCount> value{};
    /// Standard error of each coefficient from the weighted fit (delta method); 0 for terms fitted to zero.
    std::array<double, kNoiseTermCount> std_error{};
    /// True for an enabled term the fit pinned at its bound 0: the data do not resolve it, which a value of 0
    /// with a standard error of 0 would misreport as a measured zero.
    std::array<bool, kNoiseTermCount> at_bound{};
    /// For a term at its bound: the largest value whose own ADEV stays at or below the measured curve at every tau
    /// (B: the curve's minimum / 0.664). An upper bound, since the curve also holds the other terms. Read it only
    /// where at_bound is set.
    std::array<double, kNoiseTermCount> upper_bound{};
    std::vector<double> model_adev;  ///< the fitted ADEV at each input tau [U]
    double chi_square = 0.0;         ///< weighted residual sum of squares at the final weights
    int points = 0;                  ///< taus used
    bool ok = false;                 ///< false when fewer usable points than one
};

/// Fits the enabled terms to AVAR = adev^2 at `tau_s` with per-point `edf`. Points with a non-finite or
/// non-positive value are ignored. Throws std::invalid_argument when the arrays differ in length.
NoiseTermFit fit_noise_terms(std::span<const double> tau_s, std::span<const double> adev, std::span<const double> edf,
                             const NoiseTermOptions& options = {});

/// AVAR of the model at tau for given coefficients.
double noise_term_avar(const std::array<double, kNoiseTermCount>& value, double tau_s);

/// What the rate physically is, to express the terms in the units navigation engineers use.
enum class RateQuantity : std::uint8_t { unknown, angular_rate, acceleration };

/// One reported number: key with its unit in the name (e.g. "N_deg_per_sqrt_h") and value.
struct NamedValue {
    std::string key;
    /// NaN when not resolved: a 0 read without `resolved` would pass for a measured zero noise density (and be
    /// pasted into a filter's configuration as one); JSON writes it as null.
    double value = 0.0;
    bool resolved = true;      ///< false: the term is at its bound (NoiseTermFit::at_bound)
    double upper_bound = 0.0;  ///< NoiseTermFit::upper_bound in this key's unit, when not resolved
};

/// The terms in physical units. `si_per_unit` converts one data unit to rad/s (angular rate) or m/s^2
/// (acceleration). Angular rate: Q deg, N deg/s/sqrt(Hz) and deg/sqrt(h), B deg/s and deg/h, K deg/s/sqrt(s)
/// and deg/h/sqrt(h), R deg/s^2 and deg/h^2. Acceleration: Q m/s, N m/s^2/sqrt(Hz) and m/s/sqrt(h), B m/s^2
/// and mg, K m/s^2/sqrt(s), R m/s^3. Empty for RateQuantity::unknown. Unresolved terms carry their bound and a NaN
/// value.
std::vector<NamedValue> physical_terms(const NoiseTermFit& fit, RateQuantity quantity, double si_per_unit);

/// Kalibr imu.yaml continuous-time densities: {gyroscope|accelerometer}_noise_density = N [rad/s/sqrt(Hz) |
/// m/s^2/sqrt(Hz)] and {gyroscope|accelerometer}_random_walk = K [rad/s^2/sqrt(Hz) | m/s^3/sqrt(Hz)].
/// These are continuous densities (the ADEV at tau = 1 s for N), not per-sample standard deviations.
std::vector<NamedValue> kalibr_densities(const NoiseTermFit& fit, RateQuantity quantity, double si_per_unit);

}  // namespace driftlab::host::stats
