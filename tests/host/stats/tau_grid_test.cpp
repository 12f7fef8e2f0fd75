// Averaging-factor grids: octave and log spacing, and Stable32's dense "all tau" list reproduced row for row.
#include "host/stats/tau_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "host/stats/deviation.hpp"
#include "reference_data.hpp"

namespace driftlab::host::stats {
namespace {

TEST(TauGrid, OctaveIsPowersOfTwoUpToTheBound) {
    const auto ms = averaging_factors({TauGrid::octave}, 250);
    EXPECT_EQ(ms, (std::vector<std::int64_t>{1, 2, 4, 8, 16, 32, 64, 128}));
}

TEST(TauGrid, LogGridIsStrictlyIncreasingWithTheRequestedDensity) {
    TauGridOptions o{TauGrid::log, 10, 53};
    const auto ms = averaging_factors(o, 100000);
    ASSERT_FALSE(ms.empty());
    EXPECT_EQ(ms.front(), 1);
    for (std::size_t i = 1; i < ms.size(); ++i) EXPECT_GT(ms[i], ms[i - 1]);
    // Above m = 10 every decade holds exactly 10 points.
    int in_decade = 0;
    for (auto m : ms) in_decade += (m >= 1000 && m < 10000);
    EXPECT_EQ(in_decade, 10);
}

TEST(TauGrid, AllIsEveryFactor) {
    const auto ms = averaging_factors({TauGrid::all}, 7);
    EXPECT_EQ(ms, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7}));
}

TEST(TauGrid, ParsesNamesAndRejectsOthers) {
    EXPECT_EQ(parse_tau_grid("octave"), TauGrid::octave);
    EXPECT_EQ(parse_tau_grid("stable32"), TauGrid::stable32_all);
    EXPECT_THROW(parse_tau_grid("decade"), std::invalid_argument);
}

TEST(TauGrid, Stable32MaxFactorFollowsItsTables) {
    // PHASE.DAT (1001 phase samples): octave tables stop at 128 for ADEV ((N-1)/5 = 200) and OADEV (250).
    EXPECT_EQ(stable32_max_factor(1001, stable32_factor_divisor(Deviation::adev)), 200);
    EXPECT_EQ(stable32_max_factor(1001, stable32_factor_divisor(Deviation::oadev)), 250);
}

struct DenseTable {
    const char* folder;
    const char* table_file;
    std::size_t phase_samples;
    Deviation dev;
    std::int64_t step_divisor;
};

TEST(TauGrid, Stable32AllTauListReproducesTheReferenceTables) {
    const DenseTable tables[] = {
        {"phasedat", "phase_dat_oadev.txt", 1001, Deviation::oadev, 71},
        {"phasedat", "phase_dat_adev.txt", 1001, Deviation::adev, 71},
        {"ocxo", "stable32_oadev_alltau.txt", 19983, Deviation::oadev, 53},
        {"ocxo", "stable32_hdev_alltau.txt", 19983, Deviation::hdev, 53},
        {"Keysight53230A_ti_noise_floor", "tic_adev.txt", 55688, Deviation::adev, 42},
        {"pink_frequency", "adev.txt", 10001, Deviation::adev, 53},
    };
    for (const DenseTable& t : tables) {
        const auto path = test::allan_reference_dir() / t.folder / t.table_file;
        if (!std::filesystem::exists(path)) GTEST_SKIP() << "reference table not found: " << path;
        std::vector<std::int64_t> expected;
        for (const auto& row : test::read_stable32(path)) expected.push_back(row.m);
        const TauGridOptions o{TauGrid::stable32_all, 10, t.step_divisor};
        EXPECT_EQ(averaging_factors(o, stable32_max_factor(t.phase_samples, stable32_factor_divisor(t.dev))), expected)
            << t.folder << "/" << t.table_file;
    }
}

}  // namespace
}  // namespace driftlab::host::stats
