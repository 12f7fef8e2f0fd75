// SeqTracker: unwraps the 16-bit frame sequence number of protocol v1 (docs/protocol.md §2) and accounts for
// every number that never arrived (lost), arrived twice (duplicate) or arrived after a later one (reordered).
//
// `lost` is the count of numbers still missing between the first frame and the newest: a frame that turns up
// late moves from lost to reordered, so with the ground truth of what was sent, sent = received - duplicates
// + lost holds exactly. Numbers are unwrapped to the candidate nearest the newest (a wrap needs < 32768
// missing frames in a row); after a long gap the caller passes an estimate of where the count should be.
#pragma once

#include <bitset>
#include <cstdint>
#include <optional>

namespace driftlab::receiver {

enum class SeqVerdict : std::uint8_t {
    fresh,      ///< newer than every frame before (possibly after a jump: lost frames)
    late,       ///< older than the newest but never seen: it was counted lost, now reordered
    duplicate,  ///< seen before (or too old to tell)
};

struct SeqResult {
    std::uint64_t unwrapped = 0;
    SeqVerdict verdict = SeqVerdict::fresh;
};

class SeqTracker {
public:
    /// Frames this far behind the newest can still be told apart as late or duplicate.
    static constexpr std::size_t kHistory = 4096;

    SeqResult accept(std::uint16_t seq);

    /// The next frame is unwrapped nearest to `expected` (an estimate after a link gap) instead of the newest.
    void expect_near(std::uint64_t expected) { hint_ = expected; }
    /// The sender restarted its count (firmware reset): the next frame continues after the newest so far.
    void restart_epoch();

    bool started() const { return started_; }
    std::uint64_t newest() const { return newest_; }
    std::uint64_t received() const { return received_; }
    std::uint64_t lost() const { return lost_; }
    std::uint64_t duplicates() const { return duplicates_; }
    std::uint64_t reordered() const { return reordered_; }

private:
    bool started_ = false;
    bool new_epoch_ = false;
    std::uint64_t newest_ = 0;
    std::uint64_t epoch_base_ = 0;  // unwrapped number of the restarted sender's frame 0
    std::optional<std::uint64_t> hint_;
    std::bitset<kHistory> seen_;  // bit (n % kHistory) for n in (newest - kHistory, newest]
    std::uint64_t received_ = 0;
    std::uint64_t lost_ = 0;
    std::uint64_t duplicates_ = 0;
    std::uint64_t reordered_ = 0;
};

/// The 64-bit number nearest to `reference` whose low 16 bits are `low` (never below zero).
std::uint64_t unwrap_near(std::uint16_t low, std::uint64_t reference);

}  // namespace driftlab::receiver
