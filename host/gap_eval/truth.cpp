// The truth-generator table; see truth.hpp.
#include "host/gap_eval/truth.hpp"

#include <stdexcept>

namespace driftlab::host::gap {

const std::vector<TruthInfo>& truth_list() {
    using K = TruthInfo::Kind;
    static const std::vector<TruthInfo> list = {
        {"thermal_rc", "thermal_second_tc", K::shape},
        {"thermostat", "ambient_cycle", K::shape},
        {"kasdin_flicker", "flicker", K::process},
        {"wandering_ou", "gauss_markov", K::process},
        {"student_walk", "rate_random_walk", K::process},
        {"burst_spikes", "spikes", K::process},
        {"mode_hop", "", K::shape},
        {"sar_mismatch", "adc_dnl", K::converter},
        {"sar_codes", "adc_dnl", K::converter, 1},
        {"interference_bursts", "packet_loss", K::link},
        {"supply_wander", "supply_coupling", K::common},
    };
    return list;
}

const TruthInfo& truth_info(const std::string& generator) {
    for (const auto& t : truth_list())
        if (t.generator == generator) return t;
    throw std::invalid_argument("unknown truth generator: " + generator);
}

std::vector<double> make_truth(const std::string& generator, const std::vector<double>& t_s, double size_counts,
                               std::uint64_t seed, std::uint64_t noise_seed) {
    if (generator == "thermal_rc") return truth_thermal_rc(t_s, size_counts, seed);
    if (generator == "thermostat") return truth_thermostat(t_s, size_counts, seed);
    if (generator == "kasdin_flicker") return truth_kasdin_flicker(t_s, size_counts, noise_seed);
    if (generator == "wandering_ou") return truth_wandering_ou(t_s, size_counts, seed, noise_seed);
    if (generator == "student_walk") return truth_student_walk(t_s, size_counts, noise_seed);
    if (generator == "burst_spikes") return truth_burst_spikes(t_s, size_counts, noise_seed);
    if (generator == "mode_hop") return truth_mode_hop(t_s, size_counts, seed);
    if (generator == "supply_wander") return truth_supply_wander(t_s, size_counts, seed, noise_seed);
    throw std::invalid_argument("unknown signal truth generator: " + generator);
}

sim::Quantiser make_converter_truth(const std::string& generator, double size_counts,
                                    const std::vector<double>& occupancy, std::uint64_t seed,
                                    std::uint64_t noise_seed) {
    if (generator == "sar_mismatch" || generator == "sar_codes")
        return truth_sar_mismatch(size_counts, occupancy, seed, noise_seed);
    throw std::invalid_argument("unknown converter truth generator: " + generator);
}

std::vector<std::uint8_t> make_link_truth(const std::string& generator, std::size_t frames, double loss_percent,
                                          std::uint64_t seed, std::uint64_t noise_seed) {
    if (generator == "interference_bursts") return truth_interference_bursts(frames, loss_percent, seed, noise_seed);
    throw std::invalid_argument("unknown link truth generator: " + generator);
}

}  // namespace driftlab::host::gap
