// Long text files in blocks of whole lines; see line_blocks.hpp.
#include "host/log/line_blocks.hpp"

#include <algorithm>
#include <thread>

#include "host/util/input_file.hpp"

namespace driftlab::host {

void read_line_blocks(std::istream& in, const std::string& path, std::uint64_t& number, const LineBlockParser& parser) {
    // A block's halves are parsed at once only where each is worth a thread.
    constexpr std::size_t kBlockBytes = std::size_t{8} << 20, kSplitBytes = std::size_t{1} << 20;
    std::string block;
    while (true) {
        const std::size_t kept = block.size();
        block.resize(kept + kBlockBytes);
        in.read(block.data() + kept, static_cast<std::streamsize>(kBlockBytes));
        block.resize(kept + static_cast<std::size_t>(in.gcount()));
        if (in.bad()) return;
        // Only a line begun in an earlier read can be longer than a block.
        if (std::min(block.find('\n'), block.size()) > kMaxLineBytes) refuse_long_line(path, number + 1);
        const std::size_t last = block.rfind('\n'), whole = last == std::string::npos ? 0 : last + 1;
        const std::string_view lines(block.data(), whole);
        const std::size_t middle = whole < kSplitBytes ? whole : lines.find('\n', whole / 2) + 1;
        const std::string_view head = lines.substr(0, middle), tail = lines.substr(middle);
        const auto head_lines = static_cast<std::uint64_t>(std::count(head.begin(), head.end(), '\n'));
        std::thread other;
        if (!tail.empty()) other = std::thread([&] { parser.parse(1, tail, number + 1 + head_lines); });
        parser.parse(0, head, number + 1);
        if (other.joinable()) other.join();
        parser.append(0);
        if (!tail.empty()) parser.append(1);
        number += head_lines + static_cast<std::uint64_t>(std::count(tail.begin(), tail.end(), '\n'));
        block.erase(0, whole);
        if (!in) {
            if (!block.empty()) parser.cut_last_line(block, ++number);
            return;
        }
    }
}

}  // namespace driftlab::host
