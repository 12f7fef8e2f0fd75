// Decoder (decoder.hpp) on constructed streams: one exact case per reject counter, false starts, re-scan after
// a rejected candidate, zero-length and largest payloads, back-to-back frames, sync bytes inside payloads.
#include "driftlab/proto/decoder.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "driftlab/proto/encoder.hpp"

namespace driftlab {
namespace proto {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes hello(uint16_t seq) {
  Bytes f(kMaxFrameSize);
  f.resize(encode_hello(seq, f.data(), f.size()));
  return f;
}

Bytes raw_frame(const RawPayload& p, uint16_t seq) {
  Bytes f(kMaxFrameSize);
  f.resize(encode_raw(p, seq, f.data(), f.size()));
  return f;
}

// A SAMPLE frame with no sync0 after its first byte, so a reject of it drops exactly the whole frame.
Bytes sample_without_inner_sync() {
  SamplePayload p{};
  p.tick = 1000;
  p.value_q8[0] = 512 * 256;
  for (uint16_t seq = 1;; ++seq) {
    Bytes f(kMaxFrameSize);
    f.resize(encode_sample(p, seq, f.data(), f.size()));
    bool inner_sync = false;
    for (size_t i = 1; i < f.size(); ++i) {
      inner_sync = inner_sync || f[i] == kSync0;
    }
    if (!inner_sync) {
      return f;
    }
  }
}

struct Delivered {
  size_t end_offset;  // index of the byte whose feed() (or the next() after it) delivered the frame
  Bytes frame;
};

// Feeds everything, draining with next() after each delivery, and records every delivered frame.
std::vector<Delivered> feed_all(Decoder& dec, const Bytes& stream) {
  std::vector<Delivered> out;
  for (size_t i = 0; i < stream.size(); ++i) {
    if (dec.feed(stream[i])) {
      do {
        out.push_back({i, Bytes(dec.frame(), dec.frame() + dec.frame_size())});
      } while (dec.next());
    }
  }
  return out;
}

Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& p : parts) {
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

void expect_counters(const DecoderCounters& c, uint32_t ok, uint32_t bad_crc, uint32_t bad_length,
                     uint32_t unknown_type, uint32_t bad_version, uint32_t resync_bytes) {
  EXPECT_EQ(c.frames_ok, ok);
  EXPECT_EQ(c.bad_crc, bad_crc);
  EXPECT_EQ(c.bad_length, bad_length);
  EXPECT_EQ(c.unknown_type, unknown_type);
  EXPECT_EQ(c.bad_version, bad_version);
  EXPECT_EQ(c.resync_bytes, resync_bytes);
}

TEST(Decoder, BackToBackFramesAreDeliveredExactlyAtTheirLastByte) {
  const Bytes a = hello(1);
  const Bytes b = sample_without_inner_sync();
  const Bytes c = hello(2);
  Decoder dec;
  const auto got = feed_all(dec, concat({a, b, c}));
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].end_offset, a.size() - 1);
  EXPECT_EQ(got[1].end_offset, a.size() + b.size() - 1);
  EXPECT_EQ(got[2].end_offset, a.size() + b.size() + c.size() - 1);
  EXPECT_EQ(got[0].frame, a);
  EXPECT_EQ(got[1].frame, b);
  EXPECT_EQ(got[2].frame, c);
  expect_counters(dec.counters(), 3, 0, 0, 0, 0, 0);
}

TEST(Decoder, ZeroLengthPayloadIsDelivered) {
  Decoder dec;
  const auto got = feed_all(dec, hello(0xABCD));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(dec.type(), MsgType::hello);
  EXPECT_EQ(dec.seq(), 0xABCD);
  EXPECT_EQ(dec.payload_len(), 0);
}

TEST(Decoder, LargestPayloadIsDelivered) {
  const Bytes f = sample_without_inner_sync();
  ASSERT_EQ(f.size(), frame_size(kSamplePayloadSize));
  Decoder dec;
  const auto got = feed_all(dec, f);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(dec.payload_len(), kSamplePayloadSize);
}

TEST(Decoder, CorruptedPayloadCountsOneBadCrcAndDropsTheWholeFrame) {
  Bytes bad = sample_without_inner_sync();
  bad[kOffsetPayload + 3] ^= 0x10;
  const Bytes good = hello(5);
  Decoder dec;
  const auto got = feed_all(dec, concat({bad, good}));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame, good);
  expect_counters(dec.counters(), 1, 1, 0, 0, 0, static_cast<uint32_t>(bad.size()));
}

TEST(Decoder, KnownTypeWithWrongLengthCountsOneBadLength) {
  const Bytes bad = {kSync0, kSync1, kProtocolVersion, type_id(MsgType::hello), 0x00, 0x00, 0x05};
  Decoder dec;
  const auto got = feed_all(dec, concat({bad, hello(1)}));
  ASSERT_EQ(got.size(), 1u);
  expect_counters(dec.counters(), 1, 0, 1, 0, 0, static_cast<uint32_t>(bad.size()));
}

TEST(Decoder, LengthByte255IsRejectedAtTheLengthByte) {
  const Bytes bad = {kSync0, kSync1, kProtocolVersion, type_id(MsgType::sample), 0x00, 0x00, 0xFF};
  Decoder dec;
  const auto got = feed_all(dec, concat({bad, hello(1)}));
  ASSERT_EQ(got.size(), 1u);
  expect_counters(dec.counters(), 1, 0, 1, 0, 0, static_cast<uint32_t>(bad.size()));
}

TEST(Decoder, UnknownTypeCountsOneUnknownType) {
  const Bytes bad = {kSync0, kSync1, kProtocolVersion, 0x11};
  Decoder dec;
  const auto got = feed_all(dec, concat({bad, hello(1)}));
  ASSERT_EQ(got.size(), 1u);
  expect_counters(dec.counters(), 1, 0, 0, 1, 0, static_cast<uint32_t>(bad.size()));
}

TEST(Decoder, OtherVersionCountsOneBadVersion) {
  // A version-3 frame: the decoder stops at the version byte, before type or length mean anything.
  const Bytes bad = {kSync0, kSync1, 0x03};
  Decoder dec;
  const auto got = feed_all(dec, concat({bad, hello(1)}));
  ASSERT_EQ(got.size(), 1u);
  expect_counters(dec.counters(), 1, 0, 0, 0, 1, static_cast<uint32_t>(bad.size()));
}

TEST(Decoder, OfVersionOneOnlyHelloIsTakenAndSaysItsVersion) {
  // A v1 board's VERSION (type 2) stops at the type byte; a v1 host's HELLO is delivered, flagged version 1.
  const Bytes v1_version = {kSync0, kSync1, kLegacyProtocolVersion, type_id(MsgType::version)};
  Bytes v1_hello = hello(7);
  v1_hello[kOffsetVersion] = kLegacyProtocolVersion;
  // CRC-16/IBM-3740 over version 1, type 1, seq 7, len 0, then the seed 0x9F, written out independently.
  const uint8_t covered[] = {0x01, 0x01, 0x07, 0x00, 0x00, kLegacyHelloSeed};
  const uint16_t crc = crc16_ibm3740(covered, sizeof covered);
  v1_hello[7] = static_cast<uint8_t>(crc & 0xFF);
  v1_hello[8] = static_cast<uint8_t>(crc >> 8);
  Decoder dec;
  std::vector<uint8_t> versions;
  for (uint8_t b : concat({v1_version, v1_hello})) {
    if (dec.feed(b)) {
      do {
        versions.push_back(dec.version());
      } while (dec.next());
    }
  }
  EXPECT_EQ(versions, (std::vector<uint8_t>{kLegacyProtocolVersion}));
  expect_counters(dec.counters(), 1, 0, 0, 0, 1, static_cast<uint32_t>(v1_version.size()));
}

TEST(Decoder, GarbageWithoutSyncCountsEachByteAsResync) {
  const Bytes garbage = {0x00, 0xFF, 0x1A, 0x01, 0x55, 0xAA, 0xD6, 0xD8, 0x1A, 0x1A};
  Decoder dec;
  const auto got = feed_all(dec, concat({garbage, hello(1)}));
  ASSERT_EQ(got.size(), 1u);
  expect_counters(dec.counters(), 1, 0, 0, 0, 0, static_cast<uint32_t>(garbage.size()));
}

TEST(Decoder, FalseStartByteIsSkippedAndTheNextSyncReexamined) {
  // sync0 sync0 sync1...: the first sync0 is a false start, the second begins the frame.
  const Bytes f = hello(3);
  Decoder dec;
  const auto got = feed_all(dec, concat({Bytes{kSync0}, f}));
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame, f);
  expect_counters(dec.counters(), 1, 0, 0, 0, 0, 1);
}

TEST(Decoder, FrameHiddenInsideTruncatedCandidateIsFound) {
  // A SAMPLE header whose frame was cut after 3 payload bytes, then four HELLOs. The SAMPLE candidate swallows
  // the first HELLOs until its 38 bytes are in and its CRC fails; re-scanning those bytes finds them.
  // (A parser that resumes at the current byte, as MAVLink's does, loses the first three.)
  const Bytes cut = {kSync0, kSync1, kProtocolVersion, type_id(MsgType::sample), 0x10, 0x00, 29, 0x01, 0x02, 0x03};
  const Bytes h1 = hello(10);
  const Bytes h2 = hello(11);
  const Bytes h3 = hello(12);
  const Bytes h4 = hello(13);
  const Bytes stream = concat({cut, h1, h2, h3, h4});
  Decoder dec;
  std::vector<uint16_t> seqs;
  std::vector<size_t> offsets;
  for (size_t i = 0; i < stream.size(); ++i) {
    if (dec.feed(stream[i])) {
      do {
        seqs.push_back(dec.seq());
        offsets.push_back(i);
      } while (dec.next());
    }
  }
  EXPECT_EQ(seqs, (std::vector<uint16_t>{10, 11, 12, 13}));
  const size_t candidate_end = frame_size(kSamplePayloadSize) - 1;
  // h1, h2 and h3 are complete inside the failed candidate: they come out at its last byte; h4 at its own end.
  EXPECT_EQ(offsets, (std::vector<size_t>{candidate_end, candidate_end, candidate_end, stream.size() - 1}));
  expect_counters(dec.counters(), 4, 1, 0, 0, 0, static_cast<uint32_t>(cut.size()));
  EXPECT_EQ(dec.bytes_held(), 0u);
}

TEST(Decoder, HeldFramesStillComeOutInOrderWithoutNext) {
  const Bytes cut = {kSync0, kSync1, kProtocolVersion, type_id(MsgType::sample), 0x10, 0x00, 29, 0x01, 0x02, 0x03};
  const Bytes stream = concat({cut, hello(10), hello(11), hello(12), hello(13)});
  Decoder dec;
  std::vector<uint16_t> seqs;
  for (uint8_t b : stream) {
    if (dec.feed(b)) {
      seqs.push_back(dec.seq());
    }
  }
  EXPECT_EQ(seqs, (std::vector<uint16_t>{10, 11, 12, 13}));
}

TEST(Decoder, SyncBytesInsidePayloadDoNotSplitTheFrame) {
  // RAW whose payload holds a complete HELLO frame: the outer frame is delivered, the inner one is payload.
  const Bytes inner = hello(0x77);
  RawPayload p{};
  Bytes payload(inner);
  payload.resize(kRawPayloadSize, kSync0);
  ASSERT_TRUE(parse(payload.data(), payload.size(), &p));
  const Bytes outer = raw_frame(p, 0x1A1A);
  Decoder dec;
  const auto got = feed_all(dec, concat({outer, outer}));
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].frame, outer);
  EXPECT_EQ(got[1].frame, outer);
  expect_counters(dec.counters(), 2, 0, 0, 0, 0, 0);
}

TEST(Decoder, DamagedOuterFrameExposesAValidFrameInItsPayload) {
  // With the outer sync1 damaged, the bytes of the embedded HELLO are a valid frame and are delivered: the
  // decoder judges bytes, not intentions (docs/protocol.md §6).
  const Bytes inner = hello(0x77);
  RawPayload p{};
  Bytes payload(inner);
  payload.resize(kRawPayloadSize, 0x00);
  ASSERT_TRUE(parse(payload.data(), payload.size(), &p));
  Bytes outer = raw_frame(p, 0x0101);
  outer[kOffsetSync1] = 0x00;
  Decoder dec;
  const auto got = feed_all(dec, outer);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].frame, inner);
}

TEST(Decoder, NoSingleDoubleOrTripleBitErrorInAnAckFrameIsDelivered) {
  // CRC-16/IBM-3740 has Hamming distance 4 at these lengths, so no pattern of up to 3 flipped bits in the
  // CRC-covered bytes and the CRC itself may pass. Sync bytes are excluded: flipping them only hides the frame.
  AckPayload ack{};
  ack.acked_type = 4;
  ack.acked_seq = 0x0102;
  Bytes f(kMaxFrameSize);
  f.resize(encode_ack(ack, 0x0304, f.data(), f.size()));
  const size_t first_bit = kCrcStart * 8;
  const size_t bits = f.size() * 8;
  size_t delivered = 0;
  size_t patterns = 0;
  auto try_pattern = [&](std::initializer_list<size_t> flips) {
    Bytes g = f;
    for (size_t bit : flips) {
      g[bit / 8] = static_cast<uint8_t>(g[bit / 8] ^ (1u << (bit % 8)));
    }
    Decoder dec;
    delivered += feed_all(dec, g).size();
    ++patterns;
  };
  for (size_t i = first_bit; i < bits; ++i) {
    try_pattern({i});
    for (size_t j = i + 1; j < bits; ++j) {
      try_pattern({i, j});
      for (size_t k = j + 1; k < bits; ++k) {
        try_pattern({i, j, k});
      }
    }
  }
  EXPECT_EQ(delivered, 0u) << "over " << patterns << " patterns";
}

TEST(Decoder, ResetForgetsHeldBytesButKeepsCounters) {
  Decoder dec;
  const Bytes f = hello(1);
  for (size_t i = 0; i + 1 < f.size(); ++i) {
    ASSERT_FALSE(dec.feed(f[i]));
  }
  EXPECT_EQ(dec.bytes_held(), f.size() - 1);
  dec.reset();
  EXPECT_EQ(dec.bytes_held(), 0u);
  EXPECT_EQ(feed_all(dec, f).size(), 1u);
  EXPECT_EQ(feed_all(dec, f).size(), 1u);
  EXPECT_EQ(dec.counters().frames_ok, 2u);
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
