// Lag-1 autocorrelation noise identification against the Alpha column Stable32 printed, and on simulated
// power-law noise of known type.
#include "host/stats/noise_id.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "host/stats/deviation.hpp"
#include "reference_data.hpp"

namespace driftlab::host::stats {
namespace {

struct IdTable {
    const char* folder;
    const char* data_file;
    InputKind kind;
    const char* table_file;
    Deviation dev;
};

class Stable32Alpha : public ::testing::TestWithParam<IdTable> {};

TEST_P(Stable32Alpha, MatchesWhereEnoughPointsRemain) {
    const IdTable t = GetParam();
    const auto dir = test::allan_reference_dir() / t.folder;
    if (!std::filesystem::exists(dir / t.table_file)) GTEST_SKIP() << "reference table not found in " << dir;
    std::vector<double> v = test::read_column(dir / t.data_file);
    const PhaseRecord record =
        t.kind == InputKind::rate ? PhaseRecord::from_rate(v, 1.0) : PhaseRecord::from_phase(v, 1.0);
    int checked = 0;
    for (const auto& row : test::read_stable32(dir / t.table_file)) {
        const auto id = autocorr_noise_id(record, row.m, difference_order(t.dev));
        // Stable32 switches to the B1 / R(n) method below about 30 points; only the lag-1 range is compared.
        if (!id) continue;
        EXPECT_EQ(id->alpha, row.alpha) << t.table_file << " AF " << row.m << " estimate " << id->alpha_estimate;
        ++checked;
    }
    EXPECT_GT(checked, 3);
}

const IdTable kIdTables[] = {
    {"phasedat", "PHASE.DAT", InputKind::phase, "phase_dat_oadev_octave.txt", Deviation::oadev},
    {"phasedat", "PHASE.DAT", InputKind::phase, "phase_dat_ohdev_octave.txt", Deviation::ohdev},
    {"ocxo", "ocxo_frequency.txt", InputKind::rate, "oadev_octave.txt", Deviation::oadev},
    {"ocxo", "ocxo_frequency.txt", InputKind::rate, "mdev_octave.txt", Deviation::mdev},
    {"ocxo", "ocxo_frequency.txt", InputKind::rate, "ohdev_octave.txt", Deviation::ohdev},
    {"pink_frequency", "pink_frequency.txt", InputKind::rate, "s32_oadev_octave.txt", Deviation::oadev},
    {"gps", "gps_1pps_phase_data.txt.gz", InputKind::phase, "stable32_OADEV_octave.txt", Deviation::oadev},
    {"gps", "gps_1pps_phase_data.txt.gz", InputKind::phase, "stable32_OHDEV_octave.txt", Deviation::ohdev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", InputKind::phase, "tic_oadev.txt", Deviation::oadev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", InputKind::phase, "tic_ohdev.txt", Deviation::ohdev},
};

std::string id_name(const ::testing::TestParamInfo<IdTable>& info) {
    std::string s = std::string(info.param.folder) + "_" + info.param.table_file;
    for (char& ch : s) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    }
    return s;
}

INSTANTIATE_TEST_SUITE_P(AllanReference, Stable32Alpha, ::testing::ValuesIn(kIdTables), id_name);

std::vector<double> white(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<double> v(n);
    for (double& x : v) x = g(rng);
    return v;
}

TEST(NoiseId, WhiteRateIsWhiteFm) {
    const auto y = white(20000, 1);
    for (std::int64_t m : {1, 4, 16}) {
        const auto id = autocorr_noise_id(y, InputKind::rate, m, 0, 2);
        ASSERT_TRUE(id.has_value());
        EXPECT_EQ(id->alpha, 0) << m;
    }
}

TEST(NoiseId, RandomWalkRateIsRandomWalkFm) {
    auto y = white(20000, 2);
    for (std::size_t i = 1; i < y.size(); ++i) y[i] += y[i - 1];
    const auto id = autocorr_noise_id(y, InputKind::rate, 4, 0, 2);
    ASSERT_TRUE(id.has_value());
    EXPECT_EQ(id->alpha, -2);
}

TEST(NoiseId, WhitePhaseIsWhitePm) {
    const auto x = white(20000, 3);
    const auto id = autocorr_noise_id(x, InputKind::phase, 2, 0, 2);
    ASSERT_TRUE(id.has_value());
    EXPECT_EQ(id->alpha, 2);
}

// White PM given as rate (first differences of white phase): lag-1 correlation -1/2, where rho = r1 / (1 + r1) runs
// off to minus infinity on a short averaged series. The type stays within what the statistic converges for (Allan
// -2..2, Hadamard -4..2), and is white PM in most logs; a random walk of a random walk (alpha -4) reads at Allan's
// limit.
TEST(NoiseId, TypesStayWithinTheStatisticsRange) {
    int white_pm = 0, runs = 0;
    for (std::uint64_t seed = 10; seed < 60; ++seed) {
        const auto w = white(2001, seed);
        std::vector<double> y(2000);
        for (std::size_t i = 0; i < y.size(); ++i) y[i] = w[i + 1] - w[i];
        for (const int dmax : {2, 3}) {
            const auto id = autocorr_noise_id(y, InputKind::rate, 40, 0, dmax);  // 50 averaged points
            ASSERT_TRUE(id.has_value());
            EXPECT_LE(id->alpha, 2) << seed;
            EXPECT_GE(id->alpha, 2 - 2 * dmax) << seed;
            white_pm += id->alpha == 2;
            ++runs;
        }
    }
    EXPECT_GT(white_pm, runs / 2);  // 50 points identify roughly; the rest read as flicker PM
    auto rrw = white(20000, 5);
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t i = 1; i < rrw.size(); ++i) rrw[i] += rrw[i - 1];
    const auto id = autocorr_noise_id(rrw, InputKind::rate, 4, 0, 2);
    ASSERT_TRUE(id.has_value());
    EXPECT_EQ(id->alpha, -2);
}

TEST(NoiseId, TooFewPointsGivesNoAnswer) {
    const auto y = white(100, 4);
    EXPECT_FALSE(autocorr_noise_id(y, InputKind::rate, 4, 0, 2).has_value());
}

}  // namespace
}  // namespace driftlab::host::stats
