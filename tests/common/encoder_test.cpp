// Encoder (encoder.hpp): golden frames computed from the spec outside C++, encode -> decode round trips of
// every type with random field values, sequence wrap, and refusal of buffers that are too small.
#include "driftlab/proto/encoder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "driftlab/proto/decoder.hpp"
#include "random_payloads.hpp"

namespace driftlab {
namespace proto {
namespace {

using testing::expect_fields_equal;
using testing::randomize;

// Golden frames: Python's struct.pack for the payload and a bitwise CRC-16/IBM-3740, from docs/protocol.md.
const std::vector<uint8_t> kHelloSeq0x1234 = {0xD7, 0x1A, 0x02, 0x01, 0x34, 0x12, 0x00, 0x4C, 0x96};
// The same HELLO in version 1 (what encode_legacy_hello sends to find a v1 board).
const std::vector<uint8_t> kV1HelloSeq0x1234 = {0xD7, 0x1A, 0x01, 0x01, 0x34, 0x12, 0x00, 0xAC, 0x58};
// SAMPLE seq 0xFFFF: tick 0x01020304, value_q8 {512 counts, -3 counts - 1/256, INT32_MAX, INT32_MIN},
// sat_flags 0x0A, n_window 64, dropped 0xFFFF, cal_state 1 (active), cal_id 0xBEEF, temp_code 0x0123.
const std::vector<uint8_t> kSampleSeq0xFFFF = {
    0xD7, 0x1A, 0x02, 0x07, 0xFF, 0xFF, 0x1D, 0x04, 0x03, 0x02, 0x01, 0x00, 0x00, 0x02, 0x00, 0xFF, 0xFC, 0xFF, 0xFF,
    0xFF, 0xFF, 0xFF, 0x7F, 0x00, 0x00, 0x00, 0x80, 0x0A, 0x40, 0xFF, 0xFF, 0x01, 0xEF, 0xBE, 0x23, 0x01, 0x14, 0x9C};
// A v1 VERSION as a v2 board answers a v1 HELLO (seq 5): proto_version 2, firmware 0.2.0, board 3, 10 bits,
// 5000 mV, 250 kHz, 4 channels on ADC0..3, reset cause 1, no assertion; v1's 20 bytes and seed 0x59.
const std::vector<uint8_t> kV1VersionSeq5 = {0xD7, 0x1A, 0x01, 0x02, 0x05, 0x00, 0x14, 0x02, 0x00, 0x02,
                                             0x00, 0x03, 0x0A, 0x88, 0x13, 0x90, 0xD0, 0x03, 0x00, 0x04,
                                             0x00, 0x01, 0x02, 0x03, 0x01, 0x00, 0x00, 0x7F, 0xCE};

// Authenticated commands (command_auth.hpp), their tags by a SipHash-2-4 written in Python from the paper and checked
// there against its published vector. Key 00..0F throughout.
// CONFIG_SET seq 0x0102: 100 ms, 25 conversions, window 25, order 1, stream, no raw; counter 7.
const std::vector<uint8_t> kConfigSetSeq0x0102 = {0xD7, 0x1A, 0x02, 0x04, 0x02, 0x01, 0x13, 0x64, 0x00, 0x19,
                                                  0x19, 0x01, 0x01, 0x00, 0x07, 0x00, 0x00, 0x00, 0xD2, 0xCA,
                                                  0xBB, 0xC5, 0xB8, 0xB5, 0x4C, 0x7B, 0x82, 0x9F};
// The same configuration to an open board (no key: a zero tag), seq 0, counter 1.
const std::vector<uint8_t> kOpenConfigSetSeq0 = {0xD7, 0x1A, 0x02, 0x04, 0x00, 0x00, 0x13, 0x64, 0x00, 0x19,
                                                 0x19, 0x01, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00,
                                                 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x7A, 0xC1};
// KEY_SET seq 9 of the new key F0..FF, sealed with SipHash(key, A5 || counter || block) for blocks 0, 1; counter
// 0x01020304.
const std::vector<uint8_t> kKeySetSeq9 = {0xD7, 0x1A, 0x02, 0x10, 0x09, 0x00, 0x1C, 0x3D, 0xF6, 0x4D, 0xAB, 0x58, 0xC3,
                                          0xA3, 0xF2, 0x76, 0xBC, 0xC5, 0x0F, 0x8C, 0x17, 0x2A, 0x0F, 0x04, 0x03, 0x02,
                                          0x01, 0x43, 0x33, 0x30, 0x2D, 0x82, 0xA7, 0x7B, 0x2D, 0xDE, 0x4E};

constexpr Key kTestKey = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

TEST(Encoder, AuthenticatedCommandsMatchTheirGoldenFrames) {
  const ConfigPayload config = {100, 25, 25, 1, 1, 0};
  uint8_t out[kMaxFrameSize] = {};
  size_t n = encode_config_set(config, CommandAuth{&kTestKey, 7}, 0x0102, out, sizeof(out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kConfigSetSeq0x0102);
  EXPECT_TRUE(trailer_tag_matches(out, kTestKey));
  EXPECT_EQ(trailer_counter(out), 7u);
  n = encode_config_set(config, CommandAuth{nullptr, 1}, 0, out, sizeof(out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kOpenConfigSetSeq0);
  Key next = {};
  for (uint8_t i = 0; i < 16; ++i) next[i] = static_cast<uint8_t>(0xF0 + i);
  n = encode_key_set(next, CommandAuth{&kTestKey, 0x01020304}, 9, out, sizeof(out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kKeySetSeq9);
  Key unsealed = {};
  seal_key(kTestKey, 0x01020304, out + kOffsetPayload, unsealed);
  EXPECT_EQ(std::vector<uint8_t>(unsealed, unsealed + 16), std::vector<uint8_t>(next, next + 16));
  EXPECT_EQ(encode_key_set(next, CommandAuth{nullptr, 1}, 9, out, sizeof(out)), 0u) << "an open board has no key";
}

TEST(Encoder, AnyChangedByteBreaksTheTag) {
  uint8_t out[kMaxFrameSize] = {};
  const size_t n =
      encode_config_set(ConfigPayload{100, 25, 25, 1, 1, 0}, CommandAuth{&kTestKey, 7}, 3, out, sizeof(out));
  Key other = {};
  std::copy(std::begin(kTestKey), std::end(kTestKey), other);
  other[15] ^= 0x80;
  EXPECT_FALSE(trailer_tag_matches(out, other));
  // Every bit the tag covers or is: the version byte through the tag's last byte.
  for (size_t byte = kOffsetVersion; byte < n - kCrcSize; ++byte) {
    if (byte == kOffsetLen) continue;  // the length locates the trailer; the decoder fixes it per type
    for (uint8_t bit = 0; bit < 8; ++bit) {
      out[byte] ^= static_cast<uint8_t>(1U << bit);
      EXPECT_FALSE(trailer_tag_matches(out, kTestKey)) << "byte " << byte << " bit " << int{bit};
      out[byte] ^= static_cast<uint8_t>(1U << bit);
    }
  }
  EXPECT_TRUE(trailer_tag_matches(out, kTestKey));
}

TEST(Encoder, HelloMatchesGoldenFrame) {
  uint8_t out[kMaxFrameSize] = {};
  const size_t n = encode_hello(0x1234, out, sizeof(out));
  ASSERT_EQ(n, kHelloSeq0x1234.size());
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kHelloSeq0x1234);
}

TEST(Encoder, SampleMatchesGoldenFrame) {
  SamplePayload p{};
  p.tick = 0x01020304;
  p.value_q8[0] = 512 * 256;
  p.value_q8[1] = -3 * 256 - 1;
  p.value_q8[2] = INT32_MAX;
  p.value_q8[3] = INT32_MIN;
  p.sat_flags = 0x0A;
  p.n_window = 64;
  p.dropped = 0xFFFF;
  p.cal_state = 1;
  p.cal_id = 0xBEEF;
  p.temp_code = 0x0123;
  uint8_t out[kMaxFrameSize] = {};
  const size_t n = encode_sample(p, 0xFFFF, out, sizeof(out));
  ASSERT_EQ(n, kSampleSeq0xFFFF.size());
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kSampleSeq0xFFFF);
}

TEST(Encoder, VersionOneFramesMatchTheirGoldenFrames) {
  uint8_t out[kMaxFrameSize] = {};
  size_t n = encode_legacy_hello(0x1234, out, sizeof(out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kV1HelloSeq0x1234);
  VersionPayload v{};
  v.proto_version = 2;
  v.fw_minor = 2;
  v.board_id = 3;
  v.adc_bits = 10;
  v.vref_mv = 5000;
  v.tick_hz = 250000;
  v.channel_count = 4;
  for (uint8_t c = 0; c < 4; ++c) v.adc_pin[c] = c;
  v.reset_cause = 1;
  v.cal_state = 1;  // v2's own fields are cut from the v1 frame
  v.cal_id = 77;
  n = encode_legacy_version(v, 5, out, sizeof(out));
  EXPECT_EQ(std::vector<uint8_t>(out, out + n), kV1VersionSeq5);
}

// Feeds one frame and returns true if the decoder delivered it exactly at its last byte.
bool decode_exactly(Decoder& dec, const uint8_t* frame, size_t n) {
  for (size_t i = 0; i + 1 < n; ++i) {
    if (dec.feed(frame[i])) {
      return false;
    }
  }
  return dec.feed(frame[n - 1]);
}

// Random fields through `encode(payload, seq, counter, frame, size)` and the decoder: they come back, and for an
// authenticated type the trailer carries the counter and a tag that verifies.
template <typename Payload, typename Encode>
void round_trip_with(MsgType type, Encode encode, uint32_t seed, bool authenticated) {
  std::mt19937 rng(seed);
  Decoder dec;
  const size_t trailer = authenticated ? kAuthTrailerBytes : 0;
  for (int trial = 0; trial < 500; ++trial) {
    Payload sent{};
    randomize(rng, &sent);
    const uint16_t seq = testing::random_int<uint16_t>(rng);
    const uint32_t counter = testing::random_int<uint32_t>(rng);
    uint8_t frame[kMaxFrameSize] = {};
    const size_t n = encode(sent, seq, counter, frame, sizeof(frame));
    ASSERT_EQ(n, frame_size(payload_len_of(type)));
    ASSERT_TRUE(decode_exactly(dec, frame, n)) << "trial " << trial;
    EXPECT_EQ(dec.type(), type);
    EXPECT_EQ(dec.seq(), seq);
    Payload got{};
    ASSERT_TRUE(parse(dec.payload(), dec.payload_len() - trailer, &got));
    expect_fields_equal(sent, got);
    if (authenticated) {
      EXPECT_EQ(trailer_counter(dec.frame()), counter);
      EXPECT_TRUE(trailer_tag_matches(dec.frame(), kTestKey));
    }
  }
  EXPECT_EQ(dec.counters().frames_ok, 500u);
  EXPECT_EQ(dec.counters().resync_bytes, 0u);
}

template <typename Payload>
void round_trip(MsgType type, size_t (*encode)(const Payload&, uint16_t, uint8_t*, size_t), uint32_t seed) {
  round_trip_with<Payload>(
      type, [encode](const Payload& p, uint16_t seq, uint32_t, uint8_t* f, size_t n) { return encode(p, seq, f, n); },
      seed, false);
}

template <typename Payload>
void command_round_trip(MsgType type, size_t (*encode)(const Payload&, const CommandAuth&, uint16_t, uint8_t*, size_t),
                        uint32_t seed) {
  round_trip_with<Payload>(
      type,
      [encode](const Payload& p, uint16_t seq, uint32_t counter, uint8_t* f, size_t n) {
        return encode(p, CommandAuth{&kTestKey, counter}, seq, f, n);
      },
      seed, true);
}

TEST(Encoder, VersionRoundTripsWithRandomFields) { round_trip(MsgType::version, encode_version, 1); }
TEST(Encoder, ConfigSetRoundTripsWithRandomFields) { command_round_trip(MsgType::config_set, encode_config_set, 2); }
TEST(Encoder, ConfigRoundTripsWithRandomFields) { round_trip(MsgType::config, encode_config, 3); }
TEST(Encoder, SampleRoundTripsWithRandomFields) { round_trip(MsgType::sample, encode_sample, 4); }
TEST(Encoder, RawRoundTripsWithRandomFields) { round_trip(MsgType::raw, encode_raw, 5); }
TEST(Encoder, AckRoundTripsWithRandomFields) { round_trip(MsgType::ack, encode_ack, 6); }
TEST(Encoder, NakRoundTripsWithRandomFields) { round_trip(MsgType::nak, encode_nak, 7); }
TEST(Encoder, StatusRoundTripsWithRandomFields) { round_trip(MsgType::status, encode_status, 8); }
TEST(Encoder, CalSetRoundTripsWithRandomFields) { command_round_trip(MsgType::cal_set, encode_cal_set, 9); }
TEST(Encoder, CalGetRoundTripsWithRandomFields) { round_trip(MsgType::cal_get, encode_cal_get, 10); }
TEST(Encoder, CalRoundTripsWithRandomFields) { round_trip(MsgType::cal, encode_cal, 11); }

struct EmptyEncoder {
  MsgType type;
  size_t (*encode)(uint16_t, uint8_t*, size_t);
};
const EmptyEncoder kEmptyEncoders[] = {{MsgType::hello, encode_hello},
                                       {MsgType::config_get, encode_config_get},
                                       {MsgType::poll, encode_poll},
                                       {MsgType::status_get, encode_status_get}};

TEST(Encoder, EmptyPayloadTypesRoundTripWithSequenceWrap) {
  Decoder dec;
  for (const EmptyEncoder& e : kEmptyEncoders) {
    // Sequence numbers across the u16 wrap: the sender's +1 per frame goes 0xFFFE, 0xFFFF, 0, 1.
    for (uint32_t s = 0xFFFE; s <= 0x10001; ++s) {
      const uint16_t seq = static_cast<uint16_t>(s & 0xFFFFu);
      uint8_t frame[kMaxFrameSize] = {};
      const size_t n = e.encode(seq, frame, sizeof(frame));
      ASSERT_EQ(n, kFrameOverhead);
      ASSERT_TRUE(decode_exactly(dec, frame, n));
      EXPECT_EQ(dec.type(), e.type);
      EXPECT_EQ(dec.seq(), seq);
      EXPECT_EQ(dec.payload_len(), 0);
    }
  }
}

TEST(Encoder, SequenceWrapsThroughEveryValueInOrder) {
  std::mt19937 rng(99);
  Decoder dec;
  uint16_t expected = 0xFF00;
  for (uint32_t i = 0; i < 0x200; ++i) {
    RawPayload p{};
    randomize(rng, &p);
    uint8_t frame[kMaxFrameSize] = {};
    const size_t n = encode_raw(p, static_cast<uint16_t>(0xFF00u + i), frame, sizeof(frame));
    ASSERT_TRUE(decode_exactly(dec, frame, n));
    EXPECT_EQ(dec.seq(), expected);
    expected = static_cast<uint16_t>(expected + 1u);
  }
  EXPECT_EQ(expected, 0x0100);
}

TEST(Encoder, RefusesEveryBufferSmallerThanTheFrameAndWritesNothing) {
  SamplePayload p{};
  p.tick = 7;
  const size_t need = frame_size(kSamplePayloadSize);
  for (size_t size = 0; size < need; ++size) {
    std::vector<uint8_t> out(need, 0xAA);
    EXPECT_EQ(encode_sample(p, 1, out.data(), size), 0u) << "size " << size;
    EXPECT_EQ(out, std::vector<uint8_t>(need, 0xAA)) << "size " << size;
  }
  std::vector<uint8_t> out(need);
  EXPECT_EQ(encode_sample(p, 1, out.data(), need), need);
  for (size_t size = 0; size < kFrameOverhead; ++size) {
    EXPECT_EQ(encode_poll(1, out.data(), size), 0u) << "size " << size;
  }
}

TEST(Encoder, EncodeFrameRefusesUnknownTypeAndWrongLength) {
  uint8_t payload[kMaxPayload] = {};
  uint8_t out[kMaxFrameSize + 8] = {};
  EXPECT_EQ(encode_frame(0x00, 0, payload, 0, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_frame(0x11, 0, payload, 0, out, sizeof(out)), 0u);
  // An authenticated type only through encode_authenticated, which adds the trailer.
  EXPECT_EQ(encode_frame(type_id(MsgType::config_set), 0, payload, 19, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_authenticated(type_id(MsgType::config_set), 0, payload, 19, CommandAuth{}, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_authenticated(type_id(MsgType::config_set), 0, payload, 7, CommandAuth{}, out, sizeof(out)),
            frame_size(19));
  EXPECT_EQ(encode_authenticated(type_id(MsgType::status), 0, payload, 15, CommandAuth{}, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_frame(type_id(MsgType::hello), 0, payload, 1, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_frame(type_id(MsgType::sample), 0, payload, 28, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_frame(type_id(MsgType::sample), 0, payload, kMaxPayload, out, sizeof(out)), 0u);
  EXPECT_EQ(encode_frame(type_id(MsgType::sample), 0, payload, 29, out, sizeof(out)), frame_size(29));
}

TEST(Encoder, EncodeFrameEqualsTypedEncoder) {
  std::mt19937 rng(5);
  StatusPayload p{};
  randomize(rng, &p);
  uint8_t payload[kStatusPayloadSize] = {};
  ASSERT_EQ(serialize(p, payload, sizeof(payload)), kStatusPayloadSize);
  uint8_t a[kMaxFrameSize] = {};
  uint8_t b[kMaxFrameSize] = {};
  const size_t na = encode_frame(type_id(MsgType::status), 321, payload, sizeof(payload), a, sizeof(a));
  const size_t nb = encode_status(p, 321, b, sizeof(b));
  ASSERT_EQ(na, nb);
  EXPECT_EQ(std::vector<uint8_t>(a, a + na), std::vector<uint8_t>(b, b + nb));
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
