// Opening input files; see input_file.hpp.
#include "host/util/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>

#include "host/util/error.hpp"

namespace driftlab::host {

std::ifstream open_input_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw DataError(path, 0, std::string("cannot open: ") + std::strerror(errno));
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw DataError(path, 0, "is a folder, not a file");
    return in;
}

std::string read_small_file(const std::string& path, std::size_t max_bytes) {
    std::ifstream in = open_input_file(path);
    std::string text;
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_bytes)
            throw DataError(path, 0,
                            "longer than " + std::to_string(max_bytes >> 20) + " MiB, the most this file may hold");
    }
    if (in.bad()) throw DataError(path, 0, std::string("cannot read: ") + std::strerror(errno));
    return text;
}

void refuse_long_line(const std::string& path, std::uint64_t line) {
    throw DataError(path, line,
                    "a line longer than " + std::to_string(kMaxLineBytes) +
                        " bytes: no line of a log, table or capture (refused without reading it whole)");
}

bool read_line(std::istream& in, std::string& text, const std::string& path, std::uint64_t line, bool* ended) {
    // Bulk reads into a buffer one byte longer than the limit: a line that fills it is too long, and nothing more of
    // it is read. Left uninitialised, so that only the pages a line reaches are ever touched.
    constexpr std::size_t kBufferBytes = kMaxLineBytes + 2;
    thread_local const std::unique_ptr<char[]> buffer(new char[kBufferBytes]);
    in.getline(buffer.get(), static_cast<std::streamsize>(kBufferBytes));
    const std::streamsize got = in.gcount();
    if (in.fail() && !in.eof() && got == static_cast<std::streamsize>(kBufferBytes) - 1) refuse_long_line(path, line);
    if (got == 0 && (in.eof() || in.fail())) return false;
    const bool newline = !in.eof();
    text.assign(buffer.get(), static_cast<std::size_t>(got) - (newline ? 1 : 0));
    if (ended) *ended = newline;
    if (in.fail()) in.clear(in.rdstate() & ~std::ios::failbit);  // an empty last line read fully
    return true;
}

}  // namespace driftlab::host
