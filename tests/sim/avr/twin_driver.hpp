// Test driver: the same host script and the same code source run against the native board and the emulated
// ATmega328P; each run returns the raw bytes the firmware's UART sent, for byte-for-byte comparison.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "driftlab/channels.hpp"
#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/wire.hpp"
#include "firmware/core/firmware.hpp"
#include "firmware/core/hal.hpp"
#include "firmware/port/native/native_board.hpp"
#include "sim/avr/avr_board.hpp"
#include "sim/avr/simavr_adc.hpp"

namespace driftlab::sim::avr::test {

/// ADC code of `channel` for the conversion triggered at `tick` [ticks].
using CodeSource = std::function<std::uint16_t(Channel, std::uint64_t)>;

/// One host frame handed to the host's UART at t_s [s since power-on].
struct HostSend {
    double t_s;
    std::vector<std::uint8_t> frame;
};

inline constexpr double kHostByteS = 10.0 / 115200.0;  // 8N1 at 115200 baud

inline std::vector<std::uint8_t> frame_of(std::size_t n, const std::uint8_t* bytes) {
    return std::vector<std::uint8_t>(bytes, bytes + n);
}

inline std::vector<std::uint8_t> empty_frame(proto::MsgType type, std::uint16_t seq) {
    std::uint8_t buf[proto::kMaxFrameSize];
    const std::size_t n = proto::encode_frame(proto::type_id(type), seq, nullptr, 0, buf, sizeof buf);
    return frame_of(n, buf);
}

inline std::vector<std::uint8_t> config_set_frame(const proto::ConfigPayload& config, std::uint16_t seq) {
    std::uint8_t buf[proto::kMaxFrameSize];
    const std::size_t n = proto::encode_config_set(config, {nullptr, 1}, seq, buf, sizeof buf);
    return frame_of(n, buf);
}

/// The native firmware: each host byte reaches the firmware when its stop bit ends on the line.
inline std::vector<std::uint8_t> run_native(const std::vector<HostSend>& script, double end_s,
                                            const CodeSource& code_for) {
    fw::NativeBoard board;
    fw::Firmware firmware;
    firmware.start();
    std::vector<std::uint8_t> tx;
    std::uint8_t out[256];
    const auto ticks = [](double t_s) { return static_cast<std::uint64_t>(std::floor(t_s * fw::kTickHz)); };
    // Drain after every conversion: a UART empties the ring far faster than the firmware fills it.
    const auto advance = [&](std::uint64_t until) {
        while (board.next_conversion_time_ticks() <= until) {
            board.advance_to(board.next_conversion_time_ticks(), firmware, code_for);
            for (std::size_t n; (n = board.transmit(out, sizeof out)) > 0;) {
                tx.insert(tx.end(), out, out + n);
            }
        }
        board.advance_to(until, firmware, code_for);
    };
    double line_free_s = 0.0;
    for (const HostSend& send : script) {
        double t = std::max(send.t_s, line_free_s);
        for (std::uint8_t byte : send.frame) {
            t += kHostByteS;
            advance(ticks(t));
            board.receive(&byte, 1);
            board.service(firmware);
        }
        line_free_s = t;
    }
    advance(ticks(end_s));
    for (std::size_t n; (n = board.transmit(out, sizeof out)) > 0;) {
        tx.insert(tx.end(), out, out + n);
    }
    return tx;
}

/// The AVR firmware on `board`: host bytes enter UART0 from their send time on, one byte time apart. Times count
/// from the firmware's tick 0 (AvrBoard::firmware_epoch_cycle()), as the native board's do.
inline std::vector<std::uint8_t> run_avr(AvrBoard& board, const std::vector<HostSend>& script, double end_s) {
    board.run_until_armed();
    const std::uint64_t epoch = *board.firmware_epoch_cycle();
    std::vector<std::uint8_t> tx;
    std::uint8_t out[256];
    const auto drain = [&] {
        for (std::size_t n; (n = board.transmit(out, sizeof out)) > 0;) {
            tx.insert(tx.end(), out, out + n);
        }
    };
    for (const HostSend& send : script) {
        board.run_until_cycle(epoch + AvrBoard::cycles_for_s(send.t_s));
        drain();
        board.receive(send.frame.data(), send.frame.size());
    }
    board.run_until_cycle(epoch + AvrBoard::cycles_for_s(end_s));
    drain();
    return tx;
}

/// The source an AvrBoard needs for `code_for`: the input that simavr converts to exactly that code.
inline VoltageSource millivolts_from(const CodeSource& code_for) {
    return [code_for](Channel c, std::uint64_t tick) { return millivolts_for_code(code_for(c, tick)); };
}

/// ELF built by the native tree ("" when avr-g++ was missing at configure time).
inline std::string avr_elf() { return DRIFTLAB_AVR_ELF; }

}  // namespace driftlab::sim::avr::test
