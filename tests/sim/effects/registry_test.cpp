// The registry: the sixteen names and stages, identity by default, TOML round trip, and errors that name the key
// and the expected unit.
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "effect_test_support.hpp"
#include "sim/effects/gauss_markov.hpp"
#include "sim/effects/vibration.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {
namespace {

// The effect list of the simulator's specification, with the stage each belongs to.
const std::map<std::string, Stage> kExpected = {
    {"thermal_second_tc", Stage::physical}, {"ambient_cycle", Stage::physical},
    {"temp_scale_factor", Stage::physical}, {"flicker", Stage::physical},
    {"rate_random_walk", Stage::physical},  {"gauss_markov", Stage::physical},
    {"adc_dnl", Stage::converter},          {"adc_inl", Stage::converter},
    {"supply_coupling", Stage::analog},     {"cross_axis", Stage::physical},
    {"g_sensitivity", Stage::physical},     {"vibration", Stage::physical},
    {"mains_alias", Stage::analog},         {"clock_jitter", Stage::timing},
    {"saturation", Stage::physical},        {"spikes", Stage::converter},
    {"scale_factor", Stage::physical},      {"bandwidth", Stage::physical},
};

std::string text_of(const toml::node& node) {
    std::ostringstream os;
    node.visit([&](const auto& n) { os << n; });
    return os.str();
}

std::string error_of(std::string_view name, std::string_view text) {
    try {
        test::effect_from(name, text);
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "";
}

TEST(EffectRegistry, ListsExactlyTheSixteenEffectsWithTheirStages) {
    const auto& list = list_effects();
    ASSERT_EQ(list.size(), kExpected.size());
    std::set<std::string> seen;
    for (const EffectInfo& info : list) {
        ASSERT_TRUE(kExpected.count(info.name)) << info.name;
        EXPECT_TRUE(seen.insert(info.name).second) << "duplicate " << info.name;
        EXPECT_EQ(info.stage, kExpected.at(info.name)) << info.name;
        EXPECT_TRUE(is_effect_name(info.name));
        const auto e = make_effect(info.name);
        EXPECT_EQ(e->name(), info.name);
        EXPECT_EQ(e->stage(), info.stage);
        EXPECT_FALSE(info.equation.empty());
        for (const ParamInfo& p : info.params) EXPECT_FALSE(p.doc.empty()) << info.name << "." << p.key;
    }
    EXPECT_FALSE(is_effect_name("turn_on_bias"));
}

TEST(EffectRegistry, EveryEffectIsIdentityByDefault) {
    Rng rng(17, 0);
    for (const EffectInfo& info : list_effects()) {
        const auto e = make_effect(info.name);
        e->reset(3);
        for (int k = 0; k < 200; ++k) {
            EffectContext ctx;
            ctx.t_s = 0.37 * k;
            ctx.dt_s = k == 0 ? 0.0 : 0.37;
            ctx.temperature_degc = 20.0 + 10.0 * rng.uniform();
            ctx.supply_v = 4.9 + 0.2 * rng.uniform();
            ctx.true_physical = {rng.normal(), rng.normal(), rng.normal(), 1.0 + rng.normal()};
            if (k % 2 == 1) ctx.channel = static_cast<Channel>(k % 4);
            const ChannelValues in = {100 * rng.normal(), 512 + 50 * rng.normal(), 2.5 + rng.normal(), rng.uniform()};
            ChannelValues v = in;
            e->apply(v, ctx);
            EXPECT_EQ(v, in) << info.name;
            EXPECT_EQ(e->actual_instant_s(ctx.t_s, ctx), ctx.t_s) << info.name;
        }
    }
}

// The chain takes its temperature from the first effect that models one, told by a NaN at one instant
// (sensor_model.cpp): only ambient_cycle models it, at every t (25 degC with its default zero swing), the others
// at none.
TEST(EffectRegistry, OnlyAmbientCycleModelsTheTemperature) {
    for (const EffectInfo& info : list_effects()) {
        const auto e = make_effect(info.name);
        for (const double t : {0.0, 1.3, 600.0, 1e6}) {
            if (info.name == "ambient_cycle")
                EXPECT_EQ(e->temperature_degc(t), 25.0) << t;
            else
                EXPECT_TRUE(std::isnan(e->temperature_degc(t))) << info.name << " at " << t;
        }
    }
}

TEST(EffectRegistry, TomlRoundTripKeepsEveryParameter) {
    ASSERT_EQ(test::kEffectExamples.size(), kExpected.size());
    for (const auto& [name, text] : test::kEffectExamples) {
        const auto first = test::effect_from(name, text);
        const toml::table written = first->parameters();
        const auto second = make_effect(name, written, name);
        EXPECT_EQ(second->parameters(), written) << name;
        // Every key given in the example comes back with the same value.
        const toml::table given = toml::parse(text);
        for (const auto& [key, node] : given) {
            ASSERT_TRUE(written.contains(key.str())) << name << "." << key.str();
            if (node.is_array() || node.is_string() || node.is_boolean()) {
                EXPECT_EQ(text_of(*written.get(key.str())), text_of(node)) << name << "." << key.str();
            } else if (const toml::array* a = written.get(key.str())->as_array()) {
                for (const toml::node& e : *a) EXPECT_EQ(e.value<double>(), node.value<double>()) << name;  // broadcast
            } else {
                EXPECT_EQ(written.get(key.str())->value<double>(), node.value<double>()) << name << "." << key.str();
            }
        }
        // The documented keys are exactly the written keys, so docs and config cannot disagree.
        std::set<std::string> documented, keys;
        for (const auto& info : list_effects())
            if (info.name == name)
                for (const auto& p : info.params) documented.insert(p.key);
        for (const auto& [key, node] : written) keys.insert(std::string(key.str()));
        EXPECT_EQ(documented, keys) << name;
    }
}

TEST(EffectRegistry, ParsedValuesReachTheParameterStruct) {
    const auto e = test::effect_from("gauss_markov", "sigma_dps = 0.05\nsigma_g = 0.002\ntau_s = [1, 2, 3, 4.5]");
    const auto& p = dynamic_cast<const GaussMarkov&>(*e).params();
    EXPECT_EQ(p.sigma_dps, 0.05);
    EXPECT_EQ(p.sigma_g, (std::array<double, 3>{0.002, 0.002, 0.002}));  // a scalar broadcasts
    EXPECT_EQ(p.tau_s, (ChannelValues{1.0, 2.0, 3.0, 4.5}));             // integers are accepted as numbers
    const auto v = test::effect_from("vibration", "tone_hz = [10.0, 20.0]\ntone_g_x = [0.1, 0.2]");
    EXPECT_EQ(dynamic_cast<const Vibration&>(*v).params().tone_g_x, (std::vector<double>{0.1, 0.2}));
}

TEST(EffectRegistry, UnknownKeyNamesTheKeyAndSuggestsTheUnit) {
    const std::string wrong_unit = error_of("gauss_markov", "sigma_dps = 0.1\ntau_ms = 100.0");
    EXPECT_NE(wrong_unit.find("line 2: effects.gauss_markov.tau_ms"), std::string::npos) << wrong_unit;
    EXPECT_NE(wrong_unit.find("tau_s [s]"), std::string::npos) << wrong_unit;
    const std::string mg = error_of("flicker", "b_mg = 0.1");
    EXPECT_NE(mg.find("b_dps [deg/s]"), std::string::npos) << mg;
    EXPECT_NE(mg.find("b_g [g]"), std::string::npos) << mg;
    const std::string unknown = error_of("adc_inl", "bow = 1.0");
    EXPECT_NE(unknown.find("effects.adc_inl.bow: unknown key"), std::string::npos) << unknown;
}

TEST(EffectRegistry, BadValuesNameTheKeyAndTheExpectedUnit) {
    const std::string type = error_of("gauss_markov", "sigma_dps = \"fast\"");
    EXPECT_NE(type.find("effects.gauss_markov.sigma_dps: expected a number [deg/s]"), std::string::npos) << type;
    const std::string range = error_of("gauss_markov", "tau_s = -1.0");
    EXPECT_NE(range.find("tau_s: expected a number [s] > 0, got -1"), std::string::npos) << range;
    const std::string length = error_of("mains_alias", "amplitude_v = [0.1, 0.2]");
    EXPECT_NE(length.find("array of 4 numbers [V]"), std::string::npos) << length;
    const std::string choice = error_of("ambient_cycle", "waveform = \"triangle\"");
    EXPECT_NE(choice.find("expected one of \"sine\", \"square\""), std::string::npos) << choice;
    const std::string codes = error_of("adc_dnl", "missing_codes = [0]");
    EXPECT_NE(codes.find("missing_codes: expected an array of integers [counts] in [1, 1022]"), std::string::npos)
        << codes;
    const std::string table = error_of("adc_dnl", "transition_codes = [506, 507]\ntransition_counts = [505.2]");
    EXPECT_NE(table.find("transition_counts: expected one value per entry of transition_codes"), std::string::npos)
        << table;
    const std::string far = error_of("adc_dnl", "transition_codes = [506]\ntransition_counts = [507.0]");
    EXPECT_NE(far.find("within 1 LSB of its ideal place"), std::string::npos) << far;
    const std::string band = error_of("flicker", "f_low_hz = 1.0\nf_high_hz = 0.1");
    EXPECT_NE(band.find("f_high_hz: expected f_high_hz > f_low_hz"), std::string::npos) << band;
    const std::string tones = error_of("vibration", "tone_hz = [1.0, 2.0]\ntone_dps = [0.1]");
    EXPECT_NE(tones.find("tone_dps: expected 2 values"), std::string::npos) << tones;
    // Finite, but its run had ended in NaN at the converter input, reported as an internal error.
    const std::string huge = error_of("flicker", "b_dps = 1e308");
    EXPECT_NE(
        huge.find("effects.flicker.b_dps: got 1e+308: beyond +-1e+100, where the simulation's arithmetic overflows"),
        std::string::npos)
        << huge;
    EXPECT_NE(error_of("vibration", "tone_hz = [1.0]\ntone_dps = [-2e100]").find("tone_dps: got -2e+100: beyond"),
              std::string::npos);
    EXPECT_NO_THROW(test::effect_from("flicker", "b_dps = 1e100"));
}

TEST(EffectRegistry, UnknownEffectNameIsAConfigErrorListingTheKnownOnes) {
    try {
        make_effect("turn_on_bias", toml::table{}, "effects.turn_on_bias");
        FAIL() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_EQ(e.key(), "effects.turn_on_bias");
        EXPECT_NE(std::string(e.what()).find("gauss_markov"), std::string::npos);
    }
}

}  // namespace
}  // namespace driftlab::sim
