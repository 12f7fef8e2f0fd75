// Errors that end a host command (docs/style: exceptions for failures, values for results).
// Each names the input location so the user can find it: "log.csv:1274: expected 6 columns, got 5".
// Only host/cli/main.cpp catches these and maps them to exit codes.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace driftlab::host {

/// Base of every command-ending failure. `exit_code()` is what `driftlab` returns for it.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& what) : std::runtime_error(what) {}
    virtual int exit_code() const { return 1; }
};

/// What `driftlab` returns for wrong flags or arguments, its own checks' and the command-line parser's alike.
inline constexpr int kUsageExitCode = 2;

/// Wrong flags or arguments on the command line.
class UsageError : public Error {
public:
    using Error::Error;
    int exit_code() const override { return kUsageExitCode; }
};

/// Malformed or unusable input data. Carries file and line (1-based; 0 when not line-oriented).
class DataError : public Error {
public:
    DataError(const std::string& file, std::uint64_t line, const std::string& what)
        : Error(file + (line ? ":" + std::to_string(line) : std::string()) + ": " + what) {}
    int exit_code() const override { return 3; }
};

/// A device (serial port, USB, programmer) that is missing, refuses or misbehaves.
class DeviceError : public Error {
public:
    DeviceError(const std::string& port, const std::string& what) : Error(port + ": " + what) {}
    static constexpr int kExitCode = 4;
    int exit_code() const override { return kExitCode; }
};

/// A configuration file with a missing, unknown or out-of-range key.
class ConfigError : public Error {
public:
    ConfigError(const std::string& file, const std::string& key, const std::string& what)
        : Error(file + ": " + key + ": " + what) {}
    static constexpr int kExitCode = 5;
    int exit_code() const override { return kExitCode; }
};

/// The board was reconfigured by a request the recorder did not send (an over-the-air CONFIG_SET): the recording
/// stops, its log whole up to the reconfiguration (docs/security.md).
class BoardReconfigured : public Error {
public:
    using Error::Error;
    static constexpr int kExitCode = 6;
    int exit_code() const override { return kExitCode; }
};

/// The user stopped a run that has an end of its own (Ctrl-C, SIGTERM) before it: what it made so far is kept and
/// said; 130 (128 + SIGINT), as a shell reports an interrupted command, so that a script does not go on as if done.
class Interrupted : public Error {
public:
    using Error::Error;
    int exit_code() const override { return 130; }
};

}  // namespace driftlab::host
