// Channel names as users type them: the lookup and the list its errors offer.
#include <gtest/gtest.h>

#include <cstdint>

#include "host/util/channel_name.hpp"

namespace driftlab::host {
namespace {

TEST(ChannelNamed, EveryNameInKChannelNamesGivesItsOwnChannel) {
    for (std::uint8_t c = 0; c < kChannelCount; ++c) {
        const auto channel = channel_named(kChannelNames[c]);
        ASSERT_TRUE(channel.has_value()) << kChannelNames[c];
        EXPECT_EQ(channel_index(*channel), c) << kChannelNames[c];
    }
    EXPECT_EQ(channel_named("accel_z"), Channel::accel_z);
}

// Names are matched whole and case and all, as logs, JSON and model files spell them.
TEST(ChannelNamed, UnknownEmptyWrongCaseOrPartialNamesGiveNothing) {
    for (const char* name : {"gyro_x", "", "Gyro", "ACCEL_X", "accel", "accel_x ", "accel_w"})
        EXPECT_FALSE(channel_named(name).has_value()) << "'" << name << "'";
}

TEST(ChannelNameList, ListsTheFourNamesInChannelOrder) {
    EXPECT_EQ(channel_name_list(), "gyro, accel_x, accel_y, accel_z");
}

}  // namespace
}  // namespace driftlab::host
