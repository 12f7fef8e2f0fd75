// The Firmware on the native port, end to end through the protocol library: replies, SAMPLE values for known
// input, stream cadence, raw mode, loss and saturation bookkeeping, NAKs that change nothing, reject counters.
#include "firmware/core/firmware.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <vector>

#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/status.hpp"
#include "driftlab/proto/wire.hpp"
#include "tests/firmware/ls_reference.hpp"
#include "tests/firmware/native_rig.hpp"

namespace driftlab {
namespace fw {
namespace {

using proto::MsgType;
using test::Frame;
using test::is;
using test::NativeRig;
using test::parse_as;

// Default schedule: 100 ms outputs of 25 conversions per channel -> one conversion every 250 ticks, conversion i
// (from 0) triggered at tick 250 (i + 1), channel i mod 4.
constexpr uint64_t kPeriodTicks = 250;
constexpr uint64_t kOutputTicks = 25000;

uint64_t conversion_index(uint64_t trigger_tick) { return trigger_tick / kPeriodTicks - 1; }
// How many conversions `channel` had before this one.
uint64_t channel_conversion(uint64_t trigger_tick) { return conversion_index(trigger_tick) / kChannelCount; }

proto::ConfigPayload default_payload() { return config_to_payload(kDefaultConfig); }

TEST(Firmware, HelloIsAnsweredWithVersionDescribingTheBoard) {
  NativeRig rig;
  rig.send_empty(MsgType::hello);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  ASSERT_TRUE(is(frames[0], MsgType::version));
  EXPECT_EQ(frames[0].seq, 0);
  const auto v = parse_as<proto::VersionPayload>(frames[0]);
  EXPECT_EQ(v.proto_version, 2);
  EXPECT_EQ(v.adc_bits, 10);
  EXPECT_EQ(v.vref_mv, 5000);
  EXPECT_EQ(v.tick_hz, 250000U);
  EXPECT_EQ(v.channel_count, 4);
  const uint8_t pins[4] = {0, 1, 2, 3};
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(v.adc_pin[c], pins[c]);
  }
  EXPECT_EQ(v.reset_cause, kResetPowerOn);
  EXPECT_EQ(v.assert_line, 0);
}

TEST(Firmware, StartArmsTheDefaultScheduleInChannelOrder) {
  NativeRig rig;
  ASSERT_TRUE(rig.board.armed());
  EXPECT_EQ(rig.board.conversion_period_ticks(), kPeriodTicks);
  EXPECT_EQ(rig.board.next_conversion_time_ticks(), kPeriodTicks);
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(channel_index(rig.board.next_channel()), c);
    rig.board.set_time_ticks(rig.board.next_conversion_time_ticks());
    ASSERT_TRUE(rig.board.convert(512));
  }
  EXPECT_EQ(channel_index(rig.board.next_channel()), 0);
}

TEST(Firmware, PollAnswersSampleWithTheLeastSquaresValuesOfKnownInput) {
  NativeRig rig;
  proto::ConfigPayload config = default_payload();
  config.fit_order = 1;
  rig.send_config(config);
  // gyro constant, accel_x a ramp (a line fits it exactly), accel_y pseudo-random inside 1..1022 (checked
  // against the double reference), accel_z saturated at full scale.
  std::deque<uint16_t> accel_y_codes;
  uint32_t lcg = 12345;
  auto code_for = [&](Channel channel, uint64_t tick) -> uint16_t {
    switch (channel) {
    case Channel::gyro: return 505;
    case Channel::accel_x: return static_cast<uint16_t>(300 + channel_conversion(tick));
    case Channel::accel_y: {
      lcg = lcg * 1103515245U + 12345U;
      const uint16_t code = static_cast<uint16_t>(1 + (lcg >> 16) % 1022);
      accel_y_codes.push_back(code);
      if (accel_y_codes.size() > 25) {
        accel_y_codes.pop_front();
      }
      return code;
    }
    case Channel::accel_z: return 1023;
    }
    return 0;
  };
  rig.run_until(250000, code_for);  // 1000 conversions, 250 per channel
  rig.receive();
  rig.send_empty(MsgType::poll);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  ASSERT_TRUE(is(frames[0], MsgType::sample));
  const auto s = parse_as<proto::SamplePayload>(frames[0]);
  EXPECT_EQ(s.tick, 250000U);
  EXPECT_EQ(s.value_q8[0], 505 * 256);
  EXPECT_EQ(s.value_q8[1], (300 + 249) * 256);
  EXPECT_NEAR(s.value_q8[2] / 256.0, test::ls_reference(accel_y_codes, 1), 1.0 / 512.0);
  EXPECT_EQ(s.value_q8[3], 1023 * 256);
  EXPECT_EQ(s.sat_flags, 0x08);
  EXPECT_EQ(s.n_window, 25);
  EXPECT_EQ(s.dropped, 0);
}

TEST(Firmware, StreamModeSendsOneSamplePerOutputPeriodOnTheTickGrid) {
  NativeRig rig;
  proto::ConfigPayload config = default_payload();
  config.mode = 1;
  rig.send_config(config);
  rig.run_until(250000 + 249, [](Channel, uint64_t) -> uint16_t { return 512; });
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 11U);
  ASSERT_TRUE(is(frames[0], MsgType::ack));
  for (size_t k = 1; k < frames.size(); ++k) {
    ASSERT_TRUE(is(frames[k], MsgType::sample));
    EXPECT_EQ(frames[k].seq, k);
    const auto s = parse_as<proto::SamplePayload>(frames[k]);
    EXPECT_EQ(s.tick, kOutputTicks * k) << "sample " << k;
    EXPECT_EQ(s.value_q8[0], 512 * 256);
    EXPECT_EQ(s.n_window, 25);
  }
}

// docs/protocol.md §3.5: a POLL is answered at once with the windows as they are. Before the first conversion, and
// after a CONFIG_SET that emptied them, that is n_window 0, every value 0 and the last tick seen (0 before any): the
// flag, not the zeros, tells it from a reading.
TEST(Firmware, PollWithEmptyWindowsAnswersZerosFlaggedByNWindowZero) {
  NativeRig rig;
  const auto empty_answer_tick = [&rig] {
    rig.send_empty(MsgType::poll);
    const std::vector<Frame> frames = rig.receive();
    EXPECT_EQ(frames.size(), 1U);
    const auto s = parse_as<proto::SamplePayload>(frames.at(0));
    EXPECT_EQ(s.n_window, 0);
    for (int32_t v : s.value_q8) EXPECT_EQ(v, 0);
    return s.tick;
  };
  EXPECT_EQ(empty_answer_tick(), 0U);
  rig.run_until(10 * kPeriodTicks + 77, [](Channel, uint64_t) -> uint16_t { return 600; });
  proto::ConfigPayload config = default_payload();
  config.window = 8;  // a new window empties them
  rig.send_config(config);
  ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
  EXPECT_EQ(empty_answer_tick(), 10 * kPeriodTicks);
}

// docs/protocol.md §3.5: in stream mode a POLL is refused with NAK not_allowed naming it, and no SAMPLE is sent: the
// streamed SAMPLEs stay on the output grid with consecutive seqs around the NAK, and the cadence is unchanged.
TEST(Firmware, PollInStreamModeIsRefusedAndTheStreamStaysOnItsGrid) {
  NativeRig rig;
  proto::ConfigPayload config = default_payload();
  config.mode = 1;
  config.raw = 1;  // nor a RAW: a refused POLL sends nothing but the NAK
  rig.send_config(config);
  rig.run_until(kOutputTicks + 5 * kPeriodTicks + 10, [](Channel, uint64_t) -> uint16_t { return 512; });
  const uint16_t poll_seq = rig.next_host_seq();
  rig.send_empty(MsgType::poll);
  rig.run_until(2 * kOutputTicks + 10, [](Channel, uint64_t) -> uint16_t { return 512; });
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 6U);  // ACK, SAMPLE + RAW, NAK, SAMPLE + RAW
  ASSERT_TRUE(is(frames[3], MsgType::nak));
  const auto nak = parse_as<proto::NakPayload>(frames[3]);
  EXPECT_EQ(nak.nacked_type, proto::type_id(MsgType::poll));
  EXPECT_EQ(nak.nacked_seq, poll_seq);
  EXPECT_EQ(nak.status, static_cast<uint8_t>(proto::Status::not_allowed));
  EXPECT_EQ(nak.field, proto::kNakFieldNone);
  const size_t samples[] = {1, 4};
  for (size_t k = 0; k < 2; ++k) {
    const Frame& f = frames[samples[k]];
    ASSERT_TRUE(is(f, MsgType::sample)) << k;
    ASSERT_TRUE(is(frames[samples[k] + 1], MsgType::raw)) << k;
    EXPECT_EQ(parse_as<proto::SamplePayload>(f).tick, kOutputTicks * (k + 1)) << k;
  }
  for (size_t k = 0; k < frames.size(); ++k) EXPECT_EQ(frames[k].seq, k);
}

// Back in poll mode the same POLL is answered again: the refusal follows the mode in force, not a latched state.
TEST(Firmware, PollIsAnsweredAgainOnceStreamModeEnds) {
  NativeRig rig;
  proto::ConfigPayload config = default_payload();
  config.mode = 1;
  rig.send_config(config);
  rig.run_until(kOutputTicks + 10, [](Channel, uint64_t) -> uint16_t { return 512; });
  config.mode = 0;
  rig.send_config(config);  // only the mode changes: the windows are kept
  rig.receive();
  rig.send_empty(MsgType::poll);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  ASSERT_TRUE(is(frames[0], MsgType::sample));
  EXPECT_EQ(parse_as<proto::SamplePayload>(frames[0]).n_window, 25);
}

TEST(Firmware, RawModeFollowsEachSampleWithTheNewestCodes) {
  NativeRig rig;
  proto::ConfigPayload config = default_payload();
  config.mode = 1;
  config.raw = 1;
  rig.send_config(config);
  // Code = 100 x channel + the channel's conversion count, so the newest code of each channel is known.
  rig.run_until(2 * kOutputTicks, [](Channel channel, uint64_t tick) -> uint16_t {
    return static_cast<uint16_t>(100 * channel_index(channel) + channel_conversion(tick));
  });
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 5U);  // ACK, then SAMPLE + RAW twice
  for (int k = 0; k < 2; ++k) {
    const Frame& sample = frames[1 + 2 * k];
    const Frame& raw = frames[2 + 2 * k];
    ASSERT_TRUE(is(sample, MsgType::sample));
    ASSERT_TRUE(is(raw, MsgType::raw));
    EXPECT_EQ(raw.seq, sample.seq + 1);
    const auto s = parse_as<proto::SamplePayload>(sample);
    const auto r = parse_as<proto::RawPayload>(raw);
    EXPECT_EQ(r.tick, s.tick);
    const uint64_t last_conversion = 25 * (k + 1) - 1;  // per channel
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(r.code[c], 100 * c + last_conversion) << "channel " << c;
    }
  }
}

TEST(Firmware, ConversionsLostToAFullRingAreCountedAsDropped) {
  NativeRig rig;
  // 20 conversions without a main-loop pass: the ring holds 16, the last 4 are lost.
  for (int i = 0; i < 20; ++i) {
    rig.board.set_time_ticks(rig.board.next_conversion_time_ticks());
    EXPECT_EQ(rig.board.convert(512), i < kAdcRingCapacity);
  }
  rig.board.service(rig.firmware);
  rig.run_until(rig.board.time_ticks() + 10 * kPeriodTicks, [](Channel, uint64_t) -> uint16_t { return 512; });
  rig.send_empty(MsgType::poll);
  rig.send_empty(MsgType::status_get);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 2U);
  EXPECT_EQ(parse_as<proto::SamplePayload>(frames[0]).dropped, 4);
  EXPECT_EQ(parse_as<proto::StatusPayload>(frames[1]).dropped, 4);
  EXPECT_EQ(rig.firmware.dropped(), 4);
}

TEST(Firmware, SaturationFlagHoldsWhileTheSaturatedCodeIsInTheWindow) {
  NativeRig rig;
  proto::ConfigPayload config = default_payload();
  config.window = 4;
  rig.send_config(config);
  // accel_y's conversion number 10 reads 0 (the rail); every other code is mid-scale.
  auto code_for = [](Channel channel, uint64_t tick) -> uint16_t {
    return channel == Channel::accel_y && channel_conversion(tick) == 10 ? 0 : 512;
  };
  auto sat_flags_after = [&](uint64_t channel_conversions) {
    rig.run_until(channel_conversions * 4 * kPeriodTicks, code_for);
    rig.receive();
    rig.send_empty(MsgType::poll);
    const std::vector<Frame> frames = rig.receive();
    EXPECT_EQ(frames.size(), 1U);
    return parse_as<proto::SamplePayload>(frames.at(0)).sat_flags;
  };
  EXPECT_EQ(sat_flags_after(10), 0);     // conversions 0..9 per channel
  EXPECT_EQ(sat_flags_after(11), 0x04);  // number 10 entered
  EXPECT_EQ(sat_flags_after(14), 0x04);  // window {10..13}
  EXPECT_EQ(sat_flags_after(15), 0);     // window {11..14}
}

TEST(Firmware, WarmUpReportsTheLeastFilledWindow) {
  NativeRig rig;
  rig.run_until(5 * kPeriodTicks, [](Channel, uint64_t) -> uint16_t { return 512; });  // gyro 2, others 1
  rig.send_empty(MsgType::poll);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  const auto s = parse_as<proto::SamplePayload>(frames[0]);
  EXPECT_EQ(s.n_window, 1);
  EXPECT_EQ(s.tick, 5 * kPeriodTicks);
  EXPECT_EQ(rig.firmware.window(Channel::gyro).n(), 2);
}

TEST(Firmware, NakForAnyFieldLeavesConfigurationWindowsAndScheduleUnchanged) {
  struct Bad {
    proto::ConfigField field;
    proto::ConfigPayload payload;
  };
  // Each request would also change other fields (10 ms timing, window 3, line, stream, raw): none may apply.
  const proto::ConfigPayload base = {10, 1, 3, 1, 1, 1};
  std::vector<Bad> bad;
  bad.push_back({proto::ConfigField::output_period_ms, base});
  bad.back().payload.output_period_ms = 9;
  bad.push_back({proto::ConfigField::conversions_per_output, base});
  bad.back().payload.conversions_per_output = 13;  // 10 ms / 52 conversions = 48 ticks, below 50
  bad.push_back({proto::ConfigField::window, base});
  bad.back().payload.window = 65;
  bad.push_back({proto::ConfigField::fit_order, base});
  bad.back().payload.fit_order = 2;
  bad.push_back({proto::ConfigField::mode, base});
  bad.back().payload.mode = 2;
  bad.push_back({proto::ConfigField::raw, base});
  bad.back().payload.raw = 2;
  for (const Bad& b : bad) {
    NativeRig rig;
    rig.run_until(10 * kPeriodTicks, [](Channel, uint64_t) -> uint16_t { return 600; });
    rig.send_config(b.payload);
    rig.send_empty(MsgType::config_get);
    rig.run_until(20 * kPeriodTicks, [](Channel, uint64_t) -> uint16_t { return 600; });
    const std::vector<Frame> frames = rig.receive();
    ASSERT_EQ(frames.size(), 2U) << "field " << int(b.field) << ": a NAK and a CONFIG, no stream output";
    ASSERT_TRUE(is(frames[0], MsgType::nak));
    const auto nak = parse_as<proto::NakPayload>(frames[0]);
    EXPECT_EQ(nak.nacked_type, proto::type_id(MsgType::config_set));
    EXPECT_EQ(nak.nacked_seq, 100);
    EXPECT_EQ(nak.status, static_cast<uint8_t>(proto::Status::out_of_range));
    EXPECT_EQ(nak.field, static_cast<uint8_t>(b.field));
    ASSERT_TRUE(is(frames[1], MsgType::config));
    const auto current = parse_as<proto::ConfigPayload>(frames[1]);
    const proto::ConfigPayload defaults = default_payload();
    EXPECT_EQ(current.output_period_ms, defaults.output_period_ms);
    EXPECT_EQ(current.conversions_per_output, defaults.conversions_per_output);
    EXPECT_EQ(current.window, defaults.window);
    EXPECT_EQ(current.fit_order, defaults.fit_order);
    EXPECT_EQ(current.mode, defaults.mode);
    EXPECT_EQ(current.raw, defaults.raw);
    EXPECT_EQ(rig.board.arm_count(), 1U);
    EXPECT_EQ(rig.board.conversion_period_ticks(), kPeriodTicks);
    EXPECT_EQ(rig.firmware.window(Channel::gyro).n(), 5) << "20 conversions so far, windows kept";
  }
}

TEST(Firmware, AcceptedTimingChangeIsAckedAndRearmsOnTheOldGrid) {
  NativeRig rig;
  rig.run_until(10 * kPeriodTicks + 77, [](Channel, uint64_t) -> uint16_t { return 512; });
  proto::ConfigPayload config = default_payload();
  config.output_period_ms = 10;
  config.conversions_per_output = 1;
  config.window = 1;
  config.mode = 1;
  rig.send_config(config);
  rig.send_empty(MsgType::config_get);
  std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 2U);
  ASSERT_TRUE(is(frames[0], MsgType::ack));
  const auto ack = parse_as<proto::AckPayload>(frames[0]);
  EXPECT_EQ(ack.acked_type, proto::type_id(MsgType::config_set));
  EXPECT_EQ(ack.acked_seq, 100);
  const auto current = parse_as<proto::ConfigPayload>(frames[1]);
  EXPECT_EQ(current.output_period_ms, 10);
  EXPECT_EQ(current.conversions_per_output, 1);
  EXPECT_EQ(rig.firmware.config().mode, proto::OutputMode::stream);
  // The next conversion of the old grid (tick 2750) is the anchor: the new grid starts one old period later,
  // whatever time the request arrived, then runs at 10 ms / 4 = 625 ticks.
  EXPECT_EQ(rig.board.arm_count(), 1U);
  rig.run_until(11 * kPeriodTicks, [](Channel, uint64_t) -> uint16_t { return 512; });
  EXPECT_EQ(rig.board.arm_count(), 2U);
  EXPECT_EQ(rig.board.conversion_period_ticks(), 625);
  EXPECT_EQ(rig.board.next_conversion_time_ticks(), 12 * kPeriodTicks);
  EXPECT_EQ(channel_index(rig.board.next_channel()), 0);
  // Stream mode: one SAMPLE per 4 conversions of the new grid, the first stamped on its 4th trigger.
  rig.run_until(12 * kPeriodTicks + 7 * 625, [](Channel, uint64_t) -> uint16_t { return 512; });
  frames = rig.receive();
  ASSERT_EQ(frames.size(), 2U);
  EXPECT_EQ(parse_as<proto::SamplePayload>(frames[0]).tick, 12 * kPeriodTicks + 3 * 625);
  EXPECT_EQ(parse_as<proto::SamplePayload>(frames[1]).tick, 12 * kPeriodTicks + 7 * 625);
  EXPECT_EQ(rig.firmware.dropped(), 0);
}

TEST(Firmware, FirmwareToHostTypeIsNakedNotAllowed) {
  NativeRig rig;
  proto::SamplePayload sample = {};
  uint8_t frame[proto::kMaxFrameSize];
  const size_t n = proto::encode_sample(sample, 77, frame, sizeof frame);
  rig.send_bytes(frame, n);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  const auto nak = parse_as<proto::NakPayload>(frames[0]);
  EXPECT_EQ(nak.nacked_type, proto::type_id(MsgType::sample));
  EXPECT_EQ(nak.nacked_seq, 77);
  EXPECT_EQ(nak.status, static_cast<uint8_t>(proto::Status::not_allowed));
}

TEST(Firmware, RejectedFramesGetNoReplyAndAreCountedInStatus) {
  NativeRig rig;
  uint8_t frame[proto::kMaxFrameSize];
  // A HELLO with a damaged CRC.
  size_t n = proto::encode_hello(1, frame, sizeof frame);
  frame[n - 1] ^= 0x01;
  rig.send_bytes(frame, n);
  // A CONFIG_SET header announcing 6 payload bytes instead of 7.
  const uint8_t short_config[] = {
      proto::kSync0, proto::kSync1, proto::kProtocolVersion, proto::type_id(MsgType::config_set), 2, 0, 6};
  rig.send_bytes(short_config, sizeof short_config);
  // An unknown type.
  const uint8_t unknown[] = {proto::kSync0, proto::kSync1, proto::kProtocolVersion, 0x3C, 3, 0, 0};
  rig.send_bytes(unknown, sizeof unknown);
  EXPECT_TRUE(rig.receive().empty());
  rig.send_empty(MsgType::status_get);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  const auto st = parse_as<proto::StatusPayload>(frames[0]);
  EXPECT_EQ(st.rx_bad_crc, 1);
  EXPECT_EQ(st.rx_bad_length, 1);
  EXPECT_EQ(st.rx_unknown_type, 1);
  EXPECT_EQ(st.rx_frames, 1);  // the STATUS_GET itself
  EXPECT_EQ(st.rx_overflow, 0);
  EXPECT_EQ(st.tx_overflow, 0);
}

TEST(Firmware, FramesThatDoNotFitTheTxRingAreCountedAndLeaveASeqGap) {
  NativeRig rig;
  // STATUS frames are 36 bytes: 3 fill the 128-byte ring, the next 7 are lost whole.
  for (int i = 0; i < 10; ++i) {
    rig.send_empty(MsgType::status_get);
  }
  std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 3U);
  for (uint16_t k = 0; k < 3; ++k) {
    EXPECT_EQ(frames[k].seq, k);
  }
  rig.send_empty(MsgType::status_get);
  frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_EQ(frames[0].seq, 10);
  EXPECT_EQ(parse_as<proto::StatusPayload>(frames[0]).tx_overflow, 7 * 36);
  EXPECT_EQ(rig.host_decoder_counters().bad_crc, 0U) << "the firmware never sends a partial frame";
}

TEST(Firmware, StatusUptimeIsTheBoardTime) {
  NativeRig rig;
  rig.run_until(123456, [](Channel, uint64_t) -> uint16_t { return 512; });
  rig.send_empty(MsgType::status_get);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  EXPECT_EQ(parse_as<proto::StatusPayload>(frames[0]).uptime_ticks, 123456U);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
