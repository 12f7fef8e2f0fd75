// JSON of a diagnosis; see gap_json.hpp.
#include "host/gap/gap_json.hpp"

#include "host/gap/candidates.hpp"
#include "host/report/json_out.hpp"

namespace driftlab::host::gap {

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
                       {"ratio", report::json_number(l.ratio)},
                       {"difference", report::json_number(l.difference)},
                       {"interval", {report::json_number(l.interval_low), report::json_number(l.interval_high)}},
                       {"z", report::json_number(l.z)}});
    }
    return out;
}

json steps_json(const std::array<StepEstimate, 2>& steps) {
    json out = json::array();
    for (const auto& s : steps)
        out.push_back({{"t_s", report::json_number(s.t_s)}, {"size_counts", report::json_number(s.size_counts)}});
    return out;
}

json params_json(const std::vector<std::pair<std::string, double>>& list) {
    json params = json::object();
    for (const auto& [k, v] : list) params[k] = report::json_number(v);
    return params;
}

json explanation_json(const Explanation& e, InformationCriterion ic, bool added) {
    const json params = params_json(e.params);
    const StepsOverShape& s = e.shape_steps;
    const json shape_steps = s.tested ? json{{"statistic", report::json_number(s.statistic)},
                                             {"margin", report::json_number(s.margin)},
                                             {"steps", steps_json(s.steps)},
                                             {"steps_win", s.steps_win}}
                                      : json(nullptr);
    return {{"effect", e.effect},
            {"channel", e.channel},
            {"params", params},
            {"params_whole_log", e.whole_log_params.empty() ? json(nullptr) : params_json(e.whole_log_params)},
            {"gap_before", report::json_number(e.gap_before)},
            {"gap_after", report::json_number(e.gap_after)},
            {"heldout_before", report::json_number(e.heldout_before)},
            {"heldout_after", report::json_number(e.heldout_after)},
            {"heldout_shrink", report::json_number(e.heldout_shrink)},
            {"heldout_bound", report::json_number(e.heldout_bound)},
            {"within_bound_before", e.within_bound_before()},
            {"likelihood_gain", report::json_number(e.loss_gain)},
            {"penalty", report::json_number(e.penalty)},
            {"delta_ic", has_delta_ic(e) ? report::json_number(delta_ic(e, ic)) : json(nullptr)},
            {"cells_left", e.cells_left},
            {"level_step_p", e.residual_step.tested ? report::json_number(e.residual_step.p_value) : json(nullptr)},
            {"steps_over_shape", shape_steps},
            {"accepted", e.accepted},
            {"added", added},
            {"step", e.step},
            {"replaces_model", e.replaces_given},
            {"ambiguous_with", e.ambiguous_with.empty() ? json(nullptr) : json(e.ambiguous_with)},
            {"settle", e.settle}};
}

}  // namespace

json gap_to_json(const GapResult& r, const GapOptions& options) {
    json j;
    j["verdict"] = r.verdict;
    j["information_criterion"] = criterion_name(options.explain_options.information_criterion);
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
                         {"criterion_process_first", report::json_number(p.criterion_process)},
                         {"criterion_shape_first", report::json_number(p.criterion_shape)},
                         {"kept", p.shape_kept ? p.shape : p.process}});
    j["paths"] = paths;
    j["located"] = located_json(r.located, r.layout);
    j["located_after"] = located_json(r.located_after, r.layout);
    j["gap_before"] = {{"fit", report::json_number(r.gap_before_fit)},
                       {"heldout", report::json_number(r.gap_before_heldout)},
                       {"heldout_bound", report::json_number(r.gap_bound_before)}};
    j["gap_after"] = {{"fit", report::json_number(r.gap_after_fit)},
                      {"heldout", report::json_number(r.gap_after_heldout)},
                      {"heldout_bound", report::json_number(r.gap_bound_after)}};
    j["diffuse_gap"] = r.diffuse_gap;
    j["diffuse_searched"] = r.diffuse_searched;
    json constant = json::array();
    for (const auto& k : r.constant_channels)
        constant.push_back(
            {{"channel", kChannelNames[channel_index(k.channel)]}, {"counts", report::json_number(k.counts)}});
    j["constant_channels"] = constant;
    json quiet = json::array();
    for (const auto& k : r.noise_free)
        quiet.push_back({{"channel", kChannelNames[channel_index(k.channel)]},
                         {"spread_counts", report::json_number(k.spread_counts)}});
    j["noise_free_channels"] = quiet;
    json saturated = json::array();
    for (const auto& s : r.saturated)
        saturated.push_back({{"channel", kChannelNames[channel_index(s.channel)]},
                             {"rows", s.rows},
                             {"first_t_s", report::json_number(s.first_t_s)},
                             {"last_t_s", report::json_number(s.last_t_s)}});
    j["saturated"] = saturated;
    json lone = json::array();
    for (const auto& l : r.lone_values)
        lone.push_back({{"channel", kChannelNames[channel_index(l.channel)]},
                        {"t_s", l.t_s},
                        {"variance_share", report::json_number(l.variance_share)},
                        {"warning", l.warning}});
    j["lone_values"] = lone;
    json left_out = json::array();
    for (const auto& c : r.left_out)
        left_out.push_back({{"from_s", report::json_number(c.from_s)},
                            {"to_s", report::json_number(c.to_s)},
                            {"rows", c.rows},
                            {"by", c.by}});
    j["left_out"] = left_out;
    json steps = json::array();
    for (const auto& s : r.level_steps) {
        steps.push_back({{"channel", kChannelNames[channel_index(s.channel)]},
                         {"steps", steps_json(s.steps)},
                         {"impulse", report::json_number(s.impulse)},
                         {"impulse_p", report::json_number(s.impulse_p)},
                         {"statistic", report::json_number(s.statistic)},
                         {"margin", report::json_number(s.margin)},
                         {"rival_p", report::json_number(s.rival_p)},
                         {"p", report::json_number(s.p_value)},
                         {"process_gain", report::json_number(s.process_gain)},
                         {"process_margin", report::json_number(s.process_margin)},
                         {"outsized_increments", s.outsized},
                         {"significant", s.significant}});
    }
    j["level_steps"] = steps;
    json ni = json::array();
    for (const auto& n : not_identifiable_list()) ni.push_back({{"effect", n.effect}, {"reason", n.reason}});
    j["not_identifiable"] = ni;
    json nt = json::array();
    for (const auto& n : r.not_tried) nt.push_back({{"effect", n.effect}, {"reason", n.reason}});
    j["not_tried"] = nt;
    json cal = json::object();
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        if (!r.channels[c]) continue;
        const auto& b = r.base.base[c];
        cal[kChannelNames[c]] = {{"c1_counts", report::json_number(b.drift.c1_counts)},
                                 {"c2_counts", report::json_number(b.drift.c2_counts)},
                                 {"tau_s", report::json_number(b.drift.tau_s)},
                                 {"sigma_n_counts", report::json_number(b.sigma_n_counts)}};
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
                   {"dt_jitter_rel", report::json_number(r.timing.dt_jitter_rel)}};
    j["replicates"] = options.replicates;
    j["holdout"] = options.holdout == Holdout::forecast ? "forecast" : "interleaved";
    j["fit_fraction"] = options.fit_fraction;
    j["max_effects"] = options.explain_options.max_effects;
    j["threshold_z"] = report::json_number(r.before.threshold);
    j["cells"] = r.layout.size();
    return j;
}

nlohmann::json stability_to_json(const VerdictStability& s) {
    using nlohmann::json;
    json params = json::array();
    for (const ParameterSpread& p : s.params) {
        params.push_back({{"effect", p.effect},
                          {"channel", p.channel},
                          {"param", p.param},
                          {"estimate", report::json_number(p.estimate)},
                          {"values", report::json_array(p.values)},
                          {"median", report::json_number(p.quantile(0.5))},
                          {"p16", report::json_number(p.quantile(0.16))},
                          {"p84", report::json_number(p.quantile(0.84))}});
    }
    return {{"logs", s.logs},
            {"verdicts", s.verdicts},
            {"same", s.logs ? static_cast<double>(s.same) / static_cast<double>(s.logs) : 0.0},
            {"params", params}};
}

}  // namespace driftlab::host::gap
