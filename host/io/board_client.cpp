// BoardClient: handshake, requests and reception of protocol v2 (board_client.hpp).
#include "host/io/board_client.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>

#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/msg_table.hpp"
#include "driftlab/proto/status.hpp"
#include "driftlab/proto/wire.hpp"

namespace driftlab::host::io {

Frame copy_frame(const proto::Decoder& decoder) {
    Frame f;
    f.type = decoder.type();
    f.seq = decoder.seq();
    f.payload_len = decoder.payload_len();
    std::memcpy(f.payload.data(), decoder.payload(), f.payload_len);
    return f;
}
namespace {

using Clock = std::chrono::steady_clock;

std::string describe_config_difference(const proto::ConfigPayload& want, const proto::ConfigPayload& got) {
    const int w[] = {
        want.output_period_ms, want.conversions_per_output, want.window, want.fit_order, want.mode, want.raw};
    const int g[] = {got.output_period_ms, got.conversions_per_output, got.window, got.fit_order, got.mode, got.raw};
    std::string text;
    for (int i = 0; i < 6; ++i) {
        if (w[i] != g[i]) {
            text += std::string(text.empty() ? "" : ", ") + proto::config_field_name(static_cast<std::uint8_t>(i)) +
                    " is " + std::to_string(g[i]) + " instead of " + std::to_string(w[i]);
        }
    }
    return text;
}

}  // namespace

const char* status_name(std::uint8_t status) {
    const char* name = proto::status_name(static_cast<proto::Status>(status));
    return name ? name : "unknown status";
}

BoardClient::BoardClient(ByteLink& link, ClientOptions options) : link_(link), options_(options) {}

LinkStatus BoardClient::send(proto::MsgType type, std::span<const std::uint8_t> payload, std::uint16_t* seq_used) {
    std::uint8_t frame[proto::kMaxFrameSize];
    const std::uint16_t seq = tx_seq_++;
    const std::uint8_t id = proto::type_id(type);
    std::size_t n = 0;
    if (proto::is_authenticated(id)) {
        const sim::KeyBytes key(key_);
        const proto::CommandAuth auth{key.get(), next_counter_++};
        if (type == proto::MsgType::key_set && payload.size() == sizeof(proto::Key)) {
            // The new key is sealed under the counter of this very try, so a retry seals it anew.
            proto::Key next{};
            std::copy(payload.begin(), payload.end(), next);
            n = proto::encode_key_set(next, auth, seq, frame, sizeof frame);
        } else {
            n = proto::encode_authenticated(id, seq, payload.data(), payload.size(), auth, frame, sizeof frame);
        }
    } else {
        n = proto::encode_frame(id, seq, payload.data(), payload.size(), frame, sizeof frame);
    }
    if (seq_used != nullptr) *seq_used = seq;
    if (tap_) tap_(CaptureKind::tx, frame, n);
    return link_.write(frame, n);
}

void BoardClient::deliver(const Frame& frame) {
    if (handler_) handler_(frame);
    if (waiting_for_ && !awaited_ && waiting_for_(frame)) awaited_ = frame;
}

LinkStatus BoardClient::pump(int timeout_ms) {
    std::uint8_t buf[4096];
    const ReadResult r = link_.read(buf, sizeof buf, timeout_ms);
    if (r.status != LinkStatus::ok) return r.status;
    counters_.bytes_received += r.bytes;
    if (tap_) tap_(CaptureKind::rx, buf, r.bytes);
    for (std::size_t i = 0; i < r.bytes; ++i) {
        const std::uint8_t byte = buf[i];
        if (sync_state_ == 2 && byte != proto::kProtocolVersion) foreign_version_ = byte;
        sync_state_ = byte == proto::kSync0 ? 1 : (sync_state_ == 1 && byte == proto::kSync1 ? 2 : 0);
        if (!decoder_.feed(byte)) continue;
        do {
            const Frame f = copy_frame(decoder_);
            static_cast<void>(seq_.accept(f.seq));
            if (f.type == proto::MsgType::nak) {
                ++counters_.naks;
                proto::NakPayload nak{};
                if (proto::parse(f.payload.data(), f.payload_len, &nak) &&
                    nak.nacked_type == proto::type_id(proto::MsgType::poll))
                    poll_nak_ = nak;
            }
            deliver(f);
        } while (decoder_.next());
    }
    return LinkStatus::ok;
}

std::optional<Frame> BoardClient::await(const std::function<bool(const Frame&)>& match, int timeout_ms,
                                        LinkStatus* status) {
    waiting_for_ = match;
    awaited_.reset();
    const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
    *status = LinkStatus::timeout;
    while (!awaited_) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
        if (left <= 0) break;
        const LinkStatus s = pump(static_cast<int>(left));
        if (s == LinkStatus::lost) {
            *status = s;
            break;
        }
    }
    waiting_for_ = nullptr;
    if (awaited_) *status = LinkStatus::ok;
    std::optional<Frame> found = awaited_;
    awaited_.reset();
    return found;
}

HelloResult BoardClient::hello() {
    HelloResult result;
    const std::uint64_t bytes_before = counters_.bytes_received;
    const std::uint32_t frames_before = decoder_.counters().frames_ok;
    for (int attempt = 0; attempt < options_.hello_attempts; ++attempt) {
        if (send(proto::MsgType::hello, {}, nullptr) == LinkStatus::lost) {
            result.problem = "the port went away during the handshake";
            return result;
        }
        LinkStatus status;
        auto frame =
            await([](const Frame& f) { return f.type == proto::MsgType::version; }, options_.reply_timeout_ms, &status);
        if (status == LinkStatus::lost) {
            result.problem = "the port went away during the handshake";
            return result;
        }
        if (!frame) continue;
        if (!proto::parse(frame->payload.data(), frame->payload_len, &result.version)) continue;
        if (result.version.proto_version != proto::kProtocolVersion) {
            result.problem = "the board speaks protocol version " + std::to_string(result.version.proto_version) +
                             "; this driftlab speaks version " + std::to_string(proto::kProtocolVersion) +
                             " (flash matching firmware with `driftlab flash`)";
            return result;
        }
        if (result.version.tick_hz == 0) {
            result.problem = "the board reports a tick rate of 0 Hz in VERSION";
            return result;
        }
        auth_state_ = result.version.auth_state;
        next_counter_ = result.version.auth_counter + 1;
        result.ok = true;
        return result;
    }
    // A silent board may be a version-1 one in poll mode, which ignores v2 frames: its own HELLO gets its VERSION.
    if (counters_.bytes_received == bytes_before) probe_version_one();
    const std::uint64_t bytes = counters_.bytes_received - bytes_before;
    if (foreign_version_ && decoder_.counters().bad_version > 0) {
        result.problem = "the board speaks protocol version " + std::to_string(*foreign_version_) +
                         "; this driftlab speaks version " + std::to_string(proto::kProtocolVersion) +
                         " (flash matching firmware with `driftlab flash`)";
    } else if (bytes == 0) {
        result.problem = "no answer to HELLO in " +
                         std::to_string(options_.hello_attempts * options_.reply_timeout_ms / 1000.0).substr(0, 3) +
                         " s: not a driftlab board, wrong --baud, or firmware not flashed";
    } else if (decoder_.counters().frames_ok == frames_before) {
        result.problem = "the device sent " + std::to_string(bytes) +
                         " bytes but no valid driftlab frame: not a driftlab board, or wrong --baud";
    } else {
        result.problem = "the board sends frames but never answered HELLO with VERSION";
    }
    return result;
}

BoardClient::Answer BoardClient::request(proto::MsgType type, std::span<const std::uint8_t> payload,
                                         proto::MsgType reply) {
    Answer out;
    const char* name = proto::find_msg(proto::type_id(type))->name;
    if (proto::is_authenticated(proto::type_id(type))) out.problem = auth_obstacle(name);
    if (!out.problem.empty()) return out;
    for (int attempt = 0; attempt < options_.request_attempts; ++attempt) {
        std::uint16_t seq = 0;
        LinkStatus status = send(type, payload, &seq);
        std::optional<Frame> answer;
        if (status != LinkStatus::lost)
            answer =
                await([&](const Frame& f) { return answers(f, type, seq, reply); }, options_.reply_timeout_ms, &status);
        if (status == LinkStatus::lost) {
            out.problem = std::string("the port went away waiting for an answer to ") + name;
            return out;
        }
        if (!answer) continue;
        proto::NakPayload nak{};
        if (answer->type == proto::MsgType::nak && proto::parse(answer->payload.data(), answer->payload_len, &nak))
            if (const std::string why = auth_refusal(name, nak.status); !why.empty())
                out.problem = why;
            else
                out.nak = nak;
        else
            out.reply = answer;
        return out;
    }
    out.problem =
        std::string("no answer to ") + name + " after " + std::to_string(options_.request_attempts) + " tries";
    return out;
}

std::string BoardClient::auth_obstacle(const char* name) const {
    if (auth_state_ == static_cast<std::uint8_t>(proto::AuthState::keyed) && !key_)
        return std::string("the board obeys only authenticated commands: give its key with --key KEY to send ") + name +
               " (the key file `driftlab flash --key` provisioned)";
    if (auth_state_ == static_cast<std::uint8_t>(proto::AuthState::damaged))
        return std::string("the board's key record is damaged, so it refuses ") + name +
               " and every other command that changes it: provision the key again with `driftlab flash --key KEY`";
    return "";
}

std::string BoardClient::auth_refusal(const char* name, std::uint8_t status) const {
    if (status == static_cast<std::uint8_t>(proto::Status::unauthenticated))
        return std::string("the board refused ") + name +
               " as unauthenticated: the key given with --key is not this board's key";
    if (status == static_cast<std::uint8_t>(proto::Status::replayed))
        return std::string("the board refused ") + name +
               " as replayed: another sender's command took the counter since this one read it; run again";
    return "";
}

std::string BoardClient::key_change(const CommandKey& next) {
    const char* name = "KEY_SET";
    if (!key_) return "a key change needs the board's current key (--key KEY)";
    std::string problem = auth_obstacle(name);
    if (auth_state_ == static_cast<std::uint8_t>(proto::AuthState::open))
        problem = "the board has no key to change: provision one with `driftlab flash --key KEY`";
    if (!problem.empty()) return problem;
    const Answer a = request(proto::MsgType::key_set, next, proto::MsgType::ack);
    if (a.nak) return std::string("the board refused KEY_SET (NAK ") + status_name(a.nak->status) + ")";
    if (!a.reply)
        return a.problem +
               "; if only its ACK was lost the board has the new key: a command with either --key tells which";
    key_ = next;
    return "";
}

bool BoardClient::answers(const Frame& f, proto::MsgType type, std::uint16_t seq, proto::MsgType reply) {
    const auto id = proto::type_id(type);
    proto::AckPayload ack{};
    proto::NakPayload nak{};
    if (f.type == proto::MsgType::nak && proto::parse(f.payload.data(), f.payload_len, &nak))
        return nak.nacked_type == id && nak.nacked_seq == seq;
    if (f.type != reply) return false;
    return reply != proto::MsgType::ack ||
           (proto::parse(f.payload.data(), f.payload_len, &ack) && ack.acked_type == id && ack.acked_seq == seq);
}

void BoardClient::probe_version_one() {
    std::uint8_t frame[proto::kMaxFrameSize];
    const std::size_t n = proto::encode_legacy_hello(tx_seq_++, frame, sizeof frame);
    if (tap_) tap_(CaptureKind::tx, frame, n);
    if (link_.write(frame, n) == LinkStatus::lost) return;
    // A v1 board's VERSION is no frame of this decoder: it shows only as the version byte that pump() notes.
    LinkStatus status;
    static_cast<void>(await([](const Frame&) { return false; }, options_.reply_timeout_ms, &status));
}

ConfigResult BoardClient::configure(const proto::ConfigPayload& wanted) {
    ConfigResult result;
    std::uint8_t bytes[proto::kConfigPayloadSize];
    const std::size_t n = proto::serialize(wanted, bytes, sizeof bytes);
    const Answer set = request(proto::MsgType::config_set, std::span(bytes, n), proto::MsgType::ack);
    if (set.nak) {
        const char* field = proto::config_field_name(set.nak->field);
        result.problem = std::string("the board refused CONFIG_SET: ") + status_name(set.nak->status) +
                         (field ? std::string(" in field ") + field : "");
        return result;
    }
    if (!set.reply) {
        result.problem = set.problem;
        return result;
    }
    const Answer get = request(proto::MsgType::config_get, {}, proto::MsgType::config);
    if (!get.reply || !proto::parse(get.reply->payload.data(), get.reply->payload_len, &result.applied)) {
        result.problem = get.nak ? "the board refused CONFIG_GET" : get.problem;
        return result;
    }
    const std::string diff = describe_config_difference(wanted, result.applied);
    if (!diff.empty()) {
        result.problem = "the board acknowledged CONFIG_SET but CONFIG_GET reads back " + diff;
        return result;
    }
    result.ok = true;
    return result;
}

std::optional<proto::StatusPayload> BoardClient::status() {
    const Answer a = request(proto::MsgType::status_get, {}, proto::MsgType::status);
    proto::StatusPayload s{};
    if (a.reply && proto::parse(a.reply->payload.data(), a.reply->payload_len, &s)) return s;
    return std::nullopt;
}

std::optional<std::string> BoardClient::poll_refusal() const {
    if (!poll_nak_) return std::nullopt;
    std::string text = std::string("the board refused POLL (NAK ") + status_name(poll_nak_->status) + ")";
    if (poll_nak_->status == static_cast<std::uint8_t>(proto::Status::not_allowed))
        text +=
            ": it is in stream mode, not the poll mode driftlab set and read back; did another program on the "
            "port reconfigure it?";
    return text;
}

LinkStatus BoardClient::send_poll() {
    ++counters_.polls_sent;
    return send(proto::MsgType::poll, {}, nullptr);
}

}  // namespace driftlab::host::io
