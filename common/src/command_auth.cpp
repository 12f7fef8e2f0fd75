// Trailer and key sealing of authenticated commands (command_auth.hpp).
#include "driftlab/proto/command_auth.hpp"

#include "driftlab/proto/byte_order.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/wire.hpp"

namespace driftlab {
namespace proto {
namespace {

// Where the trailer starts in a frame whose length byte is written.
size_t trailer_offset(const uint8_t* frame) { return kOffsetPayload + frame[kOffsetLen] - kAuthTrailerBytes; }

uint64_t frame_tag(const uint8_t* frame, const Key& key) {
  const size_t tag_offset = trailer_offset(frame) + kAuthCounterBytes;
  return auth::siphash24(key, frame + kCrcStart, tag_offset - kCrcStart);
}

// The first byte of a sealing block's input: no tag input starts with it (a frame's version byte is 1 or 2).
constexpr uint8_t kSealDomain = 0xA5;

}  // namespace

bool is_authenticated(uint8_t type_id) {
  return type_id == proto::type_id(MsgType::config_set) || type_id == proto::type_id(MsgType::cal_set) ||
         type_id == proto::type_id(MsgType::key_set);
}

void write_trailer(uint8_t* frame, const CommandAuth& auth) {
  const size_t at = trailer_offset(frame);
  put_u32_le(frame + at, auth.counter);
  const uint64_t tag = auth.key == nullptr ? 0 : frame_tag(frame, *auth.key);
  put_u32_le(frame + at + kAuthCounterBytes, static_cast<uint32_t>(tag));
  put_u32_le(frame + at + kAuthCounterBytes + 4, static_cast<uint32_t>(tag >> 32));
}

uint32_t trailer_counter(const uint8_t* frame) { return get_u32_le(frame + trailer_offset(frame)); }

bool trailer_tag_matches(const uint8_t* frame, const Key& key) {
  const uint64_t expected = frame_tag(frame, key);
  const uint8_t* tag = frame + trailer_offset(frame) + kAuthCounterBytes;
  uint8_t differ = 0;
  for (uint8_t i = 0; i < kAuthTagBytes; ++i) {
    differ = static_cast<uint8_t>(differ | (tag[i] ^ static_cast<uint8_t>(expected >> (8U * i))));
  }
  return differ == 0;
}

void seal_key(const Key& key, uint32_t counter, const uint8_t* in, uint8_t* out) {
  uint8_t block_input[6] = {kSealDomain};
  put_u32_le(block_input + 1, counter);
  for (uint8_t block = 0; block < kKeySetFieldBytes / 8; ++block) {
    block_input[5] = block;
    const uint64_t stream = auth::siphash24(key, block_input, sizeof block_input);
    for (uint8_t i = 0; i < 8; ++i) {
      const uint8_t at = static_cast<uint8_t>(8U * block + i);
      out[at] = static_cast<uint8_t>(in[at] ^ static_cast<uint8_t>(stream >> (8U * i)));
    }
  }
}

}  // namespace proto
}  // namespace driftlab
