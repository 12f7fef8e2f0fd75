// The host's end of the line in virtual time; see host_endpoint.hpp.
#include "sim/hil/host_endpoint.hpp"

#include <cmath>
#include <utility>

#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/q8_counts.hpp"
#include "driftlab/proto/status.hpp"
#include "sim/sim_error.hpp"

namespace driftlab::sim {

namespace {

const char* request_name(HostEndpoint::Phase p) {
    switch (p) {
    case HostEndpoint::Phase::hello: return "HELLO";
    case HostEndpoint::Phase::config_set: return "CONFIG_SET";
    case HostEndpoint::Phase::config_get: return "CONFIG_GET";
    case HostEndpoint::Phase::stop_stream: return "CONFIG_SET (back to poll mode)";
    case HostEndpoint::Phase::status: return "STATUS_GET";
    default: return "nothing";
    }
}

bool same_config(const proto::ConfigPayload& a, const proto::ConfigPayload& b) {
    return a.output_period_ms == b.output_period_ms && a.conversions_per_output == b.conversions_per_output &&
           a.window == b.window && a.fit_order == b.fit_order && a.mode == b.mode && a.raw == b.raw;
}

}  // namespace

HostEndpoint::HostEndpoint(const HostPlan& plan, RecordSink sink, ReadyFn on_ready)
    : plan_(plan), sink_(std::move(sink)), on_ready_(std::move(on_ready)) {}

std::optional<double> HostEndpoint::next_action_s() const {
    switch (phase_) {
    case Phase::done: return std::nullopt;
    case Phase::running:
        if (plan_.config.mode == static_cast<std::uint8_t>(proto::OutputMode::stream)) return run_end_s_;
        if (next_poll_k_ <= poll_count_) return run_start_s_ + next_poll_k_ * period_s();
        return run_end_s_;
    default: return send_at_s_;
    }
}

void HostEndpoint::enter(Phase next, double t_s) {
    phase_ = next;
    tries_ = 0;
    send_at_s_ = t_s;
    if (next == Phase::running) {
        poll_count_ = static_cast<std::uint64_t>(std::floor(plan_.duration_s / period_s() + 1e-9));
        next_poll_k_ = 1;
        run_start_s_ = t_s;
        // Poll mode waits one reply timeout after the last poll for its answer.
        const bool stream = plan_.config.mode == static_cast<std::uint8_t>(proto::OutputMode::stream);
        run_end_s_ = t_s + poll_count_ * period_s() + (stream ? 0.0 : plan_.reply_timeout_s);
        send_at_s_.reset();
    }
    if (next == Phase::done) send_at_s_.reset();
    // The last output's RAW may still be on the line when a stream run ends; it is awaited until the firmware has
    // acknowledged the stop (a RAW before that ACK is the stream's), and missing only then.
    if (next == Phase::status || next == Phase::done) {
        if (pending_) ++counters_.rows_missing_raw;
        pending_.reset();
    }
}

void HostEndpoint::act(double t_s, std::vector<std::vector<std::uint8_t>>& out) {
    if (phase_ == Phase::running) {
        const bool stream = plan_.config.mode == static_cast<std::uint8_t>(proto::OutputMode::stream);
        while (!stream && next_poll_k_ <= poll_count_ && run_start_s_ + next_poll_k_ * period_s() <= t_s) {
            std::vector<std::uint8_t> f(proto::kMaxFrameSize);
            f.resize(proto::encode_poll(tx_seq_++, f.data(), f.size()));
            out.push_back(std::move(f));
            ++counters_.polls_sent;
            ++next_poll_k_;
        }
        if (t_s >= run_end_s_ && (stream || next_poll_k_ > poll_count_)) {
            enter(stream ? Phase::stop_stream : Phase::status, t_s);
        }
    }
    if (phase_ != Phase::running && phase_ != Phase::done && send_at_s_ && t_s >= *send_at_s_) request(t_s, out);
}

void HostEndpoint::request(double t_s, std::vector<std::vector<std::uint8_t>>& out) {
    if (tries_ >= plan_.max_tries)
        throw BoardError(std::string("no answer to ") + request_name(phase_) + " after " +
                                                      std::to_string(tries_) + " tries");
    if (tries_ > 0) ++counters_.retries;
    ++tries_;
    std::vector<std::uint8_t> f(proto::kMaxFrameSize);
    request_seq_ = tx_seq_++;
    std::size_t n = 0;
    switch (phase_) {
    case Phase::hello: n = proto::encode_hello(request_seq_, f.data(), f.size()); break;
    case Phase::config_set: n = proto::encode_config_set(plan_.config, request_seq_, f.data(), f.size()); break;
    case Phase::config_get: n = proto::encode_config_get(request_seq_, f.data(), f.size()); break;
    case Phase::stop_stream: {
        proto::ConfigPayload poll = plan_.config;
        poll.mode = static_cast<std::uint8_t>(proto::OutputMode::poll);
        n = proto::encode_config_set(poll, request_seq_, f.data(), f.size());
        break;
    }
    case Phase::status: n = proto::encode_status_get(request_seq_, f.data(), f.size()); break;
    default: break;
    }
    f.resize(n);
    out.push_back(std::move(f));
    send_at_s_ = t_s + plan_.reply_timeout_s;
}

void HostEndpoint::receive(double t_s, std::span<const std::uint8_t> bytes) {
    for (std::uint8_t b : bytes) {
        if (!decoder_.feed(b)) continue;
        do {
            handle_frame(t_s);
        } while (decoder_.next());
    }
}

std::uint64_t HostEndpoint::unwrap_tick(std::uint32_t tick) {
    if (!have_tick_) {
        have_tick_ = true;
        last_tick_ = tick;
        return last_tick_;
    }
    const auto delta = static_cast<std::uint32_t>(tick - static_cast<std::uint32_t>(last_tick_));
    // Ticks of later frames are never earlier; a "negative" delta is the same tick seen again (RAW after SAMPLE).
    if (delta < 0x80000000u) last_tick_ += delta;
    else last_tick_ -= 0x100000000ull - delta;
    return last_tick_;
}

void HostEndpoint::handle_frame(double t_s) {
    ++counters_.frames_received;
    std::uint64_t seq = decoder_.seq();
    if (have_seq_) {
        const auto delta = static_cast<std::uint16_t>(decoder_.seq() - static_cast<std::uint16_t>(counters_.last_seq));
        seq = counters_.last_seq + delta;
        if (delta > 1) counters_.frames_lost += delta - 1u;
    }
    have_seq_ = true;
    counters_.last_seq = seq;

    const std::uint8_t* p = decoder_.payload();
    const std::size_t len = decoder_.payload_len();
    switch (decoder_.type()) {
    case proto::MsgType::version:
        if (phase_ == Phase::hello && proto::parse(p, len, &version_)) enter(Phase::config_set, t_s);
        break;
    case proto::MsgType::ack: {
        proto::AckPayload ack{};
        if (!proto::parse(p, len, &ack) || ack.acked_type != static_cast<std::uint8_t>(proto::MsgType::config_set))
            break;
        if (phase_ == Phase::config_set) enter(Phase::config_get, t_s);
        else if (phase_ == Phase::stop_stream) enter(Phase::status, t_s);
        break;
    }
    case proto::MsgType::nak: {
        proto::NakPayload nak{};
        if (!proto::parse(p, len, &nak) || (phase_ != Phase::config_set && phase_ != Phase::stop_stream)) break;
        const char* name = proto::config_field_name(nak.field);
        const std::string field = name ? name : "field " + std::to_string(nak.field);
        throw ConfigRefused("the firmware refused the configuration: status " + std::to_string(nak.status) +
                               " (" + proto::status_name(static_cast<proto::Status>(nak.status)) + ") on " + field);
    }
    case proto::MsgType::config: {
        proto::ConfigPayload got{};
        if (phase_ != Phase::config_get || !proto::parse(p, len, &got)) break;
        if (!same_config(got, plan_.config))
            throw BoardError("CONFIG_GET returned a configuration that differs from the "
                                                      "one it acknowledged");
        if (on_ready_) on_ready_(version_, got);
        enter(Phase::running, t_s);
        break;
    }
    case proto::MsgType::sample: {
        proto::SamplePayload s{};
        if (phase_ == Phase::running && proto::parse(p, len, &s)) handle_sample(s, seq);
        break;
    }
    case proto::MsgType::raw: {
        proto::RawPayload r{};
        if ((phase_ == Phase::running || phase_ == Phase::stop_stream) && proto::parse(p, len, &r)) handle_raw(r, seq);
        break;
    }
    case proto::MsgType::status:
        if (phase_ == Phase::status && proto::parse(p, len, &status_)) enter(Phase::done, t_s);
        break;
    default: break;
    }
}

void HostEndpoint::handle_sample(const proto::SamplePayload& s, std::uint64_t seq) {
    ++counters_.samples_received;
    // An empty window's 0 is no reading (a POLL before any conversion, e.g. after a firmware restart): a row of it
    // would read as 0 counts.
    if (s.n_window == 0) {
        ++counters_.empty_samples;
        return;
    }
    HilRecord r;
    r.tick = unwrap_tick(s.tick);
    r.t_s = static_cast<double>(r.tick) / static_cast<double>(version_.tick_hz);
    r.seq = seq;
    for (std::size_t c = 0; c < kChannelCount; ++c) r.value_counts[c] = proto::q8_to_counts(s.value_q8[c]);
    r.sat_flags = s.sat_flags;
    r.n_window = s.n_window;
    r.dropped = s.dropped;
    if (plan_.config.raw == 0) {
        ++counters_.rows;
        sink_(r);
        return;
    }
    if (pending_) ++counters_.rows_missing_raw;
    pending_ = r;
}

void HostEndpoint::handle_raw(const proto::RawPayload& raw, std::uint64_t seq) {
    // A RAW belongs to the SAMPLE just before it (seq - 1, same tick); a lone RAW whose SAMPLE was lost is dropped.
    if (!pending_ || pending_->seq + 1 != seq || pending_->tick != unwrap_tick(raw.tick)) return;
    pending_->has_raw = true;
    for (std::size_t c = 0; c < kChannelCount; ++c) pending_->raw_counts[c] = raw.code[c];
    ++counters_.rows;
    sink_(*pending_);
    pending_.reset();
}

}  // namespace driftlab::sim
