// Same options and seed -> bit-identical records and counters; another seed -> other noise.
#include <cstring>

#include <gtest/gtest.h>

#include "tests/sim/hil/hil_test_support.hpp"

namespace driftlab::sim {
namespace {

using testing::preset;
using testing::run_into_memory;

bool identical(const HilRecord& a, const HilRecord& b) {
    return std::memcmp(&a.t_s, &b.t_s, sizeof a.t_s) == 0 && a.seq == b.seq && a.tick == b.tick &&
           std::memcmp(a.value_counts.data(), b.value_counts.data(), sizeof a.value_counts) == 0 &&
           a.has_raw == b.has_raw && a.raw_counts == b.raw_counts && a.sat_flags == b.sat_flags &&
           a.n_window == b.n_window && a.dropped == b.dropped;
}

TEST(Reproducibility, SameSeedGivesBitIdenticalRecords) {
    HilOptions o = preset(Preset::fig2, 1234);
    o.model = load_model_file(std::string(DRIFTLAB_MODELS_DIR) + "/lossy_radio.toml");
    apply_preset(Preset::fig2, o);
    const auto a = run_into_memory(o);
    const auto b = run_into_memory(o);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t i = 0; i < a.rows.size(); ++i) ASSERT_TRUE(identical(a.rows[i], b.rows[i])) << "row " << i;
    EXPECT_EQ(a.summary.host.frames_lost, b.summary.host.frames_lost);
    EXPECT_EQ(a.summary.to_host.bytes_corrupted, b.summary.to_host.bytes_corrupted);
    EXPECT_EQ(a.summary.conversions, b.summary.conversions);
}

TEST(Reproducibility, AnotherSeedGivesOtherNoise) {
    const auto a = run_into_memory(preset(Preset::fig2, 1));
    const auto b = run_into_memory(preset(Preset::fig2, 2));
    ASSERT_EQ(a.rows.size(), b.rows.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.rows.size(); ++i) differ += a.rows[i].raw_counts != b.rows[i].raw_counts;
    EXPECT_GT(differ, a.rows.size() * 9 / 10);
}

}  // namespace
}  // namespace driftlab::sim
