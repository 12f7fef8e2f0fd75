// A test's temporary folder, shared by the test folders so that every test cleans up the same way.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace driftlab::test_support {

/// A fresh folder under the system temp dir, removed by the destructor. The pid in its name keeps it apart from
/// the same test's folder in another process: ctest runs each test as its own process, side by side.
class TempDir {
public:
    explicit TempDir(const std::string& name)
        : path_(std::filesystem::temp_directory_path() / ("driftlab_" + name + "_" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() { std::filesystem::remove_all(path_); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

/// Writes `text` to a file `name` of this process under the system temp dir (its pid in the name, as TempDir's) and
/// returns its path: a file a reader under test is given.
inline std::string write_temp_file(const std::string& name, const std::string& text) {
    const auto path =
        (std::filesystem::temp_directory_path() / ("driftlab_" + std::to_string(::getpid()) + "_" + name)).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

}  // namespace driftlab::test_support
