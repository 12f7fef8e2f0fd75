// The withheld-effect benchmark; see evaluate.hpp.
#include "host/gap_eval/evaluate.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <stdexcept>

#include <Eigen/Dense>

#include "host/gap/candidates.hpp"
#include "host/gap/comparison.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap/replicates.hpp"
#include "host/gap_eval/planted_log.hpp"
#include "host/gap_eval/truth.hpp"
#include "host/util/format_number.hpp"
#include "host/util/parallel_for.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap {

namespace {

// Where the search for a_50 starts, in units of the smoothed output's white-noise standard deviation (deterministic
// generators: the RMS of their unabsorbed part): near the sizes the battery starts to see on a 1500-sample log.
// Only a starting point; detection_sizes() measures a_50.
double first_guess(const std::string& generator) {
    static const std::map<std::string, double> guess = {
        {"thermal_rc", 0.2},   {"thermostat", 0.25},         {"kasdin_flicker", 0.5}, {"wandering_ou", 0.5},
        {"student_walk", 1.0}, {"burst_spikes", 2.5},        {"mode_hop", 0.2},       {"sar_mismatch", 0.5},
        {"sar_codes", 0.25},   {"interference_bursts", 0.2}, {"supply_wander", 0.5}};
    return guess.at(generator);
}

GapOptions gap_options(std::uint64_t seed, const EvalOptions& options) {
    GapOptions go;
    go.replicates = options.replicates;
    go.holdout = options.holdout;
    go.seed = seed * 7 + 3;
    go.threads = 1;  // the logs run in parallel instead (options.threads of them): no core waits on a serial fit
    go.explain_options.fit_replicates = options.fit_replicates;
    go.explain_options.max_evaluations = options.max_evaluations;
    go.explain_options.max_effects = 1;
    go.explain_options.step_test_candidates = true;
    return go;
}

double size_of(const std::vector<DetectionSize>& sizes, const std::string& generator) {
    for (const auto& d : sizes)
        if (d.generator == generator) return d.a50;
    throw std::invalid_argument("no detection size measured for " + generator);
}

EvalCase run_case(const std::string& generator, const std::string& truth, double level, std::uint64_t seed, bool tuning,
                  const EvalOptions& options, const std::vector<DetectionSize>& sizes) {
    EvalCase c;
    c.generator = generator, c.truth = truth, c.level = level, c.seed = seed, c.tune = tuning;
    Planted p = plant(generator, generator == "none" ? 0.0 : level * size_of(sizes, generator), seed, options.samples,
                      options.clean_form);
    // A log the diagnosis refuses names the case, so that one odd size is found in a run of hundreds.
    p.log.source_name = "gap-eval log of " + generator +
                        (generator == "none" ? "" : " at " + format_double(level) + " x a_50") + " (log seed " +
                        std::to_string(seed) + ")";
    c.size_counts = p.size_counts;
    const LogData& log = p.log;
    GapOptions go = gap_options(seed, options);
    // Every candidate's metrics are kept; the thresholds are applied afterwards (decide()).
    go.explain_options.penalty_per_param = 0.0;
    go.explain_options.min_heldout_shrink = -1e9;
    const GapResult r = diagnose(log, eval_unit(generator, options.clean_form), go);
    c.detected = gap_located(r);
    c.link_only = r.located.empty() && !r.link.located.empty();
    if (r.link.added) c.link_verdict = r.link.tried[*r.link.added].effect;
    if (const CommonFit* shared = r.common.winner()) c.common_verdict = shared->reading;
    c.tried = r.tried;
    const bool right = !r.accepted.empty() && r.accepted.front().effect == truth;
    // A link generator changes no value: the channels' held-out gap has nothing of it to shrink.
    // A link or shared generator's oracle is not a gyro signal: its held-out shrink is not measured.
    const auto kind = generator == "none" ? TruthInfo::Kind::shape : truth_info(generator).kind;
    if (r.located.empty() || generator == "none" || kind == TruthInfo::Kind::link || kind == TruthInfo::Kind::common)
        return c;
    // Held-out gap on replicates the diagnosis never saw: base, chosen model, and the oracle (true model).
    BatteryOptions b;
    b.channels = r.channels;
    b.holdout = options.holdout;
    b.sample_period_s = kEvalSamplePeriodS;
    b.raw_codes = r.raw_codes;
    b.output_codes = r.output_codes;
    std::array<const std::vector<double>*, kChannelCount> y{};
    y[0] = &log.counts[0];
    RawCodes raw{};
    if (r.raw_codes[0]) raw[0] = &log.optional_columns.at("raw_gyro");
    std::vector<Cell> layout;
    const auto real = compute_battery(log.t_s, y, b, &layout, raw).values;
    const auto held = [](const Cell& cell) { return cell.segment == Segment::heldout; };
    const std::uint64_t fresh = go.seed + 1000003;
    auto heldout_gap = [&](const GapModel& m, const ReplicateExtra& extra) {
        return gap_score(
            compare(real, run_replicates(m, log.t_s, b, go.replicates, fresh, go.threads, extra), go.alpha), layout,
            held);
    };
    const double before = heldout_gap(r.base, {});
    auto shrink = [before](double after) { return before > 1.0 ? (before - after) / (before - 1.0) : 0.0; };
    const ReplicateExtra oracle = [&](std::uint64_t rs, sim::OutputRequest& req) {
        if (truth_info(generator).kind == TruthInfo::Kind::converter)
            req.quantiser[0] = make_converter_truth(generator, p.scale, p.occupancy, seed, rs);
        else
            req.added_counts[0] = make_truth(generator, log.t_s, p.scale, seed, rs);
    };
    c.oracle_shrink = shrink(heldout_gap(p.model, oracle));
    c.has_oracle = true;
    if (right) {
        c.shrink_check = shrink(heldout_gap(r.final_model, {}));
        c.has_shrink_check = true;
    }
    return c;
}

// body(n) for every n < count, options.threads logs at a time, telling options.progress after each (one call at a
// time, as EvalOptions promises).
template <class Body>
void run_logs(std::size_t count, const EvalOptions& options, Body body) {
    std::size_t done = 0;
    std::mutex progress_mutex;
    parallel_for(count, options.threads, [&](std::size_t n) {
        body(n);
        const std::lock_guard<std::mutex> lock(progress_mutex);
        ++done;
        if (options.progress) options.progress(done, count);
    });
}

// A second generator's noise is drawn apart from the first's (their generators' streams could otherwise coincide).
constexpr std::uint64_t kSecondGeneratorSeed = 0x5EC0D5EEDull;

PairCase run_pair_case(const std::string& first, const std::string& second, double level, std::uint64_t seed,
                       const EvalOptions& options, const std::vector<DetectionSize>& sizes) {
    PairCase c;
    c.first = first, c.second = second, c.level = level, c.seed = seed;
    const GapModel model = randomised_truth(seed);
    std::vector<double> added = input_signal(first, level * size_of(sizes, first), model, seed, options.samples).added;
    if (second != "none") {
        const std::vector<double> more =
            input_signal(second, level * size_of(sizes, second), model, seed ^ kSecondGeneratorSeed, options.samples)
                .added;
        for (std::size_t k = 0; k < added.size(); ++k) added[k] += more[k];
    }
    // As `driftlab gap` runs: its shipped thresholds and stepwise limit.
    GapOptions go = gap_options(seed, options);
    go.explain_options.max_effects = ExplainOptions{}.max_effects;
    go.explain_options.step_test_candidates = false;
    const GapResult r =
        diagnose(make_log(model, {added, {}, {}, {}}, {}, options.samples, seed, false), sim::paper_model(), go);
    c.detected = !r.located.empty();
    c.verdict = r.verdict;
    for (const auto& e : r.accepted) {
        c.added.push_back(e.effect);
        c.close_calls.push_back(e.ambiguous_with);
        c.within_bound.push_back(e.within_bound_before());
    }
    c.heldout_before = r.gap_before_heldout;
    c.heldout_after = r.gap_after_heldout;
    return c;
}

}  // namespace

std::string pair_refusal(const std::string& first, const std::string& second) {
    if (first == second) return first + "+" + second + " names one generator twice";
    for (const std::string& g : {first, second}) {
        if (g == "none" && g == second) continue;  // the first alone
        if (g == "none") return "none+" + second + ": the first of a pair is a generator";
        const TruthInfo& t = truth_info(g);
        if (t.kind == TruthInfo::Kind::converter) return g + " replaces the converter; pairs act at its input";
        if (t.kind == TruthInfo::Kind::link) return g + " acts on the link; pairs act at the converter input";
        if (t.kind == TruthInfo::Kind::common) return g + " acts on every channel; pairs act on the gyro";
        // A pair is scored by the library effects it holds; an out-of-library one has none to find.
        if (t.effect.empty()) return g + " stands for no library effect";
    }
    return "";
}

std::vector<std::pair<std::string, std::string>> default_pairs() {
    return {{"thermostat", "thermal_rc"},
            {"thermostat", "kasdin_flicker"},
            {"thermal_rc", "student_walk"},
            {"wandering_ou", "burst_spikes"}};
}

namespace {

std::string truth_of(const std::string& generator) { return truth_info(generator).effect; }

std::vector<std::string> generators_of(const EvalOptions& options) {
    std::vector<std::string> gens = options.generators;
    if (gens.empty())
        for (const auto& t : truth_list()) gens.push_back(t.generator);
    return gens;
}

// Seeds of the a_50 logs: drawn from the tuning range, offset far from the case seeds (seed * 1009 + index).
// `generator` is the generator's place in truth_list(), not in the run's list, so that a run of a few generators
// measures each a_50 on the same logs as the full run.
std::uint64_t detection_seed(const EvalOptions& options, std::size_t generator, int step, int log) {
    const std::uint64_t tune_count = options.tune_last - options.tune_first + 1;
    const std::uint64_t base = options.tune_first + static_cast<std::uint64_t>(log) % tune_count;
    return (base << 32) + (generator << 16) + (static_cast<std::uint64_t>(step) << 8) + static_cast<std::uint64_t>(log);
}

}  // namespace

std::optional<double> logistic_a50(const std::vector<DetectionPoint>& curve) {
    // Newton's method on the binomial log-likelihood in (a, b), x = ln size.
    double a = 0.0, b = 1.0;
    double mean_x = 0.0;
    for (const auto& p : curve) mean_x += std::log(p.size) / static_cast<double>(curve.size());
    a = -b * mean_x;
    for (int it = 0; it < 50; ++it) {
        Eigen::Vector2d grad = Eigen::Vector2d::Zero();
        Eigen::Matrix2d info = Eigen::Matrix2d::Zero();
        for (const auto& p : curve) {
            const double x = std::log(p.size);
            const double n = p.logs + 0.5, y = p.detected + 0.25;
            const double q = 1.0 / (1.0 + std::exp(-(a + b * x)));
            const Eigen::Vector2d v(1.0, x);
            grad += (y - n * q) * v;
            info += n * q * (1.0 - q) * v * v.transpose();
        }
        const Eigen::Vector2d step = info.ldlt().solve(grad);
        if (!step.allFinite()) return std::nullopt;
        a += step(0);
        b += step(1);
        if (step.norm() < 1e-10) break;
    }
    if (!(b > 0.0) || !std::isfinite(a)) return std::nullopt;
    return std::exp(-a / b);
}

std::vector<std::string> sized_generators(const EvalOptions& options) {
    auto gens = generators_of(options);
    for (const auto& [first, second] : options.pairs)
        for (const std::string& g : {first, second})
            if (g != "none" && std::find(gens.begin(), gens.end(), g) == gens.end()) gens.push_back(g);
    return gens;
}

std::vector<DetectionSize> detection_sizes(const EvalOptions& options, std::size_t shard, std::size_t shards) {
    const std::vector<std::string> gens = sized_generators(options);
    std::vector<DetectionSize> out;
    for (std::size_t g = shard; g < gens.size(); g += shards) {
        DetectionSize d{gens[g], first_guess(gens[g]), {}};
        const auto& list = truth_list();
        const auto place = static_cast<std::size_t>(
            std::find_if(list.begin(), list.end(), [&](const TruthInfo& t) { return t.generator == gens[g]; }) -
            list.begin());
        auto fraction_at = [&](double size, int step) {
            std::atomic<int> hits{0};
            parallel_for(static_cast<std::size_t>(options.detection_logs), options.threads, [&](std::size_t k) {
                const std::uint64_t seed = detection_seed(options, place, step, static_cast<int>(k));
                GapOptions go = gap_options(seed, options);
                go.explain = false;
                hits += gap_located(diagnose(plant(gens[g], size, seed, options.samples).log, eval_unit(gens[g]), go));
            });
            d.curve.push_back({size, hits, options.detection_logs});
            return static_cast<double>(hits) / options.detection_logs;
        };
        // Double or halve until the detected fraction crosses 1/2 (at most 6 steps).
        double size = d.a50;
        double f = fraction_at(size, 0);
        const bool above = f >= 0.5;
        double prev_size = size, prev_f = f;
        int step = 1;
        for (; step <= 6 && (f >= 0.5) == above; ++step) {
            prev_size = size, prev_f = f;
            size = above ? size / 2.0 : size * 2.0;
            f = fraction_at(size, step);
        }
        if ((f >= 0.5) == above) {
            d.a50 = size;  // never crossed within 64x of the guess: report the last size tried
        } else {
            const double lo = std::min(size, prev_size), hi = std::max(size, prev_size);
            const double f_lo = size < prev_size ? f : prev_f, f_hi = size < prev_size ? prev_f : f;
            const double w = f_hi > f_lo ? (0.5 - f_lo) / (f_hi - f_lo) : 0.5;
            const double crossing = std::exp(std::log(lo) + w * (std::log(hi) - std::log(lo)));
            fraction_at(crossing / std::sqrt(2.0), step++);
            fraction_at(crossing * std::sqrt(2.0), step++);
            d.a50 = logistic_a50(d.curve).value_or(crossing);
        }
        std::sort(d.curve.begin(), d.curve.end(),
                  [](const DetectionPoint& a, const DetectionPoint& b) { return a.size < b.size; });
        out.push_back(std::move(d));
        if (options.progress) options.progress(g / shards + 1, (gens.size() - shard + shards - 1) / shards);
    }
    return out;
}

namespace {

struct CaseJob {
    std::string generator, truth;
    double level;
    std::uint64_t seed;
    bool tune;
};

// The run's logs in order, each with its run seed (tuning logs too where the run does not tune: they keep their
// places).
std::vector<CaseJob> case_jobs(const EvalOptions& options) {
    const auto gens = generators_of(options);
    std::vector<CaseJob> jobs;
    // Raw-mode generators' logs come after the smoothed ones, and logs of other forms (outputs that are codes) after
    // both, so that the earlier ones' places (their seeds), and so their logs, are the same whether or not a later
    // form is in the run.
    const auto form = [](const std::string& g) {
        if (raw_mode(g)) return 1;
        const auto kind = truth_info(g).kind;
        return log_window(g) == kEvalWindow && kind != TruthInfo::Kind::link && kind != TruthInfo::Kind::common ? 0 : 2;
    };
    for (const int phase : {0, 1, 2}) {
        for (int set = 0; set < 2; ++set) {
            const std::uint64_t first = set == 0 ? options.tune_first : options.score_first;
            const std::uint64_t last = set == 0 ? options.tune_last : options.score_last;
            for (std::uint64_t s = first; s <= last; ++s) {
                // By default as many clean logs per seed as planted ones per generator: the false-positive rate needs
                // them.
                const std::size_t clean = options.clean_per_seed > 0 ? static_cast<std::size_t>(options.clean_per_seed)
                                                                     : options.levels.size();
                if (phase == 0)
                    for (std::size_t k = 0; k < clean; ++k) jobs.push_back({"none", "none", 0.0, s, set == 0});
                for (const auto& g : gens)
                    if (form(g) == phase)
                        for (double level : options.levels) jobs.push_back({g, truth_of(g), level, s, set == 0});
            }
        }
    }
    return jobs;
}

// The places of the logs the run diagnoses: without tuning the tuning logs are skipped.
std::vector<std::size_t> run_places(const EvalOptions& options, const std::vector<CaseJob>& jobs) {
    std::vector<std::size_t> places;
    for (std::size_t i = 0; i < jobs.size(); ++i)
        if (options.tune || !jobs[i].tune) places.push_back(i);
    return places;
}

}  // namespace

std::size_t case_items(const EvalOptions& options) { return run_places(options, case_jobs(options)).size(); }

std::size_t pair_items(const EvalOptions& options) {
    return static_cast<std::size_t>(options.score_last - options.score_first + 1) * options.pairs.size();
}

std::vector<std::size_t> item_shards(const EvalOptions& options) {
    const std::vector<CaseJob> jobs = case_jobs(options);
    std::vector<std::string> kinds;
    for (const std::size_t i : run_places(options, jobs))
        kinds.push_back(jobs[i].generator + "@" + format_double(jobs[i].level));
    for (std::uint64_t s = options.score_first; s <= options.score_last; ++s)
        for (std::size_t k = 0; k < options.pairs.size(); ++k) kinds.push_back("pair " + std::to_string(k));
    // Groups in the order they first appear; within a group, the items in theirs.
    std::vector<std::string> order;
    for (const std::string& k : kinds)
        if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
    std::vector<std::size_t> out(kinds.size());
    std::size_t dealt = 0;
    for (const std::string& group : order)
        for (std::size_t i = 0; i < kinds.size(); ++i)
            if (kinds[i] == group) out[i] = dealt++ % options.shards;
    return out;
}

std::vector<EvalCase> run_cases(const EvalOptions& options, const std::vector<DetectionSize>& sizes) {
    const std::vector<CaseJob> jobs = case_jobs(options);
    // Without tuning the tuning logs are skipped but keep their places, so that a scoring log's seed (its place in
    // the list) and hence the log itself are the same either way.
    const std::vector<std::size_t> places = run_places(options, jobs);
    std::vector<std::uint64_t> run_seeds(jobs.size());
    for (std::size_t i = 0; i < jobs.size(); ++i) run_seeds[i] = jobs[i].seed;
    const std::vector<std::uint64_t> log_seeds = case_seeds(run_seeds);
    // The shard's items (item n: the n-th log diagnosed).
    const std::vector<std::size_t> shard_of = item_shards(options);
    std::vector<std::size_t> mine;
    for (std::size_t n = 0; n < places.size(); ++n)
        if (shard_of[n] == options.shard) mine.push_back(n);
    std::vector<EvalCase> out(mine.size());
    run_logs(mine.size(), options, [&](std::size_t m) {
        const std::size_t i = places[mine[m]];
        const CaseJob& j = jobs[i];
        out[m] = run_case(j.generator, j.truth, j.level, log_seeds[i], j.tune, options, sizes);
        out[m].item = mine[m];
    });
    return out;
}

std::vector<std::uint64_t> case_seeds(const std::vector<std::uint64_t>& run_seeds) {
    std::vector<std::uint64_t> out(run_seeds.size());
    std::set<std::uint64_t> taken;
    for (std::size_t i = 0; i < run_seeds.size(); ++i) {
        out[i] = run_seeds[i] * 1009 + i;
        // A long run's later places can land on an earlier seed's (the raw-mode logs come last): such a log moves
        // to a seed of its own above every other, so no two logs of a run share a noise path.
        if (!taken.insert(out[i]).second) taken.insert(out[i] = kMovedCaseSeed + i);
    }
    return out;
}

std::vector<PairCase> run_pairs(const EvalOptions& options, const std::vector<DetectionSize>& sizes) {
    for (const auto& [first, second] : options.pairs)
        if (const std::string why = pair_refusal(first, second); !why.empty()) throw std::invalid_argument(why);
    struct Job {
        std::size_t pair;
        std::uint64_t seed;
    };
    std::vector<Job> jobs;
    // Seeds apart from run_cases()': seed * 1009 + place stays below 2^32 for the seeds a run takes (kMaxEvalSeed),
    // and its moved seeds lie above 2^62.
    for (std::uint64_t s = options.score_first; s <= options.score_last; ++s)
        for (std::size_t k = 0; k < options.pairs.size(); ++k) jobs.push_back({k, (s << 32) + 0x9A1Bull + k});
    // Items follow the cases': pair n is item case_items() + n.
    const std::size_t first_item = case_items(options);
    const std::vector<std::size_t> shard_of = item_shards(options);
    std::vector<std::size_t> mine;
    for (std::size_t n = 0; n < jobs.size(); ++n)
        if (shard_of[first_item + n] == options.shard) mine.push_back(n);
    std::vector<PairCase> out(mine.size());
    run_logs(mine.size(), options, [&](std::size_t m) {
        const Job& job = jobs[mine[m]];
        const auto& [first, second] = options.pairs[job.pair];
        out[m] = run_pair_case(first, second, options.pair_level, job.seed, options, sizes);
        out[m].item = first_item + mine[m];
    });
    return out;
}

}  // namespace driftlab::host::gap
