// SHA-256 after FIPS 180-4 §6.2 (sha256.hpp).
#include "driftlab/auth/sha256.hpp"

#include "rotate.hpp"

namespace driftlab {
namespace auth {
namespace {

const uint32_t kK[64] = {
    0x428a2f98UL, 0x71374491UL, 0xb5c0fbcfUL, 0xe9b5dba5UL, 0x3956c25bUL, 0x59f111f1UL, 0x923f82a4UL, 0xab1c5ed5UL,
    0xd807aa98UL, 0x12835b01UL, 0x243185beUL, 0x550c7dc3UL, 0x72be5d74UL, 0x80deb1feUL, 0x9bdc06a7UL, 0xc19bf174UL,
    0xe49b69c1UL, 0xefbe4786UL, 0x0fc19dc6UL, 0x240ca1ccUL, 0x2de92c6fUL, 0x4a7484aaUL, 0x5cb0a9dcUL, 0x76f988daUL,
    0x983e5152UL, 0xa831c66dUL, 0xb00327c8UL, 0xbf597fc7UL, 0xc6e00bf3UL, 0xd5a79147UL, 0x06ca6351UL, 0x14292967UL,
    0x27b70a85UL, 0x2e1b2138UL, 0x4d2c6dfcUL, 0x53380d13UL, 0x650a7354UL, 0x766a0abbUL, 0x81c2c92eUL, 0x92722c85UL,
    0xa2bfe8a1UL, 0xa81a664bUL, 0xc24b8b70UL, 0xc76c51a3UL, 0xd192e819UL, 0xd6990624UL, 0xf40e3585UL, 0x106aa070UL,
    0x19a4c116UL, 0x1e376c08UL, 0x2748774cUL, 0x34b0bcb5UL, 0x391c0cb3UL, 0x4ed8aa4aUL, 0x5b9cca4fUL, 0x682e6ff3UL,
    0x748f82eeUL, 0x78a5636fUL, 0x84c87814UL, 0x8cc70208UL, 0x90befffaUL, 0xa4506cebUL, 0xbef9a3f7UL, 0xc67178f2UL};

void compress(uint32_t* h, const uint8_t* block) {
  uint32_t w[16];
  for (unsigned i = 0; i < 16; ++i) {
    w[i] = (static_cast<uint32_t>(block[4 * i]) << 24) | (static_cast<uint32_t>(block[4 * i + 1]) << 16) |
           (static_cast<uint32_t>(block[4 * i + 2]) << 8) | block[4 * i + 3];
  }
  uint32_t s[8];
  for (unsigned i = 0; i < 8; ++i) {
    s[i] = h[i];
  }
  for (unsigned t = 0; t < 64; ++t) {
    // The message schedule in a ring of 16 words: W[t] replaces W[t - 16].
    if (t >= 16) {
      const uint32_t w15 = w[(t - 15) & 15U];
      const uint32_t w2 = w[(t - 2) & 15U];
      w[t & 15U] += (rotr32(w15, 7) ^ rotr32(w15, 18) ^ (w15 >> 3)) + w[(t - 7) & 15U] +
                    (rotr32(w2, 17) ^ rotr32(w2, 19) ^ (w2 >> 10));
    }
    const uint32_t t1 = s[7] + (rotr32(s[4], 6) ^ rotr32(s[4], 11) ^ rotr32(s[4], 25)) +
                        ((s[4] & s[5]) ^ (~s[4] & s[6])) + kK[t] + w[t & 15U];
    const uint32_t t2 =
        (rotr32(s[0], 2) ^ rotr32(s[0], 13) ^ rotr32(s[0], 22)) + ((s[0] & s[1]) ^ (s[0] & s[2]) ^ (s[1] & s[2]));
    for (unsigned i = 7; i > 0; --i) {
      s[i] = s[i - 1];
    }
    s[4] += t1;
    s[0] = t1 + t2;
  }
  for (unsigned i = 0; i < 8; ++i) {
    h[i] += s[i];
  }
}

}  // namespace

void sha256(const uint8_t* a, size_t a_size, const uint8_t* b, size_t b_size, uint8_t (&out)[32]) {
  uint32_t h[8] = {0x6a09e667UL, 0xbb67ae85UL, 0x3c6ef372UL, 0xa54ff53aUL,
                   0x510e527fUL, 0x9b05688cUL, 0x1f83d9abUL, 0x5be0cd19UL};
  uint8_t block[64];
  size_t fill = 0;
  const size_t total = a_size + b_size;
  for (size_t i = 0; i < total; ++i) {
    block[fill++] = i < a_size ? a[i] : b[i - a_size];
    if (fill == 64) {
      compress(h, block);
      fill = 0;
    }
  }
  // Padding: 0x80, zeros, then the length in bits as a big-endian u64, in one or two blocks.
  block[fill++] = 0x80;
  if (fill > 56) {
    while (fill < 64) {
      block[fill++] = 0;
    }
    compress(h, block);
    fill = 0;
  }
  while (fill < 56) {
    block[fill++] = 0;
  }
  const uint64_t bits = static_cast<uint64_t>(total) * 8U;
  for (unsigned i = 0; i < 8; ++i) {
    block[56 + i] = static_cast<uint8_t>(bits >> (56U - 8U * i));
  }
  compress(h, block);
  for (unsigned i = 0; i < 32; ++i) {
    out[i] = static_cast<uint8_t>(h[i / 4] >> (24U - 8U * (i % 4)));
  }
}

}  // namespace auth
}  // namespace driftlab
