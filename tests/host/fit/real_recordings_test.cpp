// The fit and whiteness test on the real recordings in the shared data folder (PROVENANCE.md there):
// gyro2_x.txt has a turn-on transient; the MPU6050 CSV has no warm-up and irregular timestamps with gaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/file_analysis.hpp"
#include "host/util/error.hpp"

namespace driftlab::host::fit {
namespace {

std::filesystem::path real_dir() { return std::filesystem::path(DRIFTLAB_SHARED_DIR) / "data" / "real"; }

TEST(RealRecordings, Gyro2xTurnOnTransientMatchesTheProvenanceFit) {
    const auto path = real_dir() / "gyro2_x.txt";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found (shared data folder absent)";
    FileAnalysisRequest request;
    request.path = path.string();  // one line of values, no rate: time in samples
    const FileAnalysis file = analyse_file(request);
    ASSERT_EQ(file.series.size(), 1u);
    ASSERT_TRUE(file.series[0].analysis) << file.series[0].error;
    const DriftAnalysis& a = *file.series[0].analysis;
    EXPECT_EQ(a.fit.n, 238256u);
    EXPECT_EQ(a.fit.status, FitStatus::converged);
    // PROVENANCE.md, from 1000-sample block means: C1 = -0.445 deg/s, C2 = 1.110 deg/s, T ~ 25 500 samples.
    EXPECT_NEAR(a.plain.c1.value, -0.445, 0.02);
    EXPECT_NEAR(a.plain.c2.value, 1.110, 0.02);
    EXPECT_NEAR(a.plain.t_s.value, 25500.0, 2500.0);
    EXPECT_LT(a.plain.c1.ci95[0], a.plain.c1.value);
    EXPECT_GT(a.plain.c1.ci95[1], a.plain.c1.value);
    // A real MEMS residual (quantised, flicker) is not white over 238 k samples; the verdict must say so.
    EXPECT_FALSE(a.whiteness.white);
    EXPECT_FALSE(a.warnings.empty());
}

TEST(RealRecordings, Mpu6050WithGapsEitherFitsOrSaysWhyPerColumn) {
    const auto path = real_dir() / "mpu6050_unmoved-with-x-pointing-forward-10min.csv";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found (shared data folder absent)";
    FileAnalysisRequest request;
    request.path = path.string();
    const FileAnalysis file = analyse_file(request);  // time from the t_s column
    ASSERT_EQ(file.series.size(), 7u);
    for (const SeriesOutcome& s : file.series) {
        if (!s.analysis) {
            // Only the temperature may be refused (a quantised, nearly constant column); the six sensor axes vary
            // and hold thousands of rows, so each must fit.
            EXPECT_EQ(s.name, "temp_C") << s.error;
            EXPECT_FALSE(s.error.empty()) << s.name;
            continue;
        }
        const DriftAnalysis& a = *s.analysis;
        EXPECT_EQ(a.fit.n, 65067u) << s.name;
        EXPECT_GT(a.time_gaps, 0u) << s.name;  // PROVENANCE: gaps up to 0.5 s
        // Gaps and (where the fit is poorly determined) the reason are in the warnings.
        bool gap_warning = false;
        for (const auto& w : a.warnings) gap_warning |= w.find("gaps in time") != std::string::npos;
        EXPECT_TRUE(gap_warning) << s.name;
        if (a.fit.status != FitStatus::converged || a.plain.t_s.value > 3.0 * a.data.t_s.back()) {
            bool reason = false;
            for (const auto& w : a.warnings)
                reason |= w.find("singular") != std::string::npos || w.find("beyond the record") != std::string::npos ||
                          w.find("evaluation limit") != std::string::npos;
            EXPECT_TRUE(reason) << s.name;
        }
    }
    // The die temperature drifts down by about 0.16 degC over the run (PROVENANCE.md): a settling fall.
    const auto temp =
        std::find_if(file.series.begin(), file.series.end(), [](const auto& s) { return s.name == "temp_C"; });
    ASSERT_NE(temp, file.series.end());
    ASSERT_TRUE(temp->analysis);
    EXPECT_LT(temp->analysis->plain.c1.value, 0.0);
    EXPECT_NEAR(temp->analysis->plain.c1.value, -0.16, 0.08);
}

TEST(RealRecordings, MalformedInputsAreDataErrorsWithTheLine) {
    const auto dir = std::filesystem::temp_directory_path();
    const auto nan_file = dir / "driftlab_fit_nan.txt";
    std::ofstream(nan_file) << "1 2\n3 nan\n";
    FileAnalysisRequest request;
    request.path = nan_file.string();
    try {
        analyse_file(request);
        FAIL() << "NaN accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(":2: field 2 'nan'"), std::string::npos) << e.what();
    }
    const auto empty = dir / "driftlab_fit_empty.csv";
    std::ofstream(empty) << "";
    request.path = empty.string();
    EXPECT_THROW(analyse_file(request), DataError);
    const auto short_log = dir / "driftlab_fit_short.csv";
    std::ofstream(short_log) << "# driftlab-log: 1\nt_s,seq,gyro,accel_x,accel_y,accel_z\n1,0,505,470,474,622\n"
                                "2,1,506,471,475,623\n";
    request.path = short_log.string();
    const FileAnalysis file = analyse_file(request);
    EXPECT_EQ(file.failures(), 4u);
    EXPECT_NE(file.failure_summary().find("2 samples in the selected time range"), std::string::npos)
        << file.failure_summary();
}

}  // namespace
}  // namespace driftlab::host::fit
