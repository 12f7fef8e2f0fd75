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

TEST(ExitCodes, ParserRefusalsAreUsageErrors) {
    TempDir dir("exitcodes");
    const RunResult unknown = run_driftlab({"gap", "x.csv", "--no-such-flag"}, dir.path());
    EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("--no-such-flag"), std::string::npos) << unknown.output;
    // Worded as every other error, and naming the help of the command it was given to.
    EXPECT_EQ(unknown.output.rfind("driftlab: error: ", 0), 0u) << unknown.output;
    EXPECT_NE(unknown.output.find("driftlab gap --help"), std::string::npos) << unknown.output;
    const RunResult invalid = run_driftlab({"gap", "x.csv", "--tau0", "-1"}, dir.path());  // a validator's refusal
    EXPECT_EQ(invalid.exit_code, 2) << invalid.output;
    EXPECT_NE(invalid.output.find("--tau0: expected a number > 0, got '-1'"), std::string::npos) << invalid.output;
    // hil --duration nan had run until the disk filled, inf wrote no row.
    for (const std::string bad : {"nan", "inf", "0"}) {
        const RunResult duration = run_driftlab({"hil", "--duration", bad, "-o", dir.file("h.csv")}, dir.path());
        EXPECT_EQ(duration.exit_code, 2) << bad << ": " << duration.output;
        EXPECT_NE(duration.output.find("--duration: expected a number > 0, got '" + bad + "'"), std::string::npos)
            << duration.output;
    }
    // A time bound of nan compared false with every time and cut nothing.
    for (const char* bound : {"--t-min", "--t-max"}) {
        const RunResult nan = run_driftlab({"fit", "x.csv", bound, "nan"}, dir.path());
        EXPECT_EQ(nan.exit_code, 2) << bound << ": " << nan.output;
        EXPECT_NE(nan.output.find("expected a finite number, got 'nan'"), std::string::npos) << nan.output;
    }
    // record --duration nan recorded until Ctrl-C.
    const RunResult record =
        run_driftlab({"record", "--port", "/dev/null", "--duration", "nan", "-o", dir.file("r.csv")}, dir.path());
    EXPECT_EQ(record.exit_code, 2) << record.output;
    EXPECT_NE(record.output.find("--duration: expected a number >= 0, got 'nan'"), std::string::npos) << record.output;
    // gap: "nan" had passed --fit-fraction's range (and --from's order check) to be refused later with the wrong
    // range; an empty --report had meant no report; sizes beyond 16 x a_50 swamp the log; a size twice was one row.
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"gap", "x.csv", "--from", "nan"}, {"gap", "x.csv", "--to", "inf"}}) {
        const RunResult r = run_driftlab(args, dir.path());
        EXPECT_EQ(r.exit_code, 2) << args[2] << ": " << r.output;
        EXPECT_NE(r.output.find("expected a finite number, got '" + args[3] + "'"), std::string::npos) << r.output;
    }
    // record and flash: a CONFIG field or a rate that is not a whole number in range had been a failed conversion in
    // the parser's words, or a check of record's own words; flash --dry-run had printed `-b -1`. Each is refused as
    // hil's are.
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"--conversions", "3.5",
                                   "--conversions: expected a whole number in [1, 64], got '3.5'"},
          {"--window", "65", "--window: expected a whole number in [1, 64], got '65'"},
          {"--order", "x", "--order: expected a whole number in [0, 1], got 'x'"},
          {"--baud", "3.5", "--baud: expected a standard rate [bit/s] (e.g. 9600, 57600, 115200), got '3.5'"},
          {"--baud", "12345", "--baud: expected a standard rate [bit/s] (e.g. 9600, 57600, 115200), got '12345'"}}) {
        const RunResult r =
            run_driftlab({"record", "--port", "/dev/null", "-o", dir.file("r.csv"), args[0], args[1]}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << args[0] << ": " << r.output;
        EXPECT_NE(r.output.find(args[2]), std::string::npos) << r.output;
    }
    for (const char* baud : {"-1", "0"}) {
        const RunResult r = run_driftlab({"flash", "--dry-run", "--port", "/dev/null", "--baud", baud}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << baud << ": " << r.output;
        EXPECT_EQ(r.output.find("avrdude"), std::string::npos) << r.output;
    }
    const RunResult sequences = run_driftlab({"whiteness", "x.csv", "--sequences", "1e-9"}, dir.path());
    EXPECT_EQ(sequences.exit_code, 2) << sequences.output;
    EXPECT_NE(sequences.output.find("--sequences: expected a whole number in [1, 1000000], got '1e-9'"),
              std::string::npos)
        << sequences.output;
    // A reversed or empty time range: gap and allan had refused it only once the log was read, fit, whiteness and
    // report as a "0 samples" error per channel (exit 3). x.csv does not exist, so exit 2 shows that nothing was read.
    // Every one of them takes both spellings (gap had not known --t-min/--t-max).
    for (const char* command : {"fit", "whiteness", "report", "allan", "gap"})
        for (const std::vector<std::string>& range : {std::vector<std::string>{"--from", "50", "--to", "40"},
                                                      {"--to", "40", "--from", "50"},
                                                      {"--from", "50", "--to", "50"},
                                                      {"--t-min", "50", "--t-max", "40"}}) {
            std::vector<std::string> args = {command, "x.csv"};
            args.insert(args.end(), range.begin(), range.end());
            const RunResult r = run_driftlab(args, dir.path());
            EXPECT_EQ(r.exit_code, 2) << command << " " << range[0] << ": " << r.output;
            EXPECT_NE(r.output.find("driftlab: error: --from must be before --to"), std::string::npos)
                << command << ": " << r.output;
        }
    const RunResult fraction = run_driftlab({"gap", "x.csv", "--fit-fraction", "nan"}, dir.path());
    EXPECT_EQ(fraction.exit_code, 2) << fraction.output;
    EXPECT_NE(fraction.output.find("--fit-fraction: expected a number in [0.3, 0.85], got 'nan'"), std::string::npos)
        << fraction.output;
    // An empty path had meant the default or nothing, without a word: --model the paper's unit, hil -o out/fig3.csv,
    // --plot no plots, --capture LOG.cap, --report no report; an empty input file had been refused as ": cannot open".
    // Each path option and input, as the command line is read (x.csv does not exist).
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
        const RunResult empty = run_driftlab(empty_path, dir.path());
        EXPECT_EQ(empty.exit_code, 2) << args[0] << " " << args.back() << ": " << empty.output;
        EXPECT_NE(empty.output.find("driftlab: error: " + args.back() + ": expected a path, got ''"), std::string::npos)
            << args[0] << ": " << empty.output;
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
        const RunResult empty = run_driftlab(run, dir.path());
        EXPECT_EQ(empty.exit_code, 2) << args[0] << ": " << empty.output;
        EXPECT_NE(empty.output.find("driftlab: error: " + args[2] + ": expected a path, got ''"), std::string::npos)
            << empty.output;
    }
    for (const auto& [id, what] :
         {std::pair<std::string, std::string>{"--programmer", "programmer"}, {"--part", "part"}}) {
        const RunResult r = run_driftlab({"flash", "--dry-run", id, ""}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find(id + ": expected an avrdude " + what + " id, got ''"), std::string::npos) << r.output;
    }
    const RunResult column = run_driftlab({"fit", "x.csv", "--time-column", ""}, dir.path());
    EXPECT_EQ(column.exit_code, 2) << column.output;
    EXPECT_NE(column.output.find("--time-column: expected a column name, got ''"), std::string::npos) << column.output;
    // allan --kind on a log: only "rate" had been checked, so "" passed for no kind at all.
    for (const char* kind : {"", "ratee"}) {
        const RunResult r = run_driftlab({"allan", "x.csv", "--kind", kind}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find(std::string("--kind: expected rate or phase, got '") + kind + "'"), std::string::npos)
            << r.output;
    }
    // gap-eval: "" had named the out-of-library generator, whose effect is none.
    const RunResult no_effect = run_driftlab({"gap-eval", "--quick", "--effects", ""}, dir.path());
    EXPECT_EQ(no_effect.exit_code, 2) << no_effect.output;
    EXPECT_NE(no_effect.output.find("--effects: unknown generator or effect ''"), std::string::npos)
        << no_effect.output;
    // hil --period: text had failed in the parser's words, and an empty value had meant the preset's period.
    for (const char* period : {"x", ""}) {
        const RunResult r = run_driftlab({"hil", "-o", dir.file("h.csv"), "--period", period}, dir.path());
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find(std::string("--period: expected a number > 0, got '") + period + "'"),
                  std::string::npos)
            << r.output;
    }
    const RunResult huge = run_driftlab({"gap-eval", "--quick", "--levels", "1000"}, dir.path());
    EXPECT_EQ(huge.exit_code, 2) << huge.output;
    EXPECT_NE(huge.output.find("--levels: expected a number in (0, 16], got '1000'"), std::string::npos) << huge.output;
    // An integer option names a fraction as outside its range, not as a failed conversion.
    const RunResult fraction_of_window = run_driftlab({"hil", "--window", "3.5", "-o", dir.file("h.csv")}, dir.path());
    EXPECT_EQ(fraction_of_window.exit_code, 2) << fraction_of_window.output;
    EXPECT_NE(fraction_of_window.output.find("--window: expected a whole number in [1, 64], got '3.5'"),
              std::string::npos)
        << fraction_of_window.output;
    const RunResult twice = run_driftlab({"gap-eval", "--quick", "--levels", "2,2"}, dir.path());
    EXPECT_EQ(twice.exit_code, 2) << twice.output;
    EXPECT_NE(twice.output.find("--levels: 2 is given twice"), std::string::npos) << twice.output;
    // A folder given as the input had read as an empty file.
    for (const char* command : {"gap", "fit", "allan"}) {
        const RunResult folder = run_driftlab({command, dir.path().string()}, dir.path());
        EXPECT_EQ(folder.exit_code, 3) << command << ": " << folder.output;
        EXPECT_NE(folder.output.find(dir.path().string() + ": is a folder, not a file"), std::string::npos)
            << folder.output;
    }
    // An empty file had been refused as a plain table without --tau0 and --as (gap) or --kind (allan): exit 2,
    // asking for options that would not have helped.
    const std::string empty = dir.file("empty.csv"), blank = dir.file("blank.csv");
    std::ofstream{empty};
    std::ofstream{blank} << "\n  \n\t\n";
    for (const std::string& file : {empty, blank})
        for (const char* command : {"gap", "fit", "allan"}) {
            const RunResult r = run_driftlab({command, file}, dir.path());
            EXPECT_EQ(r.exit_code, 3) << command << ": " << r.output;
            EXPECT_NE(r.output.find(file + ": empty file"), std::string::npos) << command << ": " << r.output;
        }
    EXPECT_EQ(run_driftlab({"gap"}, dir.path()).exit_code, 2);  // a required argument missing
    EXPECT_EQ(run_driftlab({}, dir.path()).exit_code, 2);       // no command
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
