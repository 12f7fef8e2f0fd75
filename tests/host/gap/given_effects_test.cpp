// The model file's own effects in the base (`gap --model` with effects): a Gaussian process is held at the file's
// values, simulated and in every spectrum fitted on its channel, and no candidate of it is tried there; a mean shape
// is refitted to the log with eq. 1, as eq. 1 itself is; what the file gives channels not analysed, and effects the
// diagnosis does not fit, are kept as the file gives them.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "gap_fixtures.hpp"
#include "host/gap/candidates.hpp"
#include "host/gap/diagnose.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"

namespace driftlab::host::gap {
namespace {

GapOptions options() { return testing::small_options(); }

// A Gauss-Markov process of 0.15 deg/s (about 0.8 counts, twice the output's white deviation) and 30 s on the gyro.
constexpr double kSigma = 0.15, kTau = 30.0;

sim::EffectSpec process_on_gyro_and_accel_x(const GapModel& m) {
    sim::EffectSpec spec = make_candidate_effect("gauss_markov", Channel::gyro, {kSigma, kTau}, m);
    spec.table.insert_or_assign("sigma_g", toml::array{0.001, 0.0, 0.0});  // accel_x: not varying in these logs
    return spec;
}

TEST(GivenEffects, AModelsProcessIsHeldAtItsValuesAndExplainsTheLogItMade) {
    const GapModel m = testing::paper_gyro_model(8);
    GapModel truth = m;
    truth.effects.push_back(make_candidate_effect("gauss_markov", Channel::gyro, {kSigma, kTau}, m));
    sim::SimModel unit = sim::paper_model();
    unit.effects.push_back(process_on_gyro_and_accel_x(m));
    int none = 0;
    for (std::uint64_t seed : {31, 32, 33}) {
        const LogData log = testing::gyro_log(truth, 1500, {}, seed);
        // The base alone lacks the process: its cells are located.
        EXPECT_FALSE(diagnose(log, sim::paper_model(), options()).located.empty()) << "seed " << seed;
        const GapResult r = diagnose(log, unit, options());
        none += r.verdict == "none";
        ASSERT_EQ(r.given.held.size(), 1u);
        EXPECT_EQ(r.given.held[0].effect, "gauss_markov");
        EXPECT_EQ(r.given.held[0].channel, "gyro");
        EXPECT_EQ(r.given.held[0].params,
                  (std::vector<std::pair<std::string, double>>{{"sigma_dps", kSigma}, {"tau_s", kTau}}));
        EXPECT_TRUE(r.given.refitted.empty());
        EXPECT_EQ(r.given.kept, std::vector<std::string>{"gauss_markov"}) << "what it gives accel_x, not analysed";
        ASSERT_EQ(r.base.held[0].gauss_markov.size(), 1u);
        EXPECT_DOUBLE_EQ(r.base.held[0].gauss_markov[0].variance_counts2,
                         std::pow(kSigma * counts_per_unit(m, Channel::gyro), 2));
        EXPECT_TRUE(r.base.held[1].gauss_markov.empty());
        // Simulated as the file gives it, on every channel.
        ASSERT_EQ(r.base.effects.size(), 1u);
        EXPECT_EQ(r.base.effects[0].table, unit.effects[0].table);
        // The white noise is matched with the process in place: near the planted 1.05 counts.
        EXPECT_NEAR(r.base.base[0].sigma_n_counts, 1.05, 0.12) << "seed " << seed;  // 4 x 0.03 on 1200 outputs
    }
    // Each log of the model itself is flagged with family-wise probability about 5 %.
    EXPECT_GE(none, 2);
}

// A thermal cycle beside the process: the model that states both refits the cycle to this log (its phase is the
// power-on's, not the file's) and explains the log; the model that states only the process has the cycle found.
// A Gauss-Markov candidate on the gyro is only ever fitted in place of the model's, never beside it (both would
// draw the same numbers).
TEST(GivenEffects, AModelsCycleIsRefittedToTheLogAndAMissingOneIsFoundBesideAHeldProcess) {
    const GapModel m = testing::paper_gyro_model(8);
    const double amplitude = 0.4, period = 250.0, phase = 1.0;
    GapModel truth = m;
    truth.effects.push_back(make_candidate_effect("gauss_markov", Channel::gyro, {kSigma, kTau}, m));
    truth.effects.push_back(make_candidate_effect("ambient_cycle", Channel::gyro, {amplitude, period, phase}, m));
    const LogData log = testing::gyro_log(truth, 1500, {}, 41);

    sim::SimModel both = sim::paper_model();
    both.effects.push_back(process_on_gyro_and_accel_x(m));
    both.effects.push_back(make_candidate_effect("ambient_cycle", Channel::gyro, {0.2, 240.0, 0.0}, m));
    const GapResult r = diagnose(log, both, options());
    EXPECT_EQ(r.verdict, "none") << view::gap_to_json(r, options()).dump();
    ASSERT_EQ(r.given.refitted.size(), 1u);
    const Explanation& cycle = r.given.refitted[0];
    EXPECT_EQ(cycle.effect, "ambient_cycle");
    EXPECT_NEAR(cycle.params[0].second / amplitude, 1.0, 0.15);
    EXPECT_NEAR(cycle.params[1].second / period, 1.0, 0.05);
    EXPECT_NEAR(std::remainder(cycle.params[2].second - phase, 2.0 * std::numbers::pi), 0.0, 0.25);
    // The refitted cycle is the last of the base's effects, in the candidate's form.
    ASSERT_EQ(r.base.effects.size(), 2u);
    EXPECT_EQ(r.base.effects[1].name, "ambient_cycle");
    EXPECT_DOUBLE_EQ(r.base.effects[1].table["period_s"].value_or(0.0), cycle.params[1].second);
    const std::string said = view::given_effects_sentence(r.given);
    EXPECT_NE(said.find("refitted to this log: ambient_cycle on gyro"), std::string::npos) << said;
    EXPECT_NE(said.find("held at the model's values: gauss_markov on gyro sigma_dps=0.15 tau_s=30"), std::string::npos)
        << said;
    const auto j = view::gap_to_json(r, options());
    EXPECT_EQ(j["given"]["refitted"][0]["effect"], "ambient_cycle");
    EXPECT_EQ(j["given"]["held"][0]["params"]["tau_s"], kTau);
    EXPECT_EQ(j["given"]["kept"], nlohmann::json::array({"gauss_markov"}));

    sim::SimModel process_only = sim::paper_model();
    process_only.effects.push_back(process_on_gyro_and_accel_x(m));
    const GapResult found = diagnose(log, process_only, options());
    EXPECT_EQ(found.verdict, "ambient_cycle");
    ASSERT_FALSE(found.tried.empty());
    for (const Explanation& e : found.tried)
        EXPECT_EQ(e.replaces_given, e.effect == "gauss_markov" && e.channel == "gyro") << e.effect;
    EXPECT_FALSE(found.accepted.front().replaces_given);
    EXPECT_NEAR(found.accepted.front().params[1].second / period, 1.0, 0.05);
}

// Where the log's process is not the model's, the gap names it: the candidate of its name is fitted in place of
// the model's (three times stronger than the file states, and a third as strong) and comes back near the log's own
// (within a factor 1.5: 0.11 deg/s for 0.15), the held-out gap falling at least fivefold;
// the file's process is then zeroed on the gyro and kept for accel_x, the fitted one added.
TEST(GivenEffects, AHeldProcessTheLogDisagreesWithIsRefittedInItsPlaceAndNamed) {
    const GapModel m = testing::paper_gyro_model(8);
    std::vector<std::vector<std::pair<std::string, double>>> after;
    for (const double stated : {kSigma / 3.0, kSigma * 3.0}) {
        GapModel truth = m;
        truth.effects.push_back(make_candidate_effect("gauss_markov", Channel::gyro, {kSigma, kTau}, m));
        sim::SimModel unit = sim::paper_model();
        unit.effects.push_back(make_candidate_effect("gauss_markov", Channel::gyro, {stated, kTau}, m));
        unit.effects[0].table.insert_or_assign("sigma_g", toml::array{0.001, 0.0, 0.0});
        const GapResult r = diagnose(testing::gyro_log(truth, 1500, {}, 51), unit, options());
        EXPECT_EQ(r.verdict, "gauss_markov") << "stated " << stated;
        ASSERT_FALSE(r.accepted.empty());
        const Explanation& e = r.accepted.front();
        EXPECT_TRUE(e.replaces_given);
        EXPECT_NEAR(std::log(e.params[0].second / kSigma), 0.0, std::log(1.5)) << "stated " << stated;
        EXPECT_TRUE(r.final_model.held[0].gauss_markov.empty()) << "the model's process is off the gyro";
        ASSERT_EQ(r.final_model.effects.size(), 2u);
        EXPECT_EQ(r.final_model.effects[0].table["sigma_dps"].value_or(-1.0), 0.0);
        EXPECT_EQ(r.final_model.effects[0].table["sigma_g"][0].value_or(0.0), 0.001);
        EXPECT_EQ(r.final_model.effects[1].name, "gauss_markov");
        EXPECT_LT(r.gap_after_heldout, r.gap_before_heldout / 5.0) << "stated " << stated;
        after.push_back(e.params);
        EXPECT_TRUE(view::gap_to_json(r, options())["explanations"][0]["replaces_model"].get<bool>());
    }
    // What replaces the model's process is fitted to the log alone: whatever the file stated, the same.
    ASSERT_EQ(after.size(), 2u);
    EXPECT_EQ(after[0], after[1]);
}

// Effects the diagnosis does not fit are kept as the file gives them, and a kept spikes is not tried again.
TEST(GivenEffects, EffectsTheDiagnosisDoesNotFitAreKeptAsTheFileGivesThem) {
    const GapModel m = testing::paper_gyro_model(8);
    sim::SimModel unit = sim::paper_model();
    sim::EffectSpec tempco{"temp_scale_factor", {}};
    tempco.table.insert_or_assign("scale_pct_per_k", 0.1);
    sim::EffectSpec spikes{"spikes", {}};
    spikes.table.insert_or_assign("rate_hz", 0.002);
    spikes.table.insert_or_assign("scale_counts", 40.0);
    unit.effects = {tempco, spikes};
    // A cycle the model lacks, so that candidates are tried.
    GapModel truth = m;
    truth.effects.push_back(make_candidate_effect("ambient_cycle", Channel::gyro, {0.4, 250.0, 1.0}, m));
    truth.effects.push_back(spikes);
    const GapResult r = diagnose(testing::gyro_log(truth, 1500, {}, 43), unit, options());
    EXPECT_EQ(r.given.kept, (std::vector<std::string>{"temp_scale_factor", "spikes"}));
    EXPECT_TRUE(r.given.refitted.empty() && r.given.held.empty());
    ASSERT_GE(r.final_model.effects.size(), 2u);
    EXPECT_EQ(r.final_model.effects[0].table, tempco.table);
    EXPECT_EQ(r.final_model.effects[1].table, spikes.table);
    EXPECT_EQ(r.verdict, "ambient_cycle");
    EXPECT_TRUE(
        std::none_of(r.tried.begin(), r.tried.end(), [](const Explanation& e) { return e.effect == "spikes"; }));
}

}  // namespace
}  // namespace driftlab::host::gap
