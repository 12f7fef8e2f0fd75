// Authenticated commands end to end on the native port (docs/security.md, invariants 14-17): a keyed board obeys
// only CONFIG_SET, CAL_SET and KEY_SET tagged under its key with a counter above the last it admitted, keeps that
// counter across a power cycle, counts what it refuses in STATUS, and says in VERSION whether it is open, keyed or
// damaged. The fuzz test sends a million forged, truncated, replayed and reordered commands between genuine ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"
#include "firmware/core/key_record.hpp"
#include "tests/firmware/native_rig.hpp"

namespace driftlab {
namespace fw {
namespace {

using proto::AuthState;
using proto::MsgType;
using proto::Status;
using test::ask;
using test::Frame;
using test::is;
using test::NativeRig;
using test::parse_as;

constexpr proto::Key kBoardKey = {0x3C, 0x91, 0x0E, 0x77, 0xA2, 0x5B, 0xD8, 0x14,
                                  0x6F, 0xC3, 0x29, 0xE0, 0x48, 0xB5, 0x1A, 0x86};

// The EEPROM `driftlab flash --key` leaves: erased but for the key record.
std::vector<uint8_t> keyed_eeprom(const proto::Key& key) {
  std::vector<uint8_t> eeprom(kEepromBytes, 0xFF);
  uint8_t record[kKeyRecordBytes];
  key_record_bytes(key, record);
  std::copy(std::begin(record), std::end(record), eeprom.begin() + kKeyEepromAddress);
  return eeprom;
}

std::vector<uint8_t> eeprom_of(const NativeRig& rig) {
  return std::vector<uint8_t>(rig.board.eeprom(), rig.board.eeprom() + kEepromBytes);
}

proto::ConfigPayload config_with_window(uint8_t window) { return proto::ConfigPayload{100, 25, window, 0, 0, 0}; }

std::vector<uint8_t> config_frame(const proto::ConfigPayload& config, const proto::Key* key, uint32_t counter,
                                  uint16_t seq) {
  uint8_t frame[proto::kMaxFrameSize];
  const size_t n = proto::encode_config_set(config, proto::CommandAuth{key, counter}, seq, frame, sizeof frame);
  return std::vector<uint8_t>(frame, frame + n);
}

// The one reply to `frame`: ACK, or NAK with its status.
Frame answer(NativeRig& rig, const std::vector<uint8_t>& frame) {
  rig.send_bytes(frame.data(), frame.size());
  const std::vector<Frame> frames = rig.receive();
  EXPECT_EQ(frames.size(), 1U);
  return frames.at(0);
}

uint8_t nak_status(const Frame& f) { return is(f, MsgType::nak) ? parse_as<proto::NakPayload>(f).status : 0xFF; }

TEST(FirmwareAuth, AKeyedBoardObeysOnlyItsKeyAndANewCounter) {
  const std::vector<uint8_t> eeprom = keyed_eeprom(kBoardKey);
  NativeRig rig(eeprom.data(), ResetInfo{kResetPowerOn, 0});
  const proto::VersionPayload v = ask<proto::VersionPayload>(rig, MsgType::hello);
  EXPECT_EQ(v.auth_state, static_cast<uint8_t>(AuthState::keyed));
  EXPECT_EQ(v.auth_counter, 0U);

  const proto::ConfigPayload wanted = config_with_window(20);
  EXPECT_EQ(nak_status(answer(rig, config_frame(wanted, nullptr, 1, 1))),
            static_cast<uint8_t>(Status::unauthenticated));
  proto::Key wrong = {};
  std::copy(std::begin(kBoardKey), std::end(kBoardKey), wrong);
  wrong[7] ^= 0x01;
  EXPECT_EQ(nak_status(answer(rig, config_frame(wanted, &wrong, 1, 2))), static_cast<uint8_t>(Status::unauthenticated));
  EXPECT_EQ(rig.firmware.config().window, kDefaultConfig.window) << "a refused command changes nothing";

  const std::vector<uint8_t> genuine = config_frame(wanted, &kBoardKey, 5, 3);
  ASSERT_TRUE(is(answer(rig, genuine), MsgType::ack));
  EXPECT_EQ(rig.firmware.config().window, 20);
  EXPECT_EQ(nak_status(answer(rig, genuine)), static_cast<uint8_t>(Status::replayed));
  EXPECT_EQ(nak_status(answer(rig, config_frame(config_with_window(30), &kBoardKey, 4, 4))),
            static_cast<uint8_t>(Status::replayed))
      << "an older counter, reordered";
  EXPECT_EQ(rig.firmware.config().window, 20);

  const proto::StatusPayload st = ask<proto::StatusPayload>(rig, MsgType::status_get);
  EXPECT_EQ(st.auth_refused, 2);
  EXPECT_EQ(st.auth_replayed, 2);
  EXPECT_EQ(ask<proto::VersionPayload>(rig, MsgType::hello).auth_counter, 5U);
}

TEST(FirmwareAuth, ACommandReplayedAfterAPowerCycleIsRefused) {
  const std::vector<uint8_t> eeprom = keyed_eeprom(kBoardKey);
  NativeRig before(eeprom.data(), ResetInfo{kResetPowerOn, 0});
  const std::vector<uint8_t> genuine = config_frame(config_with_window(20), &kBoardKey, 1, 1);
  ASSERT_TRUE(is(answer(before, genuine), MsgType::ack));

  const std::vector<uint8_t> kept = eeprom_of(before);
  NativeRig after(kept.data(), ResetInfo{kResetPowerOn, 0});
  EXPECT_EQ(ask<proto::VersionPayload>(after, MsgType::hello).auth_counter, 1U);
  EXPECT_EQ(nak_status(answer(after, genuine)), static_cast<uint8_t>(Status::replayed));
  EXPECT_EQ(after.firmware.config().window, kDefaultConfig.window);
  EXPECT_TRUE(is(answer(after, config_frame(config_with_window(20), &kBoardKey, 2, 2)), MsgType::ack));
}

TEST(FirmwareAuth, KeySetChangesTheKeyForGoodAndAnOpenBoardRefusesIt) {
  const std::vector<uint8_t> eeprom = keyed_eeprom(kBoardKey);
  NativeRig rig(eeprom.data(), ResetInfo{kResetPowerOn, 0});
  proto::Key next = {};
  for (uint8_t i = 0; i < 16; ++i) next[i] = static_cast<uint8_t>(0xA0 + 3 * i);
  uint8_t frame[proto::kMaxFrameSize];
  size_t n = proto::encode_key_set(next, proto::CommandAuth{&kBoardKey, 1}, 7, frame, sizeof frame);
  ASSERT_TRUE(is(answer(rig, std::vector<uint8_t>(frame, frame + n)), MsgType::ack));
  EXPECT_EQ(nak_status(answer(rig, config_frame(config_with_window(20), &kBoardKey, 2, 8))),
            static_cast<uint8_t>(Status::unauthenticated));

  const std::vector<uint8_t> kept = eeprom_of(rig);
  NativeRig after(kept.data(), ResetInfo{kResetPowerOn, 0});
  EXPECT_TRUE(is(answer(after, config_frame(config_with_window(20), &next, 2, 9)), MsgType::ack));

  NativeRig open;
  EXPECT_EQ(ask<proto::VersionPayload>(open, MsgType::hello).auth_state, static_cast<uint8_t>(AuthState::open));
  EXPECT_TRUE(is(answer(open, config_frame(config_with_window(20), nullptr, 1, 1)), MsgType::ack))
      << "an open board takes any trailer";
  n = proto::encode_key_set(next, proto::CommandAuth{&kBoardKey, 2}, 2, frame, sizeof frame);
  EXPECT_EQ(nak_status(answer(open, std::vector<uint8_t>(frame, frame + n))),
            static_cast<uint8_t>(Status::not_allowed));
  EXPECT_EQ(ask<proto::VersionPayload>(open, MsgType::hello).auth_state, static_cast<uint8_t>(AuthState::open));
}

TEST(FirmwareAuth, ADamagedKeyRecordRefusesEveryCommandThatChangesTheBoard) {
  std::vector<uint8_t> eeprom = keyed_eeprom(kBoardKey);
  eeprom[kKeyEepromAddress + 3] ^= 0x10;
  NativeRig rig(eeprom.data(), ResetInfo{kResetPowerOn, 0});
  EXPECT_EQ(ask<proto::VersionPayload>(rig, MsgType::hello).auth_state, static_cast<uint8_t>(AuthState::damaged));
  EXPECT_EQ(nak_status(answer(rig, config_frame(config_with_window(20), &kBoardKey, 1, 1))),
            static_cast<uint8_t>(Status::unauthenticated));
  EXPECT_EQ(nak_status(answer(rig, config_frame(config_with_window(20), nullptr, 1, 2))),
            static_cast<uint8_t>(Status::unauthenticated));
  rig.send_empty(MsgType::config_get);
  EXPECT_TRUE(is(rig.receive().at(0), MsgType::config)) << "reading stays open";
}

// An attacker who sees every frame and can send any bytes: it flips bits of genuine commands and recomputes their CRC,
// makes up tags, cuts frames short, sends genuine ones again and sends older genuine ones late. Between them the owner
// sends a genuine command now and then. Only the owner's are admitted, each exactly once.
class Attacker {
 public:
  explicit Attacker(uint32_t seed) : rng_(seed) {}

  std::vector<uint8_t> forged(const std::vector<uint8_t>& genuine) {
    std::vector<uint8_t> f = genuine;
    const size_t flips = 1 + rng_() % 4;
    for (size_t i = 0; i < flips; ++i) {
      // Any byte the tag covers or is, but the length (which a board reads per type) and the type.
      size_t at = 0;
      do at = proto::kOffsetVersion + rng_() % (f.size() - proto::kCrcSize - proto::kOffsetVersion);
      while (at == proto::kOffsetLen || at == proto::kOffsetType || at == proto::kOffsetVersion);
      f[at] ^= static_cast<uint8_t>(1U << (rng_() % 8));
    }
    reseal_crc(f);
    return f;
  }

  std::vector<uint8_t> made_up(uint16_t seq) {
    std::vector<uint8_t> f = config_frame(config_with_window(static_cast<uint8_t>(1 + rng_() % 64)), nullptr,
                                          static_cast<uint32_t>(rng_()), seq);
    for (size_t i = f.size() - proto::kCrcSize - proto::kAuthTagBytes; i < f.size() - proto::kCrcSize; ++i) {
      f[i] = static_cast<uint8_t>(rng_());
    }
    reseal_crc(f);
    return f;
  }

  std::vector<uint8_t> truncated(const std::vector<uint8_t>& genuine) {
    std::vector<uint8_t> f = genuine;
    f.resize(proto::kOffsetPayload + rng_() % (f.size() - proto::kOffsetPayload));
    return f;
  }

  size_t pick(size_t n) { return rng_() % n; }

 private:
  static void reseal_crc(std::vector<uint8_t>& f) {
    const size_t crc_at = f.size() - proto::kCrcSize;
    proto::MsgSpec spec = {};
    ASSERT_TRUE(proto::find_spec(f[proto::kOffsetType], &spec));
    uint16_t crc = proto::crc16_ibm3740(f.data() + proto::kCrcStart, crc_at - proto::kCrcStart);
    crc = proto::crc16_ibm3740_update(crc, spec.crc_seed);
    proto::put_u16_le(f.data() + crc_at, crc);
  }

  std::mt19937 rng_;
};

TEST(FirmwareAuth, AMillionForgedTruncatedReplayedAndReorderedCommandsAreAllRefused) {
  const std::vector<uint8_t> eeprom = keyed_eeprom(kBoardKey);
  NativeRig rig(eeprom.data(), ResetInfo{kResetPowerOn, 0});
  Attacker attacker(20261207);
  std::vector<std::vector<uint8_t>> seen;  // genuine commands sent so far, admitted once each
  uint32_t counter = 0;
  uint16_t seq = 0;
  std::vector<uint16_t> acked_seqs;
  size_t naks = 0;
  // Sends `frame` and takes what comes back (the TX ring holds a few NAKs only).
  const auto send = [&](const std::vector<uint8_t>& frame) {
    rig.send_bytes(frame.data(), frame.size());
    for (const Frame& f : rig.receive()) {
      if (is(f, MsgType::ack)) acked_seqs.push_back(parse_as<proto::AckPayload>(f).acked_seq);
      naks += is(f, MsgType::nak) ? 1 : 0;
    }
  };
  uint8_t window = 1;
  constexpr size_t kAttacks = 1000000;
  for (size_t i = 0; i < kAttacks; ++i) {
    if (i % 1000 == 0) {
      window = static_cast<uint8_t>(1 + (window % 64));
      seen.push_back(config_frame(config_with_window(window), &kBoardKey, counter += 1 + attacker.pick(3), seq++));
      send(seen.back());
      ASSERT_EQ(acked_seqs.size(), seen.size()) << "the owner's command " << seen.size() << " was not admitted";
    }
    switch (attacker.pick(5)) {
    case 0: send(attacker.forged(seen.back())); break;
    case 1: send(attacker.made_up(seq++)); break;
    case 2: send(attacker.truncated(seen.back())); break;
    case 3: send(seen.back()); break;                        // replayed
    default: send(seen[attacker.pick(seen.size())]); break;  // reordered: an older genuine one
    }
    ASSERT_EQ(acked_seqs.size(), seen.size()) << "attack " << i << " was admitted";
  }
  ASSERT_EQ(acked_seqs.size(), seen.size());
  // Every whole attack got its NAK; a cut one is answered by none (the board's decoder waits for the rest, which the
  // next frame's bytes fail), so about a fifth go unanswered.
  EXPECT_GT(naks, kAttacks * 3 / 4);
  // Bytes of a frame cut short may still wait in the board's decoder: a frame's length of zeros rejects them.
  send(std::vector<uint8_t>(proto::kMaxFrameSize, 0));
  for (size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(acked_seqs[k], proto::get_u16_le(seen[k].data() + proto::kOffsetSeq)) << "genuine command " << k;
  }
  EXPECT_EQ(rig.firmware.config().window, window) << "the last genuine command's";
  const proto::StatusPayload st = ask<proto::StatusPayload>(rig, MsgType::status_get);
  EXPECT_EQ(st.auth_refused, 0xFFFF) << "saturated";
  EXPECT_EQ(st.auth_replayed, 0xFFFF) << "saturated";
  EXPECT_EQ(ask<proto::VersionPayload>(rig, MsgType::hello).auth_counter, counter);
}

}  // namespace
}  // namespace fw
}  // namespace driftlab
