// SipHash-2-4 after the paper's specification (siphash.hpp): two compression rounds per 8-byte word, four at the end.
#include "driftlab/auth/siphash.hpp"

namespace driftlab {
namespace auth {
namespace {

inline uint64_t rotl(uint64_t x, unsigned b) { return (x << b) | (x >> (64U - b)); }

inline uint64_t load_u64_le(const uint8_t* p) {
  uint64_t v = 0;
  for (unsigned i = 8; i-- > 0;) {
    v = (v << 8) | p[i];
  }
  return v;
}

struct State {
  uint64_t v0, v1, v2, v3;

  void round() {
    v0 += v1;
    v1 = rotl(v1, 13);
    v1 ^= v0;
    v0 = rotl(v0, 32);
    v2 += v3;
    v3 = rotl(v3, 16);
    v3 ^= v2;
    v0 += v3;
    v3 = rotl(v3, 21);
    v3 ^= v0;
    v2 += v1;
    v1 = rotl(v1, 17);
    v1 ^= v2;
    v2 = rotl(v2, 32);
  }

  void absorb(uint64_t m) {
    v3 ^= m;
    round();
    round();
    v0 ^= m;
  }
};

}  // namespace

uint64_t siphash24(const uint8_t (&key)[kKeyBytes], const uint8_t* data, size_t size) {
  const uint64_t k0 = load_u64_le(key);
  const uint64_t k1 = load_u64_le(key + 8);
  State s = {k0 ^ 0x736f6d6570736575ULL, k1 ^ 0x646f72616e646f6dULL, k0 ^ 0x6c7967656e657261ULL,
             k1 ^ 0x7465646279746573ULL};
  const size_t whole = size - size % 8U;
  for (size_t i = 0; i < whole; i += 8) {
    s.absorb(load_u64_le(data + i));
  }
  // The last word: the remaining bytes, and the length's low byte on top.
  uint64_t last = static_cast<uint64_t>(size & 0xFFU) << 56;
  for (size_t i = whole; i < size; ++i) {
    last |= static_cast<uint64_t>(data[i]) << (8U * (i - whole));
  }
  s.absorb(last);
  s.v2 ^= 0xFFU;
  for (int r = 0; r < 4; ++r) {
    s.round();
  }
  return s.v0 ^ s.v1 ^ s.v2 ^ s.v3;
}

}  // namespace auth
}  // namespace driftlab
