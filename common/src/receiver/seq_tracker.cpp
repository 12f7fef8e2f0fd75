// SeqTracker: sequence unwrapping and lost/duplicate/reordered accounting (seq_tracker.hpp).
#include "driftlab/receiver/seq_tracker.hpp"

namespace driftlab::receiver {

std::uint64_t unwrap_near(std::uint16_t low, std::uint64_t reference) {
    const auto delta =
        static_cast<std::int16_t>(static_cast<std::uint16_t>(low - static_cast<std::uint16_t>(reference)));
    if (delta < 0 && reference < static_cast<std::uint64_t>(-static_cast<std::int64_t>(delta))) {
        return reference + static_cast<std::uint64_t>(static_cast<std::uint16_t>(delta));
    }
    return reference + static_cast<std::uint64_t>(static_cast<std::int64_t>(delta));
}

void SeqTracker::restart_epoch() {
    if (!started_) return;
    new_epoch_ = true;
    epoch_base_ = newest_ + 1;
    hint_.reset();
}

SeqResult SeqTracker::accept(std::uint16_t seq) {
    ++received_;
    std::uint64_t n = 0;
    if (!started_) {
        n = hint_ ? unwrap_near(seq, *hint_) : seq;
    } else if (new_epoch_) {
        n = epoch_base_ + seq;  // the restarted sender counts from 0: frames 0..seq-1 of it are lost
    } else {
        // Unwrap in the sender's own count (since its last restart), then place it after earlier epochs.
        const std::uint64_t reference = hint_ ? *hint_ : newest_;
        n = epoch_base_ + unwrap_near(seq, reference > epoch_base_ ? reference - epoch_base_ : 0);
    }
    hint_.reset();
    new_epoch_ = false;

    if (!started_) {
        started_ = true;
        newest_ = n;
        seen_.reset();
        seen_.set(n % kHistory);
        return {n, SeqVerdict::fresh};
    }
    if (n > newest_) {
        const std::uint64_t gap = n - newest_ - 1;
        lost_ += gap;
        if (gap >= kHistory) {
            seen_.reset();
        } else {
            for (std::uint64_t k = newest_ + 1; k < n; ++k) seen_.reset(k % kHistory);
        }
        seen_.set(n % kHistory);
        newest_ = n;
        return {n, SeqVerdict::fresh};
    }
    if (newest_ - n >= kHistory || seen_.test(n % kHistory)) {
        ++duplicates_;
        return {n, SeqVerdict::duplicate};
    }
    seen_.set(n % kHistory);
    --lost_;
    ++reordered_;
    return {n, SeqVerdict::late};
}

}  // namespace driftlab::receiver
