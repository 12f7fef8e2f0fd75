// Model files: the shipped files load, overrides land in the right field, bad content names file, line and key.
#include "sim/model/model_file.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "host/util/error.hpp"

namespace driftlab::sim {
namespace {

std::string error_of(const std::string& text) {
    try {
        parse_model(text, "m.toml");
    } catch (const host::ConfigError& e) {
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
)", "m.toml");
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
    EXPECT_NE(error_of("[link.to_host.packet_loss]\np_good_to_bad = 0.1\np_bad_to_good = 0\n")
                  .find("never recover"),
              std::string::npos);
}

TEST(ModelFile, RawNoiseTooSmallToCalibrateIsRejected) {
    // 0.01 deg/s = 0.057 counts: below what white noise through the quantiser can reproduce.
    const std::string e = error_of("[channels.gyro]\nraw_noise_std_dps = 0.01\n");
    EXPECT_NE(e.find("channels.gyro.raw_noise_std_dps"), std::string::npos) << e;
}

TEST(ModelFile, SyntaxErrorNamesTheLine) {
    const std::string e = error_of("name = \"a\"\n[adc\n");
    EXPECT_NE(e.find("m.toml:2"), std::string::npos) << e;
}

TEST(ModelFile, MissingFileIsAConfigError) {
    EXPECT_THROW(load_model_file("/nonexistent/model.toml"), host::ConfigError);
}

}  // namespace
}  // namespace driftlab::sim
