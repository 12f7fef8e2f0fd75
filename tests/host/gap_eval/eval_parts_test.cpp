// merge_parts() against hand-made parts of a two-shard campaign: every case and pair comes back in item order, and
// a part that holds an item twice (with one fewer of its own, so that the count still agrees), another shard's
// item, an item beyond the campaign, or misses one, is refused naming the file.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "eval_support.hpp"
#include "host/gap_eval/eval_parts.hpp"
#include "tests/support/data_error.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::host::gap {
namespace {

struct Campaign {
    EvalOptions options = quick_options();
    std::vector<std::size_t> shard_of;
    std::size_t cases = 0, pairs = 0;
    Campaign() {
        options.pairs = {{"thermal_rc", "none"}};
        options.shards = 2;
        shard_of = item_shards(options);
        cases = case_items(options);
        pairs = pair_items(options);
    }
    // Shard k's part: its items, or `items` when given.
    EvalPart part(std::size_t k, std::vector<std::size_t> items = {}) const {
        if (items.empty())
            for (std::size_t i = 0; i < shard_of.size(); ++i)
                if (shard_of[i] == k) items.push_back(i);
        EvalPart p;
        p.options = options;
        p.options.shard = k;
        p.build = "test";
        p.cases_total = cases;
        p.pairs_total = pairs;
        for (std::size_t i : items) {
            if (i < cases) {
                p.cases.emplace_back();
                p.cases.back().item = i;
            } else {
                p.pairs.emplace_back();
                p.pairs.back().item = i;
            }
        }
        return p;
    }
};

std::vector<std::size_t> items_of(const EvalPart& whole) {
    std::vector<std::size_t> out;
    for (const auto& c : whole.cases) out.push_back(c.item);
    for (const auto& p : whole.pairs) out.push_back(p.item);
    return out;
}

TEST(EvalParts, TwoShardsMergeToEveryItemInOrderAndABadPartIsNamed) {
    test_support::TempDir dir("eval_parts");
    const Campaign c;
    ASSERT_GT(c.pairs, 0U);
    const std::string zero = dir.file("0.part"), one = dir.file("1.part"), bad = dir.file("bad.part");
    write_part(c.part(0), zero);
    write_part(c.part(1), one);
    const EvalPart whole = merge_parts({one, zero});
    std::vector<std::size_t> all(c.shard_of.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    EXPECT_EQ(items_of(whole), all);
    EXPECT_EQ(whole.cases.size(), c.cases);

    std::vector<std::size_t> mine = items_of(c.part(0));
    const auto refused = [&](const std::vector<std::size_t>& items) {
        write_part(c.part(0, items), bad);
        return test_support::data_error_of([&] { merge_parts({bad, one}); });
    };
    std::vector<std::size_t> twice = mine;
    twice.back() = twice.front();
    EXPECT_EQ(refused(twice), bad + ": holds item " + std::to_string(mine.front()) + " twice");
    std::vector<std::size_t> foreign = mine;
    foreign.back() = items_of(c.part(1)).front();
    EXPECT_EQ(refused(foreign), bad + ": holds item " + std::to_string(foreign.back()) + ", not shard 0's");
    std::vector<std::size_t> missing = mine;
    missing.erase(missing.begin());
    EXPECT_EQ(refused(missing), bad + ": its parts miss item " + std::to_string(mine.front()));
    std::vector<std::size_t> beyond = mine;
    beyond.push_back(c.shard_of.size() + 1);
    EXPECT_EQ(refused(beyond), bad + ": holds item " + std::to_string(c.shard_of.size() + 1) + ", not shard 0's");
}

}  // namespace
}  // namespace driftlab::host::gap
