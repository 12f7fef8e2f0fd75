// The rest of a long text file in blocks of whole lines, each parsed in two halves at once: the log and the plain
// table readers share it, so a ten-million-line file is parsed on both cores while its errors still name the first
// bad line in the file.
#pragma once

#include <cstdint>
#include <functional>
#include <istream>
#include <string>
#include <string_view>

namespace driftlab::host {

/// What read_line_blocks() asks of a reader.
struct LineBlockParser {
    /// Parses `lines` (each ending in '\n'), the first numbered `first_line`, into half `half` (0 or 1) of the
    /// reader's own: both halves of a block are parsed at once, so it must write nothing else. An error it meets is
    /// kept in that half, for append() to throw in file order.
    std::function<void(int half, std::string_view lines, std::uint64_t first_line)> parse;
    /// Adds half `half` to what is read, half 0 before half 1, blocks in file order; throws its kept error.
    std::function<void(int half)> append;
    /// The file's last line when it has no '\n' (a writer cut mid-line), numbered `number`.
    std::function<void(std::string_view text, std::uint64_t number)> cut_last_line;
};

/// Reads the rest of `in` (`path` names it in errors) in 8 MB blocks of whole lines, each split near its middle
/// into two halves parsed on two threads and then appended in order. `number` is the last line read before, and
/// becomes the file's last. Throws DataError for a line longer than kMaxLineBytes, naming it.
void read_line_blocks(std::istream& in, const std::string& path, std::uint64_t& number, const LineBlockParser& parser);

/// Calls `line(text, number)` for each line of `lines` (each ending in '\n'; a CR before it removed), the first
/// numbered `first_line`.
template <class OnLine>
void for_each_line(std::string_view lines, std::uint64_t first_line, OnLine line) {
    std::uint64_t number = first_line;
    for (std::size_t at = 0; at < lines.size(); ++number) {
        const std::size_t end = lines.find('\n', at);
        std::string_view text = lines.substr(at, end - at);
        at = end + 1;
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        line(text, number);
    }
}

}  // namespace driftlab::host
