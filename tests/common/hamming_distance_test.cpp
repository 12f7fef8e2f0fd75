// Hamming distance of the frame check at the longest frame of protocol v2 (SAMPLE), the figure
// docs/protocol.md §7 quotes: every error of 1-3 bits is detected, and some 4-bit errors are not.
//
// The CRC is linear: flipping a set of bits is undetected exactly when the XOR of the per-bit "syndromes"
// (change of computed CRC XOR change of received CRC field) is zero. So distinct, non-zero syndromes with no
// a^b == c prove distance >= 4, and one a^b == c^d gives a concrete 4-bit error, replayed through the decoder.
#include <gtest/gtest.h>

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "driftlab/proto/crc16.hpp"
#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/encoder.hpp"

namespace driftlab {
namespace proto {
namespace {

using Bytes = std::vector<uint8_t>;

struct Syndromes {
  size_t first_bit;  // bit index in the frame of syndrome 0 (first bit after the sync bytes)
  std::vector<uint16_t> s;
};

Syndromes sample_frame_syndromes() {
  const size_t covered = kOffsetPayload - kCrcStart + kSamplePayloadSize;  // version..payload end
  Syndromes out{kCrcStart * 8, {}};
  for (size_t bit = 0; bit < covered * 8; ++bit) {
    // Error pattern through the CRC from a zero register; the seed byte is never in error, so it is a zero.
    Bytes e(covered + 1, 0);
    e[bit / 8] = static_cast<uint8_t>(1u << (bit % 8));
    out.s.push_back(crc16_ibm3740(e.data(), e.size(), 0));
  }
  for (size_t bit = 0; bit < kCrcSize * 8; ++bit) {
    // The CRC field is little-endian: bit k of byte 0 is bit k of the value, byte 1 holds bits 8..15.
    out.s.push_back(static_cast<uint16_t>(1u << bit));
  }
  return out;
}

TEST(HammingDistance, EveryErrorOfUpToThreeBitsInASampleFrameIsDetected) {
  const Syndromes syn = sample_frame_syndromes();
  std::unordered_set<uint16_t> seen;
  for (uint16_t s : syn.s) {
    ASSERT_NE(s, 0) << "a 1-bit error would pass";
    ASSERT_TRUE(seen.insert(s).second) << "a 2-bit error would pass";
  }
  for (size_t a = 0; a < syn.s.size(); ++a) {
    for (size_t b = a + 1; b < syn.s.size(); ++b) {
      ASSERT_EQ(seen.count(static_cast<uint16_t>(syn.s[a] ^ syn.s[b])), 0u) << "a 3-bit error would pass";
    }
  }
}

TEST(HammingDistance, SomeFourBitErrorInASampleFramePassesTheDecoder) {
  const Syndromes syn = sample_frame_syndromes();
  std::unordered_map<uint16_t, std::pair<size_t, size_t>> pair_of;
  std::vector<size_t> flips;
  // Search payload and CRC bits only, so the header stays acceptable and the CRC alone decides.
  const size_t payload_first = (kOffsetPayload - kCrcStart) * 8;
  for (size_t a = payload_first; a < syn.s.size() && flips.empty(); ++a) {
    for (size_t b = a + 1; b < syn.s.size() && flips.empty(); ++b) {
      const uint16_t x = static_cast<uint16_t>(syn.s[a] ^ syn.s[b]);
      const auto it = pair_of.find(x);
      if (it != pair_of.end() && it->second.first != a && it->second.second != a && it->second.second != b) {
        flips = {it->second.first, it->second.second, a, b};
      } else {
        pair_of.emplace(x, std::make_pair(a, b));
      }
    }
  }
  ASSERT_EQ(flips.size(), 4u) << "no undetected 4-bit error found: distance would exceed 4";

  SamplePayload p{};
  p.tick = 123456;
  Bytes frame(kMaxFrameSize);
  frame.resize(encode_sample(p, 42, frame.data(), frame.size()));
  for (size_t f : flips) {
    const size_t bit = syn.first_bit + f;
    frame[bit / 8] = static_cast<uint8_t>(frame[bit / 8] ^ (1u << (bit % 8)));
  }
  SCOPED_TRACE(::testing::Message() << "flipped bits " << flips[0] << " " << flips[1] << " " << flips[2] << " "
                                    << flips[3]);
  Decoder dec;
  size_t delivered = 0;
  for (uint8_t byte : frame) {
    delivered += dec.feed(byte) ? 1u : 0u;
  }
  EXPECT_EQ(delivered, 1u) << "the decoder judges by CRC; this damaged frame has a matching one";
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
