// The host protocol client over a bad radio link, in process: 10^6 SAMPLE frames through a byte error rate of
// 1e-3 and Gilbert-Elliott bursty frame loss. Against the ground truth of what was sent: no corrupted value is
// ever delivered, and every frame that did not arrive is counted lost.
#include "host/io/board_client.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <deque>
#include <random>
#include <vector>

#include "driftlab/proto/encoder.hpp"

using namespace driftlab;
using namespace driftlab::host::io;

namespace {

// The payload the sender puts in frame number n: a function of n, so the receiver can check any frame.
proto::SamplePayload payload_for(std::uint64_t n) {
    proto::SamplePayload s{};
    s.tick = static_cast<std::uint32_t>(n * 25000u);
    for (std::uint8_t c = 0; c < kChannelCount; ++c) {
        s.value_q8[c] = static_cast<std::int32_t>((512u << 8) + ((n * 2654435761u + c * 40503u) & 0xFFFFu)) - 32768;
    }
    s.sat_flags = static_cast<std::uint8_t>(n & 0x0F);
    s.n_window = static_cast<std::uint8_t>(1 + n % 64);
    s.dropped = static_cast<std::uint16_t>(n / 1000);
    return s;
}

// Firmware -> host over a radio: whole frames lost in bursts (Gilbert-Elliott), single bytes replaced by
// random ones. Reads hand out what was queued.
class LossyRadio : public ByteLink {
public:
    struct Params {
        double p_good_to_bad = 0.002;  ///< per frame
        double p_bad_to_good = 0.2;    ///< per frame: mean burst 5 frames
        double loss_good = 0.001;      ///< frame loss probability in the good state
        double loss_bad = 0.6;         ///< ... in the bad state
        double byte_error_rate = 1e-3;
    };
    explicit LossyRadio(Params p, std::uint64_t seed) : p_(p), rng_(seed) {}

    /// Sends one frame; returns false when the channel dropped it whole.
    bool send_frame(const std::uint8_t* bytes, std::size_t n) {
        bad_ = bad_ ? !chance(p_.p_bad_to_good) : chance(p_.p_good_to_bad);
        if (chance(bad_ ? p_.loss_bad : p_.loss_good)) return false;
        for (std::size_t i = 0; i < n; ++i) {
            std::uint8_t b = bytes[i];
            if (chance(p_.byte_error_rate)) {
                b = static_cast<std::uint8_t>(b ^ (1u + rng_() % 255u));  // always a different byte
                ++corrupted_bytes_;
            }
            queue_.push_back(b);
        }
        return true;
    }

    LinkStatus write(const std::uint8_t*, std::size_t) override { return LinkStatus::ok; }
    ReadResult read(std::uint8_t* out, std::size_t capacity, int) override {
        if (queue_.empty()) return {0, LinkStatus::timeout};
        const std::size_t n = std::min(capacity, queue_.size());
        std::copy_n(queue_.begin(), n, out);
        queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(n));
        return {n, LinkStatus::ok};
    }
    std::uint64_t corrupted_bytes() const { return corrupted_bytes_; }

private:
    bool chance(double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p; }

    Params p_;
    std::mt19937_64 rng_;
    bool bad_ = false;
    std::deque<std::uint8_t> queue_;
    std::uint64_t corrupted_bytes_ = 0;
};

}  // namespace

TEST(LossyLink, MillionFramesNoCorruptedValueAcceptedAndEveryLossCounted) {
    constexpr std::uint64_t kFrames = 1'000'000;
    LossyRadio radio(LossyRadio::Params{}, 20261122);
    BoardClient client(radio);
    std::vector<bool> delivered(kFrames, false);
    std::uint64_t corrupted_accepted = 0;
    std::uint64_t last_delivered = 0;
    std::uint64_t delivered_count = 0;
    client.set_frame_handler([&](const Frame& f) {
        ASSERT_EQ(f.type, proto::MsgType::sample);
        // Every frame passes through the tracker before the handler: its unwrapped number is the newest.
        const std::uint64_t n = client.sequence().newest();
        proto::SamplePayload got{};
        ASSERT_TRUE(proto::parse(f.payload.data(), f.payload_len, &got));
        std::uint8_t got_bytes[proto::kSamplePayloadSize];
        std::uint8_t want_bytes[proto::kSamplePayloadSize];
        ASSERT_EQ(proto::serialize(got, got_bytes, sizeof got_bytes), proto::kSamplePayloadSize);
        ASSERT_EQ(proto::serialize(payload_for(n), want_bytes, sizeof want_bytes), proto::kSamplePayloadSize);
        if (n >= kFrames || std::memcmp(got_bytes, want_bytes, sizeof got_bytes) != 0) {
            ++corrupted_accepted;
            return;
        }
        delivered[n] = true;
        last_delivered = n;
        ++delivered_count;
    });

    std::uint8_t frame[proto::kMaxFrameSize];
    std::uint64_t dropped_whole = 0;
    for (std::uint64_t n = 0; n < kFrames; ++n) {
        const std::size_t size =
            proto::encode_sample(payload_for(n), static_cast<std::uint16_t>(n), frame, sizeof frame);
        ASSERT_GT(size, 0u);
        if (!radio.send_frame(frame, size)) ++dropped_whole;
        if (n % 64 == 63) {
            while (client.pump(0) == LinkStatus::ok) {
            }
        }
    }
    while (client.pump(0) == LinkStatus::ok) {
    }

    EXPECT_EQ(corrupted_accepted, 0u);
    // Ground truth of the losses: frames sent between the first and last delivered that never arrived.
    std::uint64_t first = 0;
    while (first < kFrames && !delivered[first]) ++first;
    std::uint64_t missing = 0;
    for (std::uint64_t n = first; n <= last_delivered; ++n) missing += delivered[n] ? 0 : 1;
    EXPECT_EQ(client.sequence().lost(), missing);
    EXPECT_EQ(client.sequence().duplicates(), 0u);
    EXPECT_EQ(client.sequence().received(), delivered_count);
    // The channel really was bad: bursts dropped frames and bytes were hit.
    EXPECT_GT(dropped_whole, 1000u);
    EXPECT_GT(radio.corrupted_bytes(), 20000u);
    EXPECT_GT(client.decoder_counters().bad_crc, 10000u);
    EXPECT_GT(missing, dropped_whole);  // corrupted frames are lost too
}
