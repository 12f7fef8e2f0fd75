// The diagnosis's model as a model file: the analysed channels' calibration, the log's smoothing as a CONFIG the
// firmware takes, the added effects; a noise below the model file's floor is raised to it and said; a smoothing
// no CONFIG expresses is refused naming the log.
#include <cmath>

#include <gtest/gtest.h>

#include "host/gap/candidates.hpp"
#include "host/gap/model_out.hpp"
#include "host/util/error.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/white_noise.hpp"

namespace driftlab::host::gap {
namespace {

GapModel calibrated() {
    GapModel m;
    m.unit = sim::paper_model();
    m.smoothing = {0.4, 40, 40, 0};
    m.base[0] = {{-50.0, 560.0, 255.0}, 1.0};
    m.base[2] = {{3.0, 480.0, 900.0}, 0.2};
    m.effects.push_back(make_candidate_effect("gauss_markov", Channel::gyro, {0.02, 56.0}, m));
    return m;
}

TEST(ModelOut, TheAnalysedChannelsTheSmoothingAndTheEffectsAreWritten) {
    const GapModel m = calibrated();
    const ModelOut out = model_out(m, {true, false, true, false}, true, "log.csv");
    const sim::SimModel& s = out.model;
    EXPECT_EQ(s.channels[0].drift.c2_counts, 560.0);
    EXPECT_EQ(s.channels[0].drift.tau_s, 255.0);
    // Raw spread sqrt(sigma^2 + 1/12) counts, in the channel's unit.
    EXPECT_NEAR(s.channels[0].raw_noise_std_unit * counts_per_unit(m, Channel::gyro), std::sqrt(1.0 + 1.0 / 12.0),
                1e-12);
    // accel_y's 0.2 counts would be a raw spread of 0.35: below the file's 0.5, raised to it and said.
    EXPECT_NEAR(s.channels[2].raw_noise_std_unit * counts_per_unit(m, Channel::accel_y),
                sim::kMinCalibratedRawStdCounts, 1e-12);
    ASSERT_EQ(out.notes.size(), 1u);
    EXPECT_NE(out.notes[0].find("accel_y"), std::string::npos) << out.notes[0];
    // accel_x was not analysed: the unit's own.
    EXPECT_EQ(s.channels[1].drift.c2_counts, m.unit.channels[1].drift.c2_counts);
    EXPECT_EQ(s.channels[1].raw_noise_std_unit, m.unit.channels[1].raw_noise_std_unit);
    EXPECT_EQ(s.firmware.output_period_ms, 400);
    EXPECT_EQ(s.firmware.conversions_per_output, 40);
    EXPECT_EQ(s.firmware.window, 40);
    EXPECT_EQ(s.firmware.fit_order, 0);
    EXPECT_EQ(s.firmware.raw, 1);
    ASSERT_EQ(s.effects.size(), 1u);
    EXPECT_EQ(s.effects[0].name, "gauss_markov");
    EXPECT_EQ(s.effects[0].table, m.effects[0].table);
}

// A noise raised to the floor is written so that the loader, multiplying back, reads the floor and not a hair
// below it (LSB 0.0027 deg/s had written 0.5 counts as 0.49999999999999994, which the loader refused).
TEST(ModelOut, ANoiseRaisedToTheFloorReadsBackAtTheFloor) {
    for (const double lsb : {0.0027, 0.0043, 0.0099, 0.00875, 0.001, 0.0031, 0.0057, 0.0071}) {
        GapModel m = calibrated();
        m.unit.channels[0].front_end.span_unit = 512.0 * lsb;  // one code per LSB, as a plain recording's unit
        m.base[0].sigma_n_counts = 0.05;                       // a quiet sensor: raised to the floor
        const ModelOut out = model_out(m, {true, false, false, false}, false, "quiet.txt");
        EXPECT_GE(out.model.channels[0].raw_noise_std_unit * counts_per_unit(m, Channel::gyro),
                  sim::kMinCalibratedRawStdCounts)
            << lsb;
        EXPECT_NO_THROW(sim::parse_model(sim::write_model(out.model, "test"), "quiet.toml")) << lsb;
    }
}

TEST(ModelOut, ASmoothingNoFirmwareConfigExpressesIsRefusedNamingTheLog) {
    for (const Smoothing& bad : {Smoothing{0.0125, 1, 1, 0}, Smoothing{0.005, 1, 1, 0}, Smoothing{1.0, 100, 100, 0},
                                 Smoothing{1.0, 25, 65, 0}}) {
        GapModel m = calibrated();
        m.smoothing = bad;
        try {
            model_out(m, {true, false, false, false}, false, "log.csv");
            ADD_FAILURE() << bad.sample_period_s << " s, " << bad.conversions_per_output << " conversions, window "
                          << bad.window;
        } catch (const DataError& e) {
            EXPECT_NE(std::string(e.what()).find("log.csv: --model-out: the log's smoothing"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_EQ(firmware_config({0.1, 10, 10, 1}, false, "log.csv").fit_order, 1);
}

}  // namespace
}  // namespace driftlab::host::gap
