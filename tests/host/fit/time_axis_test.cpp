// The time axis of a plain table as the analysis reads and reports it: the row index when there is no time column
// (said, not labelled seconds), time columns by common names and in ms/us, clocks far from power-on, and rows in
// bursts (docs/analysis.md §1-3).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "host/fit/drift_analysis.hpp"
#include "host/fit/series.hpp"
#include "host/log/numeric_table.hpp"
#include "host/stats/whiteness.hpp"
#include "sim/model/rng.hpp"
#include "tests/support/numeric_table.hpp"

namespace driftlab::host::fit {
namespace {

bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
    for (const auto& l : lines)
        if (l.find(text) != std::string::npos) return true;
    return false;
}

/// Eq. 1 (C1 = 3, T = 150 s, C2 = 505) plus white noise at the times `t_since_on`.
std::vector<double> drift_values(const std::vector<double>& t_since_on, std::uint64_t seed) {
    sim::Rng rng(seed, 1);
    std::vector<double> v;
    for (double t : t_since_on) v.push_back(3.0 * (1.0 - std::exp(-t / 150.0)) + 505.0 + 0.25 * rng.normal());
    return v;
}

NumericTable table_of(std::vector<std::string> names, std::vector<std::vector<double>> columns) {
    return test_support::numeric_table("table.csv", std::move(names), std::move(columns));
}

TEST(TimeAxis, ARowIndexIsSaidNotPassedOffAsSeconds) {
    std::vector<double> t;
    for (int k = 0; k < 600; ++k) t.push_back(k);
    const std::vector<double> v = drift_values(t, 1);
    const Series indexed = series_from_table(table_of({"gyro"}, {v})).front();
    EXPECT_EQ(indexed.index_period_s, 1.0);
    const DriftAnalysis a = analyse_drift(indexed);
    EXPECT_TRUE(any_contains(a.warnings, "no time column: t is the row index x 1 s")) << a.warnings.size();
    // With a time column there is nothing to say.
    const Series timed = series_from_table(table_of({"t_s", "gyro"}, {t, v})).front();
    EXPECT_EQ(timed.index_period_s, 0.0);
    EXPECT_FALSE(any_contains(analyse_drift(timed).warnings, "no time column"));
}

TEST(TimeAxis, CommonTimeColumnNamesAndMillisecondsAreRecognised) {
    const std::vector<double> ms = {100.0, 200.0, 300.0}, v = {1.0, 2.0, 4.0};
    for (const char* name : {"time_s", "timestamp", "t_s", "t", "time"}) {
        const auto s = series_from_table(table_of({name, "gyro"}, {{0.1, 0.2, 0.3}, v}));
        ASSERT_EQ(s.size(), 1u) << name << ": the time column was taken as a series";
        EXPECT_EQ(s[0].t_s, (std::vector<double>{0.1, 0.2, 0.3})) << name;
    }
    const auto from_ms = series_from_table(table_of({"timestamp_ms", "gyro"}, {ms, v}));
    ASSERT_EQ(from_ms.size(), 1u);
    EXPECT_EQ(from_ms[0].name, "gyro");
    EXPECT_EQ(from_ms[0].t_s, (std::vector<double>{0.1, 0.2, 0.3}));
    // Named on the command line, a unit suffix still counts.
    const auto named = series_from_table(table_of({"clock_us", "gyro"}, {{1e5, 2e5, 3e5}, v}), {}, "clock_us");
    EXPECT_EQ(named.at(0).t_s, (std::vector<double>{0.1, 0.2, 0.3}));
    // The old names come first: a table with t_s and a millisecond column keeps t_s as its time.
    const auto both = series_from_table(table_of({"timestamp_ms", "t_s", "gyro"}, {ms, {1.0, 2.0, 3.0}, v}));
    ASSERT_EQ(both.size(), 2u);
    EXPECT_EQ(both[0].name, "timestamp_ms");
    EXPECT_EQ(both[0].t_s, (std::vector<double>{1.0, 2.0, 3.0}));
}

// Unix time: 0.1 s rows from 1.7e9 s. The fit is singular; the warnings say why and advise no (infinite) interval.
TEST(TimeAxis, UnixTimeIsWarnedAndASingularFitGetsNoIntervalAdvice) {
    Series s;
    s.name = "gyro";
    s.source = "unix.csv";
    std::vector<double> since_on;
    for (int k = 0; k < 6000; ++k) {
        s.t_s.push_back(1.7e9 + 0.1 * k);
        since_on.push_back(0.1 * k + 1.0);
    }
    s.values = drift_values(since_on, 2);
    const DriftAnalysis a = analyse_drift(s);
    ASSERT_EQ(a.fit.status, FitStatus::singular);
    EXPECT_TRUE(any_contains(a.warnings, "times start at 1.7e+09 s")) << a.warnings.front();
    EXPECT_TRUE(any_contains(a.warnings, "subtract the power-on time"));
    EXPECT_FALSE(any_contains(a.warnings, "widened"));
    // Spacing 0.0999999046 s: 500 samples are 50 s to 2e-6, no adaptation worth a 16-digit note.
    EXPECT_EQ(a.whiteness.sequence_samples, 500u);
    EXPECT_EQ(a.whiteness.adaptation, "");
    // A record starting well after power-on, but not far (t from 300 s, 600 s long), is not warned.
    Series late = s;
    for (std::size_t k = 0; k < late.t_s.size(); ++k) late.t_s[k] = 300.0 + 0.1 * static_cast<double>(k);
    EXPECT_FALSE(any_contains(analyse_drift(late).warnings, "times start at"));
}

TEST(TimeAxis, AMovedSequenceLengthIsWrittenToFourDigits) {
    std::vector<double> w;
    sim::Rng rng(4, 1);
    for (int k = 0; k < 2000; ++k) w.push_back(rng.normal());
    // 71 samples of 0.7 s = 49.699999999999996 s in full digits.
    const stats::WhitenessResult r = stats::test_whiteness(w, 0.7);
    EXPECT_EQ(r.adaptation, "sequences of 49.7 s (71 samples of 0.7 s), the nearest whole number of samples to 50 s");
}

// MPU6050-like rows: bursts of 5 rows 2 ms apart, 20 bursts a second (100 rows/s). 5 s hold 500 rows, not the
// 2500 of the 2 ms median.
TEST(TimeAxis, BurstyRowsCountSequencesAtTheirMeanSpacing) {
    Series s;
    s.name = "gx";
    s.source = "bursts.csv";
    for (int burst = 0; burst < 1200; ++burst)
        for (int i = 0; i < 5; ++i) s.t_s.push_back(1.0 + 0.05 * burst + 0.002 * i);
    s.values = drift_values(s.t_s, 3);
    AnalysisOptions o;
    o.whiteness.sequence_length_s = 5.0;
    const DriftAnalysis a = analyse_drift(s, o);
    EXPECT_NEAR(a.sample_period_s, 0.002, 1e-9);  // the median, as before
    EXPECT_NEAR(static_cast<double>(a.whiteness.sequence_samples), 500.0, 1.0);
    EXPECT_NEAR(a.whiteness.sample_period_s, 0.01, 1e-4);
    // Mean: (0.05 x 1199 + 0.008) s / 5999 spacings.
    EXPECT_TRUE(any_contains(a.warnings, "rows are 0.002 s apart (median; mean 0.00999467 s)"));
    // Each burst's end counts as a gap against the median: the warning says so, and gives the longest spacing, which
    // tells a real gap from them.
    EXPECT_EQ(a.time_gaps, 1199u);
    EXPECT_TRUE(any_contains(a.warnings,
                             "1199 gaps in time (spacing > 1.5x the median 0.002 s; the longest 0.042 s, most "
                             "of them the ends of the bursts the rows come in)"));
    // Evenly spaced rows keep the median.
    Series even = s;
    for (std::size_t k = 0; k < even.t_s.size(); ++k) even.t_s[k] = 1.0 + 0.01 * static_cast<double>(k);
    const DriftAnalysis e = analyse_drift(even, o);
    EXPECT_EQ(e.whiteness.sample_period_s, e.sample_period_s);
    EXPECT_FALSE(any_contains(e.warnings, "mean spacing"));
}

}  // namespace
}  // namespace driftlab::host::fit
