// One sensor chain: for every effect of the library at a non-trivial size, alone, with temp_scale_factor (and the
// ambient_cycle temperature it reads) and with vibration (an input effect that cross-couples), the codes the
// host-in-the-loop run converts are the codes the gap's replicate path (simulate_outputs) gives at the same
// instants, for one model and seed; and each effect changes them, so the comparison is not between two base runs.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim/hil/hil.hpp"
#include "sim/model/board_outputs.hpp"
#include "tests/sim/effects/effect_test_support.hpp"

namespace driftlab::sim {
namespace {

constexpr std::uint64_t kSeed = 11;
constexpr double kDurationS = 300.0;

using Codes = std::array<std::vector<double>, kChannelCount>;

struct HilConversions {
    std::array<std::vector<double>, kChannelCount> t_s;  // the board's nominal instants, per channel
    Codes codes;
};

// The library's examples, but for three that a unit at rest would not show in five minutes: spikes at one in 1000 s,
// a range of +-90 deg/s and +-1 g, which clips nothing at rest (here accel_z's 1 g is clipped at 0.98 g), and a
// clock 30 ppm fast, whose instants move eq. 1 by a ten-thousandth of a count (here 10 % fast).
EffectSpec spec_of(const std::string& name) {
    std::string text = test::kEffectExamples.at(name);
    if (name == "spikes") text = "rate_hz = 0.2\ndistribution = \"gaussian\"\nscale_counts = 6.0";
    if (name == "saturation") text = "min_g = [-1.0, -1.0, 0.0]\nmax_g = [1.0, 1.0, 0.98]";
    if (name == "clock_jitter") text = "drift_ppm = 1e5\njitter_s = 1e-4";
    return {name, toml::parse(text)};
}

SimModel model_with(const std::vector<std::string>& effects) {
    SimModel m = paper_model();
    for (const std::string& name : effects) m.effects.push_back(spec_of(name));
    m.firmware.output_period_ms = 100;
    m.firmware.conversions_per_output = 2;
    m.firmware.window = 2;
    m.firmware.mode = static_cast<std::uint8_t>(proto::OutputMode::stream);
    return m;
}

HilConversions through_hil(const SimModel& model) {
    HilOptions options;
    options.model = model;
    options.duration_s = kDurationS;
    options.seed = kSeed;
    HilConversions out;
    options.on_conversion = [&](Channel c, double t_s, std::uint16_t code) {
        out.t_s[channel_index(c)].push_back(t_s);
        out.codes[channel_index(c)].push_back(code);
    };
    run_hil(options, [](const HilRecord&) {});
    return out;
}

// The gap's path: the model as it replicates one (base and effects given beside the unit), each channel's codes at
// the instants hil converted it, one conversion per output so that every instant is visited.
Codes through_replicates(const SimModel& model, const HilConversions& hil) {
    OutputModel m;
    m.unit = model;
    m.smoothing = {0.025, 1, 1, 0};
    m.base = base_of(model);
    m.effects = model.effects;
    Codes codes;
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        OutputRequest request;
        request.t_s = &hil.t_s[c];
        request.channels = {};
        request.channels[c] = true;
        Codes raw;
        request.raw_codes = &raw;
        simulate_outputs(m, request, kSeed);
        codes[c] = raw[c];
    }
    return codes;
}

std::vector<std::vector<std::string>> combinations() {
    std::vector<std::vector<std::string>> out;
    for (const auto& [name, text] : test::kEffectExamples) {
        if (name != "temp_scale_factor") out.push_back({name});  // alone it has no temperature to scale by
        std::vector<std::string> thermal{name};
        for (const char* other : {"ambient_cycle", "temp_scale_factor"})
            if (name != other) thermal.push_back(other);
        out.push_back(thermal);
        if (name != "vibration") out.push_back({name, "vibration"});
    }
    return out;
}

std::string label(const std::vector<std::string>& effects) {
    std::string s;
    for (const auto& e : effects) s += (s.empty() ? "" : " + ") + e;
    return s;
}

TEST(ChainParity, HilAndTheReplicatePathGiveTheSameCodesForEveryEffect) {
    const HilConversions base = through_hil(model_with({}));
    for (const auto& effects : combinations()) {
        const SimModel model = model_with(effects);
        const HilConversions hil = through_hil(model);
        ASSERT_EQ(hil.t_s, base.t_s) << label(effects) << ": the board's schedule does not depend on the sensor";
        ASSERT_GT(hil.codes[0].size(), 5000u);  // 20 conversions a second per channel
        // A low-pass of a constant input is that input: bandwidth alone changes nothing at rest, and is compared
        // where it filters something, beside vibration.
        if (effects != std::vector<std::string>{"bandwidth"}) {
            EXPECT_NE(hil.codes, base.codes) << label(effects) << " changed no code: the comparison would be vacuous";
        }
        const Codes replicated = through_replicates(model, hil);
        for (std::size_t c = 0; c < kChannelCount; ++c) {
            ASSERT_EQ(replicated[c].size(), hil.codes[c].size());
            std::size_t differing = 0;
            for (std::size_t k = 0; k < hil.codes[c].size(); ++k) differing += replicated[c][k] != hil.codes[c][k];
            EXPECT_EQ(differing, 0u) << label(effects) << ", " << kChannelNames[c];
        }
    }
}

// The old replicate chain left the temperature unset: temp_scale_factor changed nothing there. In the one chain it
// scales the accel_z reading of 1 g as ambient_cycle's square wave moves the temperature.
TEST(ChainParity, TheReplicatePathSeesTheTemperature) {
    const SimModel cold = model_with({"ambient_cycle"});
    const SimModel scaled = model_with({"ambient_cycle", "temp_scale_factor"});
    const HilConversions schedule = through_hil(cold);
    EXPECT_NE(through_replicates(cold, schedule)[3], through_replicates(scaled, schedule)[3]);
}

}  // namespace
}  // namespace driftlab::sim
