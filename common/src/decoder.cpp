// Byte-at-a-time frame decoder with re-scan (decoder.hpp; docs/protocol.md §6).
//
// buf_ holds one candidate frame starting at buf_[0] and, after a reject, the bytes still to re-examine. Each
// byte is checked once as it becomes next in line (checked_), with the CRC kept running, so the cost per byte
// is flat; only a reject re-reads held bytes, starting over from the next sync0 among them.
#include "driftlab/proto/decoder.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/crc16.hpp"

namespace driftlab {
namespace proto {
namespace {

void saturating_add(uint32_t* counter, uint32_t n) {
  *counter = (*counter > UINT32_MAX - n) ? UINT32_MAX : *counter + n;
}

}  // namespace

uint16_t Decoder::seq() const { return get_u16_le(buf_ + kOffsetSeq); }

bool Decoder::feed(uint8_t byte) {
  if (ready_len_ != 0) {
    release();
  }
  // Room is guaranteed: an undecided candidate is shorter than kMaxFrameSize, and release() freed >= 9 bytes.
  buf_[fill_++] = byte;
  return scan();
}

bool Decoder::next() {
  if (ready_len_ == 0) {
    return false;
  }
  release();
  return scan();
}

void Decoder::release() {
  const uint8_t keep = static_cast<uint8_t>(fill_ - ready_len_);
  for (uint8_t i = 0; i < keep; ++i) {
    buf_[i] = buf_[ready_len_ + i];
  }
  fill_ = keep;
  ready_len_ = 0;
  restart_candidate();
}

bool Decoder::scan() {
  while (checked_ < fill_) {
    switch (check_next_byte()) {
    case Verdict::pass: ++checked_; break;
    case Verdict::complete:
      ready_len_ = frame_len_;
      saturating_add(&counters_.frames_ok, 1);
      return true;
    case Verdict::reject: drop_candidate(); break;
    }
  }
  return false;
}

Decoder::Verdict Decoder::check_next_byte() {
  const uint8_t i = checked_;
  if (i <= kOffsetLen) {
    return check_header_byte(i);
  }
  // Payload and CRC bytes, most of every frame: no locals and no calls beyond the CRC step.
  const uint8_t byte = buf_[i];
  const uint8_t crc_offset = static_cast<uint8_t>(frame_len_ - kCrcSize);
  if (i < crc_offset) {
    crc_ = crc16_ibm3740_update(crc_, byte);
    return Verdict::pass;
  }
  if (i == crc_offset) {
    // First CRC byte: fold in the seed now; the decision waits for the second byte.
    crc_ = crc16_ibm3740_update(crc_, seed_);
    return Verdict::pass;
  }
  if (crc_ != get_u16_le(buf_ + crc_offset)) {
    saturating_add(&counters_.bad_crc, 1);
    return Verdict::reject;
  }
  return Verdict::complete;
}

Decoder::Verdict Decoder::check_header_byte(uint8_t i) {
  const uint8_t byte = buf_[i];
  switch (i) {
  case kOffsetSync0: return byte == kSync0 ? Verdict::pass : Verdict::reject;
  case kOffsetSync1: return byte == kSync1 ? Verdict::pass : Verdict::reject;
  case kOffsetVersion:
    if (byte != kProtocolVersion && byte != kLegacyProtocolVersion) {
      saturating_add(&counters_.bad_version, 1);
      return Verdict::reject;
    }
    crc_ = crc16_ibm3740_update(kCrc16Ibm3740Init, byte);
    return Verdict::pass;
  case kOffsetType: {
    // Of version 1, only HELLO is taken (its layout and seed are v2's): a v2 board answers it by number.
    if (buf_[kOffsetVersion] == kLegacyProtocolVersion && byte != proto::type_id(MsgType::hello)) {
      saturating_add(&counters_.bad_version, 1);
      return Verdict::reject;
    }
    MsgSpec spec{};
    if (!find_spec(byte, &spec)) {
      saturating_add(&counters_.unknown_type, 1);
      return Verdict::reject;
    }
    seed_ = spec.crc_seed;
    frame_len_ = static_cast<uint8_t>(proto::frame_size(spec.payload_len));
    break;
  }
  case kOffsetLen:
    if (proto::frame_size(byte) != frame_len_) {
      saturating_add(&counters_.bad_length, 1);
      return Verdict::reject;
    }
    break;
  default:  // the two seq bytes: covered by the CRC, no check of their own
    break;
  }
  crc_ = crc16_ibm3740_update(crc_, byte);
  return Verdict::pass;
}

void Decoder::drop_candidate() {
  // The candidate's first byte is not a frame start; the next one may be any later sync0 it holds.
  uint8_t start = 1;
  while (start < fill_ && buf_[start] != kSync0) {
    ++start;
  }
  saturating_add(&counters_.resync_bytes, start);
  const uint8_t keep = static_cast<uint8_t>(fill_ - start);
  for (uint8_t i = 0; i < keep; ++i) {
    buf_[i] = buf_[start + i];
  }
  fill_ = keep;
  restart_candidate();
}

}  // namespace proto
}  // namespace driftlab
