// The withheld-effect benchmark; see evaluate.hpp.
#include "host/gap/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "host/gap/candidates.hpp"
#include "host/gap/comparison.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap/sim_chain.hpp"
#include "host/gap/truth.hpp"
#include "sim/model/rng.hpp"
#include "sim/model/white_noise.hpp"

namespace driftlab::host::gap {

namespace {

constexpr double kSamplePeriodS = 1.0;
constexpr int kWindow = 8;

// Reference size of each generator in units of the smoothed output's white-noise standard deviation; chosen
// near the sizes the battery starts to see on a 1500-sample log (docs/gap.md §Evaluation).
double reference_size(const std::string& generator) {
    static const std::map<std::string, double> ref = {
        {"thermal_rc", 1.5}, {"thermostat", 0.4}, {"kasdin_flicker", 0.5}, {"wandering_ou", 0.5},
        {"student_walk", 1.0}, {"burst_spikes", 4.0}, {"mode_hop", 0.5}};
    return ref.at(generator);
}

GapModel randomised_truth(std::uint64_t seed) {
    sim::Rng rng(seed, 0x60);
    auto factor = [&] { return std::exp(std::log(0.5) + rng.uniform() * std::log(4.0)); };  // x[0.5, 2]
    GapModel m;
    m.unit = sim::paper_model();
    m.unit.effects.clear();
    m.smoothing = {kSamplePeriodS, kWindow, kWindow, 0};
    const sim::DriftParams paper = sim::kPaperDrift[0];
    m.base[0].drift = {paper.c1_counts * factor(), paper.c2_counts, paper.tau_s * factor()};
    const double raw_counts = 0.187 * 512.0 / 90.0 * std::sqrt(factor());
    m.base[0].sigma_n_counts = sim::analog_sigma_for_raw_std_counts(std::max(raw_counts, sim::kMinCalibratedRawStdCounts));
    return m;
}

LogData make_log(const GapModel& truth, const std::vector<double>& added, std::size_t samples, std::uint64_t seed) {
    LogData log;
    log.source_name = "gap-eval";
    log.t_s.resize(samples);
    for (std::size_t k = 0; k < samples; ++k) log.t_s[k] = static_cast<double>(k + 1) * kSamplePeriodS;
    SimRequest req;
    req.t_s = &log.t_s;
    req.channels = {true, false, false, false};
    if (!added.empty()) req.added_counts[0] = added;
    const SimOutput sim = simulate(truth, req, seed ^ 0xA5A5A5A5ull);
    log.counts[0] = sim[0];
    for (std::size_t c = 1; c < kChannelCount; ++c) log.counts[c].assign(samples, 512.0);
    log.seq.resize(samples);
    for (std::size_t k = 0; k < samples; ++k) log.seq[k] = k;
    log.metadata.set("sample_period_s", kSamplePeriodS);
    log.metadata.set("conversions_per_output", static_cast<std::int64_t>(kWindow));
    log.metadata.set("window", static_cast<std::int64_t>(kWindow));
    log.metadata.set("fit_order", static_cast<std::int64_t>(0));
    return log;
}

double output_noise_sd(const GapModel& m) {
    const double s = m.base[0].sigma_n_counts;
    return std::sqrt((s * s + 1.0 / 12.0) / kWindow);
}

EvalCase run_case(const std::string& generator, const std::string& truth, double level, std::uint64_t seed, bool tuning,
                  const EvalOptions& options) {
    EvalCase c{generator, truth, level, 0.0, seed, tuning, false, {}, 0.0, false};
    const GapModel model = randomised_truth(seed);
    std::vector<double> added;
    if (generator != "none") {
        c.size_counts = level * reference_size(generator) * output_noise_sd(model);
        std::vector<double> t(options.samples);
        for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k + 1) * kSamplePeriodS;
        added = make_truth(generator, t, c.size_counts, seed);
    }
    const LogData log = make_log(model, added, options.samples, seed);
    GapOptions go;
    go.replicates = options.replicates;
    go.seed = seed * 7 + 3;
    go.threads = options.threads;
    go.explain_options.fit_replicates = options.fit_replicates;
    go.explain_options.max_evaluations = options.max_evaluations;
    go.explain_options.max_effects = 1;
    // Every candidate's metrics are kept; the thresholds are applied afterwards (decide()).
    go.explain_options.penalty_per_param = 0.0;
    go.explain_options.min_heldout_shrink = -1e9;
    const GapResult r = diagnose(log, sim::paper_model(), go);
    c.detected = !r.located.empty();
    c.tried = r.tried;
    if (!r.accepted.empty() && r.accepted.front().effect == truth) {
        // The predicted shrink re-measured on replicates the choice never saw.
        BatteryOptions b;
        b.channels = r.channels;
        b.sample_period_s = kSamplePeriodS;
        std::array<const std::vector<double>*, kChannelCount> y{};
        y[0] = &log.counts[0];
        std::vector<Cell> layout;
        const auto real = compute_battery(log.t_s, y, b, &layout).values;
        const auto held = [](const Cell& cell) { return cell.segment == Segment::heldout; };
        const std::uint64_t fresh = go.seed + 1000003;
        const double before = gap_score(compare(real, run_replicates(r.base, log.t_s, b, go.replicates, fresh, go.threads), 0.05), layout, held);
        const double after = gap_score(compare(real, run_replicates(r.final_model, log.t_s, b, go.replicates, fresh, go.threads), 0.05), layout, held);
        c.shrink_check = before > 1.0 ? (before - after) / (before - 1.0) : 0.0;
        c.has_shrink_check = true;
    }
    return c;
}

}  // namespace

std::string decide(const EvalCase& c, const Thresholds& th) {
    if (!c.detected) return "none";
    const Explanation* best = nullptr;
    for (const auto& e : c.tried)
        if (passes(e, th.penalty_per_param, th.min_heldout_shrink) && (!best || e.heldout_loss_gain > best->heldout_loss_gain)) best = &e;
    return best ? best->effect : "unexplained";
}

std::vector<EvalCase> run_cases(const EvalOptions& options) {
    std::vector<std::string> gens = options.generators;
    if (gens.empty())
        for (const auto& t : truth_list()) gens.push_back(t.generator);
    struct Job {
        std::string generator, truth;
        double level;
        std::uint64_t seed;
        bool tune;
    };
    std::vector<Job> jobs;
    for (int set = 0; set < 2; ++set) {
        const std::uint64_t first = set == 0 ? options.tune_first : options.score_first;
        const std::uint64_t last = set == 0 ? options.tune_last : options.score_last;
        for (std::uint64_t s = first; s <= last; ++s) {
            jobs.push_back({"none", "none", 0.0, s, set == 0});
            for (const auto& g : gens) {
                std::string truth;
                for (const auto& t : truth_list())
                    if (t.generator == g) truth = t.effect;
                for (double level : options.levels) jobs.push_back({g, truth, level, s, set == 0});
            }
        }
    }
    std::vector<EvalCase> out;
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        const Job& j = jobs[i];
        out.push_back(run_case(j.generator, j.truth, j.level, j.seed * 1009 + i, j.tune, options));
        if (options.progress) options.progress(i + 1, jobs.size());
    }
    return out;
}

Thresholds tune(const std::vector<EvalCase>& cases) {
    Thresholds best;
    double best_score = -1.0;
    for (double pen : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0}) {
        for (double shrink : {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6}) {
            const Thresholds th{pen, shrink};
            std::size_t none = 0, fp = 0, correct = 0, total = 0;
            for (const auto& c : cases) {
                if (!c.tune) continue;
                const std::string v = decide(c, th);
                ++total;
                if (c.truth == "none") {
                    ++none;
                    fp += v != "none";
                }
                correct += c.truth.empty() ? (v == "unexplained" || v == "none") : v == c.truth;
            }
            const double fpr = none ? static_cast<double>(fp) / static_cast<double>(none) : 0.0;
            const double score = static_cast<double>(correct) / static_cast<double>(std::max<std::size_t>(1, total)) -
                                 (fpr > 0.05 ? 1.0 : 0.0);
            if (score > best_score) best_score = score, best = th;
        }
    }
    return best;
}

std::string score_table(const std::vector<EvalCase>& cases, const Thresholds& th, const EvalOptions& options) {
    std::ostringstream md;
    std::vector<std::string> columns;
    for (const auto& info : candidate_list()) columns.push_back(info.effect);
    columns.push_back("none");
    columns.push_back("unexplained");
    std::vector<std::string> rows{"none"};
    for (const auto& c : cases)
        if (c.generator != "none" && std::find(rows.begin(), rows.end(), c.generator) == rows.end()) rows.push_back(c.generator);

    md << "Thresholds tuned on seeds " << options.tune_first << ".." << options.tune_last << ": penalty_per_param = "
       << th.penalty_per_param << ", min_heldout_shrink = " << th.min_heldout_shrink << ". Scored on seeds "
       << options.score_first << ".." << options.score_last << ", " << options.samples << "-sample logs, R = "
       << options.replicates << ".\n\n";
    md << "### Confusion (rows: truth generator -> library effect; columns: verdict), all sizes\n\n| truth |";
    for (const auto& c : columns) md << " " << c << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < columns.size(); ++i) md << "---|";
    md << "\n";
    for (const auto& row : rows) {
        std::map<std::string, int> count;
        std::string truth = "none";
        for (const auto& c : cases) {
            if (c.tune || c.generator != row) continue;
            truth = c.truth.empty() ? "out of library" : c.truth;
            ++count[decide(c, th)];
        }
        md << "| " << row << " (" << truth << ") |";
        for (const auto& col : columns) md << " " << count[col] << " |";
        md << "\n";
    }
    md << "\n### Per generator and size (scoring seeds)\n\n| truth | size x ref | n | detected | top-1 correct | "
          "held-out shrink (predicted, median) | re-measured (median) |\n|---|---|---|---|---|---|---|\n";
    for (const auto& row : rows) {
        std::vector<double> levels;
        for (const auto& c : cases)
            if (!c.tune && c.generator == row && std::find(levels.begin(), levels.end(), c.level) == levels.end())
                levels.push_back(c.level);
        for (double level : levels) {
            int n = 0, det = 0, ok = 0;
            std::vector<double> pred, check;
            for (const auto& c : cases) {
                if (c.tune || c.generator != row || c.level != level) continue;
                ++n;
                det += c.detected;
                const std::string v = decide(c, th);
                ok += c.truth.empty() ? (v == "unexplained" || v == "none") : v == c.truth;
                for (const auto& e : c.tried)
                    if (e.effect == c.truth && v == c.truth) pred.push_back(e.heldout_shrink);
                if (c.has_shrink_check && v == c.truth) check.push_back(c.shrink_check);
            }
            auto median = [](std::vector<double> v) {
                if (v.empty()) return std::string("-");
                std::sort(v.begin(), v.end());
                std::ostringstream s;
                s.precision(2);
                s << std::fixed << v[v.size() / 2];
                return s.str();
            };
            md << "| " << row << " | " << level << " | " << n << " | " << det << " | " << ok << " | " << median(pred)
               << " | " << median(check) << " |\n";
        }
    }
    return md.str();
}

}  // namespace driftlab::host::gap
