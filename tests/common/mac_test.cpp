// The MAC candidates against published values: SipHash-2-4 against the reference implementation's vectors.h, BLAKE2s
// against RFC 7693's "abc" and Python's hashlib.blake2s with a key, SHA-256 against FIPS 180-4's "abc" and hashlib,
// across block boundaries.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "driftlab/auth/blake2s.hpp"
#include "driftlab/auth/sha256.hpp"
#include "driftlab/auth/siphash.hpp"

namespace driftlab {
namespace auth {
namespace {

const uint8_t kKey[kKeyBytes] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};

std::vector<uint8_t> counting(size_t n) {
  std::vector<uint8_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = static_cast<uint8_t>(i);
  return v;
}

std::string hex(const uint8_t* p, size_t n) {
  static const char* d = "0123456789abcdef";
  std::string s;
  for (size_t i = 0; i < n; ++i) {
    s += d[p[i] >> 4];
    s += d[p[i] & 15];
  }
  return s;
}

TEST(Mac, SipHash24GivesTheReferenceVectors) {
  EXPECT_EQ(siphash24(kKey, nullptr, 0), 0x726fdb47dd0e0e31ULL);
  const std::vector<uint8_t> m15 = counting(15);
  EXPECT_EQ(siphash24(kKey, m15.data(), m15.size()), 0xa129ca6149be45e5ULL);
  const std::vector<uint8_t> m63 = counting(63);
  EXPECT_EQ(siphash24(kKey, m63.data(), m63.size()), 0x958a324ceb064572ULL);
}

TEST(Mac, Blake2sGivesRfc7693AndKeyedReferenceValues) {
  uint8_t out[32];
  const uint8_t abc[] = {'a', 'b', 'c'};
  blake2s(nullptr, 0, abc, 3, out, 32);
  EXPECT_EQ(hex(out, 32), "508c5e8c327c14e2e1a72ba34eeb452f37458b209ed63a294d999b4c86675982");
  blake2s(kKey, 16, nullptr, 0, out, 32);
  EXPECT_EQ(hex(out, 32), "fcfc1128807d157b01adec1ebe0a0927e5ac0ea65000fcec0852218dbb147106");
  const std::vector<uint8_t> m15 = counting(15);
  blake2s(kKey, 16, m15.data(), m15.size(), out, 8);
  EXPECT_EQ(hex(out, 8), "d73ed5db14887f15");
  const std::vector<uint8_t> m64 = counting(64);  // exactly one block after the key's
  blake2s(kKey, 16, m64.data(), m64.size(), out, 8);
  EXPECT_EQ(hex(out, 8), "ce49064ca817bcbd");
}

TEST(Mac, Sha256GivesFips180AndReferenceValues) {
  uint8_t out[32];
  const uint8_t abc[] = {'a', 'b', 'c'};
  sha256(abc, 3, nullptr, 0, out);
  EXPECT_EQ(hex(out, 32), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::vector<uint8_t> m40 = counting(40);  // key + 40 bytes: padding fits the one block
  sha256(kKey, 16, m40.data(), m40.size(), out);
  EXPECT_EQ(hex(out, 32), "d28c1c6bf2083abebf011267c2264b5640d7ff89c7181cc30c857e7ef60ad34b");
  const std::vector<uint8_t> m48 = counting(48);  // key + 48 bytes = 64: padding takes a second block
  sha256(kKey, 16, m48.data(), m48.size(), out);
  EXPECT_EQ(hex(out, 32), "c2e5b81371b2f08e1d49d47a8bf7f254d9e3c7cbfe75255997a12c9fd4694cf5");
}

}  // namespace
}  // namespace auth
}  // namespace driftlab
