// Test rig: the Firmware on a NativeBoard, with a host side that encodes requests and decodes every frame the
// firmware sends, using the protocol library (common/) as an independent party would.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "driftlab/channels.hpp"
#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "firmware/core/firmware.hpp"
#include "firmware/port/native/native_board.hpp"

namespace driftlab {
namespace fw {
namespace test {

struct Frame {
  uint8_t type;
  uint16_t seq;
  std::vector<uint8_t> payload;
};

class NativeRig {
 public:
  NativeRig() { firmware.start(); }

  /// A board whose die reads `die_temperature_code` at power-on.
  explicit NativeRig(uint16_t die_temperature_code) {
    board.set_die_temperature_code(die_temperature_code);
    firmware.start();
  }

  /// The board after a reset of cause `reset` that kept `eeprom` (kEepromBytes, another rig's board's): a power cycle
  /// or a warm restart.
  NativeRig(const uint8_t* eeprom, const ResetInfo& reset) {
    board.load_eeprom(eeprom, kEepromBytes);
    board.set_reset_info(reset);
    firmware.start();
  }

  /// Sends bytes as the UART delivers them: one at a time, each followed by a main-loop pass.
  void send_bytes(const uint8_t* bytes, size_t n) {
    for (size_t i = 0; i < n; ++i) {
      EXPECT_EQ(board.receive(&bytes[i], 1), 1U);
      board.service(firmware);
    }
  }

  /// Signs CONFIG_SET and CAL_SET with `key` from now on, counters from `last_counter` + 1 (docs/security.md).
  void use_key(const proto::Key& key, uint32_t last_counter) {
    std::copy(std::begin(key), std::end(key), key_);
    keyed_ = true;
    counter_ = last_counter;
  }
  /// The trailer of the next authenticated command: the key given, or none (an open board's zeros).
  proto::CommandAuth next_auth() { return proto::CommandAuth{keyed_ ? &key_ : nullptr, ++counter_}; }

  /// Seq the next frame sent to the firmware carries.
  uint16_t next_host_seq() const { return host_seq_; }

  void send_empty(proto::MsgType type) {
    uint8_t frame[proto::kMaxFrameSize];
    size_t n = proto::encode_frame(proto::type_id(type), host_seq_++, nullptr, 0, frame, sizeof frame);
    ASSERT_GT(n, 0U);
    send_bytes(frame, n);
  }

  void send_config(const proto::ConfigPayload& p) {
    uint8_t frame[proto::kMaxFrameSize];
    size_t n = proto::encode_config_set(p, next_auth(), host_seq_++, frame, sizeof frame);
    ASSERT_GT(n, 0U);
    send_bytes(frame, n);
  }

  void send_cal(const proto::CalPayload& p) {
    uint8_t frame[proto::kMaxFrameSize];
    size_t n = proto::encode_cal_set(p, next_auth(), host_seq_++, frame, sizeof frame);
    ASSERT_GT(n, 0U);
    send_bytes(frame, n);
  }

  void send_cal_get(uint8_t channel) {
    uint8_t frame[proto::kMaxFrameSize];
    size_t n = proto::encode_cal_get(proto::CalGetPayload{channel}, host_seq_++, frame, sizeof frame);
    ASSERT_GT(n, 0U);
    send_bytes(frame, n);
  }

  /// Runs conversions due by `time_ticks` with codes from `code_for(channel, trigger tick)`, taking the
  /// transmitted bytes after each one (the UART empties the ring far faster than outputs fill it).
  void run_until(uint64_t time_ticks, const std::function<uint16_t(Channel, uint64_t)>& code_for) {
    while (board.next_conversion_time_ticks() <= time_ticks) {
      board.advance_to(board.next_conversion_time_ticks(), firmware, code_for);
      take_tx();
    }
    board.advance_to(time_ticks, firmware, code_for);
  }

  /// Drains the TX ring through the host decoder; returns the frames received since the last call.
  std::vector<Frame> receive() {
    take_tx();
    std::vector<Frame> out;
    for (uint8_t byte : tx_bytes_) {
      if (decoder_.feed(byte)) {
        do {
          out.push_back(Frame{decoder_.type_id(), decoder_.seq(),
                              std::vector<uint8_t>(decoder_.payload(), decoder_.payload() + decoder_.payload_len())});
        } while (decoder_.next());
      }
    }
    tx_bytes_.clear();
    return out;
  }

  const proto::DecoderCounters& host_decoder_counters() const { return decoder_.counters(); }

  NativeBoard board;
  Firmware firmware;

 private:
  void take_tx() {
    uint8_t bytes[256];
    size_t n = 0;
    while ((n = board.transmit(bytes, sizeof bytes)) > 0) {
      tx_bytes_.insert(tx_bytes_.end(), bytes, bytes + n);
    }
  }

  std::vector<uint8_t> tx_bytes_;
  proto::Decoder decoder_;
  proto::Key key_ = {};
  bool keyed_ = false;
  uint32_t counter_ = 0;
  uint16_t host_seq_ = 100;
};

template <typename Payload>
Payload parse_as(const Frame& frame) {
  Payload p{};
  EXPECT_TRUE(proto::parse(frame.payload.data(), frame.payload.size(), &p)) << "frame type " << int(frame.type);
  return p;
}

inline bool is(const Frame& frame, proto::MsgType type) { return frame.type == proto::type_id(type); }

/// The one answer to an empty request (HELLO, STATUS_GET...), parsed.
template <typename Payload>
Payload ask(NativeRig& rig, proto::MsgType request) {
  rig.send_empty(request);
  const std::vector<Frame> frames = rig.receive();
  EXPECT_EQ(frames.size(), 1U);
  return parse_as<Payload>(frames.at(0));
}

}  // namespace test
}  // namespace fw
}  // namespace driftlab
