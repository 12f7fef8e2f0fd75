// Status (status.hpp): the NAK reason numbers are part of the wire contract (docs/protocol.md §4).
#include "driftlab/proto/status.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace driftlab {
namespace proto {
namespace {

TEST(Status, NumbersAreTheContractOnes) {
  EXPECT_EQ(static_cast<int>(Status::ok), 0);
  EXPECT_EQ(static_cast<int>(Status::bad_length), 1);
  EXPECT_EQ(static_cast<int>(Status::unknown_type), 2);
  EXPECT_EQ(static_cast<int>(Status::out_of_range), 3);
  EXPECT_EQ(static_cast<int>(Status::bad_version), 4);
  EXPECT_EQ(static_cast<int>(Status::not_allowed), 5);
  EXPECT_EQ(static_cast<int>(Status::busy), 6);
  EXPECT_EQ(static_cast<int>(Status::not_stored), 7);
  EXPECT_EQ(static_cast<int>(Status::unauthenticated), 8);
  EXPECT_EQ(static_cast<int>(Status::replayed), 9);
  EXPECT_EQ(kStatusCount, 10);
}

TEST(Status, EveryNumberHasADistinctNameAndUnknownOnesHaveNone) {
  std::set<std::string> names;
  for (uint8_t n = 0; n < kStatusCount; ++n) {
    const char* name = status_name(static_cast<Status>(n));
    ASSERT_NE(name, nullptr) << int{n};
    names.insert(name);
  }
  EXPECT_EQ(names.size(), kStatusCount);
  EXPECT_STREQ(status_name(Status::out_of_range), "out_of_range");
  EXPECT_EQ(status_name(static_cast<Status>(kStatusCount)), nullptr);
  EXPECT_EQ(status_name(static_cast<Status>(0xFF)), nullptr);
}

}  // namespace
}  // namespace proto
}  // namespace driftlab
