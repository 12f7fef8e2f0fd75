// The views of a gap result (`driftlab gap`): the terminal's text, the stable JSON (docs/gap.md §JSON) and the
// report DIR/gap.md with its plots (docs/gap.md §Report). The three say the same thing in the same words
// (gap_phrases.hpp); a new field of GapResult is shown here and nowhere else.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/gap/diagnose.hpp"
#include "host/gap/verdict_stability.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::view {

/// The diagnosis of `log` run with `options`, as the terminal shows it; with `stability` (--stability), the verdict's
/// stability under it.
void print_gap_text(const gap::GapResult& result, const gap::GapOptions& options, const LogData& log,
                    const gap::VerdictStability* stability = nullptr);

/// The top-level keys of gap_to_json(), in the order --help lists them (a test holds the two together).
inline constexpr auto kGapJsonKeys = std::to_array<const char*>({"verdict",
                                                                 "explanations",
                                                                 "paths",
                                                                 "located",
                                                                 "located_after",
                                                                 "diffuse_gap",
                                                                 "diffuse_searched",
                                                                 "gap_before",
                                                                 "gap_after",
                                                                 "information_criterion",
                                                                 "level_steps",
                                                                 "not_identifiable",
                                                                 "not_tried",
                                                                 "constant_channels",
                                                                 "noise_free_channels",
                                                                 "saturated",
                                                                 "lone_values",
                                                                 "left_out",
                                                                 "given",
                                                                 "calibration",
                                                                 "timing",
                                                                 "replicates",
                                                                 "holdout",
                                                                 "fit_fraction",
                                                                 "max_effects",
                                                                 "threshold_z",
                                                                 "cells",
                                                                 "motion",
                                                                 "link",
                                                                 "common"});

/// `gap --truth`'s motion section (GapResult::motion): the terms, their estimates and verdicts; nothing (null in
/// JSON) without it.
void print_motion_text(const gap::GapResult& result);
nlohmann::json motion_to_json(const gap::GapResult& result);
/// The link's section (GapResult::link): its frame loss against the unit's link, located cells and candidates.
void print_link_text(const gap::GapResult& result);
void write_link_markdown(std::ostream& md, const gap::GapResult& result);
nlohmann::json link_to_json(const gap::GapResult& result);
/// The shared-causes section (GapResult::common): the readings of the channels together, the located coherence
/// cells; nothing (null in JSON) where the channels were not read together.
void print_common_text(const gap::GapResult& result);
void write_common_markdown(std::ostream& md, const gap::GapResult& result);
nlohmann::json common_to_json(const gap::GapResult& result);
/// The verdict's reason where a shared reading won ("" otherwise).
std::string common_sentence(const gap::GapResult& result);
/// Whether `effect` was judged as a motion term, so it is not among the effects a static log cannot identify.
bool tried_in_motion(const gap::GapResult& result, const std::string& effect);

/// The diagnosis run with `options` under the keys kGapJsonKeys (docs/gap.md §JSON).
nlohmann::json gap_to_json(const gap::GapResult& result, const gap::GapOptions& options);

/// --stability's result: logs, verdicts, same (a share), params[] {effect, channel, param, estimate, values (sorted),
/// median, p16, p84; null medians where no log added the effect again}.
nlohmann::json stability_to_json(const gap::VerdictStability& stability);

/// Every file write_gap_report() may write into `dir`, whichever channels it plots: an input among them is refused.
std::vector<std::string> report_files(const std::string& dir);

/// The comments a model file written by `gap --model-out` opens with: where it comes from (`source`, the log and the
/// rows used), the verdict, what the file holds, the model's own effects, the model's `notes`, and with `stability`
/// the verdict's stability.
std::string model_file_comment(const gap::GapResult& result, const std::string& source,
                               const std::vector<std::string>& notes, const gap::VerdictStability* stability);

/// Writes DIR/gap.md, DIR/gap_adev_<channel>.png and DIR/gap_mean_<channel>.png (plots skipped with a note when
/// gnuplot is missing); with `stability` (--stability), the verdict's stability under the verdict.
void write_gap_report(const gap::GapResult& result, const LogData& log, const std::string& dir,
                      const gap::GapOptions& options, const gap::VerdictStability* stability = nullptr);

}  // namespace driftlab::host::view
