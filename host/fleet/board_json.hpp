// A board's result as a document: what the cache keeps and a shard's part carries (CBOR, every double exact).
#pragma once

#include <nlohmann/json.hpp>

#include "host/fleet/batch.hpp"
#include "host/fleet/board.hpp"

namespace driftlab::host::fleet {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Estimate, value, std_error, known)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(ChannelResult, channel, error, fit_status, parameters)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(BoardResult, rows, duration_s, channels, gap_run, gap_verdict, gap_located,
                                   gap_error)

// By hand: this nlohmann_json has no std::optional. A board without a result writes null.
inline void to_json(nlohmann::json& j, const BoardEntry& b) {
    j = {{"log", b.log}, {"result", nullptr}, {"error", b.error}};
    if (b.result) j["result"] = *b.result;
}

inline void from_json(const nlohmann::json& j, BoardEntry& b) {
    j.at("log").get_to(b.log);
    j.at("error").get_to(b.error);
    if (j.at("result").is_null())
        b.result.reset();
    else
        b.result = j.at("result").get<BoardResult>();
}

}  // namespace driftlab::host::fleet
