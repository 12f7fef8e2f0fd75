// Causes shared by channels: logs of all four channels simulated with the library's shared supply wander (loadings
// that follow the DC levels, or free ones), with independent processes on two channels, and with none; the reading
// chosen, its loadings and correlation time against what was simulated.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "host/gap/common_cause.hpp"
#include "sim/model/board_outputs.hpp"
#include "sim/model/drift.hpp"

namespace driftlab::host::gap {
namespace {

constexpr std::size_t kSamples = 1500;

// The paper's four channels at 1 s, a mean of 8 conversions per output, with `effects`.
GapModel four_channels(const std::vector<sim::EffectSpec>& effects) {
    GapModel m;
    m.unit = sim::paper_model();
    m.unit.effects.clear();
    m.smoothing = {1.0, 8, 8, 0};
    m.base = sim::base_of(m.unit);
    m.effects = effects;
    return m;
}

// The residuals of a log of `m` and the channels' DC levels.
struct Simulated {
    std::array<std::vector<double>, kChannelCount> residual;
    std::array<double, kChannelCount> dc{};
};

Simulated simulate(const GapModel& m, std::uint64_t seed) {
    std::vector<double> t(kSamples);
    for (std::size_t k = 0; k < kSamples; ++k) t[k] = static_cast<double>(k + 1);
    sim::OutputRequest req;
    req.t_s = &t;
    const sim::Outputs y = sim::simulate_outputs(m, req, seed);
    Simulated s;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        s.residual[c] = common_residual(t, y[c], {});
        s.dc[c] = m.base[c].drift.c2_counts;
    }
    return s;
}

CommonFindings fit(const GapModel& m, std::uint64_t seed, int threads = 2) {
    const Simulated s = simulate(m, seed);
    std::array<const std::vector<double>*, kChannelCount> r{};
    for (std::size_t c = 0; c < kChannelCount; ++c) r[c] = &s.residual[c];
    return fit_common(r, s.dc, m, threads);
}

// The library's supply wander (Gauss-Markov, `tau_s`) reaching channel c with std `loading_counts[c]`, through pickup.
sim::EffectSpec wander(const std::array<double, kChannelCount>& loading_counts, double tau_s) {
    sim::EffectSpec spec;
    spec.name = "supply_coupling";
    toml::array pickup;
    for (double l : loading_counts) pickup.push_back(l * (5.0 / 1024.0) / 0.05);
    spec.table.insert_or_assign("pickup_v_per_v", pickup);
    spec.table.insert_or_assign("wander_v", 0.05);
    spec.table.insert_or_assign("wander_tau_s", tau_s);
    return spec;
}

// One path reaches every channel, so the loadings' ratios are sharp (each channel's own noise alone scatters them:
// within 0.1 of the largest loading); their common scale and the correlation time are a process's variance and
// time read from about 12 correlation times (1500 s of a 120 s process: some 30 % scatter each), so within a
// factor 2. Sign aside: the shared process's is arbitrary.
void expect_loadings(const CommonFit& f, const std::array<double, kChannelCount>& load, double tau_s,
                     double ratio_tolerance = 0.1) {
    std::size_t big = 0;
    for (std::size_t c = 1; c < kChannelCount; ++c)
        if (std::abs(load[c]) > std::abs(load[big])) big = c;
    const double scale = f.loading[big] / load[big];
    EXPECT_GT(std::abs(scale), 0.5);
    EXPECT_LT(std::abs(scale), 2.0);
    for (std::size_t c = 0; c < kChannelCount; ++c)
        EXPECT_NEAR(f.loading[c] / scale / load[big], load[c] / load[big], ratio_tolerance) << kChannelNames[c];
    EXPECT_GT(f.tau_s, tau_s / 2.0);
    EXPECT_LT(f.tau_s, tau_s * 2.0);
}

TEST(CommonCause, ASupplyWanderFollowingTheDcLevelsIsReadAsSupplyCoupling) {
    std::array<double, kChannelCount> load{};
    for (std::size_t c = 0; c < kChannelCount; ++c) load[c] = 0.002 * sim::kPaperDrift[c].c2_counts;
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CommonFindings f = fit(four_channels({wander(load, 120.0)}), seed);
        ASSERT_TRUE(f.winner());
        EXPECT_EQ(f.winner()->reading, "supply_coupling");
        expect_loadings(*f.winner(), load, 120.0);
        EXPECT_GT(f.winner()->relative_sd, 0.001);
        EXPECT_LT(f.winner()->relative_sd, 0.004);
        for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_TRUE(f.winner()->loaded[c]);
    }
}

TEST(CommonCause, FreeLoadingsAreASharedProcessLoadingTheChannelsThatSeeIt) {
    const std::array<double, kChannelCount> load{1.0, -1.0, 0.0, 1.5};
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const CommonFindings f = fit(four_channels({wander(load, 120.0)}), seed);
        ASSERT_TRUE(f.winner());
        EXPECT_EQ(f.winner()->reading, "shared_process");
        expect_loadings(*f.winner(), load, 120.0);
        EXPECT_FALSE(f.winner()->loaded[2]);  // accel_y does not see it
    }
}

// The chosen reading, written back as the library's effect and simulated again, is read as itself with the same
// loadings: the loop the diagnosis closes (its final model judged again, --model-out).
TEST(CommonCause, TheWrittenEffectReproducesTheFittedReading) {
    const std::array<double, kChannelCount> load{1.0, -1.0, 0.0, 1.5};
    const GapModel m = four_channels({wander(load, 120.0)});
    const CommonFindings f = fit(m, 7);
    ASSERT_TRUE(f.winner());
    const CommonFindings again = fit(four_channels({common_effect(*f.winner(), m)}), 8);
    ASSERT_TRUE(again.winner());
    EXPECT_EQ(again.winner()->reading, f.winner()->reading);
    // Two estimates, each scattered as above: their ratios agree within twice the tolerance.
    expect_loadings(*again.winner(), f.winner()->loading, f.winner()->tau_s, 0.2);
}

// Processes of their own on two channels, on one, or none: each channel read alone.
TEST(CommonCause, IndependentProcessesStaySeparate) {
    sim::EffectSpec gm;
    gm.name = "gauss_markov";
    gm.table.insert_or_assign("sigma_dps", 0.3);
    gm.table.insert_or_assign("sigma_g", toml::array{0.01, 0.0, 0.0});
    gm.table.insert_or_assign("tau_s", 120.0);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) EXPECT_FALSE(fit(four_channels({gm}), seed).winner());
    // One channel's own process: the ratiometric reading would have the others see it at their DC levels.
    gm.table.insert_or_assign("sigma_g", toml::array{0.0, 0.0, 0.0});
    for (std::uint64_t seed = 1; seed <= 3; ++seed) EXPECT_FALSE(fit(four_channels({gm}), seed).winner());
    for (std::uint64_t seed = 1; seed <= 3; ++seed) EXPECT_FALSE(fit(four_channels({}), seed).winner());
}

// The channels alone and the starts run one to a thread, each with its own expected periodograms: one thread and two
// give the same readings, digit for digit.
TEST(CommonCause, OneThreadAndTwoGiveTheSameReadings) {
    const std::array<double, kChannelCount> load{1.0, -1.0, 0.0, 1.5};
    const GapModel m = four_channels({wander(load, 120.0)});
    const CommonFindings one = fit(m, 4, 1), two = fit(m, 4, 2);
    ASSERT_EQ(one.fits.size(), two.fits.size());
    for (std::size_t i = 0; i < one.fits.size(); ++i) {
        EXPECT_EQ(one.fits[i].criterion, two.fits[i].criterion) << one.fits[i].reading;
        EXPECT_EQ(one.fits[i].tau_s, two.fits[i].tau_s) << one.fits[i].reading;
        EXPECT_EQ(one.fits[i].loading, two.fits[i].loading) << one.fits[i].reading;
        EXPECT_EQ(one.fits[i].white, two.fits[i].white) << one.fits[i].reading;
        EXPECT_EQ(one.fits[i].own_tau, two.fits[i].own_tau) << one.fits[i].reading;
    }
    EXPECT_EQ(one.chosen, two.chosen);
}

}  // namespace
}  // namespace driftlab::host::gap
