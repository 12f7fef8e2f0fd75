// End to end on small simulated logs: a clean log gives "none", a planted second time constant is located,
// attributed and shrunk, a smaller one leaves a diffuse gap that is searched on request, and the JSON and the
// report carry what the diagnosis found.
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/fit/drift_analysis.hpp"
#include "host/gap/calibrate.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap_eval/truth.hpp"
#include "host/util/error.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {
namespace {

using testing::small_options;

// Each clean log is flagged with family-wise probability alpha = 5 %, so of five at most one may be (probability of
// two or more: 2.3 %); those not flagged get the verdict none and a gap score near 1. The score is a mean of
// strongly correlated z^2 (neighbouring octaves move together), so one log may reach 2.5 (200 clean logs: mean
// 0.99, 99th percentile 2.2); their mean stays near 1.
TEST(Diagnose, CleanLogsHaveNoLocatedCellsAndVerdictNone) {
    const GapModel m = testing::paper_gyro_model(8);
    GapOptions o = small_options();
    o.explain = false;
    int flagged = 0;
    double gap_sum = 0.0;
    for (std::uint64_t seed : {77, 78, 79, 80, 81}) {
        const GapResult r = diagnose(testing::gyro_log(m, 1200, {}, seed), sim::paper_model(), o);
        EXPECT_TRUE(r.channels[0]);
        EXPECT_FALSE(r.channels[1]);
        if (!r.located.empty()) {
            ++flagged;
            continue;
        }
        EXPECT_EQ(r.verdict, "none");
        EXPECT_NE(view::verdict_reason(r, o).find("explains the log"), std::string::npos) << view::verdict_reason(r, o);
        EXPECT_LT(r.gap_before_fit, 3.0) << "seed " << seed;
        gap_sum += r.gap_before_fit;
        // Calibration recovers the planted base: eq. 1 (T's Fisher standard error on 1200 outputs is about 19 s) and
        // the white noise before the quantiser (about 0.03 counts here; Calibrate.* checks it sharply on long logs): 4
        // sigma.
        EXPECT_NEAR(r.base.base[0].drift.tau_s, 411.0, 75.0) << "seed " << seed;
        EXPECT_NEAR(r.base.base[0].sigma_n_counts, 1.05, 0.12) << "seed " << seed;
    }
    EXPECT_LE(flagged, 1);
    EXPECT_LT(gap_sum / (5 - flagged), 1.8);
}

// A channel that varies without noise (here a straight ramp of a twentieth of a count per output) needs no white noise
// beyond the converter's, so its replicates are the same for every seed and every z would divide by the floor: it is
// left out and named, and the noisy gyro beside it is diagnosed as without it.
TEST(Diagnose, AChannelWithoutNoiseIsLeftOutAndNamed) {
    const GapModel m = testing::paper_gyro_model(8);
    GapOptions o = small_options();
    o.explain = false;
    LogData log = testing::gyro_log(m, 600, {}, 77);
    for (std::size_t k = 0; k < log.size(); ++k) log.counts[1][k] = 400.0 + 0.05 * static_cast<double>(k);
    log.recorded[1] = true;
    const GapResult r = diagnose(log, sim::paper_model(), o);
    EXPECT_TRUE(r.channels[0]);
    EXPECT_FALSE(r.channels[1]);
    ASSERT_EQ(r.noise_free.size(), 1u);
    EXPECT_EQ(r.noise_free[0].channel, Channel::accel_x);
    EXPECT_LT(r.noise_free[0].spread_counts, 1e-3);
    EXPECT_EQ(r.verdict, "none");
    for (const Cell& c : r.layout) EXPECT_EQ(c.channel.find("accel_x"), std::string::npos) << c.channel;
    EXPECT_NE(view::noise_free_sentence(r).find("accel_x with a short-lag spread of "), std::string::npos)
        << view::noise_free_sentence(r);
    // A noisy channel is never taken for one: the gyro with its noise at a tenth of a count is still analysed.
    GapModel quiet = m;
    quiet.base[0].sigma_n_counts = 0.1;
    const GapResult q = diagnose(testing::gyro_log(quiet, 600, {}, 78), sim::paper_model(), o);
    EXPECT_TRUE(q.channels[0]);
    EXPECT_TRUE(q.noise_free.empty());
    // Alone, it leaves nothing to compare: refused naming the log.
    GapOptions accel = o;
    accel.channels = {false, true, false, false};
    try {
        diagnose(log, sim::paper_model(), accel);
        FAIL() << "no error";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "test.csv: no selected channel has noise to compare (accel_x with a short-lag spread of "),
                  std::string::npos)
            << e.what();
    }
    // A stuck channel with one corrupt row (512 in every row but one 1023) is left out alike, and its row still named:
    // lone values are looked for before channels are left out (GapCli.AStuckChannelWithACorruptRowOrTwoIsLeftOut takes
    // a log whose calibration gives such a channel a little noise).
    for (std::size_t k = 0; k < log.size(); ++k) log.counts[1][k] = k == 300 ? 1023.0 : 512.0;
    const GapResult stuck = diagnose(log, sim::paper_model(), o);
    ASSERT_EQ(stuck.noise_free.size(), 1u);
    EXPECT_EQ(stuck.noise_free[0].channel, Channel::accel_x);
    ASSERT_EQ(stuck.lone_values.size(), 1u);
    EXPECT_EQ(stuck.lone_values[0].channel, Channel::accel_x);
    EXPECT_EQ(stuck.lone_values[0].t_s, std::vector<double>{log.t_s[300]});
    EXPECT_EQ(stuck.verdict, "none");
}

// A raw-mode log sends a SAMPLE and a RAW frame per row, so seq steps by 2 without any loss.
TEST(Diagnose, LostFramesCountTheFramesPerRow) {
    GapOptions o = small_options();
    o.explain = false;
    LogData log = testing::gyro_log(testing::paper_gyro_model(8), 1200, {}, 77);
    EXPECT_EQ(diagnose(log, sim::paper_model(), o).timing.lost_frames, 0u);
    log.seq[600] += 1;  // one lost frame before row 600, the numbering after it shifted in the real log too
    for (std::size_t k = 601; k < log.size(); ++k) log.seq[k] += 1;
    EXPECT_EQ(diagnose(log, sim::paper_model(), o).timing.lost_frames, 1u);
    for (std::size_t k = 0; k < log.size(); ++k) log.seq[k] = 3 + 2 * k;
    log.optional_columns["raw_gyro"] = log.counts[0];
    const GapResult raw = diagnose(log, sim::paper_model(), o);
    EXPECT_EQ(raw.timing.lost_frames, 0u);
    EXPECT_EQ(raw.timing.sequence_jumps, 0u);
    log.seq[900] += 2;  // a lost SAMPLE+RAW pair
    for (std::size_t k = 901; k < log.size(); ++k) log.seq[k] += 2;
    EXPECT_EQ(diagnose(log, sim::paper_model(), o).timing.lost_frames, 2u);
}

TEST(Diagnose, PlantedSecondTimeConstantIsAttributedAndShrinks) {
    const GapResult& r = testing::planted_second_time_constant().result;
    ASSERT_FALSE(r.located.empty());
    EXPECT_EQ(r.verdict, "thermal_second_tc");
    ASSERT_FALSE(r.accepted.empty());
    EXPECT_GT(r.accepted[0].heldout_shrink, 0.5);
    EXPECT_LT(r.gap_after_heldout, r.gap_before_heldout);
    // A rise is no pair of steps: the shape describes the log better than a hop and a return would.
    ASSERT_TRUE(r.accepted[0].shape_steps.tested);
    EXPECT_FALSE(r.accepted[0].shape_steps.steps_win);

    const auto j = view::gap_to_json(r, small_options());
    // The keys --help lists are the JSON's, no more and no fewer (the issue's own among them).
    std::set<std::string> listed(view::kGapJsonKeys.begin(), view::kGapJsonKeys.end()), present;
    for (const auto& [key, value] : j.items()) present.insert(key);
    EXPECT_EQ(present, listed);
    EXPECT_EQ(listed.size(), view::kGapJsonKeys.size()) << "a key listed twice";
    for (const char* key : {"verdict", "explanations", "located", "gap_before", "gap_after", "not_identifiable"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["holdout"], "interleaved");
    EXPECT_EQ(j["replicates"], small_options().replicates);
    const auto& e = j["explanations"][0];
    for (const char* key : {"effect", "params", "gap_before", "gap_after", "heldout_shrink"})
        EXPECT_TRUE(e.contains(key)) << key;
    // `added` says which candidates are in the model: the added ones first, then every other tried, whether it
    // passed (`accepted`) or not.
    std::size_t added = 0;
    for (std::size_t k = 0; k < j["explanations"].size(); ++k) {
        const bool in_model = j["explanations"][k]["added"].get<bool>();
        EXPECT_EQ(in_model, k < r.accepted.size()) << k;
        if (in_model) {
            EXPECT_TRUE(j["explanations"][k]["accepted"].get<bool>()) << k;
        }
        added += in_model;
    }
    EXPECT_EQ(added, r.accepted.size());
    const auto& cell = j["located"][0];
    for (const char* key : {"statistic", "channel", "cell", "ratio", "z"}) EXPECT_TRUE(cell.contains(key)) << key;
    bool static_listed = false;
    for (const auto& n : j["not_identifiable"]) static_listed |= n["effect"] == "cross_axis";
    EXPECT_TRUE(static_listed);
}

// A thermostat's cycle over a board's slow warm-up (gap-eval's generators, not the library's forms), diagnosed as
// `driftlab gap` runs it. Where a process beats an accepted mean shape both paths are followed: the result is the
// kept path (its effect added at the branch step, the verdict its first), kept by the criterion rule, and listed in
// the JSON. Of these seeds 12 and 13 branch and keep the process's path; 18 keeps the shape's, whose criterion ends
// 84 below that of a random walk added first.
TEST(Diagnose, WhereAProcessBeatsAShapeBothPathsAreFollowedAndTheLowerCriterionKept) {
    const GapModel m = testing::paper_gyro_model(8);
    GapOptions o = small_options();
    o.explain_options.max_effects = 3;
    std::vector<double> t_s(1500);
    for (std::size_t k = 0; k < t_s.size(); ++k) t_s[k] = static_cast<double>(k + 1);
    int process_kept = 0, shape_kept = 0;
    for (std::uint64_t seed : {12, 13, 18}) {
        std::vector<double> added = truth_thermostat(t_s, 1.0, seed);
        const std::vector<double> rise = truth_thermal_rc(t_s, 3.0, seed);
        for (std::size_t k = 0; k < added.size(); ++k) added[k] += rise[k];
        const GapResult r = diagnose(testing::gyro_log(m, t_s.size(), added, seed), sim::paper_model(), o);
        const auto j = view::gap_to_json(r, o);
        ASSERT_EQ(j["paths"].size(), r.paths.size());
        for (std::size_t n = 0; n < r.paths.size(); ++n) {
            const PathChoice& p = r.paths[n];
            EXPECT_EQ(p.shape_kept, p.criterion_shape + o.explain_options.shape_path_margin < p.criterion_process);
            ++(p.shape_kept ? shape_kept : process_kept);
            const std::string& kept = p.shape_kept ? p.shape : p.process;
            ASSERT_GE(r.accepted.size(), static_cast<std::size_t>(p.step));
            EXPECT_EQ(r.accepted[static_cast<std::size_t>(p.step - 1)].effect, kept) << "seed " << seed;
            if (p.step == 1 && r.verdict != "unexplained") {
                EXPECT_EQ(r.verdict, kept);
            }
            EXPECT_EQ(j["paths"][n]["kept"], kept);
        }
    }
    EXPECT_GE(process_kept, 1);
    EXPECT_GE(shape_kept, 1);
}

// A step's candidates are fitted side by side and the replicates on a pool: on one thread the JSON is the same.
TEST(Diagnose, TheResultDoesNotDependOnTheThreadCount) {
    GapOptions one = small_options();
    one.threads = 1;
    const testing::Planted& p = testing::planted_second_time_constant();
    ASSERT_GE(p.result.tried.size(), 3u) << "several candidates, so that they did run side by side";
    EXPECT_EQ(view::gap_to_json(diagnose(p.log, sim::paper_model(), one), one).dump(),
              view::gap_to_json(p.result, small_options()).dump());
}

// A step is marked against its channel's held-out bound at the diagnosis's level (GapOptions::alpha), as the gap
// table's bound is: a higher level is a lower order statistic of the same replicates' scores, while the score itself
// does not depend on the level.
TEST(Diagnose, TheHeldOutBoundAStepIsMarkedAgainstIsAtTheDiagnosisLevel) {
    const testing::Planted& p = testing::planted_second_time_constant();
    GapOptions loose = small_options();
    loose.alpha = 0.25;
    const GapResult r = diagnose(p.log, sim::paper_model(), loose);
    ASSERT_FALSE(r.accepted.empty());
    ASSERT_FALSE(p.result.accepted.empty());
    const Explanation& at_default = p.result.accepted[0];
    const Explanation& at_loose = r.accepted[0];
    EXPECT_EQ(at_loose.effect, at_default.effect);
    EXPECT_DOUBLE_EQ(at_loose.heldout_before, at_default.heldout_before);
    EXPECT_LT(at_loose.heldout_bound, at_default.heldout_bound);
    EXPECT_LT(r.gap_bound_before, p.result.gap_bound_before);
}

TEST(Diagnose, ADiffuseGapIsReportedAndSearchedOnRequest) {
    const GapModel m = testing::paper_gyro_model(8);
    int named = 0;
    for (const auto& [size, seed] : std::vector<std::pair<double, std::uint64_t>>{{3.0, 78}, {2.5, 81}, {2.5, 82}}) {
        std::vector<double> added(1500);
        for (std::size_t k = 0; k < added.size(); ++k)
            added[k] = -size * -std::expm1(-static_cast<double>(k + 1) / 1500.0);
        const LogData log = testing::gyro_log(m, 1500, added, seed);
        GapOptions o = small_options();
        const GapResult plain = diagnose(log, sim::paper_model(), o);
        ASSERT_TRUE(plain.located.empty()) << "seed " << seed;
        ASSERT_TRUE(plain.diffuse_gap) << "seed " << seed << ": held-out " << plain.gap_before_heldout << " bound "
                                       << plain.gap_bound_before;
        EXPECT_EQ(plain.verdict, "none");
        EXPECT_TRUE(plain.tried.empty());
        EXPECT_TRUE(view::gap_to_json(plain, o)["diffuse_gap"].get<bool>());
        EXPECT_FALSE(plain.diffuse_searched);
        o.search_diffuse = true;
        if (seed == 78) {  // with --locate-only nothing is searched, and nothing says it was
            GapOptions locate = o;
            locate.explain = false;
            const GapResult only = diagnose(log, sim::paper_model(), locate);
            EXPECT_FALSE(only.diffuse_searched);
            EXPECT_EQ(only.verdict, "none");
            EXPECT_EQ(view::verdict_reason(only, locate),
                      "no cell located, but the held-out score exceeds its bound (a diffuse gap); "
                      "no candidate tried (--locate-only)");
        }
        const GapResult searched = diagnose(log, sim::paper_model(), o);
        EXPECT_FALSE(searched.tried.empty()) << "seed " << seed;
        EXPECT_TRUE(searched.diffuse_searched);
        named += searched.verdict == "thermal_second_tc";
        if (searched.verdict == "thermal_second_tc") {
            EXPECT_LT(searched.gap_after_heldout, searched.gap_before_heldout) << "seed " << seed;
        }
    }
    EXPECT_GE(named, 2);
}

// Two channels share a white disturbance, one 3 outputs after the other. Each channel's own statistics see only
// white noise, which calibration absorbs, and the lag-0 correlation is nil; the band coherence of the pair is what
// locates it, in the bands narrow enough for the lag not to turn the phase across them.
TEST(Diagnose, ADisturbanceSharedAtALagIsLocatedByBandCoherence) {
    const GapModel m = testing::paper_gyro_model(8);
    LogData log = testing::gyro_log(m, 1500, {}, 91);
    log.counts[1] = testing::gyro_log(m, 1500, {}, 92).counts[0];
    constexpr std::size_t kLag = 3;
    const auto shared = testing::white(1500 + kLag, 0.5, 93);
    const auto q8 = [](double v) { return std::round(v * 256.0) / 256.0; };  // the firmware's output grid
    for (std::size_t k = 0; k < 1500; ++k) {
        log.counts[0][k] += q8(shared[k + kLag]);
        log.counts[1][k] += q8(shared[k]);
    }
    GapOptions o = small_options();
    o.explain = false;
    const GapResult r = diagnose(log, sim::paper_model(), o);
    ASSERT_TRUE(r.channels[0] && r.channels[1]);
    int coherence = 0;
    for (const auto& l : r.located) {
        const Cell& c = r.layout[l.index];
        EXPECT_EQ(c.channel, "gyro~accel_x") << c.statistic << " " << c.cell;
        EXPECT_NE(c.statistic, "corr") << c.cell;
        coherence += c.statistic == "coh";
    }
    EXPECT_GE(coherence, 1);
}

TEST(Diagnose, ShortLogIsADataErrorNamingTheFile) {
    const GapModel m = testing::paper_gyro_model(4);
    const LogData log = testing::gyro_log(m, 50, {}, 1);
    try {
        diagnose(log, sim::paper_model(), small_options());
        FAIL() << "expected DataError";
    } catch (const DataError& e) {
        EXPECT_NE(std::string(e.what()).find("test.csv"), std::string::npos);
    }
}

TEST(Diagnose, BadSmoothingMetadataIsADataError) {
    const GapModel m = testing::paper_gyro_model(4);
    LogData log = testing::gyro_log(m, 300, {}, 1);
    log.metadata.set("window", static_cast<std::int64_t>(99));
    EXPECT_THROW(smoothing_from_log(log), DataError);
}

}  // namespace
}  // namespace driftlab::host::gap
