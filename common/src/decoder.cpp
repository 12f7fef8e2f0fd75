// Byte-at-a-time frame decoder with re-scan (decoder.hpp; docs/protocol.md §6).
//
// buf_ holds one candidate frame starting at buf_[0] (plus, after a reject, the bytes still to re-examine).
// The candidate's header is checked again as each byte arrives, which costs a few compares and needs no
// state beyond the bytes themselves; the CRC is computed once, when the candidate is complete.
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
  // Room is guaranteed: an incomplete candidate is shorter than kMaxFrameSize, and release() freed >= 9 bytes.
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
}

bool Decoder::scan() {
  for (;;) {
    switch (check_candidate()) {
      case Verdict::incomplete:
        return false;
      case Verdict::complete:
        ready_len_ = static_cast<uint8_t>(proto::frame_size(buf_[kOffsetLen]));
        saturating_add(&counters_.frames_ok, 1);
        return true;
      case Verdict::reject:
        drop_candidate();
        break;
    }
  }
}

Decoder::Verdict Decoder::check_candidate() {
  if (fill_ <= kOffsetSync0) {
    return Verdict::incomplete;
  }
  if (buf_[kOffsetSync0] != kSync0) {
    return Verdict::reject;
  }
  if (fill_ <= kOffsetSync1) {
    return Verdict::incomplete;
  }
  if (buf_[kOffsetSync1] != kSync1) {
    return Verdict::reject;
  }
  if (fill_ <= kOffsetVersion) {
    return Verdict::incomplete;
  }
  if (buf_[kOffsetVersion] != kProtocolVersion) {
    saturating_add(&counters_.bad_version, 1);
    return Verdict::reject;
  }
  if (fill_ <= kOffsetType) {
    return Verdict::incomplete;
  }
  MsgSpec spec{};
  if (!find_spec(buf_[kOffsetType], &spec)) {
    saturating_add(&counters_.unknown_type, 1);
    return Verdict::reject;
  }
  if (fill_ <= kOffsetLen) {
    return Verdict::incomplete;
  }
  const uint8_t payload_len = buf_[kOffsetLen];
  if (payload_len != spec.payload_len) {
    saturating_add(&counters_.bad_length, 1);
    return Verdict::reject;
  }
  const size_t crc_offset = kOffsetPayload + payload_len;
  if (fill_ < crc_offset + kCrcSize) {
    return Verdict::incomplete;
  }
  uint16_t crc = crc16_ibm3740(buf_ + kCrcStart, crc_offset - kCrcStart);
  crc = crc16_ibm3740_update(crc, spec.crc_seed);
  if (crc != get_u16_le(buf_ + crc_offset)) {
    saturating_add(&counters_.bad_crc, 1);
    return Verdict::reject;
  }
  return Verdict::complete;
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
}

}  // namespace proto
}  // namespace driftlab
