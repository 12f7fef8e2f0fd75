// One MAC candidate on the ATmega328P, for simavr to time and size (bench/mac_bench.cpp): the MAC of a 25-byte
// message (the longest authenticated command: CAL_SET's header, payload and counter) under a 128-bit key, framed by
// GPIOR0 = 1 before and 0 after; 0xFF when done. DRIFTLAB_MAC picks the candidate: 0 none (the baseline every size is
// measured from), 1 SipHash-2-4, 2 keyed BLAKE2s (8-byte tag), 3 SHA-256(key || message) truncated as MAVLink's.
#include <avr/io.h>
#include <stdint.h>

#include "driftlab/auth/blake2s.hpp"
#include "driftlab/auth/sha256.hpp"
#include "driftlab/auth/siphash.hpp"

namespace {

volatile uint8_t g_sink;  // keeps the tag alive: the compiler may not drop the work

}  // namespace

int main() {
  uint8_t key[driftlab::auth::kKeyBytes];
  uint8_t message[25];
  for (uint8_t i = 0; i < sizeof key; ++i) {
    key[i] = static_cast<uint8_t>(0xA5U ^ i);
  }
  for (uint8_t i = 0; i < sizeof message; ++i) {
    message[i] = static_cast<uint8_t>(i * 7U);
  }
  GPIOR0 = 1;
#if DRIFTLAB_MAC == 1
  const uint64_t tag = driftlab::auth::siphash24(key, message, sizeof message);
  g_sink = static_cast<uint8_t>(tag);
#elif DRIFTLAB_MAC == 2
  uint8_t tag[8];
  driftlab::auth::blake2s(key, sizeof key, message, sizeof message, tag, sizeof tag);
  g_sink = tag[0];
#elif DRIFTLAB_MAC == 3
  uint8_t digest[32];
  driftlab::auth::sha256(key, sizeof key, message, sizeof message, digest);
  g_sink = digest[0];
#else
  g_sink = message[0];
#endif
  GPIOR0 = 0;
  GPIOR0 = 0xFF;
  for (;;) {
  }
}
