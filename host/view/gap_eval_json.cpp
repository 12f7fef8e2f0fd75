// The JSON of a gap-eval run; see gap_eval_view.hpp.
#include "host/gap/candidates.hpp"
#include "host/view/gap_eval_view.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {

using gap::EvalOptions;
using gap::EvalScores;
using nlohmann::json;

namespace {

json number(const std::optional<double>& v) { return v ? json_number(*v) : json(nullptr); }

// Per generator and size, and the targets read on them.
void put_by_size(json& j, const EvalScores& s) {
    json rows = json::array();
    for (const auto& z : s.by_size)
        rows.push_back({{"generator", z.generator},
                        {"truth", z.truth},
                        {"level", z.level},
                        {"logs", z.logs},
                        {"detected", z.detected},
                        {"top1", z.top1},
                        {"or_pair", z.or_pair},
                        {"shrink",
                         {{"predicted", number(z.predicted)},
                          {"remeasured", number(z.remeasured)},
                          {"oracle", number(z.oracle)},
                          {"abs_error", number(z.abs_error)}}}});
    j["by_size"] = rows;
    json targets = json::array();
    for (const auto& t : s.targets)
        targets.push_back({{"target", t.target},
                           {"count", t.count},
                           {"logs", t.logs},
                           {"rate", t.rate},
                           {"interval", {t.low, t.high}},
                           {"bound", t.bound},
                           {"at_most", t.at_most},
                           {"met", t.met},
                           {"settled", t.settled}});
    j["targets"] = targets;
}

void put_pairs(json& j, const EvalScores& s) {
    json pairs = json::array();
    for (const auto& z : s.pairs) {
        json effects = json::array({z.first_effect});
        if (!z.second_effect.empty()) effects.push_back(z.second_effect);
        pairs.push_back({{"generators", {z.first, z.second}},
                         {"effects", effects},
                         {"level", z.level},
                         {"logs", z.logs},
                         {"detected", z.detected},
                         {"verdict_one", z.verdict_one},
                         {"all", z.all},
                         {"wrong", z.wrong},
                         {"unexplained", z.unexplained},
                         {"added", z.added},
                         {"found", z.found},
                         {"truths", z.truths},
                         {"found_or_pair", z.found_or_pair},
                         {"within_bound_added", z.within_bound_added},
                         {"within_bound_true", z.within_bound_true},
                         {"precision", json_number(z.precision)},
                         {"recall", json_number(z.recall)},
                         {"recall_or_pair", json_number(z.recall_or_pair)},
                         {"f1", json_number(z.f1)},
                         {"shrink", number(z.shrink)}});
    }
    j["pairs"] = pairs;
}

}  // namespace

nlohmann::json scores_json(const EvalScores& s) {
    const EvalOptions& o = s.options;
    json j;
    j["thresholds"] = {{"penalty_per_param", s.thresholds.penalty_per_param},
                       {"min_heldout_shrink", s.thresholds.min_heldout_shrink},
                       {"step_alpha", s.thresholds.step_alpha},
                       {"information_criterion", criterion_name(s.thresholds.information_criterion)}};
    j["tune_seeds"] = o.tune ? json{o.tune_first, o.tune_last} : json(nullptr);
    j["score_seeds"] = {o.score_first, o.score_last};
    j["samples"] = o.samples;
    j["replicates"] = o.replicates;
    json a50 = json::array();
    for (const auto& d : s.sizes) {
        json curve = json::array();
        for (const auto& p : d.curve) curve.push_back({{"size", p.size}, {"detected", p.detected}, {"logs", p.logs}});
        a50.push_back({{"generator", d.generator}, {"a50", json_number(d.a50)}, {"curve", curve}});
    }
    j["a50"] = a50;
    j["false_positive"] = {
        {"clean", s.clean},
        {"flagged", s.clean_flagged},
        {"rate", s.clean ? static_cast<double>(s.clean_flagged) / static_cast<double>(s.clean) : 0.0},
        {"interval", {s.fpr_low, s.fpr_high}},
        {"raw_mode", s.options.clean_form == gap::CleanForm::raw_mode},
        {"codes", s.options.clean_form == gap::CleanForm::codes},
        {"lossy_link", s.options.clean_form == gap::CleanForm::lossy_link},
        {"four_channels", s.options.clean_form == gap::CleanForm::four_channels}};
    json confusion = json::object();
    for (const auto& [row, count] : s.confusion) confusion[row] = count;
    j["confusion"] = confusion;
    put_by_size(j, s);
    put_pairs(j, s);
    return j;
}

}  // namespace driftlab::host::view
