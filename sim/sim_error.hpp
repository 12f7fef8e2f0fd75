// Errors that end a simulator run, in the simulator's words. The simulator knows no exit codes: the host maps each
// to its own (host/cli/main.cpp; README "exit codes"). Bad keys inside a model file are sim::ConfigError
// (sim/effects/effect.hpp), which the model-file reader turns into a ModelFileError naming the file.
#pragma once

#include <stdexcept>
#include <string>

namespace driftlab::sim {

/// A model file that cannot be read, or a key of it that is missing, unknown or out of range:
/// "file[:line]: key: what".
class ModelFileError : public std::runtime_error {
public:
    ModelFileError(const std::string& file, const std::string& key, const std::string& what)
        : std::runtime_error(file + ": " + key + ": " + what) {}
};

/// The emulated board stopped answering, or answered what it was not asked: what a faulty real board would be.
class BoardError : public std::runtime_error {
public:
    explicit BoardError(const std::string& what) : std::runtime_error("emulated board: " + what) {}
};

/// The firmware refused the configuration it was asked for: a value the command line gave that it does not take.
class ConfigRefused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace driftlab::sim
