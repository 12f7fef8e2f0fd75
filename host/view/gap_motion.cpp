// The motion section of a gap result (`gap --truth`), in the terminal's text and the JSON; see gap_view.hpp.
#include <cstdio>

#include "host/util/format_number.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {
namespace {

std::string round_robin_text(const gap::MotionFindings& m) {
    return std::string(kChannelNames[static_cast<std::size_t>(m.newest_channel)]) +
           " converted last before the first row" +
           (m.newest_estimated ? " (a polled log: the phase that fits it best)" : " (streamed)");
}

}  // namespace

bool tried_in_motion(const gap::GapResult& r, const std::string& effect) {
    if (!r.motion) return false;
    for (const gap::MotionTermFit& f : r.motion->terms)
        if (f.term.effect == effect) return true;
    return false;
}

void print_motion_text(const gap::GapResult& r) {
    if (!r.motion) return;
    const gap::MotionFindings& m = *r.motion;
    std::printf("motion: known input from %s, %s; %s\n", m.truth_path.c_str(), m.input_source.c_str(),
                round_robin_text(m).c_str());
    for (const gap::MotionTermFit& f : m.terms) {
        std::printf("  %-13s %-7s %-16s ", f.term.effect.c_str(), kChannelNames[channel_index(f.term.channel)],
                    f.term.parameter.c_str());
        if (!f.tested) {
            std::printf("not tested: %s\n", f.not_tested.c_str());
            continue;
        }
        std::printf("%s %s (+- the spread at rest; z %.1f)%s\n", value_with_error(f.value, f.null_sd, "+-").c_str(),
                    f.term.unit.c_str(), f.z, f.accepted ? "  ACCEPTED" : "");
    }
    std::printf(
        "  accepted where |z| > %.2f (Student t on %d replicates of the unit at rest, family-wise alpha over "
        "the terms tested); the rest of the diagnosis reads the log less the known input and the accepted "
        "terms\n",
        m.z_threshold, m.replicates);
}

nlohmann::json motion_to_json(const gap::GapResult& r) {
    if (!r.motion) return nullptr;
    const gap::MotionFindings& m = *r.motion;
    nlohmann::json terms = nlohmann::json::array();
    for (const gap::MotionTermFit& f : m.terms) {
        nlohmann::json t = {{"effect", f.term.effect},
                            {"channel", kChannelNames[channel_index(f.term.channel)]},
                            {"parameter", f.term.parameter},
                            {"unit", f.term.unit},
                            {"input", gap::motion_quantity_name(f.term.input)},
                            {"tested", f.tested}};
        if (f.tested) {
            t["value"] = json_number(f.value);
            t["null_sd"] = json_number(f.null_sd);
            t["z"] = json_number(f.z);
            t["accepted"] = f.accepted;
        } else {
            t["not_tested"] = f.not_tested;
        }
        terms.push_back(t);
    }
    return {{"truth", m.truth_path},
            {"input_source", m.input_source},
            {"newest_channel", kChannelNames[static_cast<std::size_t>(m.newest_channel)]},
            {"newest_estimated", m.newest_estimated},
            {"threshold_z", json_number(m.z_threshold)},
            {"terms", terms}};
}

}  // namespace driftlab::host::view
