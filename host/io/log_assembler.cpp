// LogAssembler: capture stream -> canonical log (log_assembler.hpp).
#include "host/io/log_assembler.hpp"

#include <algorithm>
#include <utility>

#include "driftlab/proto/msg_table.hpp"
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
    const char* cal_state = proto::cal_state_name(v.cal_state);
    m.set("cal_state", cal_state ? std::string(cal_state) : "unknown " + std::to_string(v.cal_state));
    m.set("cal_id", static_cast<std::int64_t>(v.cal_id));
    for (const auto& [key, value] : extra) m.set(key, value);
    return m;
}

namespace {

// FNV-1a over a frame's type and payload: what tells a repeated frame from another of the same seq.
std::uint64_t fingerprint(const Frame& f) {
    std::uint64_t h = 14695981039346656037ULL;
    const auto mix = [&h](std::uint8_t b) { h = (h ^ b) * 1099511628211ULL; };
    mix(static_cast<std::uint8_t>(f.type));
    mix(f.payload_len);
    for (std::size_t i = 0; i < f.payload_len; ++i) mix(f.payload[i]);
    return h;
}

void add_difference(std::string& out, const char* name, long long was, long long is) {
    if (was != is)
        out += (out.empty() ? "" : ", ") + std::string(name) + " " + std::to_string(was) + " -> " + std::to_string(is);
}

// "tick_hz 250000 -> 0, adc_bits 10 -> 12": what a VERSION changes of the board and how it is read (not the cause
// of its last reset, which a restart changes).
std::string differences(const proto::VersionPayload& a, const proto::VersionPayload& b) {
    std::string out;
    const auto field = [&out](const char* name, long long x, long long y) { add_difference(out, name, x, y); };
    field("proto_version", a.proto_version, b.proto_version);
    field("fw_major", a.fw_major, b.fw_major);
    field("fw_minor", a.fw_minor, b.fw_minor);
    field("fw_patch", a.fw_patch, b.fw_patch);
    field("board_id", a.board_id, b.board_id);
    field("adc_bits", a.adc_bits, b.adc_bits);
    field("vref_mv", a.vref_mv, b.vref_mv);
    field("tick_hz", a.tick_hz, b.tick_hz);
    field("channel_count", a.channel_count, b.channel_count);
    for (std::size_t c = 0; c < kChannelCount; ++c) field("adc_pin", a.adc_pin[c], b.adc_pin[c]);
    return out;
}

std::string differences(const proto::ConfigPayload& a, const proto::ConfigPayload& b) {
    std::string out;
    const auto field = [&out](const char* name, long long x, long long y) { add_difference(out, name, x, y); };
    field("output_period_ms", a.output_period_ms, b.output_period_ms);
    field("conversions_per_output", a.conversions_per_output, b.conversions_per_output);
    field("window", a.window, b.window);
    field("fit_order", a.fit_order, b.fit_order);
    field("mode", a.mode, b.mode);
    field("raw", a.raw, b.raw);
    return out;
}

}  // namespace

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
        window_filled_ = false;  // the reconnect's CONFIG_SET restarts the board's windows
        if (rows_) rows_->end_of_stream();
        write_held_rows(0);
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
        write_held_rows(0);
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
        write_held_rows(0);
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
    replaying_held_ = true;
    for (const auto& [t_us, f] : frames) process_frame(t_us, f);
    replaying_held_ = false;
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
    if (seq.verdict == receiver::SeqVerdict::duplicate) {
        if (check_conflict(seq.unwrapped, frame)) take_frame(t_us, frame, seq.unwrapped);
        return;
    }
    fingerprints_[seq.unwrapped % fingerprints_.size()] = {seq.unwrapped, fingerprint(frame), false};
    take_frame(t_us, frame, seq.unwrapped);
}

void LogAssembler::take_frame(std::uint64_t t_us, const Frame& frame, std::uint64_t unwrapped_seq) {
    const std::uint8_t* p = frame.payload.data();
    switch (frame.type) {
    case proto::MsgType::version: {
        proto::VersionPayload v{};
        if (writer_)
            note_if_unexpected(frame, unwrapped_seq);
        else if (proto::parse(p, frame.payload_len, &v))
            version_ = v;
        break;
    }
    case proto::MsgType::config: {
        proto::ConfigPayload c{};
        if (writer_)
            note_if_unexpected(frame, unwrapped_seq);
        else if (proto::parse(p, frame.payload_len, &c))
            config_ = c;
        break;
    }
    case proto::MsgType::ack: {
        proto::AckPayload k{};
        const bool foreign = writer_ && !replaying_held_ && proto::parse(p, frame.payload_len, &k) &&
                             (k.acked_type == static_cast<std::uint8_t>(proto::MsgType::config_set) ||
                              k.acked_type == static_cast<std::uint8_t>(proto::MsgType::cal_set));
        if (foreign && !stats_.board_reconfigured())
            write_note(std::string("ACK of a ") + proto::find_msg(k.acked_type)->name +
                       " this recording did not send (frame seq " + std::to_string(frame.seq) +
                       "): the board was reconfigured by someone else; no row follows");
        if (foreign) ++stats_.foreign_config_acks;
        break;
    }
    case proto::MsgType::sample: {
        proto::SamplePayload s{};
        if (!proto::parse(p, frame.payload_len, &s) || stats_.board_reconfigured() || check_window(s, frame.seq) ||
            check_calibration(s, frame.seq))
            break;
        last_epoch_tick_ = s.tick;
        const std::uint64_t tick = ticks_.unwrap(s.tick);
        newest_sample_ = Stamped{t_us, tick};
        if (!epoch_first_sample_) epoch_first_sample_ = newest_sample_;
        if (rows_) rows_->sample(s, unwrapped_seq, tick);
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
    held_rows_.push_back(row);
    write_held_rows(kHeldRows);
    return true;
}

void LogAssembler::write_held_rows(std::size_t keep) {
    // The columns are the recording's start's: a CONFIG arriving later changes none of them.
    while (held_rows_.size() > keep) {
        const receiver::Row& row = held_rows_.front();
        const bool raw = rows_->options().raw;
        if (raw && !row.has_raw) ++stats_.raw_missing;
        writer_->write_row(board_log_row(row, raw, true));
        ++stats_.rows;
        if (!stats_.first_t_s) stats_.first_t_s = row.t_s;
        stats_.last_t_s = row.t_s;
        stats_.last_counts = row.value_counts;
        stats_.last_dropped = row.dropped;
        held_rows_.pop_front();
    }
}

bool LogAssembler::check_conflict(std::uint64_t seq, const Frame& frame) {
    Seen& seen = fingerprints_[seq % fingerprints_.size()];
    const std::uint64_t print = fingerprint(frame);
    if (seen.seq != seq || seen.print == print) return false;  // a repeat, or too old to tell
    ++stats_.conflicting_frames;
    // A VERSION or CONFIG that differs from the handshake cannot be the board's (its own changes only follow a
    // CONFIG_SET, whose ACK ends the rows): it is the forged one of the two, noted and ignored, and a SAMPLE of that
    // seq, before or after it, stays a row.
    if (note_if_unexpected(frame, seq)) return false;
    if (seen.unexpected && frame.type == proto::MsgType::sample) {
        seen = {seq, print, false};
        return true;
    }
    // Else neither frame can be trusted: a row of that SAMPLE (or of the SAMPLE before that RAW) stays out while held.
    const auto before = held_rows_.size();
    const std::uint64_t row_seq = frame.type == proto::MsgType::raw ? seq - 1 : seq;  // a RAW follows its SAMPLE
    std::erase_if(held_rows_, [row_seq](const receiver::Row& r) { return r.seq == row_seq; });
    stats_.conflicting_rows += before - held_rows_.size();
    return false;
}

std::string LogAssembler::unexpected_difference(const Frame& frame) const {
    if (!writer_ || replaying_held_) return {};  // before the start, or the reconnect's handshake the recorder verified
    const std::uint8_t* p = frame.payload.data();
    if (frame.type == proto::MsgType::version) {
        proto::VersionPayload v{};
        if (!proto::parse(p, frame.payload_len, &v)) return {};
        const std::string what = differences(*version_, v);
        return what.empty() ? what : "VERSION " + what;
    }
    proto::ConfigPayload c{};
    if (frame.type != proto::MsgType::config || !proto::parse(p, frame.payload_len, &c)) return {};
    const std::string what = differences(*config_, c);
    return what.empty() ? what : "CONFIG " + what;
}

bool LogAssembler::note_if_unexpected(const Frame& frame, std::uint64_t seq) {
    const std::string what = unexpected_difference(frame);
    if (what.empty()) return false;
    ++(frame.type == proto::MsgType::version ? stats_.unexpected_versions : stats_.unexpected_configs);
    Seen& seen = fingerprints_[seq % fingerprints_.size()];
    if (seen.seq == seq) seen.unexpected = true;
    write_note(what + " (frame seq " + std::to_string(frame.seq) +
               ") ignored: the rows are read as the handshake set them");
    return true;
}

bool LogAssembler::check_window(const proto::SamplePayload& s, std::uint16_t frame_seq) {
    if (!writer_ || replaying_held_) return false;
    if (s.n_window == config_->window) window_filled_ = true;
    if (s.n_window == config_->window || (!window_filled_ && s.n_window < config_->window)) return false;
    ++stats_.other_window_samples;
    write_note("SAMPLE of a window of " + std::to_string(s.n_window) + " conversions after the handshake's " +
               std::to_string(config_->window) + " had filled (frame seq " + std::to_string(frame_seq) +
               "): the board was reconfigured (its ACK lost) or restarted; no row follows");
    return true;
}

bool LogAssembler::check_calibration(const proto::SamplePayload& s, std::uint16_t frame_seq) {
    if (!writer_ || replaying_held_ || (s.cal_state == version_->cal_state && s.cal_id == version_->cal_id))
        return false;
    ++stats_.other_calibration_samples;
    const auto state = [](std::uint8_t v) {
        const char* name = proto::cal_state_name(v);
        return std::string(name ? name : "unknown");
    };
    write_note("SAMPLE of calibration state " + state(s.cal_state) + " id " + std::to_string(s.cal_id) +
               " after the handshake's " + state(version_->cal_state) + " id " + std::to_string(version_->cal_id) +
               " (frame seq " + std::to_string(frame_seq) +
               "): the board's compensation changed (a calibration uploaded, or a warm restart); no row follows");
    return true;
}

void LogAssembler::write_note(const std::string& why) {
    write_held_rows(0);
    writer_->write_unexpected(why);
}

void LogAssembler::sync() {
    if (writer_) writer_->sync();
}

void LogAssembler::finish() {
    if (holding_) release_held();
    if (rows_) rows_->end_of_stream();
    if (writer_) write_held_rows(0);
    if (writer_) writer_->close();
}

}  // namespace driftlab::host::io
