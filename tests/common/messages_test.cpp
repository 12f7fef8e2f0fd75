// Payload layouts (messages.hpp) against the byte offsets of docs/protocol.md §3, written out by hand here.
#include "driftlab/proto/messages.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "random_payloads.hpp"

namespace driftlab {
namespace proto {
namespace {

using Bytes = std::vector<uint8_t>;

template <typename Payload>
Bytes serialized(const Payload& p, size_t size) {
  Bytes out(size + 4, 0xEE);
  EXPECT_EQ(serialize(p, out.data(), out.size()), size);
  // Nothing written past the payload's fixed length.
  EXPECT_EQ(Bytes(out.begin() + static_cast<std::ptrdiff_t>(size), out.end()), Bytes(4, 0xEE));
  out.resize(size);
  return out;
}

TEST(Messages, VersionLayoutMatchesSpecOffsets) {
  VersionPayload p{};
  p.proto_version = 1;
  p.fw_major = 2;
  p.fw_minor = 3;
  p.fw_patch = 4;
  p.board_id = 5;
  p.adc_bits = 10;
  p.vref_mv = 5000;    // 0x1388
  p.tick_hz = 250000;  // 0x0003D090
  p.channel_count = 4;
  p.adc_pin[0] = 0;
  p.adc_pin[1] = 1;
  p.adc_pin[2] = 2;
  p.adc_pin[3] = 3;
  p.reset_cause = 0x08;
  p.assert_line = 0x0102;
  p.cal_state = 2;
  p.cal_id = 0xA1B2;
  p.auth_state = 1;
  p.auth_counter = 0x0A0B0C0D;
  const Bytes expected = {1, 2, 3, 4, 5, 10, 0x88, 0x13, 0x90, 0xD0, 0x03, 0x00, 4,    0,
                          1, 2, 3, 8, 2, 1,  2,    0xB2, 0xA1, 1,    0x0D, 0x0C, 0x0B, 0x0A};
  EXPECT_EQ(serialized(p, kVersionPayloadSize), expected);
}

TEST(Messages, ConfigLayoutMatchesSpecOffsets) {
  ConfigPayload p{};
  p.output_period_ms = 60000;  // 0xEA60
  p.conversions_per_output = 16;
  p.window = 64;
  p.fit_order = 1;
  p.mode = static_cast<uint8_t>(OutputMode::stream);
  p.raw = 1;
  EXPECT_EQ(serialized(p, kConfigPayloadSize), (Bytes{0x60, 0xEA, 16, 64, 1, 1, 1}));
}

TEST(Messages, RawAckNakLayoutsMatchSpecOffsets) {
  RawPayload raw{};
  raw.tick = 0xA1B2C3D4;
  raw.code[0] = 0;
  raw.code[1] = 1023;
  raw.code[2] = 512;
  raw.code[3] = 0x0201;
  EXPECT_EQ(serialized(raw, kRawPayloadSize),
            (Bytes{0xD4, 0xC3, 0xB2, 0xA1, 0x00, 0x00, 0xFF, 0x03, 0x00, 0x02, 0x01, 0x02}));

  AckPayload ack{};
  ack.acked_type = 0x04;
  ack.acked_seq = 0xBEEF;
  EXPECT_EQ(serialized(ack, kAckPayloadSize), (Bytes{0x04, 0xEF, 0xBE}));

  NakPayload nak{};
  nak.nacked_type = 0x04;
  nak.nacked_seq = 0x0102;
  nak.status = 3;
  nak.field = kNakFieldNone;
  EXPECT_EQ(serialized(nak, kNakPayloadSize), (Bytes{0x04, 0x02, 0x01, 3, 0xFF}));
}

TEST(Messages, StatusLayoutMatchesSpecOffsets) {
  StatusPayload p{};
  p.uptime_ticks = 0x11223344;
  p.rx_frames = 0x0101;
  p.rx_bad_crc = 0x0202;
  p.rx_bad_length = 0x0303;
  p.rx_unknown_type = 0x0404;
  p.rx_resync_bytes = 0x0505;
  p.rx_overflow = 0x0606;
  p.tx_overflow = 0x0707;
  p.dropped = 0xFFFF;
  p.cal_state = 3;
  p.cal_id = 0x0102;
  p.auth_refused = 0x0809;
  p.auth_replayed = 0x0A0B;
  const Bytes expected = {0x44, 0x33, 0x22, 0x11, 1,    1,    2, 2, 3, 3, 4, 4,   5,  5,
                          6,    6,    7,    7,    0xFF, 0xFF, 3, 2, 1, 9, 8, 0xB, 0xA};
  EXPECT_EQ(serialized(p, kStatusPayloadSize), expected);
}

TEST(Messages, CalLayoutMatchesSpecOffsets) {
  CalPayload p{};
  p.cal_id = 0x1234;
  p.channel = 3;
  p.flags = kCalFlagZero;
  p.c1_q8 = -2;          // 0xFFFFFFFE
  p.c2_q8 = 0x00020000;  // 512 counts
  p.t_ms = 411000;       // 0x00064578
  const Bytes expected = {0x34, 0x12, 3, 1, 0xFE, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0x02, 0x00, 0x78, 0x45, 0x06, 0x00};
  EXPECT_EQ(serialized(p, kCalPayloadSize), expected);
  CalGetPayload g{2};
  EXPECT_EQ(serialized(g, kCalGetPayloadSize), (Bytes{2}));
}

TEST(Messages, SampleNegativeValuesAreTwosComplement) {
  SamplePayload p{};
  p.value_q8[0] = -1;
  p.value_q8[1] = -256;
  p.value_q8[2] = INT32_MIN;
  p.value_q8[3] = 1;
  const Bytes b = serialized(p, kSamplePayloadSize);
  EXPECT_EQ(Bytes(b.begin() + 4, b.begin() + 20),
            (Bytes{0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x80, 0x01, 0x00, 0x00, 0x00}));
  SamplePayload back{};
  ASSERT_TRUE(parse(b.data(), b.size(), &back));
  testing::expect_fields_equal(p, back);
}

TEST(Messages, ParseRejectsAnyOtherLength) {
  const Bytes buf(40, 0);
  SamplePayload sample{};
  ConfigPayload config{};
  StatusPayload status{};
  for (size_t n = 0; n < buf.size(); ++n) {
    EXPECT_EQ(parse(buf.data(), n, &sample), n == kSamplePayloadSize) << n;
    EXPECT_EQ(parse(buf.data(), n, &config), n == kConfigPayloadSize) << n;
    EXPECT_EQ(parse(buf.data(), n, &status), n == kStatusPayloadSize) << n;
  }
}

TEST(Messages, SerializeRefusesSmallBuffers) {
  Bytes out(kSamplePayloadSize);
  SamplePayload sample{};
  VersionPayload version{};
  NakPayload nak{};
  for (size_t n = 0; n < kSamplePayloadSize; ++n) {
    EXPECT_EQ(serialize(sample, out.data(), n), 0u) << n;
  }
  EXPECT_EQ(serialize(version, out.data(), kVersionPayloadSize - 1), 0u);
  EXPECT_EQ(serialize(nak, out.data(), kNakPayloadSize - 1), 0u);
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
