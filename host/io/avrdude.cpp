// avrdude invocation for `driftlab flash`.
#include "host/io/avrdude.hpp"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "host/util/error.hpp"

namespace driftlab::host::io {
namespace {

namespace fs = std::filesystem;

bool is_executable_file(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::vector<std::string> avrdude_arguments(const FlashRequest& request) {
    std::vector<std::string> args = {request.avrdude,
                                     "-p",
                                     request.part,
                                     "-c",
                                     request.programmer,
                                     "-P",
                                     request.port,
                                     "-b",
                                     std::to_string(request.baud),
                                     "-D",
                                     "-U",
                                     "flash:w:" + request.hex_file + ":i"};
    if (!request.eeprom_hex_file.empty()) args.insert(args.end(), {"-U", "eeprom:w:" + request.eeprom_hex_file + ":i"});
    return args;
}

std::string find_in_path(const std::string& program, const std::string& path_env) {
    if (program.find('/') != std::string::npos) return is_executable_file(program) ? program : std::string();
    std::size_t start = 0;
    while (start <= path_env.size()) {
        std::size_t end = path_env.find(':', start);
        if (end == std::string::npos) end = path_env.size();
        const std::string dir = end > start ? path_env.substr(start, end - start) : std::string(".");
        const std::string candidate = dir + "/" + program;
        if (is_executable_file(candidate)) return candidate;
        start = end + 1;
    }
    return {};
}

std::string default_hex_file(const std::string& exe_path) {
    std::error_code ec;
    const fs::path exe = fs::weakly_canonical(exe_path, ec);
    // exe = <build>/<preset>/bin/driftlab; the AVR preset builds into <build>/avr, and a native build with avr-gcc
    // builds the same firmware into <build>/<preset>/avr-fw (the image `hil --target avr` runs). Each build writes
    // its image at one known path, so no folder walk picks a stray copy. A binary copied elsewhere had been sent to
    // paths derived from wherever it lay (/tmp/x/driftlab: /avr/firmware/driftlab_fw.hex).
    const fs::path tree = exe.parent_path().parent_path();
    std::error_code unreadable;  // taken as absent
    if (ec || !fs::is_regular_file(tree / "CMakeCache.txt", unreadable)) {
        throw DataError("driftlab_fw.hex", 0,
                        "no default firmware image: it is looked for beside a build tree's driftlab "
                        "(build/<preset>/bin/driftlab), and " +
                            (ec ? exe_path : exe.string()) + " is not one (a copy, or installed); pass --hex FILE");
    }
    const fs::path preset_image = tree.parent_path() / "avr" / "firmware" / "driftlab_fw.hex";
    const fs::path native_image = tree / "avr-fw" / "firmware" / "driftlab_fw.hex";
    for (const fs::path& image : {preset_image, native_image}) {
        if (fs::is_regular_file(image, unreadable)) return image.string();
    }
    throw DataError("driftlab_fw.hex", 0,
                    "firmware image not found at " + preset_image.string() + " (the AVR build's) nor at " +
                        native_image.string() +
                        " (the native build's, made when avr-gcc is installed); build it "
                        "with `cmake --preset avr && cmake --build --preset avr`, or pass --hex FILE");
}

void check_image_and_port(const FlashRequest& request) {
    if (request.hex_file.empty()) throw UsageError("--hex: empty; pass the firmware image (an Intel HEX file)");
    if (!fs::is_regular_file(request.hex_file)) {
        throw DataError(request.hex_file, 0,
                        "firmware image not found (build it with `cmake --preset avr && cmake "
                        "--build --preset avr`, or pass --hex FILE)");
    }
    if (request.port.empty()) throw UsageError("no port given: pass --port DEV (see `driftlab ports`)");
    if (::access(request.port.c_str(), F_OK) != 0) {
        throw DeviceError(request.port, "no such port (is the board plugged in? `driftlab ports` lists adapters)");
    }
}

std::string shell_quoted(const std::string& word) {
    const bool plain = !word.empty() && word.find_first_not_of(
                                            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                            "0123456789_-+=.,/:@%") == std::string::npos;
    if (plain) return word;
    std::string out = "'";
    for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

void run_avrdude(const FlashRequest& request, const std::string& path_env) {
    check_image_and_port(request);
    const std::string avrdude = find_in_path(request.avrdude, path_env);
    if (avrdude.empty()) {
        throw DeviceError(request.avrdude,
                          "avrdude not found in PATH; install it (Debian package avrdude, "
                          "scripts/setup.sh installs it)");
    }

    FlashRequest resolved = request;
    resolved.avrdude = avrdude;
    const std::vector<std::string> args = avrdude_arguments(resolved);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);

    const pid_t pid = ::fork();
    if (pid < 0) throw DeviceError(avrdude, std::string("cannot start: ") + std::strerror(errno));
    if (pid == 0) {
        ::execv(avrdude.c_str(), argv.data());
        ::_exit(127);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) throw DeviceError(avrdude, std::string("lost the child: ") + std::strerror(errno));
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
    const std::string how = WIFEXITED(status) ? "exited with status " + std::to_string(WEXITSTATUS(status))
                                              : "was killed by signal " + std::to_string(WTERMSIG(status));
    throw DeviceError(request.port, "avrdude " + how +
                                        " (wrong --programmer/--baud for this bootloader, or the board did not "
                                        "reset into it; see its output above)");
}

}  // namespace driftlab::host::io
