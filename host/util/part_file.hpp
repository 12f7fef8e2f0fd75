// A campaign shard's part file (docs/cluster.md): one CBOR document (every double exact, NaN kept), written whole —
// a temporary file beside it, then a rename — so a reader never sees half a part and a shard run twice writes the
// same bytes; stamped with the build that made it.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace driftlab::host {

/// The running executable's identity: a 64-bit FNV-1a hash of its file, in hexadecimal.
std::string build_id();

/// Writes `document` to `path` atomically. Throws DeviceError naming the path.
void write_part_file(const nlohmann::json& document, const std::string& path);

/// The document of a part file whose "kind" is `kind`. Throws DataError naming the file when it cannot be read, is
/// not CBOR, or is another kind (`what_writes` says what writes one).
nlohmann::json read_part_file(const std::string& path, const std::string& kind, const std::string& what_writes);

/// The "kind" of a part file, or "" when it is none.
std::string part_kind(const std::string& path);

}  // namespace driftlab::host
