// The board side of a LogAssembler test: frames with consecutive seq numbers (or a forged one's), each handed to the
// assembler as received bytes, and a recording of such frames read back as a log.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>

#include "driftlab/proto/encoder.hpp"
#include "host/io/log_assembler.hpp"
#include "host/log/log_reader.hpp"

namespace driftlab::host::io::test_board {

inline constexpr std::uint32_t kTickHz = 250000;
inline constexpr std::uint32_t kTicksPerOutput = 25000;  // 0.1 s

// The board side of the link: frames with consecutive seq numbers, each handed to the assembler as received bytes.
class Board {
public:
    explicit Board(LogAssembler& a) : a_(a) {}
    template <class Encode>
    void send(Encode encode) {
        std::uint8_t buf[64];
        const std::size_t n = encode(seq_++, buf, sizeof buf);
        ASSERT_GT(n, 0u);
        a_.on_rx(t_us_ += 1000, buf, n);
    }
    void version(std::uint32_t tick_hz = kTickHz) {
        proto::VersionPayload v{};
        v.proto_version = proto::kProtocolVersion;
        v.adc_bits = 10;
        v.vref_mv = 5000;
        v.tick_hz = tick_hz;
        v.channel_count = kChannelCount;
        v.cal_state = cal_state_;
        v.cal_id = cal_id_;
        send([&](std::uint16_t s, std::uint8_t* o, std::size_t n) { return proto::encode_version(v, s, o, n); });
    }
    void config(std::uint8_t raw = 0, std::uint8_t window = 8) {
        const proto::ConfigPayload c{100, 8, window, 0, static_cast<std::uint8_t>(proto::OutputMode::stream), raw};
        send([&](std::uint16_t s, std::uint8_t* o, std::size_t n) { return proto::encode_config(c, s, o, n); });
    }
    void ack(proto::MsgType acked = proto::MsgType::config_set) {
        const proto::AckPayload k{static_cast<std::uint8_t>(acked), 7};
        send([&](std::uint16_t s, std::uint8_t* o, std::size_t n) { return proto::encode_ack(k, s, o, n); });
    }
    void status(std::uint32_t uptime) {
        proto::StatusPayload st{};
        st.uptime_ticks = uptime;
        send([&](std::uint16_t s, std::uint8_t* o, std::size_t n) { return proto::encode_status(st, s, o, n); });
    }
    void sample(std::uint32_t tick, std::int32_t gyro_q8 = 500 * 256, std::uint8_t n_window = 8) {
        proto::SamplePayload p{};
        p.tick = tick;
        for (auto& v : p.value_q8) v = n_window ? 500 * 256 : 0;
        p.value_q8[0] = n_window ? gyro_q8 : 0;
        p.n_window = n_window;
        p.cal_state = cal_state_;
        p.cal_id = cal_id_;
        send([&](std::uint16_t s, std::uint8_t* o, std::size_t n) { return proto::encode_sample(p, s, o, n); });
    }
    void raw(std::uint32_t tick, std::uint16_t gyro_code) {
        proto::RawPayload r{};
        r.tick = tick;
        for (auto& c : r.code) c = 500;
        r.code[0] = gyro_code;
        send([&](std::uint16_t s, std::uint8_t* o, std::size_t n) { return proto::encode_raw(r, s, o, n); });
    }
    /// The calibration the board reports in the VERSIONs and SAMPLEs that follow.
    void calibration(proto::CalState state, std::uint16_t id) {
        cal_state_ = static_cast<std::uint8_t>(state);
        cal_id_ = id;
    }
    void skip(std::uint64_t frames) { seq_ = static_cast<std::uint16_t>(seq_ + frames); }
    /// The next frame reuses the seq of the one `frames` back (a forged or repeated frame).
    void rewind(std::uint16_t frames) { seq_ = static_cast<std::uint16_t>(seq_ - frames); }
    void event(const std::string& text) { a_.on_event(t_us_ += 1000, text); }
    void wait_us(std::uint64_t us) { t_us_ += us; }

private:
    LogAssembler& a_;
    std::uint16_t seq_ = 0;
    std::uint64_t t_us_ = 0;
    std::uint8_t cal_state_ = 0;
    std::uint16_t cal_id_ = 0;
};

inline std::string temp_log(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("driftlab_asm_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

// A recording of the frames `send` makes after the handshake (VERSION, CONFIG with `raw`, start), read back.
inline LogData recorded(const std::string& name, std::uint8_t raw, const std::function<void(Board&)>& send,
                        AssemblyStats& stats) {
    const std::string path = temp_log(name);
    {
        LogAssembler a(path, {{"port", "/dev/pts/9"}, {"capture", name + ".cap"}});
        Board b(a);
        b.version();
        b.config(raw);
        b.event("start");
        send(b);
        a.finish();
        stats = a.stats();
    }
    LogData log = read_log(path);
    std::filesystem::remove(path);
    return log;
}

}  // namespace driftlab::host::io::test_board
