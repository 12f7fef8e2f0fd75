#include "host/io/port_holders.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

namespace driftlab::host::io {
namespace {

std::string command_line(const std::filesystem::path& proc) {
    std::ifstream in(proc / "cmdline", std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (char& c : text)
        if (c == '\0') c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.size() > 120 ? text.substr(0, 117) + "..." : text;
}

}  // namespace

std::string port_holders(const std::string& path) {
    struct stat target {};
    if (::stat(path.c_str(), &target) != 0) return "";
    std::string out;
    std::error_code ec;
    for (const auto& proc : std::filesystem::directory_iterator("/proc", ec)) {
        const std::string pid = proc.path().filename().string();
        if (pid.find_first_not_of("0123456789") != std::string::npos || std::stoll(pid) == ::getpid()) continue;
        std::error_code fd_ec;
        for (const auto& fd : std::filesystem::directory_iterator(proc.path() / "fd", fd_ec)) {
            struct stat st {};
            if (::stat(fd.path().c_str(), &st) != 0 || st.st_rdev != target.st_rdev || !S_ISCHR(st.st_mode)) continue;
            out += (out.empty() ? "" : "; ") + ("PID " + pid + " (" + command_line(proc.path()) + ")");
            break;
        }
    }
    return out;
}

}  // namespace driftlab::host::io
