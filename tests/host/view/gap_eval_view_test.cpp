// The gap-eval run's scores as its views render them (host/view/gap_eval_view.hpp): counted from known decisions.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "host/gap_eval/eval_scores.hpp"
#include "host/view/gap_eval_view.hpp"

namespace driftlab::host::gap {
namespace {

TEST(GapEvalView, ScoresCountTheScoringDecisions) {
    Explanation flicker;
    flicker.effect = "flicker";
    flicker.gaussian = true;
    flicker.loss_gain = 100.0, flicker.penalty = 10.0, flicker.heldout_before = 3.0, flicker.heldout_after = 1.2;
    flicker.heldout_shrink = 0.9, flicker.heldout_loss_gain = 50.0;
    auto make = [&](const std::string& generator, const std::string& truth, double level, bool detected, bool tune) {
        EvalCase c;
        c.generator = generator, c.truth = truth, c.level = level, c.detected = detected, c.tune = tune;
        if (detected) c.tried = {flicker};
        return c;
    };
    const std::vector<EvalCase> cases{make("none", "none", 0.0, false, false),
                                      make("none", "none", 0.0, true, false),  // one false positive
                                      make("none", "none", 0.0, false, false),
                                      make("none", "none", 0.0, true, true),  // tuning: not scored
                                      make("kasdin_flicker", "flicker", 2.0, true, false),
                                      make("kasdin_flicker", "flicker", 2.0, false, false),
                                      make("mode_hop", "", 2.0, true, false)};  // out of library, attributed: wrong
    EvalOptions o;
    const EvalScores s = score(cases, Thresholds{1.0, 0.3, 0.05, InformationCriterion::bic}, o, {});
    EXPECT_EQ(s.clean, 3u);
    EXPECT_EQ(s.clean_flagged, 1u);
    EXPECT_LT(s.fpr_low, 1.0 / 3.0);
    EXPECT_GT(s.fpr_high, 1.0 / 3.0);
    ASSERT_EQ(s.by_size.size(), 3u);  // none, kasdin_flicker and mode_hop, one size each
    const SizeScore& f = s.by_size[1];
    EXPECT_EQ(f.generator, "kasdin_flicker");
    EXPECT_EQ(f.logs, 2);
    EXPECT_EQ(f.detected, 1);
    EXPECT_EQ(f.top1, 1);
    EXPECT_NEAR(*f.predicted, 0.9, 1e-12);
    EXPECT_EQ(s.by_size[2].top1, 0);
    const auto j = view::scores_json(s);
    for (const char* key : {"thresholds", "a50", "false_positive", "confusion", "by_size"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["confusion"]["mode_hop"]["flicker"], 1);
    EXPECT_EQ(j["by_size"][1]["top1"], 1);
    EXPECT_NE(view::scores_markdown(s).find("| kasdin_flicker | 2 | 2 | 1 | 1 | 1 |"), std::string::npos);
    // A size the search reached twice (0.4 and 0.4000000000000001) is one entry of both batches in the table.
    const DetectionSize twice{"thermal_rc", 0.26, {{0.2, 0, 4}, {0.2, 1, 4}, {0.4, 4, 4}, {0.4000000000000001, 4, 4}}};
    const std::string md =
        view::scores_markdown(score(cases, Thresholds{1.0, 0.3, 0.05, InformationCriterion::bic}, o, {twice}));
    EXPECT_NE(md.find("| thermal_rc | 0.26 | 0.20: 1/8; 0.40: 8/8 |"), std::string::npos) << md;

    // The targets, read at 2 x a_50 with exact intervals: the false-positive rate 1/3 (Clopper-Pearson 0.8-90.6 %),
    // flicker's top-1 1/2 and the mode hop attributed 1/1; none met, none settled by so few logs.
    ASSERT_EQ(s.targets.size(), 3u);
    EXPECT_EQ(s.targets[0].count, 1u);
    EXPECT_EQ(s.targets[0].logs, 3u);
    EXPECT_NEAR(s.targets[0].low, 0.0084, 1e-4);
    EXPECT_NEAR(s.targets[0].high, 0.9057, 1e-4);
    EXPECT_TRUE(s.targets[0].at_most);
    EXPECT_FALSE(s.targets[0].met);
    EXPECT_FALSE(s.targets[0].settled);
    EXPECT_EQ(s.targets[1].target, "top-1: kasdin_flicker -> flicker at 2 x a_50");
    EXPECT_DOUBLE_EQ(s.targets[1].rate, 0.5);
    EXPECT_FALSE(s.targets[1].at_most);
    EXPECT_FALSE(s.targets[1].met);
    EXPECT_DOUBLE_EQ(s.targets[2].rate, 1.0);
    EXPECT_FALSE(s.targets[2].met);
    EXPECT_EQ(j["targets"].size(), 3u);
    EXPECT_NE(view::scores_markdown(s).find("| top-1: kasdin_flicker -> flicker at 2 x a_50 | 1 / 2 | 50.0 % |"),
              std::string::npos);

    // 100 clean logs, none flagged: the interval (0-3.6 %) lies below 5 %, so the target is met and settled; the
    // mode hop now at two sizes also gets its all-sizes row (1 of 2 attributed).
    std::vector<EvalCase> more(100, make("none", "none", 0.0, false, false));
    more.push_back(make("mode_hop", "", 2.0, true, false));
    more.push_back(make("mode_hop", "", 1.0, false, false));
    const EvalScores t = score(more, Thresholds{1.0, 0.3, 0.05, InformationCriterion::bic}, o, {});
    ASSERT_EQ(t.targets.size(), 3u);
    EXPECT_TRUE(t.targets[0].met);
    EXPECT_TRUE(t.targets[0].settled);
    EXPECT_NEAR(t.targets[0].high, 1.0 - std::pow(0.025, 1.0 / 100.0), 1e-9);  // k = 0: 1 - (alpha/2)^(1/n)
    EXPECT_EQ(t.targets[2].target, "attributed: mode_hop (out of library), all sizes");
    EXPECT_EQ(t.targets[2].count, 1u);
    EXPECT_EQ(t.targets[2].logs, 2u);
}

// --clean-only: the false-positive rate of the shipped thresholds on many seeds, with no tuning logs and no a_50.
TEST(GapEvalView, ACleanOnlyRunScoresTheShippedThresholdsOnCleanLogsAlone) {
    EvalOptions o;
    o.tune = false;
    o.levels.clear();
    o.score_first = 21;
    o.score_last = 22;
    o.clean_per_seed = 3;
    o.samples = 800;
    o.replicates = 16;
    const auto cases = run_cases(o, {});
    ASSERT_EQ(cases.size(), 6u);
    for (const auto& c : cases) {
        EXPECT_FALSE(c.tune);
        EXPECT_EQ(c.generator, "none");
    }
    // The same scoring logs as a run that tunes first: the same seeds, so the same verdict on each.
    EvalOptions tuned = o;
    tuned.tune = true;
    std::vector<EvalCase> scored;
    for (const auto& c : run_cases(tuned, {}))
        if (!c.tune) scored.push_back(c);
    ASSERT_EQ(scored.size(), cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
        EXPECT_EQ(scored[k].seed, cases[k].seed);
        EXPECT_EQ(scored[k].detected, cases[k].detected);
    }
    const EvalScores s = score(cases, Thresholds{}, o, {});
    EXPECT_EQ(s.clean, 6u);
    EXPECT_NE(view::scores_markdown(s).find("Thresholds as `driftlab gap` ships them (not tuned)"), std::string::npos);
    EXPECT_TRUE(view::scores_json(s)["tune_seeds"].is_null());
}

TEST(GapEvalView, TwoEffectLogsAreScoredAsSetsOfEffects) {
    auto make = [](std::vector<std::string> added, std::vector<std::string> close, std::vector<bool> within,
                   std::string verdict, double before, double after) {
        PairCase c;
        c.first = "thermostat", c.second = "kasdin_flicker", c.level = 2.0, c.detected = true;
        c.added = std::move(added), c.close_calls = std::move(close), c.within_bound = std::move(within);
        c.verdict = std::move(verdict);
        c.heldout_before = before, c.heldout_after = after;
        return c;
    };
    const std::vector<PairCase> cases{
        make({"ambient_cycle", "flicker"}, {"", ""}, {false, false}, "ambient_cycle", 11.0, 2.0),  // both: shrink 0.9
        make({"gauss_markov", "ambient_cycle"}, {"flicker", ""}, {false, true}, "gauss_markov", 5.0,
             1.0),                                               // one, one by close call
        make({"flicker"}, {""}, {false}, "flicker", 21.0, 1.0),  // one of two
        make({"ambient_cycle", "flicker", "spikes"}, {"", "", ""}, {false, false, true}, "ambient_cycle", 3.0,
             2.0),  // both, one wrong: 0.5
        make({}, {}, {}, "unexplained", 4.0, 4.0)};
    const EvalScores s = score({}, Thresholds{}, EvalOptions{}, {}, cases);
    ASSERT_EQ(s.pairs.size(), 1u);
    const PairScore& z = s.pairs.front();
    EXPECT_EQ(z.first_effect, "ambient_cycle");
    EXPECT_EQ(z.second_effect, "flicker");
    EXPECT_EQ(z.logs, 5);
    EXPECT_EQ(z.verdict_one, 3);
    EXPECT_EQ(z.all, 2);
    EXPECT_EQ(z.truths, 10);
    EXPECT_EQ(z.wrong, 2);  // gauss_markov, spikes
    EXPECT_EQ(z.unexplained, 1);
    EXPECT_EQ(z.added, 8);
    EXPECT_EQ(z.found, 6);
    EXPECT_EQ(z.found_or_pair, 7);
    EXPECT_EQ(z.within_bound_added, 2);  // ambient_cycle (true) and spikes (wrong)
    EXPECT_EQ(z.within_bound_true, 1);
    EXPECT_DOUBLE_EQ(z.precision, 6.0 / 8.0);
    EXPECT_DOUBLE_EQ(z.recall, 6.0 / 10.0);
    EXPECT_DOUBLE_EQ(z.recall_or_pair, 7.0 / 10.0);
    EXPECT_NEAR(z.f1, 2.0 * 0.75 * 0.6 / 1.35, 1e-12);
    ASSERT_TRUE(z.shrink.has_value());
    EXPECT_DOUBLE_EQ(*z.shrink, 0.9);  // the upper median of {0.9, 0.5}, as the single-effect table takes it
    const auto j = view::scores_json(s);
    ASSERT_EQ(j["pairs"].size(), 1u);
    EXPECT_EQ(j["pairs"][0]["found_or_pair"], 7);
    EXPECT_EQ(j["pairs"][0]["within_bound_added"], 2);
    EXPECT_EQ(j["pairs"][0]["within_bound_true"], 1);
    EXPECT_EQ(j["pairs"][0]["effects"].size(), 2u);
    EXPECT_NEAR(j["pairs"][0]["f1"].get<double>(), z.f1, 1e-12);
    EXPECT_NE(
        view::scores_markdown(s).find("| thermostat + kasdin_flicker (ambient_cycle + flicker) | 5 | 5 | 3 | 2 | 2 | 1 "
                                      "| 0.75 | 0.60 | 0.70 | 0.67 | 1 / 2 | 0.90 |"),
        std::string::npos)
        << view::scores_markdown(s);
    EXPECT_NE(view::scores_markdown(s).find("within its bound: 1 of 2 true; the others: 5 of 6."), std::string::npos)
        << view::scores_markdown(s);

    // A generator planted alone ("none" second) has one truth effect: an extra effect beside it costs precision only.
    std::vector<PairCase> alone(2, make({"flicker", "gauss_markov"}, {"", ""}, {false, true}, "flicker", 5.0, 1.0));
    for (auto& c : alone) c.first = "kasdin_flicker", c.second = "none";
    alone[1].added = {"flicker"}, alone[1].close_calls = {""}, alone[1].within_bound = {false};
    const PairScore a = score({}, Thresholds{}, EvalOptions{}, {}, alone).pairs.at(0);
    EXPECT_EQ(a.second_effect, "");
    EXPECT_EQ(a.truths, 2);
    EXPECT_EQ(a.all, 2);
    EXPECT_EQ(a.wrong, 1);
    EXPECT_DOUBLE_EQ(a.recall, 1.0);
    EXPECT_DOUBLE_EQ(a.precision, 2.0 / 3.0);
    const EvalScores sa = score({}, Thresholds{}, EvalOptions{}, {}, alone);
    EXPECT_EQ(view::scores_json(sa)["pairs"][0]["effects"], nlohmann::json::array({"flicker"}));
    EXPECT_NE(view::scores_markdown(sa).find(
                  "| kasdin_flicker alone (flicker) | 2 | 2 | 2 | 2 | 1 | 0 | 0.67 | 1.00 | 1.00 | 0.80 | 0 / 1 |"),
              std::string::npos)
        << view::scores_markdown(sa);
}

// Two strong effects planted together are diagnosed as `driftlab gap` runs (up to three effects, stepwise): every
// log is detected and given at least one of the two, and the pooled recall is well above one of two per log. Burst
// spikes beside an RC network (4 x each a_50, 1200-sample logs): the spikes' tail cells and the rise's mean cells
// are separate features.

}  // namespace
}  // namespace driftlab::host::gap
