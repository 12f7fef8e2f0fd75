// Every option that takes a value, of every command, read from the command's own --help (so that an option added
// later is swept too), given values that break numbers, paths and names. Each run must end as README.md promises: an
// exit code of 0, 2 (usage), 3 (data), 4 (device) or 5 (configuration), never a signal; every refusal worded
// "driftlab: error: ", a usage error naming the option, and none in the parser library's own words ("Could not
// convert"), which had been how "3.5", "x" or "" met several options.
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

// The options of `command` that take a value, each with its names ("--from", "--t-min"), from its --help.
std::vector<std::vector<std::string>> value_options(const std::string& command, const TempDir& dir) {
    const RunResult help = run_driftlab({command, "--help"}, dir.path());
    EXPECT_EQ(help.exit_code, 0) << help.output;
    // "  --from,--t-min FLOAT ..." or "  -o,--output TEXT REQUIRED": names, then the value's type in capitals.
    static const std::regex line(R"(^\s+((?:-[a-zA-Z],)?--[a-z0-9-]+(?:,--[a-z0-9-]+)*) [A-Z]+\b)");
    std::vector<std::vector<std::string>> out;
    std::istringstream in(help.output);
    for (std::string text; std::getline(in, text);) {
        std::smatch m;
        if (!std::regex_search(text, m, line)) continue;
        std::vector<std::string> names;
        std::istringstream list(m[1].str());
        for (std::string name; std::getline(list, name, ',');) names.push_back(name);
        out.push_back(names);
    }
    return out;
}

TEST(CliSweep, EveryValueOptionEndsWithADocumentedExitAndItsOwnWords) {
    TempDir dir("clisweep");
    // Each command with what it needs to get past the parser and then stop at once: an input that does not exist
    // (exit 3), a port that does not exist (exit 4), a plot folder that cannot be made (exit 4), or a 10 s simulation.
    const std::map<std::string, std::vector<std::string>> base = {
        {"fit", {"x.csv"}},
        {"whiteness", {"x.csv"}},
        {"report", {"x.csv", "-o", dir.file("r.html")}},
        {"allan", {"x.csv"}},
        {"gap", {"x.csv"}},
        {"hil", {"-o", dir.file("h.csv"), "--duration", "10"}},
        {"decode", {"x.cap", "-o", dir.file("d.csv")}},
        {"record", {"--port", dir.file("no-such-port"), "-o", dir.file("rec.csv")}},
        {"flash", {"--dry-run", "--port", "/dev/null", "--hex", dir.file("no.hex")}},
        {"gap-eval", {"--quick", "--plot", "/proc/driftlab-no-folder"}},
    };
    const std::vector<std::string> values = {"3.5", "x", "-1", "nan", "1e400", ""};
    const std::regex parser_words("Could not convert|At Most|not expected|is required|ValidationError|terminate");
    std::size_t options = 0, past_the_parser = 0, refused = 0;
    for (const auto& [command, args] : base) {
        for (const std::vector<std::string>& names : value_options(command, dir)) {
            bool in_base = false;
            for (const std::string& n : names)
                for (const std::string& a : args) in_base = in_base || n == a;
            if (in_base) continue;
            ++options;
            for (const std::string& value : values) {
                std::vector<std::string> run = {command};
                run.insert(run.end(), args.begin(), args.end());
                run.insert(run.end(), {names.back(), value});
                const RunResult r = run_driftlab(run, dir.path());
                const std::string what = command + " " + names.back() + " '" + value + "': ";
                EXPECT_TRUE(r.exit_code == 0 || (r.exit_code >= 2 && r.exit_code <= 5))
                    << what << r.exit_code << " " << r.output;
                EXPECT_FALSE(std::regex_search(r.output, parser_words)) << what << r.output;
                if (r.exit_code != 0) {
                    EXPECT_NE(r.output.find("driftlab: error: "), std::string::npos) << what << r.output;
                }
                if (r.exit_code == 2) {
                    ++refused;
                    bool named = false;
                    for (const std::string& n : names) named = named || r.output.find(n) != std::string::npos;
                    EXPECT_TRUE(named) << what << r.output;
                } else {
                    ++past_the_parser;
                }
            }
        }
    }
    // Every command's options were found, and the sweep saw both outcomes: it passes neither by refusing every value
    // nor by reading none. Today about 90 options, 150 runs past the parser and 380 refused.
    EXPECT_GE(options, 60u);
    EXPECT_GE(past_the_parser, 50u);
    EXPECT_GE(refused, 200u);
}

}  // namespace
}  // namespace driftlab::e2e
