// HilOptions::stop ends a run early with what it has: the rows before the stop are those of the whole run (the
// same seed), and the summary says it was interrupted.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "tests/sim/hil/hil_test_support.hpp"

namespace driftlab::sim {
namespace {

using testing::preset;
using testing::run_into_memory;

TEST(HilStop, AStopAlreadyAskedForEndsTheRunBeforeAnyRow) {
    HilOptions o = preset(Preset::fig3);
    o.duration_s = 100.0;
    const std::atomic<bool> stop{true};
    o.stop = &stop;
    const testing::Run r = run_into_memory(o);
    EXPECT_TRUE(r.summary.interrupted);
    EXPECT_TRUE(r.rows.empty());
}

TEST(HilStop, TheRowsBeforeAStopAreTheWholeRunsFirstRows) {
    HilOptions o = preset(Preset::fig3);
    o.duration_s = 200.0;
    const testing::Run whole = run_into_memory(o);
    ASSERT_FALSE(whole.summary.interrupted);
    ASSERT_GT(whole.rows.size(), 150u);

    std::atomic<bool> stop{false};
    o.stop = &stop;
    std::vector<HilRecord> rows;
    const HilSummary s = run_hil(o, [&](const HilRecord& rec) {
        rows.push_back(rec);
        if (rows.size() == 50) stop.store(true);  // as a Ctrl-C between two events
    });
    EXPECT_TRUE(s.interrupted);
    ASSERT_EQ(rows.size(), 50u);
    EXPECT_LT(s.simulated_s, whole.summary.simulated_s);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].seq, whole.rows[i].seq);
        EXPECT_EQ(rows[i].value_counts, whole.rows[i].value_counts) << "row " << i;
    }
}

}  // namespace
}  // namespace driftlab::sim
