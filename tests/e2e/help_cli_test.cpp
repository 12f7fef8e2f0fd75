// Every command's --help reads as a user's page: an option's type and its range as one phrase ("FLOAT > 0",
// "INT in [1, 64]"), not CLI11's joined check names ("FLOAT:POSITIVE", "FLOAT:NUMBER:FLOAT in [0.3 - 0.85]").
#include <gtest/gtest.h>

#include <regex>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

// The subcommands `driftlab --help` lists: the real table, so that a command added later is checked too.
std::vector<std::string> listed_subcommands(const std::string& help) {
    std::vector<std::string> names;
    bool in_list = false;
    for (const std::string& line : lines_of(help)) {
        if (line.rfind("Subcommands:", 0) == 0) {
            in_list = true;
        } else if (in_list && line.rfind("  ", 0) == 0) {
            names.push_back(line.substr(2, line.find(' ', 2) - 2));
        } else if (in_list && !line.empty()) {
            in_list = false;
        }
    }
    return names;
}

TEST(HelpCli, NoCommandsHelpShowsTheParsersCheckNames) {
    TempDir dir("help");
    const RunResult top = run_driftlab({"--help"}, dir.path());
    ASSERT_EQ(top.exit_code, 0) << top.output;
    const std::vector<std::string> commands = listed_subcommands(top.output);
    ASSERT_GE(commands.size(), 12u) << top.output;
    // A type joined to a check by ':' (FLOAT:POSITIVE, TEXT:PATH, UINT:SEED), and CLI::Range's "[0 - 16]".
    const std::regex joined(R"(\b(TEXT|INT|UINT|FLOAT):)");
    const std::regex dash_range(R"(\[[^\]\n]* - [^\]\n]*\])");
    std::string every_help;
    for (const std::string& command : commands) {
        const RunResult help = run_driftlab({command, "--help"}, dir.path());
        EXPECT_EQ(help.exit_code, 0) << command << ": " << help.output;
        EXPECT_FALSE(std::regex_search(help.output, joined)) << command << ": " << help.output;
        EXPECT_FALSE(std::regex_search(help.output, dash_range)) << command << ": " << help.output;
        every_help += help.output;
    }
    // The ranges are still shown, as one phrase with the type.
    for (const char* phrase : {"--tau0 FLOAT > 0", "--warm FLOAT >= 0", "--fit-fraction FLOAT in [0.3, 0.85]",
                               "--levels FLOAT in (0, 16]", "--window INT in [1, 64]"}) {
        EXPECT_NE(every_help.find(phrase), std::string::npos) << phrase;
    }
}

}  // namespace
}  // namespace driftlab::e2e
