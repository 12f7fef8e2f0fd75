// The die temperature on the native port (hal.hpp hal_read_temperature(), hal_request_temperature()): read at
// power-on so that the first SAMPLE carries it, refreshed about once a second between two rounds without touching
// the channels' windows or the loss count, and reported as none where the schedule leaves no room for it.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "driftlab/proto/messages.hpp"
#include "tests/firmware/native_rig.hpp"

namespace driftlab {
namespace fw {
namespace {

using proto::MsgType;
using test::Frame;
using test::is;
using test::NativeRig;
using test::parse_as;

constexpr uint64_t kTemperatureOutputTicks = 25000;  // the default 100 ms outputs

uint16_t steady_code(Channel, uint64_t) { return 600; }

// The streamed SAMPLEs of `rig` up to `time_ticks`.
std::vector<proto::SamplePayload> samples_until(NativeRig& rig, uint64_t time_ticks) {
  rig.run_until(time_ticks, steady_code);
  std::vector<proto::SamplePayload> out;
  for (const Frame& f : rig.receive()) {
    if (is(f, MsgType::sample)) out.push_back(parse_as<proto::SamplePayload>(f));
  }
  return out;
}

void stream_default_schedule(NativeRig& rig) {
  proto::ConfigPayload stream = config_to_payload(kDefaultConfig);
  stream.mode = static_cast<uint8_t>(proto::OutputMode::stream);
  rig.send_config(stream);
  ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
}

TEST(FirmwareTemperature, ThePowerOnReadingIsInTheFirstSampleAndRefreshedOnceASecond) {
  NativeRig rig(301);
  stream_default_schedule(rig);
  std::vector<proto::SamplePayload> first =
      samples_until(rig, 5 * kTemperatureOutputTicks + kTemperatureOutputTicks / 2);
  ASSERT_EQ(first.size(), 5U);
  for (const proto::SamplePayload& s : first) {
    EXPECT_EQ(s.temp_code, 301) << "the power-on reading, then the one requested at the first output";
    EXPECT_EQ(s.dropped, 0) << "a temperature conversion is no lost sensor conversion";
  }
  // Requests at outputs 1, 11, 21 ... (one a second at 0.1 s): each converted after the next round, seen from the
  // next output on.
  rig.board.set_die_temperature_code(305);
  const std::vector<proto::SamplePayload> later =
      samples_until(rig, 25 * kTemperatureOutputTicks + kTemperatureOutputTicks / 2);
  ASSERT_EQ(later.size(), 20U);
  for (size_t i = 0; i < later.size(); ++i) {
    const size_t output = i + 6;
    EXPECT_EQ(later[i].temp_code, output <= 11 ? 301 : 305) << "output " << output;
    EXPECT_EQ(later[i].n_window, 25) << "output " << output;
    EXPECT_EQ(later[i].dropped, 0) << "output " << output;
    EXPECT_EQ(later[i].value_q8[0], 600 * 256) << "the windows hold only sensor conversions";
  }
}

TEST(FirmwareTemperature, AScheduleWithoutRoomForOneReportsNone) {
  NativeRig rig(301);
  // 10 ms outputs of 12 conversions: a conversion every 52 ticks, below kMinTemperaturePeriodTicks.
  rig.send_config(proto::ConfigPayload{10, 12, 12, 0, static_cast<uint8_t>(proto::OutputMode::stream), 0});
  ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
  const std::vector<proto::SamplePayload> samples = samples_until(rig, 2 * kTemperatureOutputTicks);
  ASSERT_GT(samples.size(), 10U);
  for (const proto::SamplePayload& s : samples) EXPECT_EQ(s.temp_code, proto::kNoTemperature);
  // Back to a slower schedule: none at its first output (the reading requested there is taken after it), then
  // readings again.
  rig.board.set_die_temperature_code(299);
  stream_default_schedule(rig);
  const std::vector<proto::SamplePayload> again = samples_until(rig, 8 * kTemperatureOutputTicks);
  ASSERT_GE(again.size(), 4U);
  EXPECT_EQ(again.front().temp_code, proto::kNoTemperature);
  EXPECT_EQ(again[1].temp_code, 299);
  EXPECT_EQ(again.back().temp_code, 299);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
