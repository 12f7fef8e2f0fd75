// Small simulated logs for the gap tests: Gaussian white noise, and a paper-unit gyro log from the replicate chain
// with an optional signal added at the converter input; the accel channels are constant and so left out of the
// analysis.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include "../stats/white_noise.hpp"
#include "host/gap/diagnose.hpp"
#include "host/gap/plain_recording.hpp"
#include "host/log/log_data.hpp"
#include "host/log/numeric_table.hpp"
#include "sim/model/board_outputs.hpp"

namespace driftlab::host::gap::testing {

using host::testing::white;

/// Diagnosis options for small test logs: 20 replicates, seed 5, one effect added, a short spikes fit.
inline GapOptions small_options() {
    GapOptions o;
    o.replicates = 20;
    o.seed = 5;
    o.explain_options.fit_replicates = 6;
    o.explain_options.max_evaluations = 12;
    o.explain_options.max_effects = 1;
    return o;
}

inline GapModel paper_gyro_model(int window) {
    GapModel m;
    m.unit = sim::paper_model();
    m.unit.effects.clear();
    m.smoothing = {1.0, window, window, 0};
    m.base[0] = {sim::kPaperDrift[0], 1.05};
    return m;
}

inline LogData gyro_log(const GapModel& m, std::size_t samples, const std::vector<double>& added, std::uint64_t seed) {
    LogData log;
    log.source_name = "test.csv";
    for (std::size_t k = 0; k < samples; ++k) {
        log.t_s.push_back(static_cast<double>(k + 1) * m.smoothing.sample_period_s);
        log.seq.push_back(k);
    }
    sim::OutputRequest req;
    req.t_s = &log.t_s;
    req.channels = {true, false, false, false};
    req.added_counts[0] = added;
    log.counts[0] = sim::simulate_outputs(m, req, seed)[0];
    for (std::size_t c = 1; c < kChannelCount; ++c) log.counts[c].assign(samples, 512.0);
    log.recorded = {true, false, false, false};
    log.metadata.set("sample_period_s", m.smoothing.sample_period_s);
    log.metadata.set("conversions_per_output", static_cast<std::int64_t>(m.smoothing.conversions_per_output));
    log.metadata.set("window", static_cast<std::int64_t>(m.smoothing.window));
    log.metadata.set("fit_order", static_cast<std::int64_t>(m.smoothing.fit_order));
    return log;
}

/// A recording of the shared folder's data/real/`file` read as a plain recording (`mappings` as --as gives them, one
/// row every `sample_period_s`, blocks of `block` rows) into `log`, and the unit it reads as into `unit`; false when
/// the file is absent, for the test to skip.
inline bool load_shared_recording(const std::string& file, std::initializer_list<const char*> mappings,
                                  double sample_period_s, int block, LogData& log, sim::SimModel& unit) {
    const std::string path = std::string(DRIFTLAB_SHARED_DIR) + "/data/real/" + file;
    if (!std::filesystem::exists(path)) return false;
    PlainRecording how;
    for (const char* m : mappings) how.columns.push_back(parse_column_mapping(m));
    how.sample_period_s = sample_period_s;
    how.block = block;
    log = log_from_table(read_numeric_table(path), how);
    unit = unit_of_recording(sim::paper_model(), how, log);
    return true;
}

/// Diagnosis options for the real recordings: R = 16, seed 3, smaller fit budgets than the command line's, and at
/// most `max_effects` effects: a test's wall time.
inline GapOptions real_data_options(int max_effects) {
    GapOptions o;
    o.replicates = 16;
    o.seed = 3;
    o.explain_options.fit_replicates = 6;
    o.explain_options.max_evaluations = 12;
    o.explain_options.max_effects = max_effects;
    return o;
}

// An opposite-sign slower exponential: an overshoot that one exponential cannot absorb. Diagnosed once, shared by
// the tests that read the result, its JSON and its report.
struct Planted {
    LogData log;
    GapResult result;
};

inline const Planted& planted_second_time_constant() {
    static const Planted planted = [] {
        const GapModel m = paper_gyro_model(8);
        std::vector<double> added(1500);
        for (std::size_t k = 0; k < added.size(); ++k)
            added[k] = -4.0 * -std::expm1(-static_cast<double>(k + 1) / 1500.0);
        Planted p{gyro_log(m, 1500, added, 78), {}};
        p.result = diagnose(p.log, sim::paper_model(), small_options());
        return p;
    }();
    return planted;
}

}  // namespace driftlab::host::gap::testing
