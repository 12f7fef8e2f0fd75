// The command table of `driftlab`: one entry per subcommand, each implemented in its own cmd_*.cpp.
// Help is generated from this table by CLI11, so listed and existing commands cannot disagree.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace driftlab::host::fit {
struct FileAnalysisRequest;
struct FileAnalysis;
struct DriftAnalysis;
}  // namespace driftlab::host::fit
namespace driftlab::host::gap {
enum class Holdout;
}
namespace driftlab::host {
struct TimeWindow;
}

namespace driftlab::host::cli {

/// What `--version` prints and a recording's header names as its recorder; the version is the CMake project's.
inline constexpr const char* kProgramVersion = "driftlab " DRIFTLAB_VERSION;

/// Registers one subcommand (its options struct, flags and callback) on the top-level app.
using RegisterFn = void (*)(CLI::App& app);

// One declaration per cmd_*.cpp; keep in the order `driftlab --help` lists them.
void register_ports(CLI::App& app);
void register_flash(CLI::App& app);
void register_keygen(CLI::App& app);
void register_record(CLI::App& app);
void register_upload(CLI::App& app);
void register_rekey(CLI::App& app);
void register_decode(CLI::App& app);
void register_hil(CLI::App& app);
void register_effects(CLI::App& app);
void register_fit(CLI::App& app);
void register_calibrate(CLI::App& app);
void register_whiteness(CLI::App& app);
void register_report(CLI::App& app);
void register_allan(CLI::App& app);
void register_gap(CLI::App& app);
void register_gap_eval(CLI::App& app);
void register_fleet(CLI::App& app);
void register_merge(CLI::App& app);
void register_nav(CLI::App& app);
void register_nav_eval(CLI::App& app);

/// The input flags fit, whiteness and report share (defined in cmd_fit.cpp).
void add_analysis_input_options(CLI::App* cmd, fit::FileAnalysisRequest& request);

/// --from/--t-min and --to/--t-max [s since power-on], finite: the rows fit, whiteness, report, allan and gap keep
/// (time_range_options.cpp). A reversed or empty range is refused, "--from must be before --to", once the command
/// line is read and before the log is (it takes `cmd`'s parse_complete_callback).
void add_time_range_options(CLI::App* cmd, double& t_min_s, double& t_max_s);

/// `--drop-cut-line`: every command that reads a driftlab log takes it alike (cmd_fit.cpp; read with
/// fit::cut_line_options and say host::dropped_cut_line_note).
void add_drop_cut_line_flag(CLI::App* cmd, bool& drop);

/// `--unit [COLUMN:]UNIT`, repeatable, for a plain table's columns: report and allan take it alike (cmd_report.cpp;
/// parse with stats::parse_unit_assignment); `takes_phase`: allan, whose phase samples name their integral's unit.
void add_unit_option(CLI::App* cmd, std::vector<std::string>& units, bool takes_phase = false);

/// The non-zero exit (DataError) for series that could not be analysed. With `reasons_printed` (a text table gave
/// each) it names them only; else it gives every reason (cmd_fit.cpp).
void throw_if_failed(const fit::FileAnalysis& file, bool reasons_printed);

/// Checks for numeric options. CLI11's PositiveNumber and NonNegativeNumber state their range as 0 to the largest
/// double written out in full; these say what is wanted and what was given, in --help too (number_checks.cpp).
const CLI::Validator& positive_number();
const CLI::Validator& non_negative_number();
/// Whether an interval's end belongs to it.
enum class Bound { closed, open };
/// A finite number from `low` (itself too unless `low_bound` is open) to `high`; CLI::Range took "nan".
CLI::Validator number_in(double low, double high, Bound low_bound = Bound::closed);
/// A whole number from `low` to `high`, for integer options ("3.5" and "65" named as such, not as a failed conversion).
CLI::Validator whole_number_in(long long low, long long high);
/// Any finite number (a time bound may be negative; "nan" compared false with every time and cut nothing).
const CLI::Validator& finite_value();
/// A baud rate termios can set (io::is_supported_baud): record's and flash's --baud, checked as the command line is
/// read (flash --dry-run had printed `-b -1`).
const CLI::Validator& baud_rate();
/// A value that is not empty, `what` naming what is wanted: an empty one had been taken for the default, or for none
/// ("--report ''" for no report at all, "hil -o ''" for out/fig3.csv, "--plot ''" for no plots).
CLI::Validator non_empty(const std::string& what);
/// non_empty("a path"): every file and folder option, and every input file.
const CLI::Validator& non_empty_path();
/// A seed: digits only, 0 to 2^64 - 1 (CLI11's unsigned parse wraps "-5" and clamps what is beyond).
const CLI::Validator& seed_number();

/// An output period [s] as the CONFIG's whole milliseconds in [10, 60000]; throws UsageError naming `option`
/// otherwise (hil --period and record --poll/--stream: 0.0105 s had been rounded to 10 ms without a word).
std::uint16_t output_period_ms(double period_s, const std::string& option);

/// The whole of `text` as a finite number; none for anything else (trailing text, "nan", "inf").
std::optional<double> finite_number(const std::string& text);

/// The formatter of every command's help: an option's type and its checks read as one phrase (help_formatter.cpp).
std::shared_ptr<CLI::Formatter> help_formatter();

/// --holdout interleaved|forecast, which gap and gap-eval share (defined in cmd_gap.cpp).
void add_holdout_option(CLI::App* cmd, gap::Holdout& holdout);

/// --exclude FROM:TO [s since power-on], repeatable: each value read into `windows` as the command line is parsed
/// (UsageError unless two finite numbers, FROM before TO); `what_becomes_of_them` ends its help (the rows either side
/// joined, a gap on the grid...). exclude_option.cpp.
void add_exclude_option(CLI::App* cmd, std::vector<TimeWindow>& windows, const std::string& what_becomes_of_them);

}  // namespace driftlab::host::cli
