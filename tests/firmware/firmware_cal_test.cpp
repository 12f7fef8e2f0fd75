// The Firmware's calibration end to end on the native port: CAL_SET stored and read back, its ranges NAKed, the
// outputs compensated against eq. 1 in double precision once the four entries agree, and what a partial upload, a
// damaged EEPROM, a power cycle and a warm restart leave the board doing (VERSION, SAMPLE and STATUS say it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "driftlab/proto/crc16.hpp"
#include "firmware/core/cal_store.hpp"
#include "tests/firmware/native_rig.hpp"

namespace driftlab {
namespace fw {
namespace {

using proto::CalState;
using proto::MsgType;
using test::ask;
using test::Frame;
using test::is;
using test::NativeRig;
using test::parse_as;

constexpr uint16_t kCode = 500;  // every conversion, so the uncompensated value is 500 counts exactly

// Table 1 of the paper, the gyro referred to mid-scale.
proto::CalPayload table1(uint8_t channel, uint16_t cal_id = 7) {
  static const int32_t kC1[] = {3, 2, 23, 28};
  static const int32_t kC2[] = {505, 470, 474, 622};
  static const uint32_t kT[] = {411000, 953000, 937000, 1050000};
  return proto::CalPayload{cal_id,
                           channel,
                           static_cast<uint8_t>(channel == 0 ? proto::kCalFlagZero : 0),
                           kC1[channel] * 256,
                           kC2[channel] * 256,
                           kT[channel]};
}

void upload(NativeRig& rig, uint16_t cal_id = 7) {
  for (uint8_t c = 0; c < kChannelCount; ++c) {
    rig.send_cal(table1(c, cal_id));
    const std::vector<Frame> frames = rig.receive();
    ASSERT_EQ(frames.size(), 1U);
    ASSERT_TRUE(is(frames[0], MsgType::ack)) << "channel " << int(c);
  }
}

proto::SamplePayload poll(NativeRig& rig) {
  rig.send_empty(MsgType::poll);
  const std::vector<Frame> frames = rig.receive();
  EXPECT_EQ(frames.size(), 1U);
  return parse_as<proto::SamplePayload>(frames.at(0));
}

uint16_t constant_code(Channel, uint64_t) { return kCode; }

TEST(FirmwareCal, AStoredEntryReadsBackAsWritten) {
  NativeRig rig;
  const proto::CalPayload written = table1(2);
  rig.send_cal(written);
  ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
  rig.send_cal_get(2);
  const std::vector<Frame> frames = rig.receive();
  ASSERT_EQ(frames.size(), 1U);
  ASSERT_TRUE(is(frames[0], MsgType::cal));
  const proto::CalPayload read = parse_as<proto::CalPayload>(frames[0]);
  EXPECT_EQ(read.cal_id, written.cal_id);
  EXPECT_EQ(read.channel, written.channel);
  EXPECT_EQ(read.flags, written.flags);
  EXPECT_EQ(read.c1_q8, written.c1_q8);
  EXPECT_EQ(read.c2_q8, written.c2_q8);
  EXPECT_EQ(read.t_ms, written.t_ms);
  // An entry never written is said so.
  rig.send_cal_get(1);
  const proto::NakPayload nak = parse_as<proto::NakPayload>(rig.receive().at(0));
  EXPECT_EQ(nak.status, static_cast<uint8_t>(proto::Status::not_stored));
}

TEST(FirmwareCal, AFieldOutOfItsRangeIsNakedByNameAndNothingIsStored) {
  struct Case {
    proto::CalPayload payload;
    proto::CalField field;
  };
  proto::CalPayload short_t = table1(0);
  short_t.t_ms = proto::kCalTMinMs - 1;
  proto::CalPayload long_t = table1(0);
  long_t.t_ms = proto::kCalTMaxMs + 1;
  proto::CalPayload big_c1 = table1(0);
  big_c1.c1_q8 = -proto::kCalCountsMaxQ8 - 1;
  proto::CalPayload big_c2 = table1(0);
  big_c2.c2_q8 = proto::kCalCountsMaxQ8 + 1;
  proto::CalPayload channel = table1(0);
  channel.channel = kChannelCount;
  proto::CalPayload flags = table1(0);
  flags.flags = 0x02;
  for (const Case& c : {Case{short_t, proto::CalField::t_ms}, Case{long_t, proto::CalField::t_ms},
                        Case{big_c1, proto::CalField::c1_q8}, Case{big_c2, proto::CalField::c2_q8},
                        Case{channel, proto::CalField::channel}, Case{flags, proto::CalField::flags}}) {
    NativeRig rig;
    rig.send_cal(c.payload);
    const proto::NakPayload nak = parse_as<proto::NakPayload>(rig.receive().at(0));
    EXPECT_EQ(nak.status, static_cast<uint8_t>(proto::Status::out_of_range));
    EXPECT_EQ(nak.field, static_cast<uint8_t>(c.field)) << proto::cal_field_name(static_cast<uint8_t>(c.field));
    for (uint16_t i = 0; i < kEepromBytes; ++i) ASSERT_EQ(rig.board.eeprom()[i], 0xFF) << "byte " << i;
  }
}

TEST(FirmwareCal, FourAgreeingEntriesCompensateEveryOutputAsEq1Predicts) {
  NativeRig rig;
  EXPECT_EQ(poll(rig).cal_state, static_cast<uint8_t>(CalState::none));
  upload(rig);
  const proto::VersionPayload version = ask<proto::VersionPayload>(rig, MsgType::hello);
  EXPECT_EQ(version.cal_state, static_cast<uint8_t>(CalState::active));
  EXPECT_EQ(version.cal_id, 7);
  // Samples over the first 40 minutes, where the transient is largest, against the double reference.
  for (uint64_t t = 250000; t < 2400ULL * 250000; t += 61ULL * 250000) {
    rig.run_until(t, constant_code);
    const proto::SamplePayload s = poll(rig);
    ASSERT_EQ(s.cal_state, static_cast<uint8_t>(CalState::active));
    ASSERT_EQ(s.cal_id, 7);
    const double t_s = s.tick / 250000.0;
    for (uint8_t c = 0; c < kChannelCount; ++c) {
      const proto::CalPayload m = table1(c);
      const double offset = c == 0 ? (m.c1_q8 + m.c2_q8 - 512.0 * 256) : 0.0;
      const double expected = kCode * 256.0 + m.c1_q8 * std::exp(-t_s * 1000.0 / m.t_ms) - offset;
      EXPECT_LE(std::fabs(s.value_q8[c] - expected), 0.5 + 0.01) << "channel " << int(c) << " at " << t_s << " s";
    }
  }
}

TEST(FirmwareCal, APartialUploadOrAClearedEntryLeavesTheOutputsAsMeasured) {
  NativeRig rig;
  for (uint8_t c = 0; c < 3; ++c) {
    rig.send_cal(table1(c));
    ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
  }
  rig.run_until(250000, constant_code);
  proto::SamplePayload s = poll(rig);
  EXPECT_EQ(s.cal_state, static_cast<uint8_t>(CalState::mixed));
  EXPECT_EQ(s.cal_id, 0);
  EXPECT_EQ(s.value_q8[0], kCode * 256);
  // A fourth entry of another calibration: still mixed.
  rig.send_cal(table1(3, 8));
  ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
  EXPECT_EQ(poll(rig).cal_state, static_cast<uint8_t>(CalState::mixed));
  // Completed, then cleared entry by entry with cal_id 0: none.
  rig.send_cal(table1(3, 7));
  ASSERT_TRUE(is(rig.receive().at(0), MsgType::ack));
  EXPECT_EQ(poll(rig).cal_state, static_cast<uint8_t>(CalState::active));
  upload(rig, 0);
  s = poll(rig);
  EXPECT_EQ(s.cal_state, static_cast<uint8_t>(CalState::none));
  EXPECT_EQ(s.value_q8[3], kCode * 256);
}

TEST(FirmwareCal, ADamagedEntryIsFoundAtBootAndSaidInStatus) {
  NativeRig before;
  upload(before);
  std::vector<uint8_t> eeprom(before.board.eeprom(), before.board.eeprom() + kEepromBytes);
  eeprom[kCalEepromAddress + 2 * kCalEntryBytes + 5] ^= 0x10;  // one bit of accel_y's C1
  NativeRig after(eeprom.data(), ResetInfo{kResetPowerOn, 0});
  EXPECT_EQ(ask<proto::StatusPayload>(after, MsgType::status_get).cal_state, static_cast<uint8_t>(CalState::damaged));
  after.run_until(250000, constant_code);
  const proto::SamplePayload s = poll(after);
  EXPECT_EQ(s.cal_state, static_cast<uint8_t>(CalState::damaged));
  for (uint8_t c = 0; c < kChannelCount; ++c) EXPECT_EQ(s.value_q8[c], kCode * 256);
}

TEST(FirmwareCal, APowerCycleStartsTheExponentialAgainAndAWarmRestartTakesItAsOver) {
  std::vector<uint8_t> eeprom;
  {
    NativeRig before;
    upload(before);
    eeprom.assign(before.board.eeprom(), before.board.eeprom() + kEepromBytes);
  }
  proto::SamplePayload c{};
  proto::SamplePayload w{};
  {
    NativeRig cold(eeprom.data(), ResetInfo{kResetPowerOn, 0});
    cold.run_until(250000, constant_code);
    c = poll(cold);
  }
  {
    NativeRig warm(eeprom.data(), ResetInfo{kResetWatchdog, 0});
    warm.run_until(250000, constant_code);
    w = poll(warm);
  }
  EXPECT_EQ(c.cal_state, static_cast<uint8_t>(CalState::active));
  EXPECT_EQ(w.cal_state, static_cast<uint8_t>(CalState::settled));
  EXPECT_EQ(w.cal_id, 7);
  // accel_z, 1 s after the reset: C1 e^(-t/1050 s) added when cold, nothing when warm.
  EXPECT_NEAR(c.value_q8[3] - kCode * 256, 28 * 256 * std::exp(-static_cast<double>(c.tick) / 250000.0 / 1050.0), 0.51);
  EXPECT_EQ(w.value_q8[3], kCode * 256);
  // The gyro referred to zero loses its settled offset C1 + C2 - 512 = -4 counts either way.
  EXPECT_EQ(w.value_q8[0], (kCode + 4) * 256);
}

TEST(FirmwareCal, AVersionOneHostIsAnsweredWithAVersionOneVersionNamingVersionTwo) {
  NativeRig rig;
  uint8_t frame[proto::kMaxFrameSize];
  const size_t n = proto::encode_legacy_hello(3, frame, sizeof frame);
  rig.send_bytes(frame, n);
  // A v1 host's decoder reads the answer: version byte 1, v1's 20-byte VERSION under v1's seed.
  std::vector<uint8_t> bytes(proto::kMaxFrameSize * 2);
  const size_t got = rig.board.transmit(bytes.data(), bytes.size());
  ASSERT_EQ(got, proto::frame_size(proto::kLegacyVersionPayloadSize));
  EXPECT_EQ(bytes[proto::kOffsetVersion], proto::kLegacyProtocolVersion);
  EXPECT_EQ(bytes[proto::kOffsetType], proto::type_id(MsgType::version));
  EXPECT_EQ(bytes[proto::kOffsetPayload], proto::kProtocolVersion);  // proto_version, where v1 reads it
  const uint16_t crc = proto::crc16_ibm3740_update(
      proto::crc16_ibm3740(bytes.data() + proto::kCrcStart, proto::kHeaderSize - proto::kCrcStart + 20),
      proto::kLegacyVersionSeed);
  EXPECT_EQ(bytes[proto::kHeaderSize + 20], crc & 0xFF);
  EXPECT_EQ(bytes[proto::kHeaderSize + 21], crc >> 8);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
