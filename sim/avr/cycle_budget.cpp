// Cycle budget runs; see cycle_budget.hpp.
#include "sim/avr/cycle_budget.hpp"

#include "driftlab/proto/decoder.hpp"
#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/wire.hpp"
#include "firmware/core/config.hpp"
#include "firmware/core/hal.hpp"
#include "sim/avr/simavr_adc.hpp"

namespace driftlab::sim::avr {
namespace {

// Inputs: mid-scale plus a small deterministic pattern per channel and tick, so the fit does real arithmetic.
std::uint32_t test_input_mv(Channel c, std::uint64_t tick) {
    const std::uint64_t pattern = (tick * 2654435761ULL >> 7) % 23;
    const auto code = static_cast<std::uint16_t>(500 + 7 * static_cast<unsigned>(c) + pattern);
    return millivolts_for_code(code);
}

void send(AvrBoard& board, const std::uint8_t* frame, std::size_t n) { board.receive(frame, n); }

}  // namespace

CycleBudget measure_cycle_budget(const std::string& elf_path, proto::ConfigPayload config, double settle_s,
                                 double measure_s, bool profile, const std::vector<std::uint8_t>& eeprom,
                                 const proto::Key* key) {
    config.mode = static_cast<std::uint8_t>(proto::OutputMode::stream);
    CycleBudget b;
    b.config = config;
    b.conversion_period_ticks = fw::conversion_period_ticks(config.output_period_ms, config.conversions_per_output);
    b.conversions_per_s = static_cast<double>(fw::kTickHz) / b.conversion_period_ticks;

    AvrBoardOptions options{elf_path};
    options.profile = profile;
    options.eeprom = eeprom;
    AvrBoard board(options, &test_input_mv);
    board.run_until_armed();
    std::uint8_t frame[proto::kMaxFrameSize];
    send(board, frame, proto::encode_config_set(config, {key, 1}, 1, frame, sizeof frame));
    board.run_until_cycle(board.cycle() + AvrBoard::cycles_for_s(settle_s));

    const std::uint64_t cycle0 = board.cycle();
    const std::uint64_t sleep0 = board.sleep_cycles();
    const std::uint64_t conversions0 = board.triggered_conversions();
    if (profile) {
        board.profiler()->clear();
    }
    board.run_until_cycle(cycle0 + AvrBoard::cycles_for_s(measure_s));
    const std::uint64_t cycles = board.cycle() - cycle0;
    b.measured_s = static_cast<double>(cycles) / AvrBoard::kCpuHz;
    b.conversions = board.triggered_conversions() - conversions0;
    b.cpu_load = 1.0 - static_cast<double>(board.sleep_cycles() - sleep0) / static_cast<double>(cycles);
    if (profile) {
        b.functions = board.profiler()->functions();
    }

    // Back to poll mode so STATUS is not stuck behind the stream, then ask for the counters.
    proto::ConfigPayload poll = config;
    poll.mode = static_cast<std::uint8_t>(proto::OutputMode::poll);
    send(board, frame, proto::encode_config_set(poll, {key, 2}, 2, frame, sizeof frame));
    board.run_until_cycle(board.cycle() + AvrBoard::cycles_for_s(0.05));
    send(board, frame, proto::encode_status_get(3, frame, sizeof frame));
    board.run_until_cycle(board.cycle() + AvrBoard::cycles_for_s(0.05));

    proto::Decoder decoder;
    std::vector<std::uint8_t> tx(1 << 16);
    for (std::size_t n; (n = board.transmit(tx.data(), tx.size())) > 0;) {
        for (std::size_t i = 0; i < n; ++i) {
            if (!decoder.feed(tx[i])) {
                continue;
            }
            do {
                if (decoder.type() == proto::MsgType::ack) {
                    proto::AckPayload ack{};
                    if (proto::parse(decoder.payload(), decoder.payload_len(), &ack) && ack.acked_seq == 1) {
                        b.accepted = true;
                    }
                } else if (decoder.type() == proto::MsgType::status) {
                    proto::StatusPayload status{};
                    if (proto::parse(decoder.payload(), decoder.payload_len(), &status)) {
                        b.dropped = status.dropped;
                        b.tx_overflow = status.tx_overflow;
                        b.rx_overflow = status.rx_overflow;
                    }
                }
            } while (decoder.next());
        }
    }
    b.stack_high_water_bytes = board.stack_high_water_bytes();
    b.stack_budget_bytes = board.stack_budget_bytes();
    return b;
}

std::vector<CycleBudget> search_max_rate(const std::string& elf_path, double measure_s,
                                         const std::vector<std::uint8_t>& eeprom) {
    // Output every 20..100 ms with 25 conversions per channel per output: conversion periods of 50 (the firmware's
    // minimum, kMinConversionPeriodTicks) to 250 ticks, SAMPLE + RAW (59 bytes, 5.1 ms at 115200) per output.
    const std::uint16_t output_periods_ms[] = {20, 22, 24, 26, 28, 32, 40, 60, 100};
    std::vector<CycleBudget> results;
    for (std::uint16_t period_ms : output_periods_ms) {
        const proto::ConfigPayload config = {period_ms, 25, 25, 1, 1, 1};
        results.push_back(measure_cycle_budget(elf_path, config, 0.2, measure_s, false, eeprom));
    }
    return results;
}

}  // namespace driftlab::sim::avr
