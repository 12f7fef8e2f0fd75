// Command decisions (commands.hpp) and config validation (config.hpp): every field's bounds, the conversion
// period limits, wrong lengths, unknown types and firmware-to-host types, each with the Status and field index
// of docs/protocol.md §3.4/§4.
#include "firmware/core/commands.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "driftlab/proto/encoder.hpp"
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

// CONFIG_SET's payload: the fields, then a trailer check_auth() judges (decide() takes its verdict).
CommandOutcome decide_config(const ConfigPayload& p, uint16_t seq = 7, Status auth = Status::ok) {
  uint8_t bytes[proto::kConfigPayloadSize + proto::kAuthTrailerBytes] = {};
  EXPECT_EQ(proto::serialize(p, bytes, proto::kConfigPayloadSize), proto::kConfigPayloadSize);
  return decide(kConfigSet, seq, bytes, sizeof bytes, OutputMode::poll, auth);
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
    expect_nak(decide(id, 3, payload, 1, OutputMode::poll, Status::ok), id, 3, Status::bad_length,
               proto::kNakFieldNone);
  }
  for (uint8_t len : {uint8_t{0}, uint8_t{6}, uint8_t{7}, uint8_t{8}, uint8_t{18}, uint8_t{20}}) {
    expect_nak(decide(kConfigSet, 4, payload, len, OutputMode::poll, Status::ok), kConfigSet, 4, Status::bad_length,
               proto::kNakFieldNone);
  }
}

TEST(Commands, UnknownTypeIsUnknownType) {
  for (uint8_t id : {uint8_t{0x00}, uint8_t{0x11}, uint8_t{0x7F}, uint8_t{0xFF}}) {
    expect_nak(decide(id, 5, nullptr, 0, OutputMode::poll, Status::ok), id, 5, Status::unknown_type,
               proto::kNakFieldNone);
  }
}

TEST(Commands, FirmwareToHostTypesAreNotAllowed) {
  const uint8_t payload[proto::kMaxPayload] = {};
  for (MsgType type : {MsgType::version, MsgType::config, MsgType::sample, MsgType::raw, MsgType::ack, MsgType::nak,
                       MsgType::status}) {
    const uint8_t id = proto::type_id(type);
    expect_nak(decide(id, 6, payload, proto::payload_len_of(type), OutputMode::poll, Status::ok), id, 6,
               Status::not_allowed, proto::kNakFieldNone);
  }
}

TEST(Commands, QueriesGetTheirRepliesInPollMode) {
  EXPECT_EQ(decide(proto::type_id(MsgType::hello), 0, nullptr, 0, OutputMode::poll, Status::ok).reply, Reply::version);
  EXPECT_EQ(decide(proto::type_id(MsgType::config_get), 0, nullptr, 0, OutputMode::poll, Status::ok).reply,
            Reply::config);
  EXPECT_EQ(decide(proto::type_id(MsgType::poll), 0, nullptr, 0, OutputMode::poll, Status::ok).reply, Reply::sample);
  EXPECT_EQ(decide(proto::type_id(MsgType::status_get), 0, nullptr, 0, OutputMode::poll, Status::ok).reply,
            Reply::status);
}

// docs/protocol.md §3.5: a streaming board refuses POLL (not_allowed, no field) and answers every other query.
TEST(Commands, PollInStreamModeIsNotAllowedAndOtherQueriesAreAnswered) {
  const uint8_t poll = proto::type_id(MsgType::poll);
  expect_nak(decide(poll, 11, nullptr, 0, OutputMode::stream, Status::ok), poll, 11, Status::not_allowed,
             proto::kNakFieldNone);
  EXPECT_EQ(decide(proto::type_id(MsgType::hello), 0, nullptr, 0, OutputMode::stream, Status::ok).reply,
            Reply::version);
  EXPECT_EQ(decide(proto::type_id(MsgType::config_get), 0, nullptr, 0, OutputMode::stream, Status::ok).reply,
            Reply::config);
  EXPECT_EQ(decide(proto::type_id(MsgType::status_get), 0, nullptr, 0, OutputMode::stream, Status::ok).reply,
            Reply::status);
  // A POLL of the wrong length is still a length error first: the mode is the last check.
  const uint8_t payload[1] = {};
  expect_nak(decide(poll, 12, payload, 1, OutputMode::stream, Status::ok), poll, 12, Status::bad_length,
             proto::kNakFieldNone);
}

// docs/security.md invariant 14: the authentication is judged after the length and before the fields, so a sender
// without the key learns nothing of which values the board would take.
TEST(Commands, AnAuthenticationRefusalComesBeforeTheFields) {
  ConfigPayload bad = valid_config();
  bad.window = 0;
  expect_out_of_range(bad, ConfigField::window);
  for (Status auth : {Status::unauthenticated, Status::replayed}) {
    expect_nak(decide_config(bad, 8, auth), kConfigSet, 8, auth, proto::kNakFieldNone);
    expect_nak(decide_config(valid_config(), 8, auth), kConfigSet, 8, auth, proto::kNakFieldNone);
  }
}

constexpr proto::Key kCheckKey = {0x10, 0x21, 0x32, 0x43, 0x54, 0x65, 0x76, 0x87,
                                  0x98, 0xA9, 0xBA, 0xCB, 0xDC, 0xED, 0xFE, 0x0F};

std::vector<uint8_t> config_frame(const proto::Key* key, uint32_t counter) {
  uint8_t frame[proto::kMaxFrameSize] = {};
  const size_t n = proto::encode_config_set(valid_config(), proto::CommandAuth{key, counter}, 1, frame, sizeof frame);
  return std::vector<uint8_t>(frame, frame + n);
}

TEST(CheckAuth, AKeyedBoardAdmitsOnlyItsTagAndANewCounter) {
  const AuthView keyed{proto::AuthState::keyed, &kCheckKey, 41};
  EXPECT_EQ(check_auth(config_frame(&kCheckKey, 42).data(), keyed), Status::ok);
  EXPECT_EQ(check_auth(config_frame(&kCheckKey, 0xFFFFFFFF).data(), keyed), Status::ok);
  EXPECT_EQ(check_auth(config_frame(&kCheckKey, 41).data(), keyed), Status::replayed);
  EXPECT_EQ(check_auth(config_frame(&kCheckKey, 0).data(), keyed), Status::replayed);
  EXPECT_EQ(check_auth(config_frame(nullptr, 42).data(), keyed), Status::unauthenticated);
  proto::Key other = {};
  std::copy(std::begin(kCheckKey), std::end(kCheckKey), other);
  other[0] ^= 1;
  EXPECT_EQ(check_auth(config_frame(&other, 42).data(), keyed), Status::unauthenticated);
  // A replayed frame with a forged tag is a forgery first.
  EXPECT_EQ(check_auth(config_frame(&other, 41).data(), keyed), Status::unauthenticated);
}

TEST(CheckAuth, AnOpenBoardTakesAnyTrailerButNoKeyAndADamagedKeyNothing) {
  const AuthView open{proto::AuthState::open, nullptr, 0};
  EXPECT_EQ(check_auth(config_frame(nullptr, 1).data(), open), Status::ok);
  EXPECT_EQ(check_auth(config_frame(&kCheckKey, 0).data(), open), Status::ok);
  uint8_t frame[proto::kMaxFrameSize] = {};
  ASSERT_GT(proto::encode_key_set(kCheckKey, proto::CommandAuth{&kCheckKey, 5}, 2, frame, sizeof frame), 0u);
  EXPECT_EQ(check_auth(frame, open), Status::not_allowed);
  const AuthView damaged{proto::AuthState::damaged, &kCheckKey, 0};
  EXPECT_EQ(check_auth(config_frame(&kCheckKey, 1).data(), damaged), Status::unauthenticated);
  EXPECT_EQ(check_auth(frame, damaged), Status::unauthenticated);
  // Types without a trailer, and a length decide() refuses anyway, pass to decide().
  ASSERT_GT(proto::encode_hello(3, frame, sizeof frame), 0u);
  EXPECT_EQ(check_auth(frame, damaged), Status::ok);
  std::vector<uint8_t> short_frame = config_frame(&kCheckKey, 1);
  short_frame[proto::kOffsetLen] = 7;
  EXPECT_EQ(check_auth(short_frame.data(), damaged), Status::ok);
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
