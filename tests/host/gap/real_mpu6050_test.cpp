// The real MPU6050 recording at rest (shared/data/real/mpu6050_unmoved-with-x-pointing-forward-10min.csv,
// PROVENANCE.md): gyro X and the three accelerometer axes, already warm, 655 s at a nominal 100 Hz with irregular
// logging. Each channel becomes counts of its own LSB (1/131 deg/s, 1/4096 g) around mid-scale, and blocks of 10
// samples are the order-0 smoother of the log (window = conversions per output = 10). The diagnosis must run on all
// four channels and report what it finds, and it must see the logger's irregular timing.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "host/gap/diagnose.hpp"
#include "host/log/numeric_table.hpp"

namespace driftlab::host::gap {
namespace {

constexpr std::size_t kBlock = 10;

bool load(LogData& log) {
    const std::string path = std::string(DRIFTLAB_SHARED_DIR) + "/data/real/mpu6050_unmoved-with-x-pointing-forward-10min.csv";
    if (!std::filesystem::exists(path)) return false;
    const NumericTable t = read_numeric_table(path);
    const std::array<std::pair<const char*, double>, kChannelCount> source = {
        {{"gx_dps", 131.0}, {"ax_g", 4096.0}, {"ay_g", 4096.0}, {"az_g", 4096.0}}};
    log.source_name = "mpu6050_unmoved-with-x-pointing-forward-10min.csv";
    const auto& time = t.columns[t.column_index("t_s")];
    for (std::size_t c = 0; c < kChannelCount; ++c) {
        const auto& v = t.columns[t.column_index(source[c].first)];
        double mean = 0.0;
        for (double x : v) mean += x;
        mean /= static_cast<double>(v.size());
        for (std::size_t b = 0; (b + 1) * kBlock <= v.size(); ++b) {
            double sum = 0.0;
            for (std::size_t i = 0; i < kBlock; ++i) sum += std::round((v[b * kBlock + i] - mean) * source[c].second);
            log.counts[c].push_back(512.0 + sum / kBlock);
        }
    }
    for (std::size_t b = 0; (b + 1) * kBlock <= time.size(); ++b) {
        log.t_s.push_back(time[(b + 1) * kBlock - 1]);
        log.seq.push_back(b);
    }
    log.metadata.set("sample_period_s", 0.1);
    log.metadata.set("conversions_per_output", static_cast<std::int64_t>(kBlock));
    log.metadata.set("window", static_cast<std::int64_t>(kBlock));
    log.metadata.set("fit_order", static_cast<std::int64_t>(0));
    return true;
}

TEST(RealData, Mpu6050RunsOnAllFourChannelsAndSeesItsIrregularTiming) {
    LogData log;
    if (!load(log)) GTEST_SKIP() << "shared/data/real/mpu6050_*.csv not found under " << DRIFTLAB_SHARED_DIR;
    GapOptions o;
    o.replicates = 16;
    o.seed = 3;
    o.explain_options.fit_replicates = 6;
    o.explain_options.max_evaluations = 12;
    o.explain_options.max_effects = 1;
    const GapResult r = diagnose(log, sim::paper_model(), o);
    std::printf("mpu6050: verdict %s, gap fit %.2f heldout %.2f -> fit %.2f heldout %.2f, %zu located, dt jitter %.2f\n",
                r.verdict.c_str(), r.gap_before_fit, r.gap_before_heldout, r.gap_after_fit, r.gap_after_heldout,
                r.located.size(), r.timing.dt_jitter_rel);
    for (const auto& l : r.located)
        std::printf("  located %s %s %s z=%.1f\n", r.layout[l.index].statistic.c_str(), r.layout[l.index].channel.c_str(),
                    r.layout[l.index].cell.c_str(), l.z);
    for (const auto& e : r.accepted) {
        std::printf("  accepted %s on %s:", e.effect.c_str(), e.channel.c_str());
        for (const auto& [k, v] : e.params) std::printf(" %s=%.4g", k.c_str(), v);
        std::printf(" heldout shrink %.2f%s%s\n", e.heldout_shrink, e.ambiguous_with.empty() ? "" : ", close call with ",
                    e.ambiguous_with.c_str());
    }
    for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_TRUE(r.channels[c]) << kChannelNames[c];
    EXPECT_TRUE(std::isfinite(r.gap_before_fit) && std::isfinite(r.gap_before_heldout));
    // PROVENANCE: sample spacing 10.07 ms mean, 17 ms standard deviation, gaps up to 0.5 s: the spacing of
    // 10-sample blocks still varies by tens of percent.
    EXPECT_GT(r.timing.dt_jitter_rel, 0.1);
    // Block noise: accel 3-5 mg = 12-20 LSB raw, gyro 0.13 deg/s = 16.5 LSB raw, all far above the quantiser.
    for (std::size_t c = 0; c < kChannelCount; ++c) EXPECT_GT(r.base.base[c].sigma_n_counts, 5.0) << kChannelNames[c];
    if (!r.accepted.empty()) {
        EXPECT_LE(r.gap_after_heldout, r.gap_before_heldout);
    }
}

}  // namespace
}  // namespace driftlab::host::gap
