// --drop-cut-line: every command that reads a driftlab log reads one whose writer was killed mid-line without the cut
// last row, says which line it left out, and gives what it gives for the same log with that line deleted by hand.
// Without the option such a log is refused, naming the option; a plain table, which is read whole, is refused it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

/// `driftlab ARGS --json`: the run (its output is the error output, where the notes go) and the document without
/// its "file" key, so that the results of two files compare.
struct JsonRun {
    RunResult run;
    nlohmann::json doc;
};

JsonRun run_json(std::vector<std::string> args, const TempDir& dir, const std::string& name) {
    args.push_back("--json");
    const std::string out = dir.file(name);
    JsonRun r{run_driftlab_stdout_to(args, out, dir.path()), {}};
    if (r.run.exit_code == 0) {
        r.doc = nlohmann::json::parse(read_text(out));
        r.doc.erase("file");
    }
    return r;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

TEST(CutLineCli, EveryLogReaderLeavesOutTheCutRowOnRequestAndSaysWhichLine) {
    TempDir dir("cutline");
    const std::string cut = dir.file("cut.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "600", "--seed", "5", "-o", cut}, dir.path()).exit_code, 0);
    // The same log with its last line deleted by hand: what reading the cut one without that line must give.
    const std::string by_hand = dir.file("by_hand.csv");
    {
        std::string text = read_text(cut);
        text.pop_back();
        text.erase(text.rfind('\n') + 1);
        std::ofstream(by_hand, std::ios::binary) << text;
    }
    const std::string line = cut_last_row(cut);
    const std::string note =
        "note: " + cut + ":" + line + ": the last line, cut without a newline, was left out (--drop-cut-line)";
    const std::string any_such_note = "was left out (--drop-cut-line)";

    const std::vector<std::vector<std::string>> commands = {
        {"fit"}, {"whiteness"}, {"allan"}, {"gap", "--locate-only", "--replicates", "10"}};
    for (const auto& command : commands) {
        const std::vector<std::string> options(command.begin() + 1, command.end());
        const std::vector<std::string> on_cut = with({command[0], cut}, options);
        const RunResult refused = run_driftlab(on_cut, dir.path());
        EXPECT_EQ(refused.exit_code, 3) << command[0] << ": " << refused.output;
        EXPECT_NE(refused.output.find(cut + ":" + line + ": truncated last line"), std::string::npos) << refused.output;
        EXPECT_NE(refused.output.find("--drop-cut-line reads the rest without it"), std::string::npos)
            << refused.output;

        const RunResult text = run_driftlab(with(on_cut, {"--drop-cut-line"}), dir.path());
        EXPECT_EQ(text.exit_code, 0) << command[0] << ": " << text.output;
        EXPECT_NE(text.output.find(note), std::string::npos) << command[0] << ": " << text.output;

        const JsonRun dropped = run_json(with(on_cut, {"--drop-cut-line"}), dir, "dropped.json");
        const JsonRun hand = run_json(with({command[0], by_hand}, options), dir, "hand.json");
        ASSERT_EQ(dropped.run.exit_code, 0) << command[0] << ": " << dropped.run.output;
        ASSERT_EQ(hand.run.exit_code, 0) << command[0] << ": " << hand.run.output;
        EXPECT_NE(dropped.run.output.find(note), std::string::npos) << command[0] << ": " << dropped.run.output;
        EXPECT_EQ(hand.run.output.find(any_such_note), std::string::npos) << command[0] << ": " << hand.run.output;
        EXPECT_EQ(dropped.doc, hand.doc) << command[0];
    }

    // The reports a person reads later say it too.
    const std::string html = dir.file("r.html");
    const RunResult report = run_driftlab({"report", cut, "-o", html, "--no-plots", "--drop-cut-line"}, dir.path());
    ASSERT_EQ(report.exit_code, 0) << report.output;
    EXPECT_NE(read_text(html).find("<p>Note: " + note.substr(6) + "; its row is not analysed</p>"), std::string::npos);
    const RunResult gap_report = run_driftlab(
        {"gap", cut, "--locate-only", "--replicates", "10", "--drop-cut-line", "--report", dir.file("rep")},
        dir.path());
    ASSERT_EQ(gap_report.exit_code, 0) << gap_report.output;
    EXPECT_NE(read_text(dir.file("rep") + "/gap.md").find("Note: " + note.substr(6)), std::string::npos);
    // gap speaks of the rows it analyses: a window that ends before the cut line has nothing left out to say.
    const RunResult early =
        run_driftlab({"gap", cut, "--locate-only", "--replicates", "10", "--drop-cut-line", "--to", "400"}, dir.path());
    EXPECT_EQ(early.exit_code, 0) << early.output;
    EXPECT_EQ(early.output.find(any_such_note), std::string::npos) << early.output;
    // A note printed before the command fails comes before the error in one output file, as it was printed.
    const RunResult too_short = run_driftlab({"gap", cut, "--drop-cut-line", "--from", "590"}, dir.path());
    EXPECT_EQ(too_short.exit_code, 3) << too_short.output;
    const std::size_t note_at = too_short.output.find(note), error_at = too_short.output.find("driftlab: error: ");
    ASSERT_NE(note_at, std::string::npos) << too_short.output;
    ASSERT_NE(error_at, std::string::npos) << too_short.output;
    EXPECT_LT(note_at, error_at) << too_short.output;
    // A whole log loses nothing and notes nothing.
    const RunResult whole = run_driftlab({"fit", by_hand, "--drop-cut-line"}, dir.path());
    EXPECT_EQ(whole.exit_code, 0) << whole.output;
    EXPECT_EQ(whole.output.find(any_such_note), std::string::npos) << whole.output;
}

TEST(CutLineCli, APlainTableIsRefusedTheOption) {
    TempDir dir("cutlinetable");
    const std::string table = dir.file("t.csv");
    std::ofstream(table) << "t_s,y\n0,1\n1,2\n2,3";  // a table's last line needs no newline: nothing is cut
    for (const char* command : {"fit", "whiteness", "report", "allan", "gap"}) {
        const RunResult r = run_driftlab({command, table, "--drop-cut-line"}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << command << ": " << r.output;
        EXPECT_NE(r.output.find("--drop-cut-line is for driftlab logs; " + table + " is a plain table"),
                  std::string::npos)
            << command << ": " << r.output;
    }
}

}  // namespace
}  // namespace driftlab::e2e
