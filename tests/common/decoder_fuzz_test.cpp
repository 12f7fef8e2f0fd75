// Decoder (decoder.hpp) on randomly damaged streams of random valid frames: bit flips, dropped and inserted
// bytes, runs of garbage (with planted false headers), cut frames. Deterministic seeds.
//
// Properties checked against what was sent (docs/protocol.md §6):
//   - every delivered frame is byte-identical to a sent frame, in sending order, never twice;
//   - every intact sent frame is delivered, at most kMaxFrameSize bytes after its last byte, and exactly at its
//     last byte when it starts more than kMaxFrameSize bytes after the damage before it (resync within one frame);
//   - every byte fed is accounted for: delivered frames + resync_bytes + bytes_held.
// A 16-bit CRC lets a damaged candidate through with probability ~2^-16, so the damage volume is sized to keep the
// expected number of such coincidences over the whole run below 0.1 (bad_crc total is printed).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/encoder.hpp"

namespace driftlab {
namespace proto {
namespace {

using Bytes = std::vector<uint8_t>;

struct SentFrame {
  Bytes bytes;
  size_t clean_start;  // offset in the undamaged stream
};

struct DamagedStream {
  Bytes rx;
  std::vector<bool> damaged_rx;              // rx byte inserted, flipped, or right before a removed span
  std::map<size_t, size_t> intact_rx_start;  // sent index -> rx offset, for frames that arrived unchanged
};

std::vector<SentFrame> random_frames(std::mt19937& rng, size_t count) {
  std::vector<SentFrame> frames;
  size_t offset = 0;
  uint16_t seq = static_cast<uint16_t>(rng());
  for (size_t i = 0; i < count; ++i) {
    const MsgInfo& info = kMsgTable[rng() % kMsgTypeCount];
    Bytes payload(info.payload_len);
    for (auto& b : payload) {
      b = static_cast<uint8_t>(rng());
    }
    Bytes frame(kMaxFrameSize);
    const uint8_t id = type_id(info.type);
    // An authenticated type's random fields get a trailer under no key (counter random, tag zero).
    frame.resize(is_authenticated(id)
                     ? encode_authenticated(id, seq, payload.data(), payload.size() - kAuthTrailerBytes,
                                            CommandAuth{nullptr, static_cast<uint32_t>(rng())}, frame.data(),
                                            frame.size())
                     : encode_frame(id, seq, payload.data(), payload.size(), frame.data(), frame.size()));
    EXPECT_EQ(frame.size(), frame_size(info.payload_len));
    frames.push_back({frame, offset});
    offset += frame.size();
    seq = static_cast<uint16_t>(seq + 1u);
  }
  return frames;
}

// Garbage that looks like frame starts: lone sync0s, sync pairs, and full false headers with a valid type and
// length, so false starts get past every header check.
Bytes garbage_run(std::mt19937& rng) {
  Bytes out(8 + rng() % 60);
  for (auto& b : out) {
    b = static_cast<uint8_t>(rng());
  }
  const size_t plants = rng() % 4;
  for (size_t p = 0; p < plants; ++p) {
    const size_t at = rng() % out.size();
    const MsgInfo& info = kMsgTable[rng() % kMsgTypeCount];
    const uint8_t header[] = {kSync0, kSync1, kProtocolVersion, type_id(info.type), 0x00, 0x00, info.payload_len};
    const size_t keep = 1 + rng() % sizeof(header);
    for (size_t i = 0; i < keep && at + i < out.size(); ++i) {
      out[at + i] = header[i];
    }
  }
  return out;
}

// Where the damage falls in the clean stream of `frames`, and which frames it touches.
struct DamagePlan {
  Bytes clean;
  std::vector<size_t> owner;  // sent index of each clean byte
  std::vector<bool> touched;
  std::vector<uint8_t> flip_mask;
  std::vector<bool> dropped;
  std::vector<Bytes> insert_before;

  explicit DamagePlan(const std::vector<SentFrame>& frames) : touched(frames.size(), false) {
    for (size_t f = 0; f < frames.size(); ++f) {
      clean.insert(clean.end(), frames[f].bytes.begin(), frames[f].bytes.end());
      owner.insert(owner.end(), frames[f].bytes.size(), f);
    }
    flip_mask.assign(clean.size(), 0);
    dropped.assign(clean.size(), false);
    insert_before.resize(clean.size() + 1);
  }

  // Bytes put in before `pos`; inside a frame (not between two) they damage it.
  void insert(size_t pos, const Bytes& extra) {
    insert_before[pos].insert(insert_before[pos].end(), extra.begin(), extra.end());
    if (pos > 0 && owner[pos - 1] == owner[pos]) {
      touched[owner[pos]] = true;
    }
  }
};

void add_damage_event(std::mt19937& rng, const std::vector<SentFrame>& frames, DamagePlan& plan) {
  const size_t pos = rng() % plan.clean.size();
  switch (rng() % 5) {
  case 0:  // 1..3 bit flips in one byte
    for (size_t k = 0; k < 1 + rng() % 3; ++k) {
      plan.flip_mask[pos] = static_cast<uint8_t>(plan.flip_mask[pos] ^ (1u << (rng() % 8)));
    }
    plan.touched[plan.owner[pos]] = plan.touched[plan.owner[pos]] || plan.flip_mask[pos] != 0;
    break;
  case 1:  // 1..8 bytes dropped
    for (size_t i = pos; i < plan.clean.size() && i < pos + 1 + rng() % 8; ++i) {
      plan.dropped[i] = true;
      plan.touched[plan.owner[i]] = true;
    }
    break;
  case 2: {  // 1..8 random bytes inserted
    Bytes extra(1 + rng() % 8);
    for (auto& b : extra) {
      b = static_cast<uint8_t>(rng());
    }
    plan.insert(pos, extra);
    break;
  }
  case 3:  // a run of garbage
    plan.insert(pos, garbage_run(rng));
    break;
  default: {  // the frame is cut from pos to its end
    const size_t f = plan.owner[pos];
    const size_t end = frames[f].clean_start + frames[f].bytes.size();
    for (size_t i = pos; i < end; ++i) {
      plan.dropped[i] = true;
    }
    plan.touched[f] = true;
    break;
  }
  }
}

DamagedStream damage(std::mt19937& rng, const std::vector<SentFrame>& frames) {
  DamagePlan plan(frames);
  const size_t events = 2 + rng() % 6;
  for (size_t e = 0; e < events; ++e) {
    add_damage_event(rng, frames, plan);
  }
  const size_t n = plan.clean.size();
  DamagedStream out;
  // The stream is followed by an idle line's worth of zero bytes (no sync0): enough to complete or reject any
  // candidate still held, so a frame near the end is not lost only because the test stopped feeding.
  plan.insert_before[n].insert(plan.insert_before[n].end(), kMaxFrameSize, 0x00);
  auto push = [&out](uint8_t b, bool damaged) {
    out.rx.push_back(b);
    out.damaged_rx.push_back(damaged);
  };
  for (size_t i = 0; i <= n; ++i) {
    for (uint8_t b : plan.insert_before[i]) {
      push(b, true);
    }
    if (i == n) {
      break;
    }
    if (plan.dropped[i]) {
      // The byte before a removed span is where the stream stops making sense.
      if (!out.damaged_rx.empty()) {
        out.damaged_rx.back() = true;
      }
      continue;
    }
    const size_t f = plan.owner[i];
    if (!plan.touched[f] && i == frames[f].clean_start) {
      out.intact_rx_start[f] = out.rx.size();
    }
    push(static_cast<uint8_t>(plan.clean[i] ^ plan.flip_mask[i]), plan.flip_mask[i] != 0);
  }
  return out;
}

// What the decoder delivered from one damaged stream.
struct Delivery {
  std::map<size_t, size_t> delivered_at;         // sent index -> rx offset of the byte fed when it came out
  std::map<size_t, size_t> frame_end;            // sent index -> rx offset of the delivered frame's last byte
  std::vector<std::pair<size_t, size_t>> spans;  // rx [first, last] of every delivered frame
  size_t delivered_bytes = 0;
};

// Feeds `stream` to `dec`; every delivered frame must be one that was sent, in order, never twice.
Delivery decode_stream(Decoder& dec, const DamagedStream& stream, const std::vector<SentFrame>& sent, uint32_t seed) {
  std::map<Bytes, size_t> index_of;
  for (size_t i = 0; i < sent.size(); ++i) {
    index_of[sent[i].bytes] = i;
  }
  Delivery d;
  long last_index = -1;
  auto take = [&](size_t rx_offset) {
    const Bytes got(dec.frame(), dec.frame() + dec.frame_size());
    const auto it = index_of.find(got);
    ASSERT_NE(it, index_of.end()) << "seed " << seed << ": delivered a frame that was never sent, at rx " << rx_offset;
    ASSERT_GT(static_cast<long>(it->second), last_index) << "seed " << seed << ": out of order or repeated";
    last_index = static_cast<long>(it->second);
    d.delivered_at[it->second] = rx_offset;
    // Bytes still held lie after the delivered frame, so its last byte is that far back.
    const size_t end = rx_offset - dec.bytes_held();
    d.frame_end[it->second] = end;
    d.spans.emplace_back(end + 1 - got.size(), end);
    d.delivered_bytes += got.size();
  };
  for (size_t i = 0; i < stream.rx.size(); ++i) {
    if (dec.feed(stream.rx[i])) {
      do {
        take(i);
      } while (dec.next());
    }
  }
  return d;
}

// Every intact frame was delivered from its own bytes, within one frame of its end, and exactly at its end when it
// starts more than a frame after the damage before it. Counts the intact frames and those far from damage.
void check_intact_frames(const DamagedStream& stream, const std::vector<SentFrame>& sent, const Delivery& d,
                         uint32_t seed, uint64_t& intact_frames, uint64_t& late_checked) {
  size_t last_damage = 0;
  bool any_damage = false;
  size_t next_rx = 0;
  for (const auto& kv : stream.intact_rx_start) {
    const size_t f = kv.first;
    const size_t start = kv.second;
    for (; next_rx < start; ++next_rx) {
      if (stream.damaged_rx[next_rx]) {
        last_damage = next_rx;
        any_damage = true;
      }
    }
    const size_t last_byte = start + sent[f].bytes.size() - 1;
    // A frame whose last bytes were dropped can borrow the next frame's first byte when it equals the lost one
    // (a CRC byte of 0xD7, say) and then arrives intact itself; the borrowed-from frame is lost legitimately.
    bool borrowed = false;
    for (const auto& span : d.spans) {
      borrowed = borrowed || (span.first < start && start <= span.second);
    }
    if (borrowed) {
      continue;
    }
    ++intact_frames;
    const auto it = d.delivered_at.find(f);
    ASSERT_NE(it, d.delivered_at.end()) << "seed " << seed << ": intact frame " << f << " (rx " << start
                                        << ") was not delivered";
    EXPECT_EQ(d.frame_end.at(f), last_byte) << "seed " << seed << ", frame " << f << " came from other bytes";
    EXPECT_LE(it->second - last_byte, kMaxFrameSize) << "seed " << seed << ", frame " << f;
    if (!any_damage || start - last_damage > kMaxFrameSize) {
      ++late_checked;
      EXPECT_EQ(it->second, last_byte) << "seed " << seed << ", frame " << f << " starts " << start - last_damage
                                       << " bytes after damage";
    }
  }
}

TEST(DecoderFuzz, DamagedStreamsNeverYieldForeignFramesAndResyncWithinOneFrame) {
  uint64_t total_bad_crc = 0;
  uint64_t total_rejects = 0;
  uint64_t intact_frames = 0;
  uint64_t late_checked = 0;
  for (uint32_t seed = 1; seed <= 1500; ++seed) {
    std::mt19937 rng(seed);
    const std::vector<SentFrame> sent = random_frames(rng, 50);
    const DamagedStream stream = damage(rng, sent);
    Decoder dec;
    const Delivery d = decode_stream(dec, stream, sent, seed);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    check_intact_frames(stream, sent, d, seed, intact_frames, late_checked);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());

    const DecoderCounters& c = dec.counters();
    EXPECT_EQ(stream.rx.size(), d.delivered_bytes + c.resync_bytes + dec.bytes_held()) << "seed " << seed;
    EXPECT_EQ(c.frames_ok, d.delivered_at.size());
    total_bad_crc += c.bad_crc;
    total_rejects += c.bad_crc + c.bad_length + c.unknown_type + c.bad_version;
  }
  std::printf("fuzz: %llu intact frames (%llu far from damage), %llu rejected candidates, %llu by CRC\n",
              static_cast<unsigned long long>(intact_frames), static_cast<unsigned long long>(late_checked),
              static_cast<unsigned long long>(total_rejects), static_cast<unsigned long long>(total_bad_crc));
  // The damage must actually exercise the reject paths, and the run must stay within its collision budget.
  EXPECT_GT(total_rejects, 1000u);
  EXPECT_LT(static_cast<double>(total_bad_crc) / 65536.0, 0.1);
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
