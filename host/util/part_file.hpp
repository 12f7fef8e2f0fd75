// A campaign shard's part file (docs/cluster.md): one CBOR document (every double exact, NaN kept), written whole —
// a temporary file beside it, then a rename — so a reader never sees half a part and a shard run twice writes the
// same bytes; stamped with the build that made it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/util/error.hpp"

namespace driftlab::host {

/// The running executable's identity: a 64-bit FNV-1a hash of its file, in hexadecimal.
std::string build_id();

/// Writes `document` to `path` atomically. Throws DeviceError naming the path.
void write_part_file(const nlohmann::json& document, const std::string& path);

/// The document of a part file whose "kind" is `kind` and "format" `format`. Throws DataError naming the file when it
/// cannot be read, is not CBOR, or is another kind (`what_writes` says what writes one) or format.
nlohmann::json read_part_file(const std::string& path, const std::string& kind, int format,
                              const std::string& what_writes);

/// The "kind" of a part file, or "" when it is none.
std::string part_kind(const std::string& path);

/// The shards a merge meets, each part by its path: every one of 0 .. N-1 once, all made by one build.
class ShardSet {
public:
    ShardSet(std::size_t shards, std::string build) : paths_(shards), build_(std::move(build)) {}
    /// Records `path` as shard `shard` of `shards`, made by `build`. Throws DataError naming it when it is of another
    /// N or build, or a shard already met (naming that part too).
    void add(std::size_t shard, std::size_t shards, const std::string& build, const std::string& path);
    /// Throws DataError naming `first` (the campaign's first part) when a shard is missing.
    void check_complete(const std::string& first) const;

private:
    std::vector<std::string> paths_;
    std::string build_;
};

/// The items of a campaign's parts, each put in its place as the parts are read (a fleet's boards, the sizes stage's
/// generators, gap-eval's cases and pairs, nav-eval's seeds): every item once, from the shard that owns it, none
/// missing.
template <class T>
class ItemSlots {
public:
    /// Items numbered `first` .. `first` + `items` - 1 (a campaign's pairs follow its cases, nav-eval's seeds start at
    /// its first seed); `noun` names one in messages ("board", "generator").
    ItemSlots(std::size_t items, std::string noun, std::uint64_t first = 0)
        : slots_(items), noun_(std::move(noun)), first_(first) {}
    /// Puts `value` as item `item` of shard `shard`, read from `path`, where `owner` is the shard that owns the item.
    /// Throws DataError naming `path` when the item is outside the campaign, another shard's, or met before (shards
    /// are met once each, so only twice in one part).
    void put(std::uint64_t item, std::size_t shard, std::size_t owner, T value, const std::string& path) {
        const auto refuse = [&](const std::string& why) {
            throw DataError(path, 0, "holds " + noun_ + " " + std::to_string(item) + why);
        };
        if (item < first_ || item - first_ >= slots_.size() || owner != shard)
            refuse(", not shard " + std::to_string(shard) + "'s");
        auto& slot = slots_[item - first_];
        if (slot) refuse(" twice");
        slot = std::move(value);
    }
    /// Every item in order. Throws DataError naming `first` (the campaign's first part) when one is missing.
    std::vector<T> take(const std::string& first) {
        std::vector<T> out;
        for (std::size_t i = 0; i < slots_.size(); ++i) {
            if (!slots_[i]) throw DataError(first, 0, "its parts miss " + noun_ + " " + std::to_string(first_ + i));
            out.push_back(std::move(*slots_[i]));
        }
        return out;
    }

private:
    std::vector<std::optional<T>> slots_;
    std::string noun_;
    std::uint64_t first_;
};

}  // namespace driftlab::host
