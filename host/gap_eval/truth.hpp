// Truth generators of the withheld-effect benchmark (gap-eval). Each makes a signal in counts, added at the
// converter input of a simulated log, whose FORM differs from what the diagnosis fits (no inverse crime):
//   thermal_rc      -> thermal_second_tc (fits one more exponential): a three-node die/package/board RC network
//   thermostat      -> ambient_cycle (fits a sine): a bang-bang thermostat with hysteresis through a thermal lag
//   kasdin_flicker  -> flicker (fits a sum of Gauss-Markov processes): FFT-shaped 1/f noise (Kasdin 1995)
//   wandering_ou    -> gauss_markov (fits one exact GM): Euler-Maruyama OU whose correlation time wanders
//   student_walk    -> rate_random_walk (fits a Gaussian walk): a walk with Student-t (nu = 4) steps
//   burst_spikes    -> spikes (fits single-conversion Gaussian spikes): bursts of 1-3 whole output periods,
//                      Laplace amplitudes
//   mode_hop        -> out of the library: a bias step and a later partial return (mode hop)
//   sar_mismatch    -> adc_dnl (fits one transition per code, a deterministic table): a successive-approximation
//                      converter whose binary-weighted DAC has unit-capacitor mismatch, with a noisy comparator;
//                      it replaces the quantiser and its logs are raw-mode
//   sar_codes       -> adc_dnl: the same converter behind outputs of one conversion each (window 1) and no raw
//                      column, so the outputs are the codes
//   interference_bursts -> packet_loss (fits a Gilbert chain: geometric bursts, every frame of one lost): episodes
//                      of log-normal length within which frames are lost with probability 0.7-1; it takes rows out
//                      of the log
//   supply_wander   -> supply_coupling (fits one Gauss-Markov wander whose loadings follow the DC levels): a
//                      regulator's reference wander through a lag (second order), reaching every channel through
//                      its DC level times a mismatch of +-10 % of its own; its logs record all four channels
// `size_counts` sets the scale [counts = LSB], and every signal generator is linear in it: the level the RC network's
// rise approaches (thermal_rc: the log holds 80-99 % of it), the thermostat's extremes, the standard deviation of
// the random signals (kasdin_flicker, wandering_ou; student_walk's end point), the standard deviation of one burst's
// Laplace amplitude (burst_spikes: the signal's own is sqrt(2/150) of it, bursts being rare), the step (mode hop),
// or the rms of the converter's DAC step errors over the codes a log occupies (sar_mismatch: its rms DNL while no
// code goes missing). Tests: tests/host/gap_eval/truth_*_test.cpp.
// gap-eval sizes a deterministic generator by the part of it the base's eq. 1 fit cannot absorb (evaluate.cpp).
// docs/gap.md §Evaluation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/model/sensor_model.hpp"

namespace driftlab::host::gap {

/// A truth generator: the generator name, the library effect it stands for ("" = out of library).
struct TruthInfo {
    enum class Kind {
        shape,      ///< a deterministic signal added at the converter input (sized by what eq. 1 cannot absorb)
        process,    ///< a random signal added there (sized by a standard deviation; see size_counts above)
        converter,  ///< a quantiser replacing the converter (sized by its DAC's rms step error); its logs are raw-mode
        link,       ///< frames lost on the way (sized by the share of frames lost, in per cent): rows out of the log
        common,  ///< a random signal every channel sees through its DC level (sized as the gyro's standard deviation)
    };
    std::string generator;
    std::string effect;
    Kind kind = Kind::shape;
    int window = 8;  ///< the smoothing of its log [conversions]; 1: every output is one code
};

/// Every generator, in the order gap-eval lists them.
const std::vector<TruthInfo>& truth_list();

/// The entry of truth_list() for `generator`. Throws std::invalid_argument on a bad name.
const TruthInfo& truth_info(const std::string& generator);

/// The signal of `generator` at the output instants `t_s` [counts]. `seed` draws the generator's shape (time
/// constants, period, step instants); `noise_seed` draws the random path of the random generators, so that
/// fresh realisations of one truth share its shape (gap-eval's oracle). Throws std::invalid_argument on a bad name.
std::vector<double> make_truth(const std::string& generator, const std::vector<double>& t_s, double size_counts,
                               std::uint64_t seed, std::uint64_t noise_seed);

/// The quantiser of a converter generator (Kind::converter): `size_counts` is its rms DNL [LSB] over the codes as
/// `occupancy` weights them (index = code; empty: the inner codes 1..1022 alike); `seed` draws the device (its
/// mismatch), `noise_seed` the comparator's noise. Throws std::invalid_argument on a bad name.
sim::Quantiser make_converter_truth(const std::string& generator, double size_counts,
                                    const std::vector<double>& occupancy, std::uint64_t seed, std::uint64_t noise_seed);

/// The frames a link generator (Kind::link) loses out of `frames`: 1 per lost frame. `loss_percent` is the long-run
/// share lost [%]; `seed` draws the device (its episodes' typical length and loss within), `noise_seed` the path.
/// Throws std::invalid_argument on a bad name.
std::vector<std::uint8_t> make_link_truth(const std::string& generator, std::size_t frames, double loss_percent,
                                          std::uint64_t seed, std::uint64_t noise_seed);

/// The per-sample signal generators, one file each (truth_*.cpp).
std::vector<double> truth_thermal_rc(const std::vector<double>& t_s, double size_counts, std::uint64_t seed);
std::vector<double> truth_thermostat(const std::vector<double>& t_s, double size_counts, std::uint64_t seed);
std::vector<double> truth_kasdin_flicker(const std::vector<double>& t_s, double size_counts, std::uint64_t noise_seed);
std::vector<double> truth_wandering_ou(const std::vector<double>& t_s, double size_counts, std::uint64_t seed,
                                       std::uint64_t noise_seed);
std::vector<double> truth_student_walk(const std::vector<double>& t_s, double size_counts, std::uint64_t noise_seed);
std::vector<double> truth_burst_spikes(const std::vector<double>& t_s, double size_counts, std::uint64_t noise_seed);
std::vector<double> truth_mode_hop(const std::vector<double>& t_s, double size_counts, std::uint64_t seed);
/// The supply's relative deviation path (standard deviation `size`).
std::vector<double> truth_supply_wander(const std::vector<double>& t_s, double size, std::uint64_t seed,
                                        std::uint64_t noise_seed);
std::vector<std::uint8_t> truth_interference_bursts(std::size_t frames, double loss_percent, std::uint64_t seed,
                                                    std::uint64_t noise_seed);
sim::Quantiser truth_sar_mismatch(double size_counts, const std::vector<double>& occupancy, std::uint64_t seed,
                                  std::uint64_t noise_seed);

}  // namespace driftlab::host::gap
