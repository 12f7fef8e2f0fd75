// The link in the diagnosis: the frames a log lost, read from its sequence numbers, against the unit's link model
// (sim/link: a Gilbert-Elliott chain per frame, and byte errors or drops that fail a frame's CRC). Loss rate, burst
// length and row timing are cells like the battery's, compared with replicates of the model's link on the log's
// frame slots; two candidates explain a located gap, each judged by the exact likelihood of the frame slots:
// `packet_loss` (bursty: a Gilbert chain, lost in its bad state) and `byte_errors`
// (memoryless: each frame corrupted alone). docs/gap.md §The link.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "host/gap/comparison.hpp"
#include "host/gap/explain.hpp"
#include "host/gap/statistics.hpp"
#include "host/log/log_data.hpp"
#include "sim/link/link_params.hpp"

namespace driftlab::host::gap {

/// The bytes of a POLL request, over which the other direction's errors act.
std::size_t poll_frame_bytes();

/// The link's candidates, in the order they are tried. In a polled log each also fits the share of requests lost
/// (`polls_unanswered`) from the row steps off their slots.
inline constexpr std::array<const char*, 2> kLinkCandidates = {"packet_loss", "byte_errors"};

/// Frame loss as the diagnosis models it: a Gilbert-Elliott chain stepped once per frame slot and, apart from it,
/// a frame corrupted with probability `corrupted` (its CRC fails).
struct FrameLoss {
    sim::PacketLossParams chain;  ///< unit frame; p_good_to_bad 0 for none
    double corrupted = 0.0;       ///< per frame [0, 1]
    /// A polled log: per poll, the request lost on its way to the board, which then sends nothing (a row's time
    /// steps on, its sequence number does not) [0, 1].
    double unanswered = 0.0;

    /// Probability that a frame is lost in the chain's good (`bad` false) or bad state.
    double p_lost(bool bad) const;
};

/// The bytes of the frame a row stands for (a SAMPLE frame), over which byte errors and drops act.
std::size_t sample_frame_bytes();

/// The frame loss of a unit's link: towards the host its chain, and its byte error and drop rates over a SAMPLE frame;
/// for a `polled` log, the requests the other direction loses (its rates over a POLL frame, its chain's long-run loss).
FrameLoss frame_loss_of(const sim::LinkParams& link, bool polled);

/// The log's frame slots, one per row the board sent from the first row to the last (sequence numbers stepping by
/// the frames a row takes), and which part of the log each falls in.
struct FrameSlots {
    std::vector<std::uint8_t> lost;      ///< per slot: 1 where no row arrived
    std::vector<std::uint8_t> observed;  ///< per slot: 0 inside a stretch the user left out (the join of a cut)
    std::vector<bool> fitting;           ///< per slot: in the fitting part (the battery's split, by slot index)
    /// Per part (fitting, held-out): the share of row steps whose time step disagrees with their slot step by more
    /// than half a period (a row out of its place in time, which no link model makes).
    std::array<double, 2> spacing_off{};
    std::array<double, 2> steps{};  ///< per part: the row steps spacing_off counts over
    bool polled = false;            ///< a polled log: a row step off its slots is a request the board never saw
};

/// The slots of `log` under the battery's split. A `# gap:` event is a burst like any other.
FrameSlots frame_slots(const LogData& log, const BatteryOptions& battery);

/// The link cells of one slot pattern (the log's, or a replicate's with the log's observed and fitting masks) with
/// their layout when `layout` is not null: per part, `loss` (lost slots / observed slots), `burst` (mean length of a
/// run of lost slots; 0 without one) and `spacing` (FrameSlots::spacing_off; 0 for a replicate).
std::vector<double> link_cells(const std::vector<std::uint8_t>& lost, const FrameSlots& slots,
                               const std::array<double, 2>& spacing, std::vector<Cell>* layout = nullptr);

/// Per link cell, the least standard deviation its z divides by: half of one frame's (or one step's) share of the
/// part, a tenth of a frame for the mean burst.
std::vector<double> link_cell_floors(const FrameSlots& slots);

/// A slot pattern of `model` over `count` slots, drawn with `seed`.
std::vector<std::uint8_t> simulate_slots(const FrameLoss& model, std::size_t count, std::uint64_t seed);

/// Log-likelihood of the lost/arrived pattern of the observed slots `in` accepts under `model` (forward algorithm;
/// the chain runs on through the others unobserved). -inf where the model cannot make the pattern.
double slot_log_likelihood(const FrameLoss& model, const FrameSlots& slots, const std::vector<bool>& in);

/// A link candidate's parameter `key` as it reports it (Explanation::estimate()), or none where it has none.
std::optional<double> link_parameter(const Explanation& candidate, const std::string& key);

/// `link` with its loss replaced by candidate `added` (its whole-log estimate): what --model-out writes. packet_loss
/// sets the chain towards the host and clears its byte errors; byte_errors the reverse; polls_unanswered becomes
/// the other direction's byte error rate over a POLL frame.
void set_link_loss(sim::LinkParams& link, const Explanation& added);

/// The link's cells are located at a tenth of the channels' family-wise level, on this many replicates at least
/// (cheap: a slot pattern each), so that the link adds a few tenths of a per cent to the false-positive rate.
inline constexpr double kLinkAlphaShare = 0.1;
inline constexpr int kLinkReplicates = 400;

/// The link's part of a diagnosis.
struct LinkFindings {
    bool observed = false;  ///< false for a log whose rows came in no frames (a plain recording): nothing compared
    FrameLoss model;        ///< the unit's link loss, compared with
    std::uint64_t slots = 0, lost = 0;
    std::vector<Cell> layout;
    std::vector<double> real;
    Comparison before;
    std::vector<LocatedCell> located;
    std::vector<Explanation> tried;    ///< packet_loss and byte_errors (channel "link") where a cell is located
    std::optional<std::size_t> added;  ///< into tried: the accepted candidate of the lower whole-log AIC
};

/// Compares `log`'s frame loss with `link`'s on `replicates` replicates and, when `explain`, where a cell is located,
/// fits and judges the candidates: accepted where, fitted to the whole log, the exact likelihood of its slots gains
/// more over the model's than the Schwarz price of its parameters; the accepted one of the lower AIC is added. Fitted
/// on the fitting part, each is also scored on the held-out part's cells (reported, not decided on).
LinkFindings diagnose_link(const LogData& log, const sim::LinkParams& link, const BatteryOptions& battery,
                           int replicates, std::uint64_t seed, double alpha, bool explain);

}  // namespace driftlab::host::gap
