// Helpers of the end-to-end tests (e2e_support.hpp).
#include "tests/e2e/e2e_support.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace driftlab::e2e {

std::uint16_t synthetic_code(Channel c, std::uint64_t tick) {
    const double t_s = static_cast<double>(tick) / 250000.0;
    std::uint64_t h = (tick * 0x9E3779B97F4A7C15ull) ^ (static_cast<std::uint64_t>(channel_index(c)) << 56);
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 29;
    const int noise = static_cast<int>(h % 5) - 2;
    const double rise = 3.0 * (1.0 - std::exp(-t_s / 411.0)) + 10.0 * channel_index(c);
    return static_cast<std::uint16_t>(500 + static_cast<int>(rise) + noise);
}

host::io::PtyBoardOptions paced_board(double speed, double duration_s) {
    host::io::PtyBoardOptions options;
    options.speed = speed;
    options.duration_s = duration_s;
    return options;
}

BoardThread::BoardThread(host::io::PtyBoardOptions options) : options_(std::move(options)) {
    thread_ = std::thread([this] {
        summary_ = host::io::serve_pty_board(options_, synthetic_code, stop_, [this](const std::string& p) {
            if (!ready_.load()) {
                path_ = p;
                ready_.store(true);
            }
        });
    });
}

BoardThread::~BoardThread() { stop(); }

void BoardThread::stop() {
    stop_.store(true);
    join();
}

void BoardThread::join() {
    if (thread_.joinable()) thread_.join();
}

std::string BoardThread::path() {
    while (!ready_.load()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return path_;
}

pid_t spawn_program(const std::string& program, const std::vector<std::string>& args, const std::string& output_file,
                    const std::string& stdout_file) {
    // Built before the fork: the child of a process with threads may only make async-signal-safe calls until it execs
    // (an allocation there had waited forever on a sanitizer's lock held by another thread at the fork).
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int fd = ::open(output_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(stdout_file.empty() ? fd : ::open(stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), 1);
        ::dup2(fd, 2);
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
    }
    return pid;
}

pid_t spawn_driftlab(const std::vector<std::string>& args, const std::string& output_file,
                     const std::string& stdout_file) {
    return spawn_program(DRIFTLAB_BIN, args, output_file, stdout_file);
}

RunResult wait_child(pid_t pid, const std::string& output_file) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    RunResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.output = read_text(output_file);
    return r;
}

RunResult run_driftlab(const std::vector<std::string>& args, const std::filesystem::path& dir) {
    const std::string out = (dir / "driftlab.out").string();
    return wait_child(spawn_driftlab(args, out), out);
}

RunResult run_driftlab_stdout_to(const std::vector<std::string>& args, const std::string& stdout_file,
                                 const std::filesystem::path& dir) {
    const std::string err = (dir / "driftlab.err").string();
    return wait_child(spawn_driftlab(args, err, stdout_file), err);
}

SplitRun run_driftlab_split(const std::vector<std::string>& args, const std::filesystem::path& dir) {
    const std::string out = (dir / "driftlab.stdout").string();
    const RunResult r = run_driftlab_stdout_to(args, out, dir);
    return {r.exit_code, read_text(out), r.output};
}

PlainHilRun plain_hil_with_model(const TempDir& dir, const std::string& name, const std::string& toml) {
    PlainHilRun r;
    r.model = dir.file(name);
    std::ofstream(r.model) << toml;
    r.hil = run_driftlab({"hil", "--model", r.model, "--duration", "1", "-o", dir.file("h.csv")}, dir.path());
    return r;
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string cut_last_row(const std::string& log) {
    std::string text = read_text(log);
    EXPECT_EQ(text.back(), '\n');
    text.resize(text.size() - 4);
    std::ofstream(log, std::ios::binary | std::ios::trunc) << text;
    return std::to_string(std::count(text.begin(), text.end(), '\n') + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t nl = text.find('\n', start);
        if (nl == std::string::npos) break;  // an unterminated last line is not a line
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
    }
    return lines;
}

// Every recorded row must be a row the firmware sent: same tick, same seq, same four values.
void expect_rows_in_truth(const host::LogData& log, const host::LogData& truth) {
    std::map<std::uint64_t, std::size_t> truth_by_tick;
    const auto& truth_ticks = truth.optional_columns.at("tick");
    for (std::size_t i = 0; i < truth.size(); ++i) truth_by_tick[static_cast<std::uint64_t>(truth_ticks[i])] = i;
    const auto& ticks = log.optional_columns.at("tick");
    for (std::size_t r = 0; r < log.size(); ++r) {
        const auto it = truth_by_tick.find(static_cast<std::uint64_t>(ticks[r]));
        ASSERT_NE(it, truth_by_tick.end()) << "row " << r << " tick " << ticks[r] << " was never sent";
        const std::size_t i = it->second;
        EXPECT_EQ(log.seq[r], truth.seq[i]) << "row " << r;
        EXPECT_EQ(log.t_s[r], truth.t_s[i]) << "row " << r;
        for (std::uint8_t c = 0; c < kChannelCount; ++c) EXPECT_EQ(log.counts[c][r], truth.counts[c][i]) << "row " << r;
    }
}

}  // namespace driftlab::e2e
