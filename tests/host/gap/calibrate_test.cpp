// Calibration of the base: a log without a warm-up (a unit already warm, a slow straight drift) drives the eq. 1
// fit's T far beyond the log; the base must still reproduce the log's level and slope, or every replicate drifts
// away from the real log and the battery locates a gap that is the calibration's.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/gap/calibrate.hpp"
#include "host/util/error.hpp"
#include "sim/model/drift.hpp"

namespace driftlab::host::gap {
namespace {

double mean_of(const std::vector<double>& v, std::size_t from, std::size_t to) {
    double s = 0.0;
    for (std::size_t k = from; k < to; ++k) s += v[k];
    return s / static_cast<double>(to - from);
}

TEST(Calibrate, AStraightLogKeepsItsLevelAndSlopeWhenTheTimeConstantIsBounded) {
    GapModel m = testing::paper_gyro_model(8);
    m.base[0].drift = {0.0, 508.0, 411.0};  // warm already: no rise
    std::vector<double> ramp(1500);
    for (std::size_t k = 0; k < ramp.size(); ++k) ramp[k] = 0.0005 * static_cast<double>(k + 1);  // 0.75 counts
    const LogData log = testing::gyro_log(m, 1500, ramp, 31);
    const GapModel base = calibrate_base(log, sim::paper_model(), {true, false, false, false}, 1);
    const double span = log.t_s.back() - log.t_s.front();
    const auto& d = base.base[0].drift;
    EXPECT_LE(d.tau_s, 1e3 * span * (1 + 1e-12)) << "T is bounded";
    const sim::Drift drift(d);
    // The model's level over the first and the last tenth against the log's (noise of a tenth's mean: ~0.03 counts).
    double model_first = 0.0, model_last = 0.0;
    for (std::size_t k = 0; k < 150; ++k) model_first += drift.at_counts(log.t_s[k]) / 150.0;
    for (std::size_t k = 1350; k < 1500; ++k) model_last += drift.at_counts(log.t_s[k]) / 150.0;
    EXPECT_NEAR(model_first, mean_of(log.counts[0], 0, 150), 0.1);
    EXPECT_NEAR(model_last, mean_of(log.counts[0], 1350, 1500), 0.1);
    EXPECT_NEAR(model_last - model_first, 0.0005 * 1350.0, 0.15);
}

// The white noise before the quantiser comes back (the replicates quantise it, adding lsb^2/12): a calibration that
// matched the codes' spread without that correction would read sqrt(1.05^2 + 1/12) = 1.089 (+3.7 %) and
// sqrt(0.6^2 + 1/12) = 0.666 (+11 %). Over 40 000 outputs the short-lag spread is known to 1/sqrt(2n) = 0.35 %, and the
// three replicates it is matched against add a third of that variance: 0.41 %, so 2 % is about 5 sigma (seeds 101..106
// scattered 0.5 % and 0.6 %). T from the same logs: 4 times their spread (7.5 s) around the planted 411 s.
TEST(Calibrate, TheWhiteNoiseBeforeTheQuantiserAndTheTimeConstantComeBack) {
    for (double sigma : {1.05, 0.6}) {
        GapModel m = testing::paper_gyro_model(8);
        m.base[0].sigma_n_counts = sigma;
        for (std::uint64_t seed : {1, 2, 3}) {
            const LogData log = testing::gyro_log(m, 40000, {}, 100 + seed);
            const GapModel base = calibrate_base(log, sim::paper_model(), {true, false, false, false}, seed);
            EXPECT_NEAR(base.base[0].sigma_n_counts / sigma, 1.0, 0.02) << sigma << " seed " << seed;
            EXPECT_NEAR(base.base[0].drift.tau_s, 411.0, 30.0) << sigma << " seed " << seed;
        }
    }
}

// The stated output period is checked against the rows (a wrong one misplaces every lag and band), with lost frames
// taken out: a radio link that lost every other frame, seq stepping by 2, still has its period; a period ten times
// the rows' is refused naming its line.
TEST(Calibrate, TheStatedPeriodMustMatchTheRowsLostFramesTakenOut) {
    const GapModel m = testing::paper_gyro_model(8);
    LogData log = testing::gyro_log(m, 400, {}, 5);
    LogData lossy;
    lossy.source_name = log.source_name;
    lossy.metadata = log.metadata;
    for (std::size_t k = 0; k < log.size(); k += 2) {  // every other frame lost: rows 2 s apart, seq steps by 2
        lossy.t_s.push_back(log.t_s[k]);
        lossy.seq.push_back(log.seq[k]);
    }
    EXPECT_DOUBLE_EQ(smoothing_from_log(lossy).sample_period_s, 1.0);
    lossy.seq.assign(lossy.t_s.size(), 0);
    for (std::size_t k = 0; k < lossy.seq.size(); ++k) lossy.seq[k] = k;  // the same times without the lost frames' seq
    EXPECT_THROW(smoothing_from_log(lossy), DataError);
    log.metadata.set("sample_period_s", 10.0);
    log.metadata.set_line("sample_period_s", 4);
    try {
        smoothing_from_log(log);
        FAIL() << "a period ten times the rows' accepted";
    } catch (const DataError& e) {
        EXPECT_NE(
            std::string(e.what()).find("test.csv:4: metadata 'sample_period_s' is 10 s, but the rows are 1 s apart"),
            std::string::npos)
            << e.what();
    }
}

// `record --poll 1` against `hil --pty --speed 10`: the board outputs every second, the polls come every 10 s of its
// clock, give or take the recorder's scheduling (here +-10 ms). The rows' period (the lags) and the output period
// (the conversions) are both kept, and the noise before the quantiser comes back: 400 rows know the short-lag spread
// to 1/sqrt(2 * 400) = 3.5 %, 15 % is over 4 sigma. A stream log's rows are its outputs, and polled rows cannot come
// faster than the outputs (a poll between two repeats a row): both still refused.
TEST(Calibrate, PolledRowsSlowerThanTheOutputsKeepBothPeriods) {
    GapModel m = testing::paper_gyro_model(25);
    m.smoothing = {10.0, 25, 25, 0, 10.0};
    LogData log = testing::gyro_log(m, 400, {}, 9);
    for (std::size_t k = 0; k < log.size(); ++k) log.t_s[k] += 0.01 * std::sin(1.7 * static_cast<double>(k));
    log.metadata.set("sample_period_s", 1.0);
    log.metadata.set("mode", "poll");
    const Smoothing s = smoothing_from_log(log);
    EXPECT_NEAR(s.sample_period_s, 10.0, 0.02);
    EXPECT_NEAR(s.output_period_s(), 1.0, 1e-12);
    EXPECT_NEAR(s.conversion_period_s(), 0.04, 1e-14);
    const GapModel base = calibrate_base(log, sim::paper_model(), {true, false, false, false}, 1);
    EXPECT_NEAR(base.base[0].sigma_n_counts / 1.05, 1.0, 0.15);

    log.metadata.set("mode", "stream");
    EXPECT_THROW(smoothing_from_log(log), DataError);
    log.metadata.set("mode", "poll");
    log.metadata.set("sample_period_s", 100.0);
    try {
        smoothing_from_log(log);
        FAIL() << "polled rows faster than the outputs accepted";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("polled rows cannot come faster than the outputs"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace driftlab::host::gap
