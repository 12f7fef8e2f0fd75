// The exit codes README.md promises, for mistakes the command-line parser catches before any command runs: 2 for
// usage like the commands' own checks, 0 for help and the version, never the parser library's private codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

// Runs `args` and expects `exit_code` with `message` in what it printed.
void expect_refused(const std::vector<std::string>& args, const TempDir& dir, const std::string& message,
                    int exit_code = 2) {
    const RunResult r = run_driftlab(args, dir.path());
    std::string line;
    for (const std::string& a : args) line += a + " ";
    EXPECT_EQ(r.exit_code, exit_code) << line << ": " << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << line << ": " << r.output;
}

TEST(ExitCodes, ParserRefusalsAreUsageErrors) {
    TempDir dir("exitcodes");
    // Worded as every other error, and naming the help of the command it was given to.
    expect_refused({"gap", "x.csv", "--no-such-flag"}, dir, "--no-such-flag");
    const RunResult unknown = run_driftlab({"gap", "x.csv", "--no-such-flag"}, dir.path());
    EXPECT_EQ(unknown.output.rfind("driftlab: error: ", 0), 0u) << unknown.output;
    EXPECT_NE(unknown.output.find("driftlab gap --help"), std::string::npos) << unknown.output;
    expect_refused({"gap", "x.csv", "--tau0", "-1"}, dir, "--tau0: expected a number > 0, got '-1'");  // a validator
    EXPECT_EQ(run_driftlab({"gap"}, dir.path()).exit_code, 2);  // a required argument missing
    EXPECT_EQ(run_driftlab({}, dir.path()).exit_code, 2);       // no command
}

TEST(ExitCodes, NumbersThatAreNotFiniteOrInRangeAreRefused) {
    TempDir dir("exitcodes");
    const std::string h = dir.file("h.csv");
    // hil --duration nan had run until the disk filled, inf wrote no row.
    for (const std::string bad : {"nan", "inf", "0"})
        expect_refused({"hil", "--duration", bad, "-o", h}, dir,
                       "--duration: expected a number > 0, got '" + bad + "'");
    // A time bound of nan compared false with every time and cut nothing.
    for (const char* bound : {"--t-min", "--t-max"})
        expect_refused({"fit", "x.csv", bound, "nan"}, dir, "expected a finite number, got 'nan'");
    // record --duration nan recorded until Ctrl-C.
    expect_refused({"record", "--port", "/dev/null", "--duration", "nan", "-o", dir.file("r.csv")}, dir,
                   "--duration: expected a number >= 0, got 'nan'");
    // gap: "nan" had passed --fit-fraction's range (and --from's order check) to be refused later with the wrong
    // range; sizes beyond 16 x a_50 swamp the log; a size twice was one row.
    expect_refused({"gap", "x.csv", "--from", "nan"}, dir, "expected a finite number, got 'nan'");
    expect_refused({"gap", "x.csv", "--to", "inf"}, dir, "expected a finite number, got 'inf'");
    expect_refused({"gap", "x.csv", "--fit-fraction", "nan"}, dir,
                   "--fit-fraction: expected a number in [0.3, 0.85], got 'nan'");
    expect_refused({"gap-eval", "--quick", "--levels", "1000"}, dir,
                   "--levels: expected a number in (0, 16], got '1000'");
    expect_refused({"gap-eval", "--quick", "--levels", "2,2"}, dir, "--levels: 2 is given twice");
    expect_refused({"whiteness", "x.csv", "--sequences", "1e-9"}, dir,
                   "--sequences: expected a whole number in [1, 1000000], got '1e-9'");
    // hil --period: text had failed in the parser's words, and an empty value had meant the preset's period.
    for (const std::string period : {"x", ""})
        expect_refused({"hil", "-o", h, "--period", period}, dir,
                       "--period: expected a number > 0, got '" + period + "'");
    // An integer option names a fraction as outside its range, not as a failed conversion.
    expect_refused({"hil", "--window", "3.5", "-o", h}, dir, "--window: expected a whole number in [1, 64], got '3.5'");
}

// record and flash: a CONFIG field or a rate that is not a whole number in range had been a failed conversion in the
// parser's words, or a check of record's own words; flash --dry-run had printed `-b -1`. Each is refused as hil's are.
TEST(ExitCodes, RecordAndFlashRefuseFieldsAndRatesOutOfRange) {
    TempDir dir("exitcodes");
    const std::string baud = "--baud: expected a standard rate [bit/s] (e.g. 9600, 57600, 115200), got '";
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"--conversions", "3.5",
                                   "--conversions: expected a whole number in [1, 64], got '3.5'"},
          {"--window", "65", "--window: expected a whole number in [1, 64], got '65'"},
          {"--order", "x", "--order: expected a whole number in [0, 1], got 'x'"},
          {"--baud", "3.5", baud + "3.5'"},
          {"--baud", "12345", baud + "12345'"}})
        expect_refused({"record", "--port", "/dev/null", "-o", dir.file("r.csv"), args[0], args[1]}, dir, args[2]);
    for (const char* rate : {"-1", "0"}) {
        const RunResult r = run_driftlab({"flash", "--dry-run", "--port", "/dev/null", "--baud", rate}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << rate << ": " << r.output;
        EXPECT_EQ(r.output.find("avrdude"), std::string::npos) << r.output;
    }
}

// A reversed or empty time range: gap and allan had refused it only once the log was read, fit, whiteness and report
// as a "0 samples" error per channel (exit 3). x.csv does not exist, so exit 2 shows that nothing was read. Every one
// of them takes both spellings (gap had not known --t-min/--t-max).
TEST(ExitCodes, AReversedTimeRangeIsRefusedBeforeTheLogIsRead) {
    TempDir dir("exitcodes");
    for (const char* command : {"fit", "whiteness", "report", "allan", "gap"})
        for (const std::vector<std::string>& range : {std::vector<std::string>{"--from", "50", "--to", "40"},
                                                      {"--to", "40", "--from", "50"},
                                                      {"--from", "50", "--to", "50"},
                                                      {"--t-min", "50", "--t-max", "40"}}) {
            std::vector<std::string> args = {command, "x.csv"};
            args.insert(args.end(), range.begin(), range.end());
            expect_refused(args, dir, "driftlab: error: --from must be before --to");
        }
}

// An empty path had meant the default or nothing, without a word: --model the paper's unit, hil -o out/fig3.csv,
// --plot no plots, --capture LOG.cap, --report no report; an empty input file had been refused as ": cannot open".
// Each path option and input, as the command line is read (x.csv does not exist).
TEST(ExitCodes, AnEmptyPathOrNameIsRefused) {
    TempDir dir("exitcodes");
    const std::string h = dir.file("h.csv");
    for (const std::vector<std::string>& args : {std::vector<std::string>{"gap", "x.csv", "--report"},
                                                 {"gap", "x.csv", "--model-out"},
                                                 {"gap", "x.csv", "--model"},
                                                 {"hil", "-o", h, "--model"},
                                                 {"hil", "--output"},
                                                 {"hil", "--pty", "--pty-link"},
                                                 {"hil", "-o", h, "--target", "avr", "--elf"},
                                                 {"fit", "x.csv", "--plot"},
                                                 {"whiteness", "x.csv", "--plot"},
                                                 {"allan", "x.csv", "--plot"},
                                                 {"report", "x.csv", "--output"},
                                                 {"record", "--port", "/dev/null", "-o", h, "--capture"},
                                                 {"record", "-o", h, "--port"},
                                                 {"record", "--port", "/dev/null", "--output"},
                                                 {"decode", "x.cap", "--output"},
                                                 {"flash", "--dry-run", "--hex"},
                                                 {"flash", "--dry-run", "--port"},
                                                 {"flash", "--dry-run", "--avrdude"},
                                                 {"gap-eval", "--quick", "--plot"}}) {
        std::vector<std::string> empty_path = args;
        empty_path.push_back("");
        expect_refused(empty_path, dir, "driftlab: error: " + args.back() + ": expected a path, got ''");
    }
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << "hil -o '' wrote its default log";
    for (const std::vector<std::string>& args : {std::vector<std::string>{"fit", "", "log"},
                                                 {"whiteness", "", "log"},
                                                 {"report", "", "log"},
                                                 {"allan", "", "file"},
                                                 {"gap", "", "file"},
                                                 {"decode", "", "capture"}}) {
        std::vector<std::string> run = {args[0], args[1]};
        if (args[0] == "decode") run.insert(run.end(), {"-o", dir.file("d.csv")});
        expect_refused(run, dir, "driftlab: error: " + args[2] + ": expected a path, got ''");
    }
    for (const std::string what : {"programmer", "part"})
        expect_refused({"flash", "--dry-run", "--" + what, ""}, dir,
                       "--" + what + ": expected an avrdude " + what + " id, got ''");
    expect_refused({"fit", "x.csv", "--time-column", ""}, dir, "--time-column: expected a column name, got ''");
    // allan --kind on a log: only "rate" had been checked, so "" passed for no kind at all.
    for (const std::string kind : {"", "ratee"})
        expect_refused({"allan", "x.csv", "--kind", kind}, dir, "--kind: expected rate or phase, got '" + kind + "'");
    // gap-eval: "" had named the out-of-library generator, whose effect is none.
    expect_refused({"gap-eval", "--quick", "--effects", ""}, dir, "--effects: unknown generator or effect ''");
}

// A folder given as the input had read as an empty file; an empty file had been refused as a plain table without
// --tau0 and --as (gap) or --kind (allan): exit 2, asking for options that would not have helped.
TEST(ExitCodes, AFolderOrAnEmptyFileAsInputIsADataError) {
    TempDir dir("exitcodes");
    const std::string empty = dir.file("empty.csv"), blank = dir.file("blank.csv");
    std::ofstream{empty};
    std::ofstream{blank} << "\n  \n\t\n";
    for (const char* command : {"gap", "fit", "allan"}) {
        expect_refused({command, dir.path().string()}, dir, dir.path().string() + ": is a folder, not a file", 3);
        for (const std::string& file : {empty, blank}) expect_refused({command, file}, dir, file + ": empty file", 3);
    }
}

// `decode cap -o cap` had replaced the capture, the only byte-for-byte record, with its log; `report`, `hil` and
// `gap` could likewise write over the log or model file they read. Each is refused before anything is written,
// whatever spelling names the file.
TEST(ExitCodes, NoCommandWritesOverTheFileItReads) {
    TempDir dir("overwrite");
    const std::string input = dir.file("in.csv");
    {
        std::ofstream out(input, std::ios::binary);
        out << "t_s y\n0 1\n1 2\n";
    }
    const std::string other_spelling = (dir.path() / "." / "in.csv").string();
    const std::vector<std::vector<std::string>> runs = {
        {"decode", input, "-o", other_spelling},
        {"report", input, "-o", input},
        {"hil", "--model", input, "-o", other_spelling},
        {"gap", input, "--tau0", "1", "--model-out", input},
    };
    for (const auto& args : runs) {
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.output;
        EXPECT_NE(r.output.find("writing there would destroy it"), std::string::npos) << args[0] << ": " << r.output;
        EXPECT_EQ(read_text(input), "t_s y\n0 1\n1 2\n") << args[0];
    }
}

// flash --dry-run had skipped every check and printed `-U flash:w::i` with exit 0 when no image existed: it now checks
// the image (exit 3) and the port (exit 4) first, and quotes a path the shell would split.
TEST(ExitCodes, FlashDryRunChecksTheImageAndThePortFirst) {
    TempDir dir("exitflash");
    const RunResult no_image =
        run_driftlab({"flash", "--port", "/dev/null", "--hex", dir.file("none.hex"), "--dry-run"}, dir.path());
    EXPECT_EQ(no_image.exit_code, 3) << no_image.output;
    EXPECT_NE(no_image.output.find("none.hex: firmware image not found"), std::string::npos) << no_image.output;
    const std::string hex = dir.file("my fw.hex");
    std::ofstream(hex) << ":00000001FF\n";
    const RunResult no_port =
        run_driftlab({"flash", "--port", dir.file("ttyNONE"), "--hex", hex, "--dry-run"}, dir.path());
    EXPECT_EQ(no_port.exit_code, 4) << no_port.output;
    const RunResult dry = run_driftlab({"flash", "--port", "/dev/null", "--hex", hex, "--dry-run"}, dir.path());
    EXPECT_EQ(dry.exit_code, 0) << dry.output;
    EXPECT_NE(dry.output.find("-P /dev/null -b 115200 -D -U 'flash:w:" + hex + ":i'"), std::string::npos) << dry.output;
}

// `flash` from a copy of the binary outside its build tree had named a firmware image derived from wherever the copy
// lay (/tmp/x/driftlab: "/avr/firmware/driftlab_fw.hex: firmware image not found"); it now says why there is no
// default image and names --hex (exit 3), before any port or avrdude is looked at.
TEST(ExitCodes, FlashFromACopiedBinaryNamesHexInsteadOfADerivedPath) {
    TempDir dir("exitflashcopy");
    std::filesystem::create_directories(dir.file("x"));
    const std::string copy = dir.file("x/driftlab");
    std::error_code ec;
    // The binary is large; a link where the file system allows
    std::filesystem::create_hard_link(DRIFTLAB_BIN, copy, ec);
    if (ec) std::filesystem::copy_file(DRIFTLAB_BIN, copy);
    const std::string out = dir.file("flash.out");
    const RunResult r = wait_child(spawn_program(copy, {"flash", "--port", "/dev/null", "--dry-run"}, out), out);
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(
        r.output.find("driftlab_fw.hex: no default firmware image: it is looked for beside a build tree's driftlab "
                      "(build/<preset>/bin/driftlab), and " +
                      copy + " is not one (a copy, or installed); pass --hex FILE"),
        std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("/avr/firmware/"), std::string::npos) << r.output;
}

TEST(ExitCodes, HelpAndVersionSucceed) {
    TempDir dir("exithelp");
    const RunResult help = run_driftlab({"gap", "--help"}, dir.path());
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--exclude-saturated"), std::string::npos) << help.output;
    EXPECT_EQ(run_driftlab({"--version"}, dir.path()).exit_code, 0);
}

// A result that could not be written (a full disk) must not pass for written: gap --json > /dev/full had exited 0.
TEST(ExitCodes, AStandardOutputThatCannotBeWrittenIsADeviceError) {
    TempDir dir("exitfull");
    const RunResult full = run_driftlab_stdout_to({"effects"}, "/dev/full", dir.path());
    EXPECT_EQ(full.exit_code, 4) << full.output;
    EXPECT_NE(full.output.find("driftlab: error: writing the standard output: "), std::string::npos) << full.output;
    EXPECT_EQ(run_driftlab_stdout_to({"effects"}, "/dev/null", dir.path()).exit_code, 0);
}

// report -o into folders that do not exist yet makes them, as --plot does; one that cannot be made exits 4.
TEST(ExitCodes, ReportMakesItsFolderOrSaysItCannot) {
    TempDir dir("exitreport");
    const std::string log = dir.file("h.csv");
    ASSERT_EQ(run_driftlab({"hil", "--duration", "300", "-o", log}, dir.path()).exit_code, 0);
    const std::string nested = dir.file("new/sub/r.html");
    const RunResult made = run_driftlab({"report", log, "-o", nested, "--no-plots"}, dir.path());
    EXPECT_EQ(made.exit_code, 0) << made.output;
    EXPECT_TRUE(std::filesystem::is_regular_file(nested));
    const RunResult blocked = run_driftlab({"report", log, "-o", log + "/r.html", "--no-plots"}, dir.path());
    EXPECT_EQ(blocked.exit_code, 4) << blocked.output;
}

}  // namespace
}  // namespace driftlab::e2e
