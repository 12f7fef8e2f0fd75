// The host's end of the line in virtual time; see host_endpoint.hpp.
#include "sim/hil/host_endpoint.hpp"

#include <cmath>
#include <utility>

#include "driftlab/proto/encoder.hpp"
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
    if ((next == Phase::status || next == Phase::done) && rows_) rows_->end_of_stream();
}

HostCounters HostEndpoint::counters() const {
    HostCounters c = counters_;
    c.frames_lost = seq_.lost();
    c.last_seq = seq_.newest();
    if (rows_) {
        c.samples_received = rows_->counts().samples;
        c.empty_samples = rows_->counts().empty_samples;
        c.rows_missing_raw = rows_->counts().dropped_rows;
    }
    return c;
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
        throw BoardError(std::string("no answer to ") + request_name(phase_) + " after " + std::to_string(tries_) +
                         " tries");
    if (tries_ > 0) ++counters_.retries;
    ++tries_;
    std::vector<std::uint8_t> f(proto::kMaxFrameSize);
    request_seq_ = tx_seq_++;
    std::size_t n = 0;
    switch (phase_) {
    case Phase::hello: n = proto::encode_hello(request_seq_, f.data(), f.size()); break;
    case Phase::config_set: n = encode_config_set(plan_.config, f); break;
    case Phase::config_get: n = proto::encode_config_get(request_seq_, f.data(), f.size()); break;
    case Phase::stop_stream: {
        proto::ConfigPayload poll = plan_.config;
        poll.mode = static_cast<std::uint8_t>(proto::OutputMode::poll);
        n = encode_config_set(poll, f);
        break;
    }
    case Phase::status: n = proto::encode_status_get(request_seq_, f.data(), f.size()); break;
    default: break;
    }
    f.resize(n);
    out.push_back(std::move(f));
    send_at_s_ = t_s + plan_.reply_timeout_s;
}

std::size_t HostEndpoint::encode_config_set(const proto::ConfigPayload& config, std::span<std::uint8_t> frame) {
    const KeyBytes key(plan_.key);
    return proto::encode_config_set(config, {key.get(), next_counter_++}, request_seq_, frame.data(), frame.size());
}

void HostEndpoint::receive(double t_s, std::span<const std::uint8_t> bytes) {
    for (std::uint8_t b : bytes) {
        if (!decoder_.feed(b)) continue;
        do {
            handle_frame(t_s);
        } while (decoder_.next());
    }
}

void HostEndpoint::handle_frame(double t_s) {
    ++counters_.frames_received;
    const receiver::SeqResult accepted = seq_.accept(decoder_.seq());
    if (accepted.verdict == receiver::SeqVerdict::duplicate) return;
    const std::uint64_t seq = accepted.unwrapped;

    const std::uint8_t* p = decoder_.payload();
    const std::size_t len = decoder_.payload_len();
    switch (decoder_.type()) {
    case proto::MsgType::version:
        if (phase_ == Phase::hello && proto::parse(p, len, &version_)) {
            next_counter_ = version_.auth_counter + 1;
            enter(Phase::config_set, t_s);
        }
        break;
    case proto::MsgType::ack: {
        proto::AckPayload ack{};
        if (!proto::parse(p, len, &ack) || ack.acked_type != static_cast<std::uint8_t>(proto::MsgType::config_set))
            break;
        if (phase_ == Phase::config_set)
            enter(Phase::config_get, t_s);
        else if (phase_ == Phase::stop_stream)
            enter(Phase::status, t_s);
        break;
    }
    case proto::MsgType::nak: {
        proto::NakPayload nak{};
        if (!proto::parse(p, len, &nak) || (phase_ != Phase::config_set && phase_ != Phase::stop_stream)) break;
        const char* name = proto::config_field_name(nak.field);
        const std::string field = name ? name : "field " + std::to_string(nak.field);
        throw ConfigRefused("the firmware refused the configuration: status " + std::to_string(nak.status) + " (" +
                            proto::status_name(static_cast<proto::Status>(nak.status)) + ") on " + field);
    }
    case proto::MsgType::config: {
        proto::ConfigPayload got{};
        if (phase_ != Phase::config_get || !proto::parse(p, len, &got)) break;
        if (!same_config(got, plan_.config))
            throw BoardError(
                "CONFIG_GET returned a configuration that differs from the "
                "one it acknowledged");
        if (on_ready_) on_ready_(version_, got);
        rows_.emplace(receiver::RowOptions{version_.tick_hz, plan_.config.raw != 0, receiver::MissingRaw::drop},
                      [this](const receiver::Row& row) {
                          ++counters_.rows;
                          sink_(row);
                          return true;
                      });
        enter(Phase::running, t_s);
        break;
    }
    case proto::MsgType::sample: {
        proto::SamplePayload s{};
        if (phase_ == Phase::running && proto::parse(p, len, &s)) rows_->sample(s, seq, ticks_.unwrap(s.tick));
        break;
    }
    case proto::MsgType::raw: {
        proto::RawPayload r{};
        if ((phase_ == Phase::running || phase_ == Phase::stop_stream) && proto::parse(p, len, &r)) rows_->raw(r);
        break;
    }
    case proto::MsgType::status:
        if (phase_ == Phase::status && proto::parse(p, len, &status_)) enter(Phase::done, t_s);
        break;
    default: break;
    }
}

}  // namespace driftlab::sim
