// Command decisions (commands.hpp) and config validation (config.hpp): every field's bounds, the conversion
// period limits, wrong lengths, unknown types and firmware-to-host types, each with the Status and field index
// of docs/protocol.md §3.4/§4.
#include "firmware/core/commands.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/status.hpp"
#include "driftlab/proto/wire.hpp"
#include "firmware/core/config.hpp"

namespace driftlab {
namespace fw {
namespace {

using proto::ConfigField;
using proto::ConfigPayload;
using proto::MsgType;
using proto::OutputMode;
using proto::Status;

constexpr uint8_t kConfigSet = static_cast<uint8_t>(MsgType::config_set);

// A configuration well inside every range: 100 ms, 25 conversions -> 250-tick conversions.
ConfigPayload valid_config() { return ConfigPayload{100, 25, 25, 0, 0, 0}; }

CommandOutcome decide_config(const ConfigPayload& p, uint16_t seq = 7) {
  uint8_t bytes[proto::kConfigPayloadSize] = {};
  EXPECT_EQ(proto::serialize(p, bytes, sizeof bytes), proto::kConfigPayloadSize);
  return decide(kConfigSet, seq, bytes, proto::kConfigPayloadSize, OutputMode::poll);
}

void expect_nak(const CommandOutcome& out, uint8_t type, uint16_t seq, Status status, uint8_t field) {
  ASSERT_EQ(out.reply, Reply::nak);
  EXPECT_EQ(out.nak.nacked_type, type);
  EXPECT_EQ(out.nak.nacked_seq, seq);
  EXPECT_EQ(out.nak.status, static_cast<uint8_t>(status));
  EXPECT_EQ(out.nak.field, field);
}

void expect_out_of_range(const ConfigPayload& p, ConfigField field) {
  expect_nak(decide_config(p, 42), kConfigSet, 42, Status::out_of_range, static_cast<uint8_t>(field));
}

void expect_accepted(const ConfigPayload& p) {
  const CommandOutcome out = decide_config(p, 9);
  ASSERT_EQ(out.reply, Reply::ack) << "period " << p.output_period_ms << " ms, " << int(p.conversions_per_output)
                                   << " conversions";
  EXPECT_EQ(out.ack.acked_type, kConfigSet);
  EXPECT_EQ(out.ack.acked_seq, 9);
  const ConfigPayload back = config_to_payload(out.config);
  EXPECT_EQ(back.output_period_ms, p.output_period_ms);
  EXPECT_EQ(back.conversions_per_output, p.conversions_per_output);
  EXPECT_EQ(back.window, p.window);
  EXPECT_EQ(back.fit_order, p.fit_order);
  EXPECT_EQ(back.mode, p.mode);
  EXPECT_EQ(back.raw, p.raw);
}

TEST(Commands, ConfigSetAcceptsEveryFieldAtItsBounds) {
  expect_accepted(valid_config());
  ConfigPayload p = valid_config();
  p.output_period_ms = 10;  // 10 ms / (4 x 1) = 625 ticks
  p.conversions_per_output = 1;
  expect_accepted(p);
  p = valid_config();
  p.output_period_ms = 60000;  // 60 s / (4 x 64) = 58594 ticks, inside Timer1's 16 bits
  p.conversions_per_output = 64;
  expect_accepted(p);
  for (uint8_t window : {uint8_t{1}, uint8_t{64}}) {
    p = valid_config();
    p.window = window;
    expect_accepted(p);
  }
  p = valid_config();
  p.fit_order = 1;
  p.mode = 1;
  p.raw = 1;
  expect_accepted(p);
}

TEST(Commands, ConfigSetRejectsEachFieldJustOutsideItsRangeNamingThatField) {
  ConfigPayload p = valid_config();
  p.output_period_ms = 9;
  expect_out_of_range(p, ConfigField::output_period_ms);
  p.output_period_ms = 60001;
  expect_out_of_range(p, ConfigField::output_period_ms);
  p = valid_config();
  p.conversions_per_output = 0;
  expect_out_of_range(p, ConfigField::conversions_per_output);
  p.conversions_per_output = 65;
  expect_out_of_range(p, ConfigField::conversions_per_output);
  p = valid_config();
  p.window = 0;
  expect_out_of_range(p, ConfigField::window);
  p.window = 65;
  expect_out_of_range(p, ConfigField::window);
  p = valid_config();
  p.fit_order = 2;
  expect_out_of_range(p, ConfigField::fit_order);
  p = valid_config();
  p.mode = 2;
  expect_out_of_range(p, ConfigField::mode);
  p = valid_config();
  p.raw = 2;
  expect_out_of_range(p, ConfigField::raw);
  p = valid_config();
  p.raw = 255;
  expect_out_of_range(p, ConfigField::raw);
}

TEST(Commands, ConfigSetRejectsConversionPeriodsTheAdcOrTimerCannotDo) {
  // Shortest: 200 us = 50 ticks. 100 ms / (4 x 64) = 97.7 ticks passes; 40 ms / (4 x 64) = 39 ticks does not.
  ConfigPayload p = valid_config();
  p.output_period_ms = 40;
  p.conversions_per_output = 64;
  expect_out_of_range(p, ConfigField::conversions_per_output);
  p.output_period_ms = 52;  // 52 ms x 250 / 256 = 50.8 -> 51 ticks: accepted
  expect_accepted(p);
  p.output_period_ms = 51;  // 49.8 -> 50 ticks: accepted (rounded to the nearest tick)
  expect_accepted(p);
  p.output_period_ms = 50;  // 48.8 -> 49 ticks: rejected
  expect_out_of_range(p, ConfigField::conversions_per_output);
  // Longest: 65535 ticks (262 ms). 1 s / 4 = 62500 ticks passes; 1.1 s / 4 = 68750 does not.
  p = valid_config();
  p.conversions_per_output = 1;
  p.output_period_ms = 1000;
  expect_accepted(p);
  p.output_period_ms = 1100;
  expect_out_of_range(p, ConfigField::conversions_per_output);
}

TEST(Commands, ConversionPeriodRoundsOutputPeriodOverFourConversionsPerOutput) {
  EXPECT_EQ(conversion_period_ticks(100, 25), 250U);
  EXPECT_EQ(conversion_period_ticks(100, 16), 391U);  // 25000 / 64 = 390.6
  EXPECT_EQ(conversion_period_ticks(10, 1), 625U);
  EXPECT_EQ(conversion_period_ticks(60000, 64), 58594U);  // 15000000 / 256 = 58593.75
}

TEST(Commands, WrongLengthIsBadLengthForEveryHostType) {
  const uint8_t payload[proto::kMaxPayload] = {};
  for (MsgType type : {MsgType::hello, MsgType::config_get, MsgType::poll, MsgType::status_get}) {
    const uint8_t id = proto::type_id(type);
    expect_nak(decide(id, 3, payload, 1, OutputMode::poll), id, 3, Status::bad_length, proto::kNakFieldNone);
  }
  for (uint8_t len : {uint8_t{0}, uint8_t{6}, uint8_t{8}}) {
    expect_nak(decide(kConfigSet, 4, payload, len, OutputMode::poll), kConfigSet, 4, Status::bad_length,
               proto::kNakFieldNone);
  }
}

TEST(Commands, UnknownTypeIsUnknownType) {
  for (uint8_t id : {uint8_t{0x00}, uint8_t{0x10}, uint8_t{0x7F}, uint8_t{0xFF}}) {
    expect_nak(decide(id, 5, nullptr, 0, OutputMode::poll), id, 5, Status::unknown_type, proto::kNakFieldNone);
  }
}

TEST(Commands, FirmwareToHostTypesAreNotAllowed) {
  const uint8_t payload[proto::kMaxPayload] = {};
  for (MsgType type : {MsgType::version, MsgType::config, MsgType::sample, MsgType::raw, MsgType::ack, MsgType::nak,
                       MsgType::status}) {
    const uint8_t id = proto::type_id(type);
    expect_nak(decide(id, 6, payload, proto::payload_len_of(type), OutputMode::poll), id, 6, Status::not_allowed,
               proto::kNakFieldNone);
  }
}

TEST(Commands, QueriesGetTheirRepliesInPollMode) {
  EXPECT_EQ(decide(proto::type_id(MsgType::hello), 0, nullptr, 0, OutputMode::poll).reply, Reply::version);
  EXPECT_EQ(decide(proto::type_id(MsgType::config_get), 0, nullptr, 0, OutputMode::poll).reply, Reply::config);
  EXPECT_EQ(decide(proto::type_id(MsgType::poll), 0, nullptr, 0, OutputMode::poll).reply, Reply::sample);
  EXPECT_EQ(decide(proto::type_id(MsgType::status_get), 0, nullptr, 0, OutputMode::poll).reply, Reply::status);
}

// docs/protocol.md §3.5: a streaming board refuses POLL (not_allowed, no field) and answers every other query.
TEST(Commands, PollInStreamModeIsNotAllowedAndOtherQueriesAreAnswered) {
  const uint8_t poll = proto::type_id(MsgType::poll);
  expect_nak(decide(poll, 11, nullptr, 0, OutputMode::stream), poll, 11, Status::not_allowed, proto::kNakFieldNone);
  EXPECT_EQ(decide(proto::type_id(MsgType::hello), 0, nullptr, 0, OutputMode::stream).reply, Reply::version);
  EXPECT_EQ(decide(proto::type_id(MsgType::config_get), 0, nullptr, 0, OutputMode::stream).reply, Reply::config);
  EXPECT_EQ(decide(proto::type_id(MsgType::status_get), 0, nullptr, 0, OutputMode::stream).reply, Reply::status);
  // A POLL of the wrong length is still a length error first: the mode is the last check.
  const uint8_t payload[1] = {};
  expect_nak(decide(poll, 12, payload, 1, OutputMode::stream), poll, 12, Status::bad_length, proto::kNakFieldNone);
}

TEST(Config, DefaultsAreValidAndGiveAnExactHundredMillisecondOutput) {
  const ConfigCheck check = validate(config_to_payload(kDefaultConfig));
  EXPECT_EQ(check.status, Status::ok);
  const AdcSchedule schedule = adc_schedule(kDefaultConfig, 0);
  EXPECT_EQ(schedule.conversion_period_ticks * 4U * kDefaultConfig.conversions_per_output, 25000U);
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(channel_index(schedule.order[c]), c);
  }
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
