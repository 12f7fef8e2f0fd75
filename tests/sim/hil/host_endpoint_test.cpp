// HostEndpoint driven by hand-made firmware frames: what reaches the log sink from SAMPLEs the firmware can send.
#include "sim/hil/host_endpoint.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/wire.hpp"

namespace driftlab::sim {
namespace {

std::vector<std::uint8_t> frame(std::size_t size, const std::uint8_t* bytes) { return {bytes, bytes + size}; }

// Poll mode at the defaults, 100 ms outputs, for 10 s.
HostPlan poll_plan() {
    HostPlan plan;
    plan.config = {100, 25, 25, 0, 0, 0};
    plan.duration_s = 10.0;
    return plan;
}

// A host past its handshake (VERSION, ACK of CONFIG_SET, CONFIG read back), polling, with its rows in `rows`.
class RunningHost : public ::testing::Test {
protected:
    void SetUp() override {
        std::uint8_t f[proto::kMaxFrameSize];
        proto::VersionPayload v{};
        v.proto_version = proto::kProtocolVersion;
        v.tick_hz = 250000;
        step(frame(proto::encode_version(v, fw_seq_++, f, sizeof f), f));
        const proto::AckPayload ack{proto::type_id(proto::MsgType::config_set), 0};
        step(frame(proto::encode_ack(ack, fw_seq_++, f, sizeof f), f));
        step(frame(proto::encode_config(plan_.config, fw_seq_++, f, sizeof f), f));
        ASSERT_EQ(host_.phase(), HostEndpoint::Phase::running);
    }

    // The host acts on what is due, then receives `bytes`, 10 ms later than the previous step.
    void step(const std::vector<std::uint8_t>& bytes) {
        t_s_ += 0.01;
        std::vector<std::vector<std::uint8_t>> out;
        host_.act(t_s_, out);
        host_.receive(t_s_, bytes);
    }

    void send_sample(std::uint32_t tick, std::uint8_t n_window, std::int32_t value_q8) {
        proto::SamplePayload s{};
        s.tick = tick;
        for (std::int32_t& v : s.value_q8) v = value_q8;
        s.n_window = n_window;
        std::uint8_t f[proto::kMaxFrameSize];
        step(frame(proto::encode_sample(s, fw_seq_++, f, sizeof f), f));
    }

    const HostPlan plan_ = poll_plan();
    std::vector<HilRecord> rows_;
    HostEndpoint host_{plan_, [this](const HilRecord& r) { rows_.push_back(r); }};
    std::uint16_t fw_seq_ = 0;
    double t_s_ = 0.0;
};

// docs/protocol.md §3.6: n_window 0 means the zeros are no reading (a POLL answered before any conversion, as after a
// firmware restart); it is counted, not logged, and the next SAMPLE with an estimate is.
TEST_F(RunningHost, ASampleWithAnEmptyWindowIsCountedAndNotLogged) {
    send_sample(250, 0, 0);
    send_sample(25000, 25, 512 * 256);
    ASSERT_EQ(rows_.size(), 1U);
    EXPECT_EQ(rows_[0].n_window, 25);
    EXPECT_EQ(rows_[0].tick, 25000U);
    EXPECT_DOUBLE_EQ(rows_[0].value_counts[0], 512.0);
    EXPECT_EQ(host_.counters().samples_received, 2U);
    EXPECT_EQ(host_.counters().empty_samples, 1U);
    EXPECT_EQ(host_.counters().rows, 1U);
}

// A window still filling (n_window below window) holds real estimates and is logged with its count.
TEST_F(RunningHost, ASampleOfAFillingWindowIsLoggedWithItsCount) {
    send_sample(25000, 1, 300 * 256);
    ASSERT_EQ(rows_.size(), 1U);
    EXPECT_EQ(rows_[0].n_window, 1);
    EXPECT_EQ(host_.counters().empty_samples, 0U);
}

}  // namespace
}  // namespace driftlab::sim
