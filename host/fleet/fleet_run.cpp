// A fleet's boards analysed one after another; see fleet_run.hpp.
#include "host/fleet/fleet_run.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>

#include "host/fit/series.hpp"
#include "host/fleet/board_cache.hpp"
#include "host/fleet/board_json.hpp"
#include "host/gap/canonical_log.hpp"
#include "host/util/error.hpp"
#include "host/util/fnv1a.hpp"
#include "sim/model/model_file.hpp"

namespace driftlab::host::fleet {
namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::vector<std::string> logs_in(const std::string& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file(ec) && ends_with(name, ".csv") && !ends_with(name, ".truth.csv"))
            out.push_back(e.path().string());
    }
    if (ec) throw UsageError(dir + ": cannot list the folder: " + ec.message());
    std::sort(out.begin(), out.end());
    if (out.empty()) throw UsageError(dir + ": a folder without a log (*.csv)");
    return out;
}

// One board: read back when the cache has it, else read against the unit and analysed (and kept).
BoardEntry board(const std::string& path, const sim::SimModel& unit, const FleetOptions& o, const std::string& key,
                 std::size_t& from_cache) {
    BoardEntry entry{path, std::nullopt, ""};
    if (!key.empty()) {
        entry.result = cached_board(o.cache_dir, key);
        if (entry.result) {
            ++from_cache;
            return entry;
        }
    }
    try {
        fit::OpenedSource source = fit::open_source(path);
        if (!source.canonical_log)
            throw DataError(path, 1, "not a driftlab log (its first line is not '# driftlab-log: 1')");
        const LogData log = gap::read_canonical_log(source.in, path, {}, unit, false);
        entry.result = analyse_board(log, unit, o.board);
    } catch (const Error& e) {  // this log's, not the fleet's: a log without a channel --channel names, too
        entry.error = e.what();
        return entry;
    }
    if (!key.empty()) store_board(o.cache_dir, key, *entry.result);
    return entry;
}

}  // namespace

std::vector<std::string> fleet_logs(const std::vector<std::string>& inputs) {
    std::vector<std::string> out;
    for (const std::string& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            const std::vector<std::string> logs = logs_in(input);
            out.insert(out.end(), logs.begin(), logs.end());
        } else if (fs::exists(input, ec)) {
            out.push_back(input);
        } else {
            throw UsageError(input + ": no such log or folder");
        }
    }
    return out;
}

nlohmann::json analysis_options(const FleetOptions& o) {
    return {{"channels", o.board.channels},
            {"gap", o.board.gap},
            {"replicates", o.board.replicates},
            {"seed", o.board.seed},
            {"model", o.model_path.empty() ? std::string("paper") : file_fingerprint(o.model_path)}};
}

FleetRun run_fleet(const std::vector<std::string>& logs, const FleetOptions& o, std::size_t shard, std::size_t shards,
                   const FleetProgress& progress) {
    const sim::SimModel unit = o.model_path.empty() ? sim::paper_model() : sim::load_model_file(o.model_path);
    const nlohmann::json options = analysis_options(o);
    FleetRun run;
    for (std::size_t i = shard; i < logs.size(); i += shards) run.items.push_back(i);
    for (std::size_t n = 0; n < run.items.size(); ++n) {
        const std::string& path = logs[run.items[n]];
        if (progress) progress(n, run.items.size(), path);
        const std::string key = o.cache_dir.empty() ? "" : board_key(path, options);
        run.boards.push_back(board(path, unit, o, key, run.from_cache));
    }
    return run;
}

}  // namespace driftlab::host::fleet
