// Chi-square quantiles against closed forms, and Greenhall-Riley EDF confidence intervals against the Min/Max
// Sigma columns Stable32 printed (68.3 %, with Stable32's own noise type alpha), as allantools checks them.
#include "host/stats/edf.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "host/stats/chi_square.hpp"
#include "host/stats/deviation.hpp"
#include "reference_data.hpp"

namespace driftlab::host::stats {
namespace {

TEST(ChiSquare, TwoDofQuantileIsMinusTwoLogOfTheTail) {
    for (double p : {1e-6, 0.01, 0.158655, 0.5, 0.841345, 0.99, 1.0 - 1e-9}) {
        EXPECT_NEAR(chi_square_quantile(p, 2.0) / (-2.0 * std::log1p(-p)), 1.0, 1e-12) << p;
    }
}

TEST(ChiSquare, CdfMatchesClosedFormsForOneAndFourDof) {
    for (double x : {1e-4, 0.3, 1.0, 4.0, 17.0, 60.0}) {
        EXPECT_NEAR(chi_square_cdf(x, 1.0), std::erf(std::sqrt(x / 2.0)), 1e-14) << x;
        EXPECT_NEAR(chi_square_cdf(x, 4.0), 1.0 - std::exp(-x / 2.0) * (1.0 + x / 2.0), 1e-14) << x;
    }
}

TEST(ChiSquare, QuantileInvertsCdfForFractionalDof) {
    for (double dof : {0.7, 1.0, 3.3, 12.5, 140.0, 25000.0}) {
        for (double p : {0.001, 0.158655, 0.5, 0.841345, 0.999}) {
            const double x = chi_square_quantile(p, dof);
            // Large dof: ln Gamma(a) ~ 1e5 limits the CDF itself to about 1e-11.
            EXPECT_NEAR(chi_square_cdf(x, dof), p, dof > 1000.0 ? 1e-10 : 1e-12) << dof << " " << p;
        }
    }
}

TEST(ChiSquare, LargeDofAgreesWithWilsonHilferty) {
    const double dof = 500.0;
    const double z = 1.0;  // p = Phi(1)
    const double k = 2.0 / (9.0 * dof);
    const double wh = dof * std::pow(1.0 - k + z * std::sqrt(k), 3.0);
    EXPECT_NEAR(chi_square_quantile(0.5 * std::erfc(-1.0 / std::sqrt(2.0)), dof) / wh, 1.0, 1e-4);
}

TEST(ChiSquare, RejectsOutOfDomain) {
    EXPECT_THROW(chi_square_quantile(0.0, 3.0), std::invalid_argument);
    EXPECT_THROW(chi_square_quantile(0.5, -1.0), std::invalid_argument);
}

TEST(Edf, GreenhallApproachesTheUncorrelatedCountForWhitePmNonOverlapping) {
    // White PM, non-overlapping Allan, m = 1: the terms are 2nd differences of white noise; Greenhall's case 4
    // gives 1/edf = (a0 - a1/r)/M with a0 = C(8,4)/C(4,2)^2 = 70/36 (Table 2, d = 2).
    const double n = 1001.0;
    const auto edf = edf_greenhall(2, 2, 1.0, n, false, false);
    ASSERT_TRUE(edf.has_value());
    const double big_m = n - 2.0;
    EXPECT_NEAR(1.0 / *edf, (70.0 / 36.0 - 1.0 / big_m) / big_m, 1e-12);
}

// ---- Stable32 Min/Max Sigma ------------------------------------------------------------------------------

struct CiTable {
    const char* folder;
    const char* table_file;
    Deviation dev;
    double phase_samples;
    double rel_tolerance;
};

class Stable32Interval : public ::testing::TestWithParam<CiTable> {};

TEST_P(Stable32Interval, BoundsMatchWithStable32Alpha) {
    const CiTable t = GetParam();
    const auto path = test::allan_reference_dir() / t.folder / t.table_file;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "reference table not found: " << path;
    int checked = 0;
    for (const auto& row : test::read_stable32(path)) {
        if (row.dev_min <= 0.0) continue;  // Stable32 did not compute an interval for this row
        SCOPED_TRACE(std::string(t.table_file) + " AF " + std::to_string(row.m));
        const double edf = edf_for(t.dev, row.alpha, static_cast<double>(row.m), t.phase_samples);
        const ConfidenceInterval ci = confidence_interval(row.dev, edf);
        EXPECT_NEAR(ci.low / row.dev_min, 1.0, t.rel_tolerance);
        EXPECT_NEAR(ci.high / row.dev_max, 1.0, t.rel_tolerance);
        ++checked;
    }
    EXPECT_GT(checked, 0);
}

const CiTable kCiTables[] = {
    {"phasedat", "phase_dat_adev_octave.txt", Deviation::adev, 1001, 1e-3},
    {"phasedat", "phase_dat_oadev_octave.txt", Deviation::oadev, 1001, 1e-3},
    {"phasedat", "phase_dat_mdev_octave.txt", Deviation::mdev, 1001, 1e-3},
    {"phasedat", "phase_dat_hdev_octave.txt", Deviation::hdev, 1001, 1e-3},
    {"phasedat", "phase_dat_ohdev_octave.txt", Deviation::ohdev, 1001, 1e-3},
    {"ocxo", "adev_octave.txt", Deviation::adev, 19983, 1e-3},
    {"ocxo", "oadev_octave.txt", Deviation::oadev, 19983, 1e-3},
    {"ocxo", "mdev_octave.txt", Deviation::mdev, 19983, 1e-3},
    {"ocxo", "hdev_octave.txt", Deviation::hdev, 19983, 1e-3},
    {"ocxo", "ohdev_octave.txt", Deviation::ohdev, 19983, 1e-3},
    {"pink_frequency", "s32_oadev_octave.txt", Deviation::oadev, 10001, 1e-3},
    {"gps", "stable32_ADEV_decade.txt", Deviation::adev, 241218, 1e-3},
    {"gps", "stable32_OADEV_octave.txt", Deviation::oadev, 241218, 1e-3},
    {"gps", "stable32_MDEV_octave.txt", Deviation::mdev, 241218, 1e-3},
    {"gps", "stable32_HDEV_octave.txt", Deviation::hdev, 241218, 1e-3},
    {"gps", "stable32_OHDEV_octave.txt", Deviation::ohdev, 241218, 1e-3},
    {"Keysight53230A_ti_noise_floor", "tic_oadev.txt", Deviation::oadev, 55688, 1e-3},
    {"Keysight53230A_ti_noise_floor", "tic_mdev.txt", Deviation::mdev, 55688, 1e-3},
    {"Keysight53230A_ti_noise_floor", "tic_hdev.txt", Deviation::hdev, 55688, 1e-3},
    {"Keysight53230A_ti_noise_floor", "tic_ohdev.txt", Deviation::ohdev, 55688, 1e-3},
};

std::string ci_name(const ::testing::TestParamInfo<CiTable>& info) {
    std::string s = std::string(info.param.folder) + "_" + info.param.table_file;
    for (char& ch : s) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    }
    return s;
}

INSTANTIATE_TEST_SUITE_P(AllanReference, Stable32Interval, ::testing::ValuesIn(kCiTables), ci_name);

}  // namespace
}  // namespace driftlab::host::stats
