// The link section of a gap result (GapResult::link), in the terminal's text, the report and the JSON; see
// gap_view.hpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <ostream>

#include "host/util/format_number.hpp"
#include "host/view/gap_phrases.hpp"
#include "host/view/gap_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {
namespace {

// "2.0 % lost, bursts of 4.1 frames": what a link candidate's parameters mean.
std::string reading(const gap::Explanation& e) {
    const auto value = [&](const char* key) { return gap::link_parameter(e, key); };
    std::string out;
    if (const auto to_bad = value("p_good_to_bad"), to_good = value("p_bad_to_good"); to_bad && to_good) {
        const double loss = *to_bad + *to_good > 0 ? *to_bad / (*to_bad + *to_good) : 0.0;
        out = fixed_point(100.0 * loss, 2) + " % of frames lost in bursts of " +
              significant(*to_good > 0 ? 1.0 / *to_good : 0.0, 3) + " frames on average";
    }
    if (const auto rate = value("byte_error_rate"))
        out = "each frame of " + std::to_string(gap::sample_frame_bytes()) + " bytes lost alone with probability " +
              significant(1.0 - std::pow(1.0 - *rate, static_cast<double>(gap::sample_frame_bytes())), 3);
    if (const auto polls = value("polls_unanswered"))
        out += "; " + fixed_point(100.0 * *polls, 2) + " % of polls unanswered";
    return out;
}

std::string model_text(const gap::FrameLoss& m) {
    return "the unit's link loses " +
           (m.chain.p_good_to_bad > 0 ? "frames in Gilbert-Elliott bursts (p " + significant(m.chain.p_good_to_bad, 3) +
                                            ", r " + significant(m.chain.p_bad_to_good, 3) + ")"
                                      : std::string("no frame to bursts")) +
           " and " + significant(100.0 * m.corrupted, 3) + " % of frames to byte errors";
}

}  // namespace

void print_link_text(const gap::GapResult& r) {
    const gap::LinkFindings& k = r.link;
    if (!k.observed) {
        std::printf("link: not compared (a plain recording: its rows came in no frames)\n");
        return;
    }
    std::printf("link: %llu of %llu frame slots lost; %s; %zu link cell%s located\n",
                static_cast<unsigned long long>(k.lost), static_cast<unsigned long long>(k.slots),
                model_text(k.model).c_str(), k.located.size(), k.located.size() == 1 ? "" : "s");
    for (const auto& l : k.located) {
        const auto& c = k.layout[l.index];
        std::printf("  %-7s %-36s %-7s z %9.1f  log %s, model %s\n", c.statistic.c_str(), c.shown().c_str(),
                    gap::segment_name(c.segment), l.z, significant(l.real, 3).c_str(),
                    significant(l.sim_mean, 3).c_str());
    }
    for (std::size_t i = 0; i < k.tried.size(); ++i) {
        const gap::Explanation& e = k.tried[i];
        std::printf("  %-12s %s heldout %.3g -> %.3g (shrink %s%%)  gain %s vs penalty %s  %s: %s%s\n",
                    e.effect.c_str(),
                    k.added == i ? "ADDED   "
                    : e.accepted ? "passed  "
                                 : "rejected",
                    e.heldout_before, e.heldout_after, fixed_point(100 * e.heldout_shrink, 0).c_str(),
                    significant(e.loss_gain, 3).c_str(), fixed_point(e.penalty, 1).c_str(),
                    parameter_list(e.estimate()).c_str(), reading(e).c_str(),
                    e.ambiguous_with.empty() ? "" : ("  AMBIGUOUS with " + e.ambiguous_with).c_str());
    }
}

void write_link_markdown(std::ostream& md, const gap::GapResult& r) {
    const gap::LinkFindings& k = r.link;
    if (!k.observed) return;
    md << "## The link\n\n"
       << k.lost << " of " << k.slots << " frame slots lost (sequence numbers); " << model_text(k.model) << ".\n\n"
       << "| statistic | cell | part | log | model | z | located |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t j = 0; j < k.layout.size(); ++j) {
        const bool located =
            std::any_of(k.located.begin(), k.located.end(), [&](const gap::LocatedCell& l) { return l.index == j; });
        md << "| " << k.layout[j].statistic << " | " << k.layout[j].shown() << " | "
           << gap::segment_name(k.layout[j].segment) << " | " << significant(k.real[j], 3) << " | "
           << significant(k.before.sim_mean[j], 3) << " | " << significant(k.before.z[j], 3) << " | "
           << (located ? "yes" : "") << " |\n";
    }
    for (std::size_t i = 0; i < k.tried.size(); ++i)
        md << "\n- `" << k.tried[i].effect << "` "
           << (k.added == i          ? "**added**"
               : k.tried[i].accepted ? "passed"
                                     : "rejected")
           << ": " << parameter_list(k.tried[i].estimate()) << " (" << reading(k.tried[i]) << "); held-out score "
           << significant(k.tried[i].heldout_before, 3) << " -> " << significant(k.tried[i].heldout_after, 3) << "\n";
    md << "\n";
}

nlohmann::json link_to_json(const gap::GapResult& r) {
    const gap::LinkFindings& k = r.link;
    if (!k.observed) return nullptr;
    nlohmann::json cells = nlohmann::json::array(), located = nlohmann::json::array(), tried = nlohmann::json::array();
    for (std::size_t j = 0; j < k.layout.size(); ++j)
        cells.push_back({{"statistic", k.layout[j].statistic},
                         {"cell", k.layout[j].cell},
                         {"segment", gap::segment_name(k.layout[j].segment)},
                         {"log", json_number(k.real[j])},
                         {"model", json_number(k.before.sim_mean[j])},
                         {"z", json_number(k.before.z[j])}});
    for (const auto& l : k.located)
        located.push_back({{"statistic", k.layout[l.index].statistic},
                           {"segment", gap::segment_name(k.layout[l.index].segment)},
                           {"z", json_number(l.z)}});
    for (std::size_t i = 0; i < k.tried.size(); ++i) {
        const gap::Explanation& e = k.tried[i];
        nlohmann::json params = nlohmann::json::object(), whole = nlohmann::json::object();
        for (const auto& [name, value] : e.params) params[name] = json_number(value);
        for (const auto& [name, value] : e.whole_log_params) whole[name] = json_number(value);
        tried.push_back({{"effect", e.effect},
                         {"params", params},
                         {"params_whole_log", whole},
                         {"heldout_before", json_number(e.heldout_before)},
                         {"heldout_after", json_number(e.heldout_after)},
                         {"heldout_shrink", json_number(e.heldout_shrink)},
                         {"likelihood_gain", json_number(e.loss_gain)},
                         {"penalty", json_number(e.penalty)},
                         {"accepted", e.accepted},
                         {"added", k.added == i},
                         {"ambiguous_with", e.ambiguous_with}});
    }
    return {{"slots", k.slots},
            {"lost", k.lost},
            {"model",
             {{"p_good_to_bad", json_number(k.model.chain.p_good_to_bad)},
              {"p_bad_to_good", json_number(k.model.chain.p_bad_to_good)},
              {"frame_corrupted", json_number(k.model.corrupted)}}},
            {"threshold_z", json_number(k.before.threshold)},
            {"cells", cells},
            {"located", located},
            {"candidates", tried}};
}

}  // namespace driftlab::host::view
