// BLAKE2s after RFC 7693 §3 (blake2s.hpp).
#include "driftlab/auth/blake2s.hpp"

#include "rotate.hpp"

namespace driftlab {
namespace auth {
namespace {

const uint32_t kIv[8] = {0x6A09E667UL, 0xBB67AE85UL, 0x3C6EF372UL, 0xA54FF53AUL,
                         0x510E527FUL, 0x9B05688CUL, 0x1F83D9ABUL, 0x5BE0CD19UL};

const uint8_t kSigma[10][16] = {
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}, {14, 10, 4, 8, 9, 15, 13, 6, 1, 12, 0, 2, 11, 7, 5, 3},
    {11, 8, 12, 0, 5, 2, 15, 13, 10, 14, 3, 6, 7, 1, 9, 4}, {7, 9, 3, 1, 13, 12, 11, 14, 2, 6, 5, 10, 4, 0, 15, 8},
    {9, 0, 5, 7, 2, 4, 10, 15, 14, 1, 11, 12, 6, 8, 3, 13}, {2, 12, 6, 10, 0, 11, 8, 3, 4, 13, 7, 5, 15, 14, 1, 9},
    {12, 5, 1, 15, 14, 13, 4, 10, 0, 7, 6, 3, 9, 2, 8, 11}, {13, 11, 7, 14, 12, 1, 3, 9, 5, 0, 15, 4, 8, 6, 2, 10},
    {6, 15, 14, 9, 11, 3, 0, 8, 12, 2, 13, 7, 1, 4, 10, 5}, {10, 2, 8, 4, 7, 6, 1, 5, 15, 11, 9, 14, 3, 12, 13, 0}};

inline uint32_t load_u32_le(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}

void mix(uint32_t* v, unsigned a, unsigned b, unsigned c, unsigned d, uint32_t x, uint32_t y) {
  v[a] = v[a] + v[b] + x;
  v[d] = rotr32(v[d] ^ v[a], 16);
  v[c] = v[c] + v[d];
  v[b] = rotr32(v[b] ^ v[c], 12);
  v[a] = v[a] + v[b] + y;
  v[d] = rotr32(v[d] ^ v[a], 8);
  v[c] = v[c] + v[d];
  v[b] = rotr32(v[b] ^ v[c], 7);
}

void compress(uint32_t* h, const uint8_t* block, uint32_t counter, bool last) {
  uint32_t v[16];
  uint32_t m[16];
  for (unsigned i = 0; i < 8; ++i) {
    v[i] = h[i];
    v[i + 8] = kIv[i];
  }
  v[12] ^= counter;  // messages here are far below 2^32 bytes: the counter's high word stays 0
  if (last) {
    v[14] = ~v[14];
  }
  for (unsigned i = 0; i < 16; ++i) {
    m[i] = load_u32_le(block + 4 * i);
  }
  for (unsigned r = 0; r < 10; ++r) {
    const uint8_t* s = kSigma[r];
    mix(v, 0, 4, 8, 12, m[s[0]], m[s[1]]);
    mix(v, 1, 5, 9, 13, m[s[2]], m[s[3]]);
    mix(v, 2, 6, 10, 14, m[s[4]], m[s[5]]);
    mix(v, 3, 7, 11, 15, m[s[6]], m[s[7]]);
    mix(v, 0, 5, 10, 15, m[s[8]], m[s[9]]);
    mix(v, 1, 6, 11, 12, m[s[10]], m[s[11]]);
    mix(v, 2, 7, 8, 13, m[s[12]], m[s[13]]);
    mix(v, 3, 4, 9, 14, m[s[14]], m[s[15]]);
  }
  for (unsigned i = 0; i < 8; ++i) {
    h[i] ^= v[i] ^ v[i + 8];
  }
}

}  // namespace

void blake2s(const uint8_t* key, size_t key_size, const uint8_t* data, size_t size, uint8_t* out, size_t out_size) {
  uint32_t h[8];
  for (unsigned i = 0; i < 8; ++i) {
    h[i] = kIv[i];
  }
  h[0] ^= 0x01010000UL ^ (static_cast<uint32_t>(key_size) << 8) ^ static_cast<uint32_t>(out_size);
  uint8_t block[64];
  uint32_t counter = 0;
  // A key, padded to a block, is the first block; the data follow, the last block zero-padded.
  size_t fill = 0;
  if (key_size > 0) {
    for (size_t i = 0; i < 64; ++i) {
      block[i] = i < key_size ? key[i] : 0;
    }
    fill = 64;
  }
  for (size_t i = 0; i < size; ++i) {
    if (fill == 64) {
      counter += 64;
      compress(h, block, counter, false);
      fill = 0;
    }
    block[fill++] = data[i];
  }
  counter += static_cast<uint32_t>(fill);
  for (size_t i = fill; i < 64; ++i) {
    block[i] = 0;
  }
  compress(h, block, counter, true);
  for (size_t i = 0; i < out_size; ++i) {
    out[i] = static_cast<uint8_t>(h[i / 4] >> (8 * (i % 4)));
  }
}

}  // namespace auth
}  // namespace driftlab
