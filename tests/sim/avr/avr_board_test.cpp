// AvrBoard against the native board: same code source, same host script, byte-identical UART streams
// (docs/avr-in-the-loop.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/status.hpp"
#include "sim/avr/avr_board.hpp"
#include "sim/model/model_file.hpp"
#include "sim/model/sensor_model.hpp"
#include "tests/sim/avr/twin_driver.hpp"

namespace driftlab::sim::avr::test {
namespace {

// A deterministic code per (channel, tick): mid-scale plus a hash, so any misplaced channel or tick shows.
std::uint16_t hashed_code(Channel c, std::uint64_t tick) {
    std::uint64_t x = (tick + 1) * 0x9E3779B97F4A7C15ULL ^ (static_cast<std::uint64_t>(c) + 7) * 0xC2B2AE3D27D4EB4FULL;
    x ^= x >> 29;
    return static_cast<std::uint16_t>(400 + x % 224);
}

// The paper's sensor model with a seed, evaluated at the firmware's trigger instants: one instance per run, so
// both targets draw the same noise in the same order.
CodeSource paper_model_source(std::uint64_t seed) {
    auto model = std::make_shared<SensorModel>(parse_model(paper_model_text(), "paper"), seed);
    return [model](Channel c, std::uint64_t tick) {
        return model->convert(c, static_cast<double>(tick) / fw::kTickHz).code;
    };
}

// The AVR answers the same conversion a little later than the native board: the ADC takes 104 us after the
// trigger and UDR0 bytes leave one at a time at the UART's rate (the native board hands a frame over at once). So the
// AVR runs kAvrTailS longer and may have sent the frames of at most one more output (SAMPLE + RAW = 59 bytes);
// everything the native board sent must be there, byte for byte, in the same order.
constexpr double kAvrTailS = 0.020;
constexpr std::size_t kOneOutputBytes = 59;

void expect_same_stream(const std::vector<std::uint8_t>& avr, const std::vector<std::uint8_t>& native) {
    const std::size_t common = std::min(avr.size(), native.size());
    const auto common_end = native.begin() + static_cast<std::ptrdiff_t>(common);
    const auto mismatch = std::mismatch(native.begin(), common_end, avr.begin());
    ASSERT_GE(avr.size(), native.size()) << "first difference at byte " << (mismatch.first - native.begin());
    EXPECT_LE(avr.size() - native.size(), kOneOutputBytes);
    EXPECT_TRUE(common == native.size() && mismatch.first == native.end())
        << "first difference at byte " << (mismatch.first - native.begin()) << " of " << native.size();
}

class AvrTwin : public ::testing::Test {
protected:
    void SetUp() override {
        if (avr_elf().empty() || !std::filesystem::exists(avr_elf())) {
            GTEST_SKIP() << "AVR firmware ELF not built (avr-g++ missing at configure time): " << avr_elf();
        }
    }
};

TEST_F(AvrTwin, HelloAnswersTheSameVersionFrame) {
    const std::vector<HostSend> script = {{0.01, empty_frame(proto::MsgType::hello, 0)}};
    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(hashed_code));
    const auto avr = run_avr(board, script, 0.05);
    const auto native = run_native(script, 0.05, hashed_code);
    ASSERT_FALSE(native.empty());
    EXPECT_EQ(avr, native);
}

// simavr's loader messages ("Loaded 9124 .text at address 0x0") are not printed on stdout, where `hil -o -` writes
// the log and `hil --json` its summary.
TEST_F(AvrTwin, LoadingTheFirmwarePrintsNothingOnStandardOutput) {
    ::testing::internal::CaptureStdout();
    { AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(hashed_code)); }
    EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
}

constexpr double kEndS = 60.0;

proto::ConfigPayload default_config() { return {100, 25, 25, 0, 0, 0}; }

TEST_F(AvrTwin, StreamModeIsByteIdenticalOverSixtySeconds) {
    proto::ConfigPayload stream = default_config();
    stream.mode = 1;
    stream.raw = 1;
    stream.fit_order = 1;
    const std::vector<HostSend> script = {{0.01, empty_frame(proto::MsgType::hello, 0)},
                                          {0.02, config_set_frame(stream, 1)}};
    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(paper_model_source(7)));
    const auto avr = run_avr(board, script, kEndS + kAvrTailS);
    const auto native = run_native(script, kEndS, paper_model_source(7));
    // About 600 SAMPLE + RAW pairs of 54 bytes.
    ASSERT_GT(native.size(), 590U * 54U);
    expect_same_stream(avr, native);
}

TEST_F(AvrTwin, PollModeIsByteIdenticalOverSixtySeconds) {
    std::vector<HostSend> script = {{0.01, empty_frame(proto::MsgType::hello, 0)}};
    std::uint16_t seq = 1;
    for (int k = 1; k < 600; ++k) {
        script.push_back({0.1 * k, empty_frame(proto::MsgType::poll, seq++)});
    }
    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(paper_model_source(11)));
    const auto avr = run_avr(board, script, kEndS + kAvrTailS);
    const auto native = run_native(script, kEndS, paper_model_source(11));
    ASSERT_GT(native.size(), 598U * 33U);
    expect_same_stream(avr, native);
}

// A CONFIG_SET that changes the period re-arms on the next conversion after it: both boards take it in the same
// conversion slot because the driver counts AVR time from the firmware's tick 0.
TEST_F(AvrTwin, RearmedStreamWithHashedCodesIsByteIdentical) {
    proto::ConfigPayload fast = {20, 4, 8, 1, 1, 1};  // 1.25 ms conversions, order-1 fit, SAMPLE + RAW every 20 ms
    const std::vector<HostSend> script = {{0.01, config_set_frame(fast, 0)}};
    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(hashed_code));
    const auto avr = run_avr(board, script, 10.0 + kAvrTailS);
    const auto native = run_native(script, 10.0, hashed_code);
    ASSERT_GT(native.size(), 495U * 54U);
    expect_same_stream(avr, native);
}

struct DecodedFrame {
    proto::MsgType type;
    std::vector<std::uint8_t> payload;
};

std::vector<DecodedFrame> decode_all(const std::vector<std::uint8_t>& bytes) {
    proto::Decoder decoder;
    std::vector<DecodedFrame> frames;
    for (std::uint8_t b : bytes) {
        if (decoder.feed(b)) {
            do {
                const std::uint8_t* p = decoder.payload();
                frames.push_back({decoder.type(), std::vector<std::uint8_t>(p, p + decoder.payload_len())});
            } while (decoder.next());
        }
    }
    return frames;
}

TEST_F(AvrTwin, DefaultConfigStreamsWithoutDropsAndTheStackStaysClearOfData) {
    proto::ConfigPayload stream = default_config();
    stream.mode = 1;
    stream.raw = 1;
    const std::vector<HostSend> script = {{0.01, config_set_frame(stream, 0)}};
    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(paper_model_source(3)));
    const auto frames = decode_all(run_avr(board, script, 20.05));
    std::size_t samples = 0;
    for (const DecodedFrame& f : frames) {
        if (f.type != proto::MsgType::sample) {
            continue;
        }
        proto::SamplePayload sample{};
        ASSERT_TRUE(proto::parse(f.payload.data(), f.payload.size(), &sample));
        EXPECT_EQ(sample.dropped, 0U) << "at tick " << sample.tick;
        ++samples;
    }
    EXPECT_GE(samples, 199U);
    // 4 conversions per ms, 20 s: every trigger reached the firmware's ring.
    EXPECT_GE(board.triggered_conversions(), 4U * 1000U * 20U / 4U - 2U);
    // Some painted bytes between the data and the deepest stack frame are still untouched.
    EXPECT_GT(board.stack_high_water_bytes(), 0U);
    EXPECT_LT(board.stack_high_water_bytes(), board.stack_budget_bytes());
}

TEST_F(AvrTwin, MalformedAndOutOfRangeCommandsAreNakedAndChangeNothing) {
    std::vector<HostSend> script;
    double t = 0.01;
    std::uint16_t seq = 0;
    const auto at = [&](std::vector<std::uint8_t> frame) {
        script.push_back({t, std::move(frame)});
        t += 0.01;
    };
    proto::ConfigPayload bad = default_config();
    bad.window = 0;  // out of range
    at(config_set_frame(bad, seq++));
    bad = default_config();
    bad.output_period_ms = 5;  // below 10 ms
    at(config_set_frame(bad, seq++));
    bad = default_config();
    bad.output_period_ms = 10;  // 10 ms / (4 x 64) = 39 ticks: faster than the ADC allows
    bad.conversions_per_output = 64;
    at(config_set_frame(bad, seq++));
    bad = default_config();
    bad.fit_order = 2;
    at(config_set_frame(bad, seq++));
    std::uint8_t ack[proto::kMaxFrameSize];
    at(frame_of(proto::encode_ack(proto::AckPayload{1, 2}, seq++, ack, sizeof ack), ack));  // firmware-to-host type
    // Framing errors are not answered (the decoder cannot trust the header); the firmware counts them.
    at({0xD7, 0x1A, 0x02, 0x04, 0x07, 0x00, 0x06, 100, 0, 25, 25, 0, 0, 0x00, 0x00});  // CONFIG_SET, len 6
    at({0xD7, 0x1A, 0x02, 0x7E, 0x08, 0x00, 0x00, 0x00, 0x00});                        // unknown type 0x7E
    at({0xD7, 0x1A, 0x02, 0x06, 0x09, 0x00, 0x00, 0x12, 0x34});                        // POLL, bad CRC
    at(empty_frame(proto::MsgType::status_get, seq++));
    at(empty_frame(proto::MsgType::config_get, seq++));

    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(hashed_code));
    const auto bytes = run_avr(board, script, t + 0.02);
    const auto frames = decode_all(bytes);
    ASSERT_EQ(frames.size(), 7U);  // 5 NAKs, STATUS, CONFIG
    for (std::size_t i = 0; i < 5; ++i) {
        ASSERT_EQ(frames[i].type, proto::MsgType::nak) << "reply " << i;
        proto::NakPayload nak{};
        ASSERT_TRUE(proto::parse(frames[i].payload.data(), frames[i].payload.size(), &nak));
        const auto expected = i < 4 ? proto::Status::out_of_range : proto::Status::not_allowed;
        EXPECT_EQ(nak.status, static_cast<std::uint8_t>(expected)) << "reply " << i;
        EXPECT_EQ(nak.nacked_seq, i) << "reply " << i;
    }
    ASSERT_EQ(frames[5].type, proto::MsgType::status);
    proto::StatusPayload status{};
    ASSERT_TRUE(proto::parse(frames[5].payload.data(), frames[5].payload.size(), &status));
    EXPECT_EQ(status.rx_bad_length, 1U);
    EXPECT_EQ(status.rx_unknown_type, 1U);
    EXPECT_EQ(status.rx_bad_crc, 1U);
    EXPECT_EQ(status.dropped, 0U);
    ASSERT_EQ(frames[6].type, proto::MsgType::config);
    proto::ConfigPayload config{};
    ASSERT_TRUE(proto::parse(frames[6].payload.data(), frames[6].payload.size(), &config));
    const proto::ConfigPayload expect = default_config();
    EXPECT_EQ(config.output_period_ms, expect.output_period_ms);
    EXPECT_EQ(config.conversions_per_output, expect.conversions_per_output);
    EXPECT_EQ(config.window, expect.window);
    EXPECT_EQ(config.fit_order, expect.fit_order);
    EXPECT_EQ(config.mode, expect.mode);
    EXPECT_EQ(config.raw, expect.raw);
}

// A POLL to a streaming board is refused on both builds alike: the same NAKs in the same places, and the SAMPLEs
// around them still on the 100 ms grid (docs/protocol.md §3.5).
TEST_F(AvrTwin, PollsInStreamModeAreNakedByteIdentically) {
    proto::ConfigPayload stream = default_config();
    stream.mode = 1;
    std::vector<HostSend> script = {{0.01, config_set_frame(stream, 0)}};
    std::uint16_t seq = 1;
    for (int k = 1; k < 50; ++k) script.push_back({0.1 * k + 0.037, empty_frame(proto::MsgType::poll, seq++)});
    AvrBoard board(AvrBoardOptions{avr_elf()}, millivolts_from(hashed_code));
    const auto avr = run_avr(board, script, 5.0 + kAvrTailS);
    const auto native = run_native(script, 5.0, hashed_code);
    expect_same_stream(avr, native);
    std::size_t naks = 0;
    std::uint32_t previous_tick = 0;
    for (const DecodedFrame& f : decode_all(native)) {
        if (f.type == proto::MsgType::nak) {
            proto::NakPayload nak{};
            ASSERT_TRUE(proto::parse(f.payload.data(), f.payload.size(), &nak));
            EXPECT_EQ(nak.nacked_type, proto::type_id(proto::MsgType::poll));
            EXPECT_EQ(nak.status, static_cast<std::uint8_t>(proto::Status::not_allowed));
            EXPECT_EQ(nak.nacked_seq, naks + 1);
            ++naks;
        } else if (f.type == proto::MsgType::sample) {
            proto::SamplePayload sample{};
            ASSERT_TRUE(proto::parse(f.payload.data(), f.payload.size(), &sample));
            if (previous_tick != 0) {
                EXPECT_EQ(sample.tick - previous_tick, 25000U);  // one output period apart
            }
            previous_tick = sample.tick;
        }
    }
    EXPECT_EQ(naks, 49U);
}

}  // namespace
}  // namespace driftlab::sim::avr::test
