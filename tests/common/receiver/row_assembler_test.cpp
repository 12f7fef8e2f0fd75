// The one row assembly: time from the unwrapped tick, Q8 to counts, RAW pairing by tick, and the rows that are not
// rows (an empty window, a repeated answer, a SAMPLE whose RAW was lost under each policy).
#include "driftlab/receiver/row_assembler.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace driftlab::receiver {
namespace {

constexpr std::uint32_t kTickHz = 250000;

proto::SamplePayload sample(std::uint32_t tick, std::int32_t gyro_q8, std::uint8_t n_window = 8) {
    proto::SamplePayload s{};
    s.tick = tick;
    s.value_q8[0] = gyro_q8;
    s.value_q8[3] = -1;
    s.n_window = n_window;
    s.sat_flags = 2;
    s.dropped = 7;
    return s;
}

proto::RawPayload raw(std::uint32_t tick, std::uint16_t gyro) {
    proto::RawPayload r{};
    r.tick = tick;
    r.code[0] = gyro;
    return r;
}

struct Collected {
    std::vector<Row> rows;
    RowAssembler::Sink sink() {
        return [this](const Row& r) {
            rows.push_back(r);
            return true;
        };
    }
};

TEST(RowAssembler, ARowHasItsTimeFromTheUnwrappedTickAndItsValuesFromQ8) {
    Collected out;
    RowAssembler a({kTickHz, false, MissingRaw::mark}, out.sink());
    a.sample(sample(5, 129 * 256 + 64), 3, (std::uint64_t{1} << 32) + 5);
    ASSERT_EQ(out.rows.size(), 1u);
    const Row& r = out.rows[0];
    EXPECT_EQ(r.t_s, (4294967296.0 + 5.0) / kTickHz);
    EXPECT_EQ(r.seq, 3u);
    EXPECT_EQ(r.value_counts[0], 129.25);
    EXPECT_EQ(r.value_counts[3], -1.0 / 256.0);
    EXPECT_EQ(r.sat_flags, 2);
    EXPECT_EQ(r.n_window, 8);
    EXPECT_EQ(r.dropped, 7);
    EXPECT_FALSE(r.has_raw);
}

TEST(RowAssembler, AnEmptyWindowAndARepeatedAnswerAreCountedNotRows) {
    Collected out;
    RowAssembler a({kTickHz, false, MissingRaw::mark}, out.sink());
    a.sample(sample(100, 0, 0), 1, 100);
    a.sample(sample(200, 256), 2, 200);
    a.sample(sample(200, 256), 3, 200);  // the same output answered twice
    a.sample(sample(150, 256), 4, 150);
    EXPECT_EQ(out.rows.size(), 1u);
    EXPECT_EQ(a.counts().samples, 4u);
    EXPECT_EQ(a.counts().empty_samples, 1u);
    EXPECT_EQ(a.counts().stale_samples, 2u);
}

TEST(RowAssembler, RawModePairsEachSampleWithTheRawOfItsTick) {
    Collected out;
    RowAssembler a({kTickHz, true, MissingRaw::mark}, out.sink());
    a.sample(sample(100, 256), 1, 100);
    EXPECT_TRUE(out.rows.empty());  // waiting for its RAW
    a.raw(raw(99, 5));              // another tick's: not its RAW
    EXPECT_TRUE(out.rows.empty());
    a.raw(raw(100, 511));
    ASSERT_EQ(out.rows.size(), 1u);
    EXPECT_TRUE(out.rows[0].has_raw);
    EXPECT_EQ(out.rows[0].raw_counts[0], 511);
    a.raw(raw(100, 511));  // a lone RAW: nothing waits for it
    EXPECT_EQ(out.rows.size(), 1u);
}

TEST(RowAssembler, ASampleWhoseRawWasLostIsMarkedOrDroppedByPolicy) {
    for (MissingRaw policy : {MissingRaw::mark, MissingRaw::drop}) {
        Collected out;
        RowAssembler a({kTickHz, true, policy}, out.sink());
        a.sample(sample(100, 256), 1, 100);
        a.sample(sample(200, 512), 3, 200);  // the RAW of tick 100 never came
        a.raw(raw(200, 2));
        a.sample(sample(300, 768), 5, 300);
        a.end_of_stream();  // nor that of tick 300
        if (policy == MissingRaw::mark) {
            ASSERT_EQ(out.rows.size(), 3u);
            EXPECT_FALSE(out.rows[0].has_raw);
            EXPECT_TRUE(out.rows[1].has_raw);
            EXPECT_FALSE(out.rows[2].has_raw);
            EXPECT_EQ(a.counts().dropped_rows, 0u);
        } else {
            ASSERT_EQ(out.rows.size(), 1u);
            EXPECT_EQ(out.rows[0].seq, 3u);
            EXPECT_EQ(a.counts().dropped_rows, 2u);
        }
    }
}

TEST(RowAssembler, ARowTheSinkRefusesLeavesTheNextOneFresh) {
    std::vector<double> taken;
    RowAssembler a({kTickHz, false, MissingRaw::mark}, [&](const Row& r) {
        if (r.value_counts[0] > 1000.0) return false;  // a value no converter makes
        taken.push_back(r.t_s);
        return true;
    });
    a.sample(sample(100, 256), 1, 100);
    a.sample(sample(200, 2000 * 256), 2, 200);
    a.sample(sample(150, 256), 3, 150);  // before the refused row, after the last row taken: a row
    a.sample(sample(300, 256), 4, 300);
    EXPECT_EQ(taken, (std::vector<double>{100.0 / kTickHz, 150.0 / kTickHz, 300.0 / kTickHz}));
    EXPECT_EQ(a.counts().stale_samples, 0u);
}

}  // namespace
}  // namespace driftlab::receiver
