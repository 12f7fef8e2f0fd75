// AvrTarget in the host-in-the-loop: the same model, seed and configuration give the same log records on the
// AVR and native targets (docs/avr-in-the-loop.md).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <memory>
#include <vector>

#include "driftlab/proto/temperature.hpp"
#include "sim/avr/avr_target.hpp"
#include "sim/hil/eeprom_image.hpp"
#include "sim/hil/hil.hpp"
#include "sim/model/model_file.hpp"
#include "sim/motion/trajectories.hpp"
#include "sim/sim_error.hpp"
#include "tests/sim/avr/twin_driver.hpp"

namespace driftlab::sim::avr::test {
namespace {

struct Run {
    std::vector<HilRecord> records;
    HilSummary summary;
};

Run run(HilOptions options, bool on_avr) {
    if (on_avr) {
        options.make_board = [eeprom = options.eeprom, die = options.die_temperature] {
            AvrBoardOptions board{avr_elf()};
            board.eeprom = eeprom;
            board.die_temperature = die;
            return std::make_unique<AvrTarget>(board);
        };
    }
    Run r;
    r.summary = run_hil(options, [&](const HilRecord& rec) { r.records.push_back(rec); });
    return r;
}

void expect_same_records(const Run& avr, const Run& native, std::size_t min_records) {
    ASSERT_GE(native.records.size(), min_records);
    ASSERT_EQ(avr.records.size(), native.records.size());
    for (std::size_t i = 0; i < native.records.size(); ++i) {
        const HilRecord& a = avr.records[i];
        const HilRecord& n = native.records[i];
        ASSERT_EQ(a.tick, n.tick) << "record " << i;
        EXPECT_EQ(a.seq, n.seq) << "record " << i;
        EXPECT_EQ(a.value_counts, n.value_counts) << "record " << i;
        EXPECT_EQ(a.raw_counts, n.raw_counts) << "record " << i;
        EXPECT_EQ(a.sat_flags, n.sat_flags) << "record " << i;
        EXPECT_EQ(a.n_window, n.n_window) << "record " << i;
        EXPECT_EQ(a.dropped, n.dropped) << "record " << i;
        EXPECT_EQ(a.temp_code, n.temp_code) << "record " << i;
    }
    EXPECT_EQ(avr.summary.status.dropped, 0U);
    EXPECT_EQ(avr.summary.host.frames_lost, native.summary.host.frames_lost);
}

constexpr std::array<std::uint8_t, 16> kKey = {0x51, 0x0C, 0xE7, 0x2A, 0x93, 0x6D, 0xB8, 0x04,
                                               0x7F, 0xC1, 0x35, 0x9E, 0x48, 0xD2, 0x16, 0xAB};

class AvrHil : public ::testing::Test {
protected:
    void SetUp() override {
        if (avr_elf().empty() || !std::filesystem::exists(avr_elf())) {
            GTEST_SKIP() << "AVR firmware ELF not built (avr-g++ missing at configure time): " << avr_elf();
        }
    }
};

TEST_F(AvrHil, PaperModelPolledGivesTheSameRecordsAsNative) {
    HilOptions options;
    options.model = paper_model();
    options.duration_s = 60.0;
    options.seed = 5;
    expect_same_records(run(options, true), run(options, false), 59);
}

// The unit on a robot: the real firmware reads the same moving input at the same instants as the native core, so a
// minute of figure8 at 0.1 s outputs gives the same records.
TEST_F(AvrHil, AFigureEightMinuteGivesTheSameRecordsAsNative) {
    HilOptions options;
    options.model = paper_model();
    options.model.firmware.output_period_ms = 100;
    options.model.firmware.conversions_per_output = 10;  // 2.5 ms per conversion: a whole number of ticks
    options.model.firmware.window = 10;
    options.duration_s = 60.0;
    options.seed = 3;
    options.trajectory = std::make_shared<const Trajectory>(make_trajectory("figure8", 120.0, 2.0, 3));
    expect_same_records(run(options, true), run(options, false), 590);
}

// Compensation and authentication on the chip: the calibration and the key in the EEPROM at power-on (as upload and
// flash --key leave them), the configuration signed by the host; the same corrected values from the AVR's integer
// arithmetic as from the native core's, over 10 minutes of the transient at 0.1 s outputs.
TEST_F(AvrHil, ACompensatedRunWithAnAuthenticatedConfigurationGivesTheSameRecordsAsNative) {
    HilOptions options;
    options.model = paper_model();
    options.model.firmware.output_period_ms = 100;
    options.model.firmware.conversions_per_output = 10;  // as above: a poll lands mid-period on both boards
    options.model.firmware.window = 10;
    options.duration_s = 600.0;
    options.seed = 11;
    const std::int32_t c1[] = {3 * 256, 2 * 256, 23 * 256, 28 * 256};
    const std::int32_t c2[] = {505 * 256, 470 * 256, 474 * 256, 622 * 256};
    const std::uint32_t t_ms[] = {411000, 953000, 937000, 1050000};
    std::vector<proto::CalPayload> entries;
    for (std::uint8_t c = 0; c < kChannelCount; ++c)
        entries.push_back(proto::CalPayload{4242, c, static_cast<std::uint8_t>(c == 0 ? proto::kCalFlagZero : 0), c1[c],
                                            c2[c], t_ms[c]});
    options.key = kKey;
    options.eeprom = eeprom_image(entries, kKey);
    const auto avr = run(options, true);
    const auto native = run(options, false);
    EXPECT_EQ(avr.summary.version.auth_state, static_cast<std::uint8_t>(proto::AuthState::keyed));
    EXPECT_EQ(avr.summary.version.cal_state, static_cast<std::uint8_t>(proto::CalState::active));
    EXPECT_EQ(avr.summary.version.cal_id, 4242);
    expect_same_records(avr, native, 5990);
    // The die read at power-on and about once a second: 25 °C warming towards 28 °C with tau 300 s
    // (die_temperature.hpp).
    EXPECT_EQ(native.records.front().temp_code, proto::temperature_code_of_celsius(25.0));
    EXPECT_NEAR(native.records.back().temp_code, options.die_temperature.code(native.records.back().t_s), 1);
    EXPECT_GT(native.records.back().temp_code, native.records.front().temp_code);
    // And compensated: the gyro, referred to zero, near mid-scale from the start.
    EXPECT_NEAR(native.records.front().value_counts[0], 512.0, 1.0);
}

// The AVR refuses a configuration under another key, as the native core does, and the run says why.
TEST_F(AvrHil, AConfigurationUnderAnotherKeyIsRefusedAsUnauthenticated) {
    HilOptions options;
    options.model = paper_model();
    options.duration_s = 5.0;
    options.eeprom = eeprom_image({}, kKey);
    options.key = kKey;
    options.key->at(0) ^= 1;
    for (bool on_avr : {true, false}) {
        try {
            run(options, on_avr);
            ADD_FAILURE() << (on_avr ? "AVR" : "native") << ": the run went on";
        } catch (const ConfigRefused& e) {
            EXPECT_NE(std::string(e.what()).find("unauthenticated"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace driftlab::sim::avr::test
