// One board of a fleet (`driftlab fleet`, docs/fleet.md): what its log says of it — per channel the eq. 1 fit and
// the IEEE 952 noise terms of the drift-removed rate, and the gap verdict against the unit the fleet is built to.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "host/log/log_data.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::fleet {

/// The parameters a board is described by, per channel: eq. 1's C1, C2, T, then the noise terms N, B, K. The terms
/// are fitted without Q and R, which on an hour at rest trade against N at the shortest and K at the longest tau and
/// would scatter N and K from board to board by the trade, not by the boards.
inline constexpr std::size_t kParameterCount = 6;

struct ParameterInfo {
    const char* name;
    const char* unit;
    /// Positive and spread by factors (a time constant, a noise density): compared on a log scale.
    bool log_scale;
};

inline constexpr std::array<ParameterInfo, kParameterCount> kParameters = {{{"C1", "counts", false},
                                                                            {"C2", "counts", false},
                                                                            {"T", "s", true},
                                                                            {"N", "counts s^0.5", true},
                                                                            {"B", "counts", true},
                                                                            {"K", "counts s^-0.5", true}}};

/// One parameter of one channel. Unknown where the log does not determine it (T beyond the record, a term the
/// Allan curve does not resolve): such a value is left out of the batch, never read as a measurement.
struct Estimate {
    double value = std::numeric_limits<double>::quiet_NaN();
    double std_error = std::numeric_limits<double>::quiet_NaN();  ///< eq. 1: widened for a coloured residual
    bool known = false;
};

struct ChannelResult {
    std::string channel;
    std::string error;  ///< why the channel has no result; "" when analysed
    std::string fit_status;
    std::array<Estimate, kParameterCount> parameters;
};

struct BoardResult {
    std::size_t rows = 0;
    double duration_s = 0.0;  ///< first to last row
    std::vector<ChannelResult> channels;
    bool gap_run = false;
    std::string gap_verdict;  ///< an effect's name, "none" or "unexplained"; "" when not run or failed
    std::size_t gap_located = 0;
    std::string gap_error;  ///< why the diagnosis failed, when it did
};

struct BoardOptions {
    std::vector<std::string> channels;  ///< empty: every channel of the log
    bool gap = true;
    int replicates = 40;
    std::uint64_t seed = 1;
};

/// Analyses one board's log. A channel that cannot be analysed (constant, too short) keeps its reason; a diagnosis
/// that fails keeps its reason; neither stops the rest.
BoardResult analyse_board(const LogData& log, const sim::SimModel& unit, const BoardOptions& options);

}  // namespace driftlab::host::fleet
