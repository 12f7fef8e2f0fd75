// A fleet's kept results; see board_cache.hpp.
#include "host/fleet/board_cache.hpp"

#include <cstdlib>
#include <filesystem>

#include "host/fleet/board_json.hpp"
#include "host/util/error.hpp"
#include "host/util/fnv1a.hpp"
#include "host/util/part_file.hpp"

namespace driftlab::host::fleet {
namespace {

constexpr const char* kEntryKind = "fleet board";
constexpr int kEntryFormat = 1;

std::string entry_path(const std::string& dir, const std::string& key) { return dir + "/" + key + ".board"; }

}  // namespace

std::string board_key(const std::string& log, const nlohmann::json& options) {
    const std::string bytes = file_fingerprint(log);
    if (bytes.empty()) return "";
    Fnv1a h;
    h.add(bytes);
    h.add(options.dump());
    h.add(build_id());
    return h.hex();
}

std::optional<BoardResult> cached_board(const std::string& dir, const std::string& key) {
    const std::string path = entry_path(dir, key);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    try {
        return read_part_file(path, kEntryKind, kEntryFormat, "driftlab fleet").at("result").get<BoardResult>();
    } catch (const DataError&) {
        return std::nullopt;
    } catch (const nlohmann::json::exception&) {
        return std::nullopt;
    }
}

void store_board(const std::string& dir, const std::string& key, const BoardResult& result) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw DeviceError(dir, "cannot make the fleet's cache folder: " + ec.message());
    write_part_file({{"kind", kEntryKind}, {"format", kEntryFormat}, {"result", result}}, entry_path(dir, key));
}

std::string default_cache_dir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::string(xdg) + "/driftlab/fleet";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/driftlab/fleet";
    return "";
}

}  // namespace driftlab::host::fleet
