// KeyStore on the native board's EEPROM: an erased record is no key, a stored key survives a reset, and a record whose
// CRC fails (one bit of the key) is damaged rather than taken.
#include "firmware/core/key_store.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "firmware/port/native/native_board.hpp"

namespace driftlab {
namespace fw {
namespace {

const uint8_t kKey[auth::kKeyBytes] = {0x10, 0x32, 0x54, 0x76, 0x98, 0xBA, 0xDC, 0xFE,
                                       0x01, 0x23, 0x45, 0x67, 0x89, 0xAB, 0xCD, 0xEF};

TEST(KeyStore, ErasedIsNoKeyAStoredKeySurvivesAResetAndADamagedOneIsNotTaken) {
  NativeBoard board;
  KeyStore fresh;
  fresh.load();
  EXPECT_EQ(fresh.state(), proto::AuthState::open);
  fresh.store(kKey);
  KeyStore after_reset;
  after_reset.load();
  ASSERT_EQ(after_reset.state(), proto::AuthState::keyed);
  for (uint8_t i = 0; i < auth::kKeyBytes; ++i) EXPECT_EQ(after_reset.key()[i], kKey[i]) << int(i);
  board.eeprom()[kKeyEepromAddress + 5] ^= 0x04;
  KeyStore damaged;
  damaged.load();
  EXPECT_EQ(damaged.state(), proto::AuthState::damaged);
}

TEST(KeyStore, TheRecordAProgrammerWritesIsTheOneTheBoardReads) {
  NativeBoard board;
  uint8_t record[kKeyRecordBytes];
  key_record_bytes(kKey, record);
  for (uint8_t i = 0; i < kKeyRecordBytes; ++i) board.eeprom()[kKeyEepromAddress + i] = record[i];
  KeyStore store;
  store.load();
  EXPECT_EQ(store.state(), proto::AuthState::keyed);
  EXPECT_EQ(store.key()[15], 0xEF);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
