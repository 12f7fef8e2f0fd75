// check_output_file(), write_output_file(); see output_file.hpp.
#include "host/util/output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "host/util/error.hpp"

namespace driftlab::host {

namespace {

// `p` made absolute, its links, "." and ".." resolved as far as it exists; empty where that fails.
std::filesystem::path resolved_path(const std::string& p) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(p, ec);
    if (ec) return {};
    std::filesystem::path out = std::filesystem::weakly_canonical(absolute, ec);
    if (ec) return {};
    return out.has_filename() ? out : out.parent_path();  // "rep/" names the folder "rep"
}

// Outputs need not exist yet, which std::filesystem::equivalent() requires: their paths are compared once resolved
// as far as they exist (a folder's link, "."), and a hard link to an existing file by identity.
bool same_output(const std::string& path, const std::string& other) {
    if (path.empty() || other.empty()) return false;
    std::error_code ec;
    const std::filesystem::path resolved = resolved_path(path);
    return std::filesystem::equivalent(path, other, ec) || (!resolved.empty() && resolved == resolved_path(other));
}

}  // namespace

void check_output_file(const std::string& path, const std::string& what) {
    std::error_code ec;
    const bool existed = std::filesystem::exists(path, ec);
    errno = 0;
    const bool ok = static_cast<bool>(std::ofstream(path, std::ios::app));
    const int error = errno;
    if (!existed) std::filesystem::remove(path, ec);
    if (!ok)
        throw DeviceError(path, "cannot write the " + what + ": " + (error ? std::strerror(error) : "unknown reason"));
}

void refuse_writing_over_input(const std::string& output, const std::string& option, const std::string& input,
                               const std::string& input_what) {
    std::error_code ec;  // either missing: not the same file
    if (!output.empty() && !input.empty() && std::filesystem::equivalent(output, input, ec))
        throw UsageError(option + ": '" + output + "' is the " + input_what + " this command reads ('" + input +
                         "'); writing there would destroy it");
}

void refuse_replacing(const std::string& path, const std::string& what, const std::string& option, bool overwrite) {
    std::error_code ec;
    if (!overwrite && std::filesystem::exists(path, ec))
        throw UsageError(path + ": a " + what + " is already there; name another " + option +
                         ", or pass --overwrite to replace it");
}

void refuse_two_outputs_in_one_file(const std::string& path, const std::string& option, const std::string& other,
                                    const std::string& other_option) {
    if (same_output(path, other))
        throw UsageError(option + ": '" + path + "' is a file " + other_option + " writes ('" + other +
                         "'); one would be written over the other");
}

void refuse_file_on_output_folder(const std::string& path, const std::string& option, const std::string& folder,
                                  const std::string& folder_option) {
    if (same_output(path, folder))
        throw UsageError(option + ": '" + path + "' is the folder " + folder_option +
                         " writes into; name a file, such as '" +
                         (std::filesystem::path(folder) / "model.toml").string() + "'");
}

void write_output_file(const std::string& path, const std::string& text, const std::string& what) {
    const std::string temporary = path + ".part";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!(out << text) || !out.flush()) {
            const int error = errno;
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);  // no part of the file left behind
            throw DeviceError(temporary, "cannot write the " + what + ": " + std::strerror(error));
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        throw DeviceError(path, "cannot write the " + what + ": " + ec.message());
    }
}

}  // namespace driftlab::host
