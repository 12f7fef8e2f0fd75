// Message table (msg_table.hpp) against protocol v2 as specified in docs/protocol.md §2-§3: ids, lengths,
// directions, and each CRC seed recomputed from its definition string.
#include "driftlab/proto/msg_table.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>

#include "driftlab/proto/crc16.hpp"
#include "driftlab/proto/wire.hpp"

namespace driftlab {
namespace proto {
namespace {

struct Expected {
  uint8_t id;
  const char* name;
  uint8_t payload_len;
  Direction direction;
  const char* definition;  // docs/protocol.md §2.2
};

// Written from the protocol contract, independently of kMsgTable.
const Expected kContract[] = {
    {0x01, "HELLO", 0, Direction::host_to_fw, "HELLO"},
    {0x02, "VERSION", 28, Direction::fw_to_host,
     "VERSION u8 proto_version u8 fw_major u8 fw_minor u8 fw_patch u8 board_id u8 adc_bits u16 vref_mv "
     "u32 tick_hz u8 channel_count u8[4] adc_pin u8 reset_cause u16 assert_line u8 cal_state u16 cal_id "
     "u8 auth_state u32 auth_counter"},
    {0x03, "CONFIG_GET", 0, Direction::host_to_fw, "CONFIG_GET"},
    {0x04, "CONFIG_SET", 19, Direction::host_to_fw,
     "CONFIG_SET u16 output_period_ms u8 conversions_per_output u8 window u8 fit_order u8 mode u8 raw "
     "u32 auth_counter u8[8] auth_tag"},
    {0x05, "CONFIG", 7, Direction::fw_to_host,
     "CONFIG u16 output_period_ms u8 conversions_per_output u8 window u8 fit_order u8 mode u8 raw"},
    {0x06, "POLL", 0, Direction::host_to_fw, "POLL"},
    {0x07, "SAMPLE", 29, Direction::fw_to_host,
     "SAMPLE u32 tick i32[4] value_q8 u8 sat_flags u8 n_window u16 dropped u8 cal_state u16 cal_id u16 temp_code"},
    {0x08, "RAW", 12, Direction::fw_to_host, "RAW u32 tick u16[4] code"},
    {0x09, "ACK", 3, Direction::fw_to_host, "ACK u8 acked_type u16 acked_seq"},
    {0x0A, "NAK", 5, Direction::fw_to_host, "NAK u8 nacked_type u16 nacked_seq u8 status u8 field"},
    {0x0B, "STATUS_GET", 0, Direction::host_to_fw, "STATUS_GET"},
    {0x0C, "STATUS", 27, Direction::fw_to_host,
     "STATUS u32 uptime_ticks u16 rx_frames u16 rx_bad_crc u16 rx_bad_length u16 rx_unknown_type "
     "u16 rx_resync_bytes u16 rx_overflow u16 tx_overflow u16 dropped u8 cal_state u16 cal_id "
     "u16 auth_refused u16 auth_replayed"},
    {0x0D, "CAL_SET", 28, Direction::host_to_fw,
     "CAL_SET u16 cal_id u8 channel u8 flags i32 c1_q8 i32 c2_q8 u32 t_ms u32 auth_counter u8[8] auth_tag"},
    {0x0E, "CAL_GET", 1, Direction::host_to_fw, "CAL_GET u8 channel"},
    {0x0F, "CAL", 16, Direction::fw_to_host, "CAL u16 cal_id u8 channel u8 flags i32 c1_q8 i32 c2_q8 u32 t_ms"},
    {0x10, "KEY_SET", 28, Direction::host_to_fw, "KEY_SET u8[16] sealed_key u32 auth_counter u8[8] auth_tag"},
};

uint8_t seed_of(const char* definition) {
  const uint16_t crc = crc16_ibm3740(reinterpret_cast<const uint8_t*>(definition), std::strlen(definition));
  return static_cast<uint8_t>((crc >> 8) ^ (crc & 0xFFu));
}

TEST(MsgTable, EveryRowMatchesTheContract) {
  ASSERT_EQ(kMsgTypeCount, sizeof(kContract) / sizeof(kContract[0]));
  for (const Expected& e : kContract) {
    const MsgInfo* info = find_msg(e.id);
    ASSERT_NE(info, nullptr) << "id " << int{e.id};
    EXPECT_EQ(type_id(info->type), e.id);
    EXPECT_STREQ(info->name, e.name);
    EXPECT_EQ(info->payload_len, e.payload_len) << e.name;
    EXPECT_EQ(info->direction, e.direction) << e.name;
  }
}

TEST(MsgTable, SeedsAreDerivedFromDefinitionStrings) {
  for (const Expected& e : kContract) {
    const MsgInfo* info = find_msg(e.id);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->crc_seed, seed_of(e.definition)) << e.name;
  }
}

TEST(MsgTable, SeedsDifferBetweenTypes) {
  // Not required for safety (the type byte is under the CRC), but CONFIG and CONFIG_SET share a layout and
  // distinct seeds keep one from ever validating as the other after a type-byte error.
  std::set<uint8_t> seeds;
  for (const MsgInfo& info : kMsgTable) {
    seeds.insert(info.crc_seed);
  }
  EXPECT_EQ(seeds.size(), kMsgTypeCount);
}

TEST(MsgTable, PayloadsFitTheContractMaximumOf32Bytes) {
  EXPECT_EQ(kMaxPayload, 32u);
  for (const MsgInfo& info : kMsgTable) {
    EXPECT_LE(info.payload_len, kMaxPayload) << info.name;
  }
}

TEST(MsgTable, UnknownIdsAreNotFound) {
  MsgSpec spec{};
  for (int id : {0x00, 0x11, 0x7F, 0x80, 0xFF}) {
    EXPECT_EQ(find_msg(static_cast<uint8_t>(id)), nullptr) << id;
    EXPECT_FALSE(find_spec(static_cast<uint8_t>(id), &spec)) << id;
  }
}

TEST(MsgTable, SpecAgreesWithFullRow) {
  for (const MsgInfo& info : kMsgTable) {
    MsgSpec spec{};
    ASSERT_TRUE(find_spec(type_id(info.type), &spec));
    EXPECT_EQ(spec.payload_len, info.payload_len);
    EXPECT_EQ(spec.crc_seed, info.crc_seed);
    EXPECT_EQ(spec.direction, info.direction);
  }
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
