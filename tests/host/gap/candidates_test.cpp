// The diagnosis accounts for the whole effect library: each effect is a candidate it fits, or is named as one a
// static log cannot identify, with the reason; and a candidate's parameters build the library's effect.
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "host/gap/candidates.hpp"
#include "sim/effects/effect.hpp"
#include "sim/effects/flicker.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {
namespace {

TEST(Candidates, EveryLibraryEffectIsACandidateOrNamedNotIdentifiableNeverBoth) {
    std::set<std::string> library, candidates, unidentifiable;
    for (const sim::EffectInfo& e : sim::list_effects()) library.insert(e.name);
    for (const CandidateInfo& c : candidate_list())
        EXPECT_TRUE(candidates.insert(c.effect).second) << c.effect << " twice";
    for (const NotIdentifiable& n : not_identifiable_list()) {
        EXPECT_TRUE(unidentifiable.insert(n.effect).second) << n.effect << " twice";
        EXPECT_FALSE(n.reason.empty()) << n.effect;
    }
    for (const std::string& name : library)
        EXPECT_NE(candidates.count(name), unidentifiable.count(name))
            << name << ": a candidate, or not identifiable, exactly one";
    for (const std::string& name : candidates) EXPECT_TRUE(library.count(name)) << name << " is no library effect";
    for (const std::string& name : unidentifiable) EXPECT_TRUE(library.count(name)) << name << " is no library effect";
}

// Each candidate with fixed parameter keys, at plausible values on the gyro and on accel_y, builds its library effect
// (the registry validates every key), and the keys it reports are the channel's.
TEST(Candidates, ACandidatesParametersBuildItsLibraryEffectOnEitherKindOfChannel) {
    GapModel m;
    m.unit = sim::paper_model();
    for (const CandidateInfo& c : candidate_list()) {
        if (c.param_keys.empty()) continue;  // adc_dnl: one transition per code the log crosses
        const std::vector<double> p = c.effect == "ambient_cycle" ? std::vector<double>{0.01, 600.0, 0.3}
                                                                  : std::vector<double>(c.param_keys.size(), 0.5);
        for (const Channel ch : {Channel::gyro, Channel::accel_y}) {
            const sim::EffectSpec spec = make_candidate_effect(c.effect, ch, p, m);
            EXPECT_NO_THROW(sim::make_effect(spec.name, spec.table, "effects." + spec.name)) << c.effect;
            const auto names = candidate_param_names(c.effect, ch);
            ASSERT_EQ(names.size(), c.param_keys.size()) << c.effect;
            for (const std::string& n : names) EXPECT_EQ(n.find("_unit"), std::string::npos) << c.effect << ": " << n;
        }
    }
}

// A model file's effect (gap --model) is read per channel where the diagnosis takes it on: its size (a cycle's is the
// coupling times the swing), zeroed on one channel with the others kept; an effect no shape or process fits has none.
TEST(Candidates, AModelFilesSizeIsReadPerChannelAndZeroedOnOne) {
    sim::EffectSpec cycle{"ambient_cycle", {}};
    cycle.table.insert_or_assign("amplitude_k_pp", 2.0);
    cycle.table.insert_or_assign("coupling_dps_per_k", 0.05);
    cycle.table.insert_or_assign("coupling_g_per_k", toml::array{0.001, 0.0, 0.002});
    EXPECT_DOUBLE_EQ(candidate_size_in(cycle, Channel::gyro), 0.1);
    EXPECT_DOUBLE_EQ(candidate_size_in(cycle, Channel::accel_x), 0.002);
    EXPECT_DOUBLE_EQ(candidate_size_in(cycle, Channel::accel_y), 0.0);
    EXPECT_DOUBLE_EQ(candidate_size_in(cycle, Channel::accel_z), 0.004);
    const sim::EffectSpec rest = without_channel(cycle, Channel::accel_x);
    EXPECT_DOUBLE_EQ(candidate_size_in(rest, Channel::gyro), 0.1);
    EXPECT_DOUBLE_EQ(candidate_size_in(rest, Channel::accel_x), 0.0);
    EXPECT_DOUBLE_EQ(candidate_size_in(rest, Channel::accel_z), 0.004);
    EXPECT_NO_THROW(sim::make_effect(rest.name, rest.table, "effects.ambient_cycle"));

    sim::EffectSpec gm{"gauss_markov", {}};
    gm.table.insert_or_assign("sigma_g", 0.003);  // a scalar broadcast to the three axes
    gm.table.insert_or_assign("tau_s", toml::array{10.0, 20.0, 30.0, 40.0});
    EXPECT_DOUBLE_EQ(candidate_size_in(gm, Channel::gyro), 0.0);
    EXPECT_EQ(file_process_params(gm, Channel::accel_y), (std::vector<double>{0.003, 30.0}));

    const sim::EffectSpec tempco{"temp_scale_factor", {}};
    EXPECT_EQ(candidate_size_in(tempco, Channel::gyro), 0.0);
    EXPECT_THROW(without_channel(tempco, Channel::gyro), std::invalid_argument);
}

// A model file's process is held with the spectrum the simulator gives it: a Gauss-Markov process as the candidate's
// one component, flicker as the library's components for the FILE's band (not the candidate's), a walk's step
// variance per second; all in counts through the channel's front end.
TEST(Candidates, AModelFilesProcessIsHeldWithItsOwnSpectrum) {
    GapModel m;
    m.unit = sim::paper_model();
    m.smoothing = {1.0, 8, 8, 0};
    const double cpu = counts_per_unit(m, Channel::gyro);
    HeldNoise held;
    hold_noise(held, make_candidate_effect("gauss_markov", Channel::gyro, {0.05, 30.0}, m), Channel::gyro, m);
    ASSERT_EQ(held.gauss_markov.size(), 1u);
    EXPECT_DOUBLE_EQ(held.gauss_markov[0].variance_counts2, std::pow(0.05 * cpu, 2));
    EXPECT_DOUBLE_EQ(held.gauss_markov[0].tau_s, 30.0);

    sim::EffectSpec flicker{"flicker", {}};
    flicker.table.insert_or_assign("b_dps", 0.02);
    flicker.table.insert_or_assign("f_low_hz", 1e-4);
    flicker.table.insert_or_assign("f_high_hz", 0.05);
    hold_noise(held, flicker, Channel::gyro, m);
    sim::FlickerParams band;
    band.f_low_hz = 1e-4;
    band.f_high_hz = 0.05;
    const std::vector<double> taus = sim::Flicker(band).component_tau_s();
    ASSERT_EQ(held.gauss_markov.size(), 1 + taus.size());
    for (std::size_t k = 0; k < taus.size(); ++k) {
        EXPECT_DOUBLE_EQ(held.gauss_markov[1 + k].tau_s, taus[k]);
        EXPECT_DOUBLE_EQ(held.gauss_markov[1 + k].variance_counts2,
                         std::pow(0.02 * cpu * sim::Flicker::component_sigma_per_b(), 2));
    }
    sim::FlickerParams candidate_band;
    candidate_band.f_low_hz = 1e-5;
    candidate_band.f_high_hz = 0.1;
    EXPECT_NE(taus, sim::Flicker(candidate_band).component_tau_s());

    hold_noise(held, make_candidate_effect("rate_random_walk", Channel::gyro, {0.002}, m), Channel::gyro, m);
    EXPECT_DOUBLE_EQ(held.walk_counts2_per_s, std::pow(0.002 * cpu, 2));
}

}  // namespace
}  // namespace driftlab::host::gap
