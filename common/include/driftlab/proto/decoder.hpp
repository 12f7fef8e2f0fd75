// Decoder: byte-at-a-time, allocation-free parser of protocol v2 frames (and a v1 HELLO) with reject counters.
// Spec: docs/protocol.md §6.
//
// How to use: feed every received byte to feed(). When it returns true, a complete frame whose CRC matched is
// available through type()/seq()/payload()/payload_len() until the next call to feed() or next(). Call next()
// until it returns false to collect further frames that the bytes already held may contain (this only happens
// after a rejected candidate; skipping it just delays those frames to later feed() calls, in order).
//
//   proto::Decoder dec;
//   if (dec.feed(byte)) {
//     do { handle(dec.type(), dec.seq(), dec.payload(), dec.payload_len()); } while (dec.next());
//   }
//
// A candidate frame starts at sync0; its bytes are kept until it is delivered or rejected. On a reject the
// first byte is dropped and the rest is re-examined from the next sync0 inside it, so a real frame hidden
// behind a false start or a damaged frame is still found (MAVLink's parser never looks at consumed bytes again).
// Every byte fed ends up in exactly one of: a delivered frame, counters().resync_bytes, or bytes_held().
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/nodiscard.hpp"
#include "driftlab/proto/wire.hpp"

namespace driftlab {
namespace proto {

/// Reject and success counts. 32-bit and saturating: they never wrap back to small numbers.
struct DecoderCounters {
  uint32_t frames_ok;     ///< frames delivered [frames]
  uint32_t bad_crc;       ///< candidates whose CRC (with the type's seed) did not match [frames]
  uint32_t bad_length;    ///< known type, length byte differs from its fixed length [frames]
  uint32_t unknown_type;  ///< type byte not in the message table [frames]
  uint32_t bad_version;   ///< version byte is not kProtocolVersion (nor a v1 HELLO) [frames]
  uint32_t resync_bytes;  ///< bytes dropped while searching for a frame start [bytes]
};

class Decoder {
 public:
  /// Adds one received byte. Returns true when a valid frame is now available (see the file comment).
  DRIFTLAB_NODISCARD bool feed(uint8_t byte);

  /// Releases the current frame and returns true if the bytes already held complete another frame.
  DRIFTLAB_NODISCARD bool next();

  /// Accessors of the available frame; meaningful only after feed() or next() returned true.
  MsgType type() const { return static_cast<MsgType>(buf_[kOffsetType]); }
  uint8_t type_id() const { return buf_[kOffsetType]; }
  /// kProtocolVersion, or kLegacyProtocolVersion for a version-1 HELLO (the one v1 frame taken).
  uint8_t version() const { return buf_[kOffsetVersion]; }
  uint16_t seq() const;
  const uint8_t* payload() const { return buf_ + kOffsetPayload; }
  uint8_t payload_len() const { return buf_[kOffsetLen]; }
  /// The whole frame as received, sync0 to CRC [frame_size() bytes].
  const uint8_t* frame() const { return buf_; }
  size_t frame_size() const { return proto::frame_size(buf_[kOffsetLen]); }

  const DecoderCounters& counters() const { return counters_; }

  /// Bytes held that belong to no delivered frame yet (a candidate being received, or bytes still to re-scan).
  size_t bytes_held() const { return static_cast<size_t>(fill_ - ready_len_); }

  /// Forgets held bytes and any available frame; counters are kept.
  void reset() {
    fill_ = 0;
    ready_len_ = 0;
    restart_candidate();
  }

 private:
  enum class Verdict : uint8_t { pass, complete, reject };

  void release();
  bool scan();
  Verdict check_next_byte();
  Verdict check_header_byte(uint8_t i);
  void drop_candidate();
  void restart_candidate() {
    checked_ = 0;
    frame_len_ = 0;
  }

  uint8_t buf_[kMaxFrameSize] = {};
  uint8_t fill_ = 0;       // bytes held in buf_
  uint8_t ready_len_ = 0;  // size of the delivered frame at buf_[0], 0 when none is available
  // Progress through the candidate at buf_[0]: each byte is checked once, when it first becomes next in line,
  // so a payload byte costs one CRC step and the header checks are not repeated.
  uint8_t checked_ = 0;    // bytes of the candidate that passed their check
  uint8_t frame_len_ = 0;  // the candidate's frame size, known from its type byte on
  uint8_t seed_ = 0;       // the candidate's CRC seed once its type byte passed
  uint16_t crc_ = 0;       // CRC over buf_[kCrcStart, checked_)
  DecoderCounters counters_ = {};
};

}  // namespace proto
}  // namespace driftlab
