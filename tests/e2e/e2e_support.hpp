// Helpers of the end-to-end tests: a simulated board on a pseudo-terminal in a thread, the driftlab binary as
// a child process, temporary folders, and file comparison.
#pragma once

#include <sys/types.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "host/io/pty_board.hpp"
#include "host/log/log_data.hpp"
#include "tests/support/temp_dir.hpp"

namespace driftlab::e2e {

/// A deterministic sensor: mid-scale plus a slow rise and +-2 counts of hashed noise, per channel.
std::uint16_t synthetic_code(Channel c, std::uint64_t tick);

/// A board's options paced at `speed` times the wall clock, for `duration_s` of board time.
host::io::PtyBoardOptions paced_board(double speed, double duration_s);

/// A board served on a pseudo-terminal from a thread until destroyed (or its duration ends).
class BoardThread {
public:
    explicit BoardThread(host::io::PtyBoardOptions options);
    ~BoardThread();
    /// Waits until the pseudo-terminal exists and returns the path clients open.
    std::string path();
    void join();
    /// Stops the board before its duration and waits for it, so its ground-truth log is complete on disk.
    void stop();
    const host::io::PtyBoardSummary& summary() const { return summary_; }

private:
    host::io::PtyBoardOptions options_;
    std::atomic<bool> stop_{false};
    std::atomic<bool> ready_{false};
    std::string path_;
    host::io::PtyBoardSummary summary_;
    std::thread thread_;
};

/// Result of a finished child process.
struct RunResult {
    int exit_code = -1;  ///< -1 when killed by a signal
    std::string output;  ///< stdout and stderr together
};

/// Starts `program args...` with its output going to `output_file` (its standard output to `stdout_file` instead,
/// when one is given); returns its pid.
pid_t spawn_program(const std::string& program, const std::vector<std::string>& args, const std::string& output_file,
                    const std::string& stdout_file = "");
/// spawn_program() of the driftlab binary under test.
pid_t spawn_driftlab(const std::vector<std::string>& args, const std::string& output_file,
                     const std::string& stdout_file = "");
/// Waits for the child and collects its exit status and output.
RunResult wait_child(pid_t pid, const std::string& output_file);
/// spawn + wait.
RunResult run_driftlab(const std::vector<std::string>& args, const std::filesystem::path& dir);
/// spawn + wait with the standard output sent to `stdout_file` (made or emptied; e.g. /dev/full); RunResult::output
/// holds stderr.
RunResult run_driftlab_stdout_to(const std::vector<std::string>& args, const std::string& stdout_file,
                                 const std::filesystem::path& dir);

/// A run whose standard output is kept apart from its error output: the document of --json, and the notes beside it.
struct SplitRun {
    int exit_code = -1;  ///< -1 when killed by a signal
    std::string out;     ///< standard output
    std::string err;     ///< error output
};
/// spawn + wait, the standard output read back from a file in `dir`.
SplitRun run_driftlab_split(const std::vector<std::string>& args, const std::filesystem::path& dir);

using test_support::TempDir;

/// A model file and what plain `driftlab hil` (no --pty) made of it.
struct PlainHilRun {
    std::string model;  ///< the model file's path
    RunResult hil;  ///< `hil --model MODEL --duration 1 -o DIR/h.csv`: exit 5 when the file's configuration is refused
};

/// Writes `toml` as the model file `name` in `dir` and runs plain `hil` on it, for a test whose model plain hil
/// refuses (a [firmware] or [link] the firmware or the simulated link cannot meet) to check that refusal first.
PlainHilRun plain_hil_with_model(const TempDir& dir, const std::string& name, const std::string& toml);

std::string read_text(const std::string& path);
/// Cuts the log's last row as a kill inside write(2) would: it loses its newline and the tail of its last value.
/// Returns that line's number.
std::string cut_last_row(const std::string& log);
std::vector<std::string> lines_of(const std::string& text);

/// Every row of `log` is a row the firmware sent (in `truth`, the board's own decoding of its output): same tick, same
/// seq, same time, same four values.
void expect_rows_in_truth(const host::LogData& log, const host::LogData& truth);

}  // namespace driftlab::e2e
