// A campaign shard's part file; see part_file.hpp.
#include "host/util/part_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "host/util/error.hpp"
#include "host/util/fnv1a.hpp"

namespace driftlab::host {
namespace {

nlohmann::json read_cbor(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DataError(path, 0, "cannot read it");
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return nlohmann::json::from_cbor(bytes, true, false);
}

}  // namespace

std::string build_id() {
    static const std::string id = file_fingerprint("/proc/self/exe");  // the executable does not change under us
    return id;
}

void write_part_file(const nlohmann::json& document, const std::string& path) {
    const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(document);
    // Beside the target, so that the rename stays on one file system; named by the process, so that two shards
    // writing one name by mistake do not mix their bytes.
    const std::string temporary = path + ".tmp." + std::to_string(getpid());
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw DeviceError(path, "cannot write the part");
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        throw DeviceError(path, "cannot write the part");
    }
}

std::string part_kind(const std::string& path) {
    const nlohmann::json j = read_cbor(path);
    return j.is_object() && j.contains("kind") && j["kind"].is_string() ? j["kind"].get<std::string>() : "";
}

nlohmann::json read_part_file(const std::string& path, const std::string& kind, int format,
                              const std::string& what_writes) {
    nlohmann::json j = read_cbor(path);
    if (j.is_discarded() || !j.is_object() || j.value("kind", "") != kind)
        throw DataError(path, 0, "not a " + kind + " (" + what_writes + " writes one)");
    if (const int f = j.value("format", 0); f != format)
        throw DataError(path, 0, "a " + kind + " of format " + std::to_string(f) + ", not " + std::to_string(format));
    return j;
}

void ShardSet::add(std::size_t shard, std::size_t shards, const std::string& build, const std::string& path) {
    if (build != build_)
        throw DataError(path, 0, "made by another build of driftlab (" + build + ", not " + build_ + ")");
    const std::size_t n = paths_.size();
    if (shards != n) throw DataError(path, 0, "one of " + std::to_string(shards) + " shards, not " + std::to_string(n));
    if (shard >= n) throw DataError(path, 0, "shard " + std::to_string(shard) + " of " + std::to_string(n));
    if (!paths_[shard].empty())
        throw DataError(
            path, 0,
            "shard " + std::to_string(shard) + "/" + std::to_string(n) + " again (also " + paths_[shard] + ")");
    paths_[shard] = path;
}

void ShardSet::check_complete(const std::string& first) const {
    for (std::size_t k = 0; k < paths_.size(); ++k)
        if (paths_[k].empty())
            throw DataError(
                first, 0,
                "shard " + std::to_string(k) + "/" + std::to_string(paths_.size()) + " of its campaign is missing");
}

}  // namespace driftlab::host
