// Model files: the shipped files load, overrides land in the right field, bad content names file, line and key.
#include "sim/model/model_file.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "sim/sim_error.hpp"

namespace driftlab::sim {
namespace {

std::string error_of(const std::string& text) {
    try {
        parse_model(text, "m.toml");
    } catch (const ModelFileError& e) {
        return e.what();
    }
    return "no error";
}

TEST(ModelFile, BuiltInModelIsThePaperUnit) {
    const SimModel m = paper_model();
    EXPECT_EQ(m.name, "paper");
    EXPECT_EQ(m.adc.bits, 10);
    EXPECT_EQ(m.adc.vref_v, 5.0);
    EXPECT_EQ(m.channels[0].drift.c2_counts, 505.0);
    EXPECT_EQ(m.channels[3].drift.tau_s, 1050.0);
    EXPECT_EQ(m.channels[0].raw_noise_std_unit, 0.187);
    EXPECT_EQ(m.channels[1].raw_noise_std_unit, 0.0141);
    EXPECT_EQ(m.channels[3].input_unit, 1.0);
    EXPECT_EQ(m.firmware.output_period_ms, 1000);
    EXPECT_EQ(m.firmware.window, 25);
    EXPECT_EQ(m.link.baud, 9600.0);
    EXPECT_TRUE(m.effects.empty());
}

TEST(ModelFile, ShippedPaperFileEqualsTheBuiltInText) {
    const std::filesystem::path p = std::filesystem::path(DRIFTLAB_MODELS_DIR) / "paper.toml";
    const SimModel m = load_model_file(p.string());
    EXPECT_EQ(m.channels[2].drift.c1_counts, paper_model().channels[2].drift.c1_counts);
}

TEST(ModelFile, EveryShippedModelLoads) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(DRIFTLAB_MODELS_DIR)) {
        if (e.path().extension() != ".toml") continue;
        EXPECT_NO_THROW(load_model_file(e.path().string())) << e.path();
        ++n;
    }
    EXPECT_GE(n, 3);
}

// A folder opens as a stream that reads empty: `hil --model FOLDER` had run the paper's model under its name.
TEST(ModelFile, AFolderIsNotAModelFile) {
    try {
        load_model_file(DRIFTLAB_MODELS_DIR);
        ADD_FAILURE() << "a folder was loaded as a model";
    } catch (const ModelFileError& e) {
        EXPECT_NE(std::string(e.what()).find("is a folder, not a model file"), std::string::npos) << e.what();
    }
}

// Model files are untrusted input read whole (docs/security.md): one past kMaxModelFileBytes is refused before it is
// parsed, even when it is valid TOML, and one just under the limit is read.
TEST(ModelFile, AFileLongerThanTheLimitIsRefusedBeforeItIsParsed) {
    const std::string path = (std::filesystem::temp_directory_path() / "driftlab_long_model.toml").string();
    const std::string comment = "# " + std::string(98, 'x') + "\n";
    std::string text;
    while (text.size() + comment.size() <= kMaxModelFileBytes) text += comment;
    std::ofstream(path, std::ios::binary) << text;
    EXPECT_NO_THROW(load_model_file(path));
    std::ofstream(path, std::ios::binary | std::ios::app) << comment;
    try {
        load_model_file(path);
        ADD_FAILURE() << "a model file past the limit was read";
    } catch (const ModelFileError& e) {
        EXPECT_NE(std::string(e.what()).find("longer than 1 MiB"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

TEST(ModelFile, KeysOverrideThePaperDefaults) {
    const SimModel m = parse_model(R"(
name = "x"
[channels.accel_y]
drift_tau_s = 12.5
raw_noise_std_g = 0.002
[firmware]
mode = "stream"
raw = true
[link]
baud = 115200
[link.to_host.packet_loss]
unit = "byte"
p_good_to_bad = 0.01
p_bad_to_good = 0.5
)",
                                   "m.toml");
    EXPECT_EQ(m.name, "x");
    EXPECT_EQ(m.channels[2].drift.tau_s, 12.5);
    EXPECT_EQ(m.channels[2].drift.c1_counts, 23.0);  // untouched key keeps the paper's value
    EXPECT_EQ(m.firmware.mode, 1);
    EXPECT_EQ(m.firmware.raw, 1);
    EXPECT_EQ(m.link.baud, 115200.0);
    EXPECT_EQ(m.link.to_host.packet_loss.unit, LossUnit::byte);
    EXPECT_EQ(m.link.to_host.packet_loss.p_good_to_bad, 0.01);
    EXPECT_EQ(m.link.to_firmware.packet_loss.p_good_to_bad, 0.0);
}

TEST(ModelFile, UnknownKeyNamesFileLineAndKey) {
    const std::string e = error_of("[channels.gyro]\nspan_dps = 90\nspan_g = 1\n");
    EXPECT_NE(e.find("m.toml:3"), std::string::npos) << e;
    EXPECT_NE(e.find("channels.gyro.span_g"), std::string::npos) << e;
    EXPECT_NE(e.find("unknown key"), std::string::npos) << e;
}

TEST(ModelFile, UnknownChannelIsRejected) {
    const std::string e = error_of("[channels.magnetometer]\nnull_v = 1\n");
    EXPECT_NE(e.find("channels.magnetometer"), std::string::npos) << e;
}

TEST(ModelFile, OutOfRangeValuesNameTheKeyAndTheRange) {
    EXPECT_NE(error_of("[channels.gyro]\ndrift_tau_s = -3\n").find("channels.gyro.drift_tau_s: must be > 0"),
              std::string::npos);
    EXPECT_NE(error_of("[firmware]\nwindow = 65\n").find("firmware.window: must be in [1, 64]"), std::string::npos);
    EXPECT_NE(error_of("[link.to_host]\nbyte_error_rate = 1.5\n").find("link.to_host.byte_error_rate"),
              std::string::npos);
    EXPECT_NE(error_of("[firmware]\nmode = \"burst\"\n").find("expected one of \"poll\", \"stream\""),
              std::string::npos);
    EXPECT_NE(error_of("[adc]\nbits = 2.5\n").find("adc.bits: expected an integer"), std::string::npos);
    // Checks that join keys name a line too.
    EXPECT_NE(error_of("[link.to_host.packet_loss]\np_good_to_bad = 0.1\np_bad_to_good = 0\n")
                  .find("m.toml:3: link.to_host.packet_loss.p_bad_to_good: must be > 0 when p_good_to_bad > 0 (the "
                        "link would never recover)"),
              std::string::npos);
    // The firmware, 10-bit, is all a model can run on: 12 bits had aborted the run at its first 4-digit code.
    EXPECT_NE(error_of("[adc]\nbits = 12\n").find("m.toml:2: adc.bits: must be in [10, 10], got 12"),
              std::string::npos);
    // The firmware's own check, fields joined: 64 conversions per 10 ms output is a conversion every 39 us.
    const std::string fast = error_of("[firmware]\noutput_period_ms = 10\nconversions_per_output = 64\n");
    EXPECT_NE(fast.find("m.toml:3: firmware.conversions_per_output: the firmware refuses this configuration"),
              std::string::npos)
        << fast;
    // With the values it saw (10 000 us / 256 = 39 us, 10 ticks of 4 us), not only the rule.
    EXPECT_NE(
        fast.find("output_period_ms 10 / (4 channels x conversions_per_output 64) gives a conversion period of 10 "
                  "ticks of 4 us; the firmware needs 50 to 65535"),
        std::string::npos)
        << fast;
}

// Each field the firmware refuses is named with its own range and value; the conversion-period rule had been given
// as the reason whatever the field.
TEST(ModelFile, TheFirmwaresRefusalSaysWhatTheFieldMustBe) {
    const proto::ConfigPayload paper = paper_model().firmware;
    EXPECT_FALSE(firmware_refusal(paper).has_value());
    const auto reason_for = [&paper](auto change) {
        proto::ConfigPayload fw = paper;
        change(fw);
        const auto r = firmware_refusal(fw);
        return r ? r->field + ": " + r->reason : std::string("accepted");
    };
    EXPECT_NE(reason_for([](auto& fw) { fw.fit_order = 2; })
                  .find("fit_order: the firmware refuses this configuration "
                        "(out_of_range): must be 0 to 1, got 2"),
              std::string::npos);
    EXPECT_NE(reason_for([](auto& fw) { fw.output_period_ms = 5; }).find("output_period_ms: "), std::string::npos);
    EXPECT_NE(reason_for([](auto& fw) { fw.output_period_ms = 5; }).find("must be 10 to 60000, got 5"),
              std::string::npos);
    EXPECT_NE(reason_for([](auto& fw) { fw.conversions_per_output = 0; }).find("must be 1 to 64, got 0"),
              std::string::npos);
    EXPECT_NE(reason_for([](auto& fw) { fw.raw = 3; }).find("raw: "), std::string::npos);
}

// Jitter comparable to a channel's conversion interval reorders conversions (the bias processes then took the
// square root of a negative step); the paper's 1000 ms / 25 conversions is 40 ms a channel, so 4 ms is the most.
TEST(ModelFile, ClockJitterThatWouldReorderConversionsOrStopTheClockIsRejected) {
    EXPECT_EQ(error_of("[effects.clock_jitter]\njitter_s = 0.004\n"), "no error");
    const std::string jitter =
        error_of("[effects.gauss_markov]\nsigma_dps = 0.2\n\n[effects.clock_jitter]\njitter_s = 0.01\n");
    EXPECT_NE(jitter.find("m.toml:5: effects.clock_jitter.jitter_s: 0.01 s is not well below a channel's conversion "
                          "interval (0.04 s"),
              std::string::npos)
        << jitter;
    // The interval is the configuration that runs: 10 conversions an output leave 100 ms, room for 10 ms of jitter.
    EXPECT_EQ(error_of("[effects.clock_jitter]\njitter_s = 0.01\n\n[firmware]\nconversions_per_output = 10\n"),
              "no error");
    const std::string stopped = error_of("[effects.clock_jitter]\ndrift_ppm = -1e6\n");
    EXPECT_NE(stopped.find("m.toml:2: effects.clock_jitter.drift_ppm: expected drift_ppm > -1e6"), std::string::npos)
        << stopped;
}

// Only ambient_cycle gives the chain a temperature: temp_scale_factor alone had loaded and done nothing.
TEST(ModelFile, TempScaleFactorWithoutATemperatureIsRejected) {
    const std::string alone = error_of("[effects.temp_scale_factor]\nscale_pct_per_k = 0.1\n");
    EXPECT_NE(alone.find("m.toml:1: effects.temp_scale_factor: needs the unit's temperature"), std::string::npos)
        << alone;
    EXPECT_EQ(
        error_of("[effects.temp_scale_factor]\nscale_pct_per_k = 0.1\n[effects.ambient_cycle]\namplitude_k_pp = 2.0\n"),
        "no error");
}

TEST(ModelFile, RawNoiseTooSmallToCalibrateIsRejected) {
    // 0.01 deg/s = 0.057 counts: below what white noise through the quantiser can reproduce.
    const std::string e = error_of("[channels.gyro]\nraw_noise_std_dps = 0.01\n");
    EXPECT_NE(e.find("m.toml:2: channels.gyro.raw_noise_std_dps"), std::string::npos) << e;
    // The counts follow from the front end as well: a file that only widens the gyro's span shrinks its noise in
    // counts below the floor (it had been checked only where the file set the noise, and read NaN, then code 0).
    const std::string span = error_of("[channels.gyro]\nspan_dps = 2000\n");
    EXPECT_NE(span.find("m.toml:1: channels.gyro.raw_noise_std_dps: is "), std::string::npos) << span;
}

// Each number finite alone, but not what the front end makes of them: a span of 1e-308 gave the amplifier an
// infinite gain, and the run's first conversion an internal error (NaN at the converter input, blamed on an effect).
TEST(ModelFile, AFrontEndBeyondTheRangeOfADoubleIsRejected) {
    const std::string tiny_span = error_of("name = \"x\"\n[channels.accel_x]\nspan_g = 1e-308\n");
    EXPECT_NE(
        tiny_span.find("m.toml:2: channels.accel_x: its front end leaves the range of a double: amplifier gain "
                       "vref_v / 2 / (sensitivity_v_per_g x span_g) = inf V/V, converter input at input_g = nan V"),
        std::string::npos)
        << tiny_span;
    // A gain that underflows to 0 would stick the channel at mid-scale whatever its input.
    const std::string huge =
        error_of("[adc]\nvref_v = 1e-300\n[channels.gyro]\nsensitivity_v_per_dps = 1e100\nspan_dps = 1e100\n");
    EXPECT_NE(huge.find("channels.gyro: its front end leaves the range of a double: amplifier gain vref_v / 2 / "
                        "(sensitivity_v_per_dps x span_dps) = 0 V/V"),
              std::string::npos)
        << huge;
    // An input the transducer turns into more volts than a double holds.
    const std::string input = error_of("[channels.accel_z]\nspan_g = 1e-250\ninput_g = 1e100\n");
    EXPECT_NE(input.find("converter input at input_g = inf V"), std::string::npos) << input;
    // A number near the largest double is refused at its key, whatever the front end makes of it.
    const std::string c1 = error_of("[channels.gyro]\ndrift_c1_counts = -1e200\n");
    EXPECT_NE(c1.find("m.toml:2: channels.gyro.drift_c1_counts: got -1e+200: beyond +-1e+100"), std::string::npos)
        << c1;
    // Extreme but representable front ends still load.
    EXPECT_NO_THROW(parse_model("[channels.gyro]\nspan_dps = 1e-6\nraw_noise_std_dps = 0\n", "m.toml"));
}

TEST(ModelFile, SyntaxErrorNamesTheLine) {
    const std::string e = error_of("name = \"a\"\n[adc\n");
    EXPECT_NE(e.find("m.toml:2"), std::string::npos) << e;
}

TEST(ModelFile, MissingFileIsAConfigError) { EXPECT_THROW(load_model_file("/nonexistent/model.toml"), ModelFileError); }

// Every field of two models, so that a written file can be checked to read back as what was written.
void expect_same(const SimModel& a, const SimModel& b, const std::string& what) {
    SCOPED_TRACE(what);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.adc.bits, b.adc.bits);
    EXPECT_EQ(a.adc.vref_v, b.adc.vref_v);
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        const ChannelModel &x = a.channels[i], &y = b.channels[i];
        EXPECT_EQ(x.front_end.sensitivity_v_per_unit, y.front_end.sensitivity_v_per_unit) << i;
        EXPECT_EQ(x.front_end.null_v, y.front_end.null_v) << i;
        EXPECT_EQ(x.front_end.span_unit, y.front_end.span_unit) << i;
        EXPECT_EQ(x.front_end.center_unit, y.front_end.center_unit) << i;
        EXPECT_EQ(x.input_unit, y.input_unit) << i;
        EXPECT_EQ(x.raw_noise_std_unit, y.raw_noise_std_unit) << i;
        EXPECT_EQ(x.drift.c1_counts, y.drift.c1_counts) << i;
        EXPECT_EQ(x.drift.c2_counts, y.drift.c2_counts) << i;
        EXPECT_EQ(x.drift.tau_s, y.drift.tau_s) << i;
    }
    ASSERT_EQ(a.effects.size(), b.effects.size());
    for (std::size_t k = 0; k < a.effects.size(); ++k) {
        EXPECT_EQ(a.effects[k].name, b.effects[k].name) << k;
        EXPECT_EQ(a.effects[k].table, b.effects[k].table) << k;
    }
    EXPECT_EQ(std::memcmp(&a.firmware, &b.firmware, sizeof a.firmware), 0);
    EXPECT_EQ(a.link.baud, b.link.baud);
    for (const auto& [x, y] :
         {std::pair{a.link.to_host, b.link.to_host}, std::pair{a.link.to_firmware, b.link.to_firmware}}) {
        EXPECT_EQ(x.latency_s, y.latency_s);
        EXPECT_EQ(x.byte_error_rate, y.byte_error_rate);
        EXPECT_EQ(x.byte_drop_rate, y.byte_drop_rate);
        EXPECT_EQ(x.packet_loss.unit, y.packet_loss.unit);
        EXPECT_EQ(x.packet_loss.p_good_to_bad, y.packet_loss.p_good_to_bad);
        EXPECT_EQ(x.packet_loss.p_bad_to_good, y.packet_loss.p_bad_to_good);
        EXPECT_EQ(x.packet_loss.loss_in_good, y.packet_loss.loss_in_good);
        EXPECT_EQ(x.packet_loss.loss_in_bad, y.packet_loss.loss_in_bad);
    }
}

// What write_model() writes reads back as the model, bit for bit: every shipped model, and one whose values have
// no short decimal form, whose fields all differ from the paper's, and whose Gauss-Markov effect appears twice.
TEST(ModelFile, AWrittenModelReadsBackAsItself) {
    for (const auto& e : std::filesystem::directory_iterator(DRIFTLAB_MODELS_DIR)) {
        if (e.path().extension() != ".toml") continue;
        const SimModel m = load_model_file(e.path().string());
        expect_same(parse_model(write_model(m, "from " + e.path().filename().string()), "written"), m,
                    e.path().string());
    }
    SimModel m = parse_model(R"(
[[effects.gauss_markov]]
sigma_dps = 0.05
tau_s = [30.0, 100.0, 100.0, 100.0]
[[effects.gauss_markov]]
sigma_g = [0.0, 0.002, 0.0]
tau_s = [100.0, 100.0, 7.5, 100.0]
[effects.spikes]
rate_hz = 0.01
scale_counts = 40.0
)",
                             "two.toml");
    ASSERT_EQ(m.effects.size(), 3u);
    m.name = "odd \"quoted\" name";
    m.adc = {10, 3.3};  // the only resolution a model takes; the reference is odd
    for (std::size_t i = 0; i < kChannelCount; ++i) {
        ChannelModel& ch = m.channels[i];
        ch.front_end = {
            0.1 + 0.2 * static_cast<double>(i),
            1.0 / 3.0,
            7.0 / 9.0,
            -1e-7,
        };
        ch.input_unit = std::nextafter(1.0, 2.0);
        ch.raw_noise_std_unit = 0.2 / 3.0;
        ch.drift = {std::sqrt(2.0), 511.0 + 1.0 / 7.0, 1234.5678901234567};
    }
    m.firmware = {250, 10, 7, 1, 1, 1};
    m.link.baud = 115200.0;
    m.link.to_host = {0.02, 1e-4, 3e-5, {LossUnit::byte, 0.01, 0.3, 0.001, 0.9}};
    const std::string text = write_model(m, "two lines\nof comment");
    EXPECT_EQ(text.rfind("# two lines\n# of comment\n", 0), 0u) << text;
    EXPECT_NE(text.find("[[effects.gauss_markov]]"), std::string::npos) << text;
    expect_same(parse_model(text, "written"), m, text);
}

TEST(ModelFile, AnEffectsArrayOfTablesIsOneInstanceEachAndABadOneIsNamed) {
    const std::string e =
        error_of("[[effects.gauss_markov]]\nsigma_dps = 0.1\n[[effects.gauss_markov]]\nsigma_dps = -1.0\n");
    EXPECT_NE(e.find("effects.gauss_markov[1]"), std::string::npos) << e;
}

}  // namespace
}  // namespace driftlab::sim
