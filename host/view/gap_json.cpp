// The JSON of a gap result; see gap_view.hpp.
#include "host/gap/candidates.hpp"
#include "host/view/gap_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {

using gap::Cell;
using gap::Explanation;
using gap::GapOptions;
using gap::GapResult;
using gap::InformationCriterion;
using gap::LocatedCell;
using gap::ParameterSpread;
using gap::StepEstimate;
using gap::StepsOverShape;
using gap::VerdictStability;

namespace {

using nlohmann::json;

json located_json(const std::vector<LocatedCell>& cells, const std::vector<Cell>& layout) {
    json out = json::array();
    for (const auto& l : cells) {
        const Cell& c = layout[l.index];
        out.push_back({{"statistic", c.statistic},
                       {"channel", c.channel},
                       {"cell", c.cell},
                       {"segment", segment_name(c.segment)},
                       {"ratio", json_number(l.ratio)},
                       {"difference", json_number(l.difference)},
                       {"interval", {json_number(l.interval_low), json_number(l.interval_high)}},
                       {"z", json_number(l.z)}});
    }
    return out;
}

json steps_json(const std::array<StepEstimate, 2>& steps) {
    json out = json::array();
    for (const auto& s : steps)
        out.push_back({{"t_s", json_number(s.t_s)}, {"size_counts", json_number(s.size_counts)}});
    return out;
}

json params_json(const std::vector<std::pair<std::string, double>>& list) {
    json params = json::object();
    for (const auto& [k, v] : list) params[k] = json_number(v);
    return params;
}

json explanation_json(const Explanation& e, InformationCriterion ic, bool added) {
    const json params = params_json(e.params);
    const StepsOverShape& s = e.shape_steps;
    const json shape_steps = s.tested ? json{{"statistic", json_number(s.statistic)},
                                             {"margin", json_number(s.margin)},
                                             {"steps", steps_json(s.steps)},
                                             {"steps_win", s.steps_win}}
                                      : json(nullptr);
    return {{"effect", e.effect},
            {"channel", e.channel},
            {"params", params},
            {"params_whole_log", e.whole_log_params.empty() ? json(nullptr) : params_json(e.whole_log_params)},
            {"gap_before", json_number(e.gap_before)},
            {"gap_after", json_number(e.gap_after)},
            {"heldout_before", json_number(e.heldout_before)},
            {"heldout_after", json_number(e.heldout_after)},
            {"heldout_shrink", json_number(e.heldout_shrink)},
            {"heldout_bound", json_number(e.heldout_bound)},
            {"within_bound_before", e.within_bound_before()},
            {"likelihood_gain", json_number(e.loss_gain)},
            {"penalty", json_number(e.penalty)},
            {"delta_ic", has_delta_ic(e) ? json_number(delta_ic(e, ic)) : json(nullptr)},
            {"cells_left", e.cells_left},
            {"level_step_p", e.residual_step.tested ? json_number(e.residual_step.p_value) : json(nullptr)},
            {"steps_over_shape", shape_steps},
            {"accepted", e.accepted},
            {"added", added},
            {"step", e.step},
            {"replaces_model", e.replaces_given},
            {"ambiguous_with", e.ambiguous_with.empty() ? json(nullptr) : json(e.ambiguous_with)},
            {"settle", e.settle}};
}

// What the search tried and added, the model's own effects, and the paths followed.
void put_explanations(json& j, const GapResult& r, const GapOptions& options) {
    json ex = json::array();
    for (const auto& e : r.accepted)
        ex.push_back(explanation_json(e, options.explain_options.information_criterion, true));
    for (const auto& e : r.tried)
        if (!was_added(r, e)) ex.push_back(explanation_json(e, options.explain_options.information_criterion, false));
    j["explanations"] = ex;
    const auto given_json = [](const std::vector<Explanation>& list) {
        json out = json::array();
        for (const auto& e : list)
            out.push_back({{"effect", e.effect}, {"channel", e.channel}, {"params", params_json(e.params)}});
        return out;
    };
    j["given"] = {
        {"refitted", given_json(r.given.refitted)}, {"held", given_json(r.given.held)}, {"kept", r.given.kept}};
    json paths = json::array();
    for (const auto& p : r.paths)
        paths.push_back({{"step", p.step},
                         {"channel", p.channel},
                         {"process_first", p.process},
                         {"shape_first", p.shape},
                         {"criterion_process_first", json_number(p.criterion_process)},
                         {"criterion_shape_first", json_number(p.criterion_shape)},
                         {"kept", p.shape_kept ? p.shape : p.process}});
    j["paths"] = paths;
}

// The rows and channels left out of the comparison, and why.
void put_left_out(json& j, const GapResult& r) {
    json constant = json::array();
    for (const auto& k : r.constant_channels)
        constant.push_back({{"channel", kChannelNames[channel_index(k.channel)]}, {"counts", json_number(k.counts)}});
    j["constant_channels"] = constant;
    json quiet = json::array();
    for (const auto& k : r.noise_free)
        quiet.push_back(
            {{"channel", kChannelNames[channel_index(k.channel)]}, {"spread_counts", json_number(k.spread_counts)}});
    j["noise_free_channels"] = quiet;
    json saturated = json::array();
    for (const auto& s : r.saturated)
        saturated.push_back({{"channel", kChannelNames[channel_index(s.channel)]},
                             {"rows", s.rows},
                             {"first_t_s", json_number(s.first_t_s)},
                             {"last_t_s", json_number(s.last_t_s)}});
    j["saturated"] = saturated;
    json lone = json::array();
    for (const auto& l : r.lone_values)
        lone.push_back({{"channel", kChannelNames[channel_index(l.channel)]},
                        {"t_s", l.t_s},
                        {"variance_share", json_number(l.variance_share)},
                        {"warning", l.warning}});
    j["lone_values"] = lone;
    json left_out = json::array();
    for (const auto& c : r.left_out)
        left_out.push_back(
            {{"from_s", json_number(c.from_s)}, {"to_s", json_number(c.to_s)}, {"rows", c.rows}, {"by", c.by}});
    j["left_out"] = left_out;
}

void put_level_steps(json& j, const GapResult& r) {
    json steps = json::array();
    for (const auto& s : r.level_steps) {
        steps.push_back({{"channel", kChannelNames[channel_index(s.channel)]},
                         {"steps", steps_json(s.steps)},
                         {"impulse", json_number(s.impulse)},
                         {"impulse_p", json_number(s.impulse_p)},
                         {"statistic", json_number(s.statistic)},
                         {"margin", json_number(s.margin)},
                         {"rival_p", json_number(s.rival_p)},
                         {"p", json_number(s.p_value)},
                         {"process_gain", json_number(s.process_gain)},
                         {"process_margin", json_number(s.process_margin)},
                         {"outsized_increments", s.outsized},
                         {"significant", s.significant}});
    }
    j["level_steps"] = steps;
}

// The calibrated base and the log's timing.
void put_calibration(json& j, const GapResult& r) {
    json cal = json::object();
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!r.channels[c]) continue;
        const auto& b = r.base.base[c];
        cal[kChannelNames[c]] = {{"c1_counts", json_number(b.drift.c1_counts)},
                                 {"c2_counts", json_number(b.drift.c2_counts)},
                                 {"tau_s", json_number(b.drift.tau_s)},
                                 {"sigma_n_counts", json_number(b.sigma_n_counts)}};
    }
    j["calibration"] = {{"channels", cal},
                        {"sample_period_s", r.base.smoothing.sample_period_s},
                        {"outputs_per_row", r.base.smoothing.outputs_per_row},
                        {"conversions_per_output", r.base.smoothing.conversions_per_output},
                        {"window", r.base.smoothing.window},
                        {"fit_order", r.base.smoothing.fit_order}};
    j["timing"] = {{"sequence_jumps", r.timing.sequence_jumps},
                   {"lost_frames", r.timing.lost_frames},
                   {"gap_events", r.timing.gap_events},
                   {"dt_jitter_rel", json_number(r.timing.dt_jitter_rel)}};
}

}  // namespace

json gap_to_json(const GapResult& r, const GapOptions& options) {
    json j;
    j["verdict"] = r.verdict;
    j["information_criterion"] = criterion_name(options.explain_options.information_criterion);
    put_explanations(j, r, options);
    j["located"] = located_json(r.located, r.layout);
    j["located_after"] = located_json(r.located_after, r.layout);
    j["gap_before"] = {{"fit", json_number(r.gap_before_fit)},
                       {"heldout", json_number(r.gap_before_heldout)},
                       {"heldout_bound", json_number(r.gap_bound_before)}};
    j["gap_after"] = {{"fit", json_number(r.gap_after_fit)},
                      {"heldout", json_number(r.gap_after_heldout)},
                      {"heldout_bound", json_number(r.gap_bound_after)}};
    j["diffuse_gap"] = r.diffuse_gap;
    j["diffuse_searched"] = r.diffuse_searched;
    put_left_out(j, r);
    put_level_steps(j, r);
    json ni = json::array();
    for (const auto& n : gap::not_identifiable_list())
        if (!tried_in_motion(r, n.effect)) ni.push_back({{"effect", n.effect}, {"reason", n.reason}});
    j["not_identifiable"] = ni;
    json nt = json::array();
    for (const auto& n : r.not_tried) nt.push_back({{"effect", n.effect}, {"reason", n.reason}});
    j["not_tried"] = nt;
    put_calibration(j, r);
    j["replicates"] = options.replicates;
    j["holdout"] = options.holdout == gap::Holdout::forecast ? "forecast" : "interleaved";
    j["fit_fraction"] = options.fit_fraction;
    j["max_effects"] = options.explain_options.max_effects;
    j["threshold_z"] = json_number(r.before.threshold);
    j["cells"] = r.layout.size();
    j["motion"] = motion_to_json(r);
    j["link"] = link_to_json(r);
    j["common"] = common_to_json(r);
    return j;
}

nlohmann::json stability_to_json(const VerdictStability& s) {
    using nlohmann::json;
    json params = json::array();
    for (const ParameterSpread& p : s.params) {
        params.push_back({{"effect", p.effect},
                          {"channel", p.channel},
                          {"param", p.param},
                          {"estimate", json_number(p.estimate)},
                          {"values", json_array(p.values)},
                          {"median", json_number(p.quantile(0.5))},
                          {"p16", json_number(p.quantile(0.16))},
                          {"p84", json_number(p.quantile(0.84))}});
    }
    return {{"logs", s.logs},
            {"verdicts", s.verdicts},
            {"same", s.logs ? static_cast<double>(s.same) / static_cast<double>(s.logs) : 0.0},
            {"params", params}};
}

}  // namespace driftlab::host::view
