// Calibration upload and verification (calibration_upload.hpp).
#include "host/io/calibration_upload.hpp"

namespace driftlab::host::io {
namespace {

std::string refusal(const char* request, const proto::NakPayload& nak) {
    const char* status = proto::status_name(static_cast<proto::Status>(nak.status));
    const char* field = proto::cal_field_name(nak.field);
    return std::string("the board refused ") + request + " (NAK " + (status ? status : "unknown status") +
           (field ? std::string(" in field ") + field : "") + ")";
}

bool same(const proto::CalPayload& a, const proto::CalPayload& b) {
    return a.cal_id == b.cal_id && a.channel == b.channel && a.flags == b.flags && a.c1_q8 == b.c1_q8 &&
           a.c2_q8 == b.c2_q8 && a.t_ms == b.t_ms;
}

// CAL_GET of `wanted`'s channel: "" when it reads back equal.
std::string read_back(BoardClient& client, const proto::CalPayload& wanted) {
    const std::uint8_t ask[proto::kCalGetPayloadSize] = {wanted.channel};
    const BoardClient::Answer a = client.request(proto::MsgType::cal_get, ask, proto::MsgType::cal);
    if (a.nak) return refusal("CAL_GET", *a.nak);
    proto::CalPayload got{};
    if (!a.reply || !proto::parse(a.reply->payload.data(), a.reply->payload_len, &got)) return a.problem;
    if (!same(got, wanted))
        return std::string("the board acknowledged CAL_SET of ") + kChannelNames[wanted.channel] +
               " but CAL_GET reads back another entry (cal_id " + std::to_string(got.cal_id) + ")";
    return "";
}

}  // namespace

UploadResult upload_calibration(BoardClient& client, const std::array<proto::CalPayload, kChannelCount>& entries) {
    UploadResult out;
    const HelloResult hello = client.hello();
    if (!hello.ok) {
        out.problem = hello.problem;
        return out;
    }
    for (const proto::CalPayload& entry : entries) {
        std::uint8_t bytes[proto::kCalPayloadSize];
        const std::size_t n = proto::serialize(entry, bytes, sizeof bytes);
        const BoardClient::Answer a = client.request(proto::MsgType::cal_set, std::span(bytes, n), proto::MsgType::ack);
        out.problem = a.nak ? refusal("CAL_SET", *a.nak) : (a.reply ? "" : a.problem);
        if (out.problem.empty()) out.problem = read_back(client, entry);
        if (!out.problem.empty()) return out;
    }
    const HelloResult after = client.hello();
    if (!after.ok) {
        out.problem = after.problem;
        return out;
    }
    out.version = after.version;
    const std::uint16_t id = entries[0].cal_id;
    const auto want = id == 0 ? proto::CalState::none : proto::CalState::active;
    const bool settled_ok = id != 0 && after.version.cal_state == static_cast<std::uint8_t>(proto::CalState::settled);
    if ((after.version.cal_state != static_cast<std::uint8_t>(want) && !settled_ok) || after.version.cal_id != id) {
        const char* state = proto::cal_state_name(after.version.cal_state);
        out.problem = "the board stored every entry but reports calibration state " +
                      std::string(state ? state : "unknown") + " with id " + std::to_string(after.version.cal_id) +
                      " instead of " + proto::cal_state_name(static_cast<std::uint8_t>(want)) + " with id " +
                      std::to_string(id);
        return out;
    }
    out.ok = true;
    return out;
}

}  // namespace driftlab::host::io
