// LogAssembler: capture stream -> canonical log (log_assembler.hpp).
#include "host/io/log_assembler.hpp"

#include <algorithm>
#include <utility>

#include "driftlab/proto/q8_counts.hpp"
#include "host/util/error.hpp"
#include "host/util/format_number.hpp"

namespace driftlab::host::io {
namespace {

// Codes are 0..1023; -1 marks a raw code that never arrived.

std::string header_value(const CaptureHeader& header, const std::string& key) {
    for (const auto& [k, v] : header) {
        if (k == key) return v;
    }
    return {};
}

}  // namespace

LogMetadata board_metadata(std::string_view source, const proto::VersionPayload& v, const proto::ConfigPayload& c,
                           const CaptureHeader& extra) {
    LogMetadata m;
    m.set("source", std::string(source));
    m.set("firmware_version",
          std::to_string(v.fw_major) + "." + std::to_string(v.fw_minor) + "." + std::to_string(v.fw_patch));
    m.set("protocol_version", static_cast<std::int64_t>(v.proto_version));
    m.set("board_id", static_cast<std::int64_t>(v.board_id));
    m.set("sample_period_s", c.output_period_ms / 1000.0);
    m.set("conversions_per_output", static_cast<std::int64_t>(c.conversions_per_output));
    m.set("window", static_cast<std::int64_t>(c.window));
    m.set("fit_order", static_cast<std::int64_t>(c.fit_order));
    m.set("mode", std::string(c.mode == static_cast<std::uint8_t>(proto::OutputMode::stream) ? "stream" : "poll"));
    m.set("raw", static_cast<std::int64_t>(c.raw));
    m.set("adc_bits", static_cast<std::int64_t>(v.adc_bits));
    m.set("vref_v", v.vref_mv / 1000.0);
    m.set("tick_hz", static_cast<std::int64_t>(v.tick_hz));
    std::string pins;
    for (std::uint8_t ch = 0; ch < kChannelCount; ++ch) {
        pins += std::string(ch ? " " : "") + kChannelNames[ch] + "=ADC" + std::to_string(v.adc_pin[ch]);
    }
    m.set("adc_pins", pins);
    m.set("reset_cause", static_cast<std::int64_t>(v.reset_cause));
    m.set("assert_line", static_cast<std::int64_t>(v.assert_line));
    for (const auto& [key, value] : extra) m.set(key, value);
    return m;
}

LogAssembler::LogAssembler(std::string log_path, CaptureHeader capture_header)
    : log_path_(std::move(log_path)), capture_header_(std::move(capture_header)) {}

void LogAssembler::on_rx(std::uint64_t t_us, const std::uint8_t* bytes, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        if (!decoder_.feed(bytes[i])) continue;
        do {
            const Frame f = copy_frame(decoder_);
            handle_frame(t_us, f);
        } while (decoder_.next());
    }
}

void LogAssembler::on_event(std::uint64_t t_us, const std::string& text) {
    if (text == "start") {
        start_log();
    } else if (text == "lost") {
        decoder_.reset();
        if (rows_) rows_->end_of_stream();
        if (!holding_) {
            holding_ = true;
            lost_t_us_ = t_us;
            first_held_t_us_.reset();
            held_status_.reset();
        }
    } else if (text == "resumed") {
        if (holding_) release_held();
    } else if (text.rfind("gap: ", 0) == 0) {
        ++stats_.gaps;
        if (writer_) writer_->write_gap(text.substr(5));
    }
    // Other events are notes for a person reading the capture; the log does not depend on them.
}

void LogAssembler::handle_frame(std::uint64_t t_us, const Frame& frame) {
    if (!holding_) {
        process_frame(t_us, frame);
        return;
    }
    if (!first_held_t_us_) first_held_t_us_ = t_us;
    held_.emplace_back(t_us, frame);
    // The handshake's STATUS tells whether the firmware restarted; the frames stay held until "resumed", which
    // follows the gap line: an output streamed during the handshake is a row after the gap, not before it.
    proto::StatusPayload status{};
    if (frame.type == proto::MsgType::status && proto::parse(frame.payload.data(), frame.payload_len, &status))
        held_status_ = Stamped{t_us, status.uptime_ticks};
}

std::optional<std::pair<double, double>> LogAssembler::board_ticks_since_newest(std::uint64_t t_us) const {
    if (!version_ || !config_ || !newest_sample_ || t_us < newest_sample_->t_us) return std::nullopt;
    // The rate of the board's clock against the host's, measured over this firmware run's rows, takes in the
    // resonator's error (0.5 % on an Arduino) and a simulated board's speed. Each row's arrival lags its tick by
    // up to an output period (a POLL answers the newest output) plus the link's latency; that is the rate's
    // error over the span, used where it is below 2 %, else the nominal tick_hz within 1 %.
    const double period_us = config_->output_period_ms * 1000.0;
    const double jitter_us = period_us + 100000.0;
    double rate = version_->tick_hz / 1e6;
    double rate_error = 0.01;
    const double span_us = static_cast<double>(newest_sample_->t_us - epoch_first_sample_->t_us);
    if (span_us > 0.0 && 0.005 + jitter_us / span_us <= 0.02) {
        rate = static_cast<double>(newest_sample_->tick - epoch_first_sample_->tick) / span_us;
        rate_error = 0.005 + jitter_us / span_us;
    }
    const double ticks = static_cast<double>(t_us - newest_sample_->t_us) * rate;
    return std::make_pair(ticks, ticks * rate_error + jitter_us * rate);
}

bool LogAssembler::settle_gap(const Stamped& evidence) {
    awaiting_evidence_ = false;
    // Did the firmware run on through the gap? Its count must then be the newest row's tick plus what the host's
    // clock says the board's clock ran meanwhile, whole wraps of the 32-bit tick included. Short of that, beyond
    // the tolerance, it restarted, whichever side of the last tick it is. Past it proves nothing (the host's clock
    // stops while the PC sleeps), so there only a count below the last tick is a restart.
    const auto uptime = static_cast<std::uint32_t>(evidence.tick);
    std::optional<std::uint64_t> ran_on;
    bool short_of_run_on = false;
    if (const auto elapsed = board_ticks_since_newest(evidence.t_us)) {
        ran_on = receiver::ticks_run_on(last_epoch_tick_, uptime, elapsed->first, elapsed->second);
        short_of_run_on = uptime >= last_epoch_tick_ &&
                          static_cast<double>(uptime - last_epoch_tick_) < elapsed->first - elapsed->second;
    }
    if (ran_on) {
        ticks_.expect_near(newest_sample_->tick + *ran_on);
        return false;
    }
    if (!ticks_.started() || (uptime >= last_epoch_tick_ && !short_of_run_on)) return false;
    ++stats_.firmware_restarts;
    seq_.restart_epoch();
    ticks_.restart_epoch(ticks_.last() + 1);
    last_epoch_tick_ = 0;
    epoch_first_sample_.reset();
    newest_sample_.reset();
    if (writer_) {
        writer_->write_gap("firmware restarted during the gap (uptime " +
                           format_double(version_ ? static_cast<double>(uptime) / version_->tick_hz : 0.0) +
                           " s); tick and seq continue after the last row");
    }
    return true;
}

void LogAssembler::release_held() {
    holding_ = false;
    // The handshake's STATUS tells how tick and seq continue; without one (its request went unanswered) the first
    // SAMPLE after the gap does, before its seq is taken (process_frame).
    awaiting_evidence_ = ticks_.started();
    const bool restarted = held_status_ && settle_gap(*held_status_);
    if (!restarted && config_ && seq_.started() && first_held_t_us_ &&
        config_->mode == static_cast<std::uint8_t>(proto::OutputMode::stream)) {
        // A streaming board kept sending while unplugged: unwrap near where its count should be now.
        const auto elapsed = board_ticks_since_newest(*first_held_t_us_);
        const double gap_outputs =
            elapsed ? elapsed->first / (config_->output_period_ms / 1000.0 * version_->tick_hz)
                    : static_cast<double>(*first_held_t_us_ - lost_t_us_) / (config_->output_period_ms * 1000.0);
        const double frames_per_output = config_->raw ? 2.0 : 1.0;
        seq_.expect_near(seq_.newest() + static_cast<std::uint64_t>(gap_outputs * frames_per_output));
    }
    std::vector<std::pair<std::uint64_t, Frame>> frames;
    frames.swap(held_);
    for (const auto& [t_us, f] : frames) process_frame(t_us, f);
}

void LogAssembler::process_frame(std::uint64_t t_us, const Frame& frame) {
    if (awaiting_evidence_ && frame.type == proto::MsgType::sample) {
        proto::SamplePayload s{};
        if (proto::parse(frame.payload.data(), frame.payload_len, &s)) settle_gap(Stamped{t_us, s.tick});
    }
    ++stats_.frames;
    const receiver::SeqResult seq = seq_.accept(frame.seq);
    stats_.lost_frames = seq_.lost();
    stats_.duplicate_frames = seq_.duplicates();
    stats_.reordered_frames = seq_.reordered();
    if (seq.verdict == receiver::SeqVerdict::duplicate) return;

    const std::uint8_t* p = frame.payload.data();
    switch (frame.type) {
    case proto::MsgType::version: {
        proto::VersionPayload v{};
        if (proto::parse(p, frame.payload_len, &v)) version_ = v;
        break;
    }
    case proto::MsgType::config: {
        proto::ConfigPayload c{};
        if (proto::parse(p, frame.payload_len, &c)) config_ = c;
        break;
    }
    case proto::MsgType::sample: {
        proto::SamplePayload s{};
        if (!proto::parse(p, frame.payload_len, &s)) break;
        last_epoch_tick_ = s.tick;
        const std::uint64_t tick = ticks_.unwrap(s.tick);
        newest_sample_ = Stamped{t_us, tick};
        if (!epoch_first_sample_) epoch_first_sample_ = newest_sample_;
        if (rows_) rows_->sample(s, seq.unwrapped, tick);
        break;
    }
    case proto::MsgType::raw: {
        proto::RawPayload r{};
        if (rows_ && proto::parse(p, frame.payload_len, &r)) rows_->raw(r);
        break;
    }
    default: break;
    }
}

AssemblyStats LogAssembler::stats() const {
    AssemblyStats s = stats_;
    if (rows_) {
        s.stale_samples = rows_->counts().stale_samples;
        s.empty_samples = rows_->counts().empty_samples;
    }
    return s;
}

void LogAssembler::start_log() {
    if (writer_) return;
    if (!version_ || !config_) {
        throw DataError(header_value(capture_header_, "capture"), 0,
                        "recording started before the board's VERSION and CONFIG were received");
    }
    writer_ = std::make_unique<LogWriter>(log_path_, board_metadata("record", *version_, *config_, capture_header_),
                                          board_columns(config_->raw != 0, true));
    rows_.emplace(receiver::RowOptions{version_->tick_hz, config_->raw != 0, receiver::MissingRaw::mark},
                  [this](const receiver::Row& row) { return write(row); });
}

bool LogAssembler::write(const receiver::Row& r) {
    // A frame can pass its CRC and still carry a value no converter of this resolution makes (a firmware fault):
    // skipped and counted, as the reader would reject the row.
    const auto range = converter_range(version_->adc_bits);
    if (range && !std::all_of(r.value_counts.begin(), r.value_counts.end(),
                              [&](double v) { return range->holds_estimate(v); })) {
        ++stats_.unreachable_samples;
        return false;
    }
    receiver::Row row = r;
    // A RAW frame with a code the converter cannot make is kept out like a lost one (its CRC held; the fault is the
    // firmware's), so that the log stays readable.
    if (row.has_raw && range && !std::all_of(row.raw_counts.begin(), row.raw_counts.end(), [&](auto code) {
            return range->holds_raw_code(static_cast<double>(code));
        }))
        row.has_raw = false;
    // The columns are the recording's start's: a CONFIG arriving later changes none of them.
    const bool raw = rows_->options().raw;
    if (raw && !row.has_raw) ++stats_.raw_missing;
    writer_->write_row(board_log_row(row, raw, true));
    ++stats_.rows;
    if (!stats_.first_t_s) stats_.first_t_s = row.t_s;
    stats_.last_t_s = row.t_s;
    stats_.last_counts = row.value_counts;
    stats_.last_dropped = row.dropped;
    return true;
}

void LogAssembler::flush() {
    if (writer_) writer_->flush();
}

void LogAssembler::finish() {
    if (holding_) release_held();
    if (rows_) rows_->end_of_stream();
    if (writer_) writer_->close();
}

}  // namespace driftlab::host::io
