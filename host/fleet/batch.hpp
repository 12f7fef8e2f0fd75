// A fleet as a batch (docs/fleet.md): per channel and parameter the boards' median and robust spread, and the boards
// that stand out, with why. Robust, so that the boards being looked for do not hide themselves: the spread is
// 1.4826 x the median absolute deviation (the standard deviation for normal scatter, unmoved by a few outliers), and a
// board stands out where its value lies more such spreads from the median than standout_limit() allows — on a log
// scale for positive parameters spread by factors (kParameters' log_scale), and counting the board's own standard
// error, so that a value the log determines poorly is not called an outlier for its noise.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "host/fleet/board.hpp"

namespace driftlab::host::fleet {

/// Fewer boards with a value give no spread worth judging by.
inline constexpr std::size_t kMinBoardsToJudge = 5;

/// One board's log, by the name it was given: its result, or why it could not be read.
struct BoardEntry {
    std::string log;
    std::optional<BoardResult> result;
    std::string error;
};

struct Distribution {
    std::string channel;
    std::size_t parameter = 0;  ///< into kParameters
    std::size_t boards = 0;     ///< boards whose value is known
    double median = 0.0;
    double spread = 0.0;  ///< 1.4826 x MAD of the values [the parameter's unit]
    double factor = 1.0;  ///< log-scale parameters: exp(1.4826 x MAD of ln value), the spread as a factor
    double low = 0.0, high = 0.0;
    double limit = 0.0;  ///< the robust z-score beyond which a board stands out (standout_limit()); 0: not judged
    /// Where judged (kMinBoardsToJudge boards or more): each board's robust z-score, by its index in the entries.
    std::vector<std::size_t> judged_boards;
    std::vector<double> z;
};

/// Why a board stands out: a parameter far from the batch, or an analysis without result.
struct Standout {
    std::size_t board = 0;  ///< into the entries
    std::string channel;    ///< "" for a diagnosis that failed
    std::string parameter;  ///< kParameters' name, or "analysis"
    double z = 0.0;         ///< parameters: the robust z-score (signed)
    std::string reason;
};

struct Batch {
    std::size_t boards = 0, analysed = 0;
    std::vector<Distribution> distributions;  ///< channel by channel (first board's order), parameter by parameter
    std::vector<Standout> standouts;          ///< board by board
    /// Gap verdict -> the boards that got it. Told apart from the standouts: at the diagnosis's level a clean log
    /// gets a verdict about once in 20 (GapOptions::alpha), so in a fleet one such board is what chance gives.
    std::map<std::string, std::vector<std::size_t>> verdicts;
    std::size_t diagnosed = 0;  ///< boards with a verdict
};

Batch summarise(const std::vector<BoardEntry>& boards);

}  // namespace driftlab::host::fleet
