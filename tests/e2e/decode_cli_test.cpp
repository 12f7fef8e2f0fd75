// `driftlab decode` on captures written here record by record, so every byte offset a summary names is known:
// `--json` (the summary as one object on standard output) and `--strict` (exit 3 when bytes were not decoded).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "driftlab/proto/encoder.hpp"
#include "driftlab/proto/wire.hpp"
#include "e2e_support.hpp"
#include "host/io/capture.hpp"
#include "host/log/log_reader.hpp"

namespace driftlab::e2e {
namespace {

constexpr int kSamples = 10;
constexpr int kBadCrcSample = 3;   // its frame's last byte (the CRC's) flipped
constexpr int kGarbageBefore = 7;  // damage inserted in front of this sample's record
constexpr std::size_t kGarbageBytes = 7;

/// Where the damage in a capture made by write_capture() lies.
struct Layout {
    std::uint64_t bad_crc_record = 0;  ///< byte offset of the record holding the failing frame
    std::uint64_t garbage = 0;         ///< byte offset of the inserted bytes
    std::uint64_t cut_record = 0;      ///< byte offset of the last record, cut short
};

/// A recording as the recorder captures it: VERSION and CONFIG received, the start event, then kSamples SAMPLEs of
/// a board at mid-scale, one record each. With `damaged`: the frame of sample kBadCrcSample fails its CRC,
/// kGarbageBytes of 0xff stand in front of sample kGarbageBefore's record, and one more SAMPLE record is cut.
/// A `capture_name` goes into the header as record writes it, the capture's file name, which decode puts in the log.
Layout write_capture(const std::string& path, bool damaged, const std::string& capture_name = "") {
    Layout at;
    std::vector<std::uint64_t> sample_offsets;
    std::uint16_t seq = 0;
    {
        host::io::CaptureHeader header = {{"port", "/dev/pts/3"}, {"baud", "115200"}};
        if (!capture_name.empty()) header.emplace_back("capture", capture_name);
        host::io::CaptureWriter w(path, header);
        std::uint8_t buf[64];
        const auto receive = [&](std::size_t n) {
            ASSERT_GT(n, 0u);
            w.write(host::io::CaptureKind::rx, buf, n);
        };
        proto::VersionPayload v{};
        v.proto_version = proto::kProtocolVersion;
        v.adc_bits = 10;
        v.vref_mv = 5000;
        v.tick_hz = 250000;
        v.channel_count = kChannelCount;
        receive(proto::encode_version(v, seq++, buf, sizeof buf));
        const proto::ConfigPayload c{100, 8, 8, 0, static_cast<std::uint8_t>(proto::OutputMode::stream), 0};
        receive(proto::encode_config(c, seq++, buf, sizeof buf));
        w.write_event("start");
        for (int k = 0; k < kSamples + (damaged ? 1 : 0); ++k) {
            proto::SamplePayload p{};
            p.tick = 25000u * static_cast<std::uint32_t>(k + 1);
            for (auto& value : p.value_q8) value = 512 * 256;
            p.n_window = 8;
            const std::size_t n = proto::encode_sample(p, seq++, buf, sizeof buf);
            if (damaged && k == kBadCrcSample) buf[n - 1] ^= 0x10;
            sample_offsets.push_back(std::filesystem::file_size(path));
            receive(n);
        }
    }
    if (!damaged) return at;
    std::string bytes = read_text(path);
    at.bad_crc_record = sample_offsets[kBadCrcSample];
    at.garbage = sample_offsets[kGarbageBefore];
    bytes.insert(at.garbage, kGarbageBytes, '\xff');
    at.cut_record = sample_offsets.back() + kGarbageBytes;
    bytes.resize(bytes.size() - 3);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    return at;
}

// Every located damage is in the JSON with its byte offset, beside the counts the text summary gives; the warnings
// stay on standard error, so the standard output is the one document.
TEST(DecodeCli, JsonListsTheCountsAndEveryLocatedDamage) {
    TempDir dir("decodejson");
    const std::string cap = dir.file("d.cap");
    const Layout at = write_capture(cap, true);
    const std::string json_out = dir.file("summary.json");
    std::ofstream(json_out).close();  // standard output is opened there, not created
    const RunResult r =
        run_driftlab_stdout_to({"decode", cap, "-o", dir.file("d.csv"), "--json"}, json_out, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning: " + cap + ": byte offset " + std::to_string(at.cut_record) + ": last record cut"),
              std::string::npos)
        << r.output;
    const auto j = nlohmann::json::parse(read_text(json_out));
    EXPECT_EQ(j["capture"], cap);
    EXPECT_EQ(j["log"], dir.file("d.csv"));
    EXPECT_EQ(j["rows"], kSamples - 1);  // the sample whose CRC failed is lost, the cut one never arrived whole
    EXPECT_EQ(j["frames_lost"], 1);
    EXPECT_EQ(j["crc_errors"], 1);
    EXPECT_EQ(j["crc_failures"],
              nlohmann::json::parse(R"([{"offset": )" + std::to_string(at.bad_crc_record) + R"(, "frames": 1}])"));
    EXPECT_EQ(j["damaged"], nlohmann::json::parse(R"([{"offset": )" + std::to_string(at.garbage) + R"(, "bytes": )" +
                                                  std::to_string(kGarbageBytes) + "}]"));
    EXPECT_EQ(j["truncated_at"], at.cut_record);
    EXPECT_TRUE(j["retimed"].empty());
    EXPECT_TRUE(j["start_read_at"].is_null());
    // Every good row is in the log: t_s = 0.1 s per sample, the failed one's missing.
    const host::LogData log = host::read_log(dir.file("d.csv"));
    std::vector<double> expected_t_s;
    for (int k = 0; k < kSamples; ++k)
        if (k != kBadCrcSample) expected_t_s.push_back(0.1 * (k + 1));
    ASSERT_EQ(log.t_s.size(), expected_t_s.size());
    for (std::size_t i = 0; i < expected_t_s.size(); ++i) EXPECT_NEAR(log.t_s[i], expected_t_s[i], 1e-9) << i;

    // The text summary gives the same counts.
    const RunResult text = run_driftlab({"decode", cap, "-o", dir.file("t.csv")}, dir.path());
    ASSERT_EQ(text.exit_code, 0) << text.output;
    EXPECT_NE(text.output.find("decoded " + std::to_string(kSamples - 1) + " rows to " + dir.file("t.csv") +
                               "; frames " + j["frames_received"].dump() + ", lost 1 ("),
              std::string::npos)
        << text.output;
    EXPECT_EQ(read_text(dir.file("t.csv")), read_text(dir.file("d.csv")));
}

// The log on standard output and the JSON there too would be one unreadable stream: refused before anything runs.
TEST(DecodeCli, JsonWithTheLogOnStandardOutputIsRefused) {
    TempDir dir("decodejsonstdout");
    const std::string cap = dir.file("c.cap");
    write_capture(cap, false);
    const std::string out = dir.file("out.txt");
    std::ofstream(out).close();
    const RunResult r = run_driftlab_stdout_to({"decode", cap, "-o", "-", "--json"}, out, dir.path());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--json: the log goes to standard output (-o -); write it to a file"), std::string::npos)
        << r.output;
    EXPECT_EQ(read_text(out), "");
}

// --strict fails a capture with bytes it could not decode (exit 3, naming each kind), after writing the same log
// as without it; an intact capture passes. Without it the same damage had been a warning with exit 0 only.
TEST(DecodeCli, StrictExitsThreeOnUndecodedBytesAndStillWritesEveryGoodRow) {
    TempDir dir("decodestrict");
    const std::string cap = dir.file("d.cap");
    write_capture(cap, true);
    ASSERT_EQ(run_driftlab({"decode", cap, "-o", dir.file("lenient.csv")}, dir.path()).exit_code, 0);
    const RunResult strict = run_driftlab({"decode", cap, "-o", dir.file("strict.csv"), "--strict"}, dir.path());
    EXPECT_EQ(strict.exit_code, 3) << strict.output;
    EXPECT_NE(strict.output.find(cap + ": --strict: 1 frame failed its CRC check, " + std::to_string(kGarbageBytes) +
                                 " damaged bytes skipped in 1 stretch, the last record is cut (the log holds every "
                                 "good row)"),
              std::string::npos)
        << strict.output;
    EXPECT_NE(strict.output.find("decoded " + std::to_string(kSamples - 1) + " rows"), std::string::npos)
        << strict.output;
    EXPECT_EQ(read_text(dir.file("strict.csv")), read_text(dir.file("lenient.csv")));

    const std::string intact = dir.file("intact.cap");
    write_capture(intact, false);
    const RunResult clean = run_driftlab({"decode", intact, "-o", dir.file("intact.csv"), "--strict"}, dir.path());
    EXPECT_EQ(clean.exit_code, 0) << clean.output;
    EXPECT_EQ(host::read_log(dir.file("intact.csv")).t_s.size(), static_cast<std::size_t>(kSamples));
}

// A log whose writer was killed mid-line is refused (its last value may be cut); when the recording's capture sits
// beside it under record's default name, the refusal names the decode command that gets that row back whole.
TEST(DecodeCli, ACutLogNamesTheCaptureThatRebuildsItsLastRow) {
    TempDir dir("decodecutlog");
    const std::string log = dir.file("rec.csv");
    const std::string cap = log + ".cap";
    write_capture(cap, false);
    ASSERT_EQ(run_driftlab({"decode", cap, "-o", log}, dir.path()).exit_code, 0);
    const std::string last_line = cut_last_row(log);

    const RunResult cut = run_driftlab({"fit", log}, dir.path());
    EXPECT_EQ(cut.exit_code, 3) << cut.output;
    EXPECT_NE(cut.output.find(log + ":" + last_line + ": truncated last line"), std::string::npos) << cut.output;
    const std::string command = "`driftlab decode " + cap + " -o LOG.csv`";
    EXPECT_NE(cut.output.find("--drop-cut-line reads the rest without it, or rebuild the whole log from its capture: " +
                              command),
              std::string::npos)
        << cut.output;

    // The command it names rebuilds every row, the cut one included, where dropping the line keeps one fewer.
    const std::string rebuilt = dir.file("rebuilt.csv");
    ASSERT_EQ(run_driftlab({"decode", cap, "-o", rebuilt}, dir.path()).exit_code, 0);
    EXPECT_EQ(host::read_log(rebuilt).t_s.size(), static_cast<std::size_t>(kSamples));
    host::ReadOptions drop;
    drop.drop_truncated_tail = true;
    EXPECT_EQ(host::read_log(log, drop).t_s.size(), static_cast<std::size_t>(kSamples - 1));

    // Without the capture there is nothing to rebuild from, and the refusal does not send the user looking for it.
    std::filesystem::remove(cap);
    const RunResult alone = run_driftlab({"fit", log}, dir.path());
    EXPECT_EQ(alone.exit_code, 3) << alone.output;
    EXPECT_NE(alone.output.find("--drop-cut-line reads the rest without it"), std::string::npos) << alone.output;
    EXPECT_EQ(alone.output.find("driftlab decode"), std::string::npos) << alone.output;
}

// A capture recorded under another name (record --capture) is found by the name the log's metadata gives it: beside
// the log, its decode command is named with its path; moved elsewhere, it is named as the metadata names it.
TEST(DecodeCli, ACutLogFindsTheCaptureItsMetadataNames) {
    TempDir dir("decodecutnamed");
    const std::string log = dir.file("rec.csv");
    const std::string cap = dir.file("raw-run.bin");
    write_capture(cap, false, "raw-run.bin");
    ASSERT_EQ(run_driftlab({"decode", cap, "-o", log}, dir.path()).exit_code, 0);
    ASSERT_EQ(host::read_log(log).metadata.get("capture"), "raw-run.bin");
    const std::string last_line = cut_last_row(log);

    const RunResult beside = run_driftlab({"fit", log}, dir.path());
    EXPECT_EQ(beside.exit_code, 3) << beside.output;
    EXPECT_NE(beside.output.find(log + ":" + last_line + ": truncated last line"), std::string::npos) << beside.output;
    EXPECT_NE(beside.output.find("rebuild the whole log from its capture: `driftlab decode " + cap + " -o LOG.csv`"),
              std::string::npos)
        << beside.output;

    const std::string away = dir.file("elsewhere");
    std::filesystem::create_directory(away);
    std::filesystem::rename(cap, away + "/raw-run.bin");
    const RunResult moved = run_driftlab({"fit", log}, dir.path());
    EXPECT_EQ(moved.exit_code, 3) << moved.output;
    EXPECT_NE(moved.output.find("which the metadata names 'raw-run.bin' and is not beside the log"), std::string::npos)
        << moved.output;
    EXPECT_EQ(moved.output.find(cap), std::string::npos) << moved.output;  // no path where the capture is not

    // A file of that name that is not a capture is not sent to decode, which would refuse it.
    std::ofstream(cap) << "t_s,gyro\n0,1\n";
    const RunResult impostor = run_driftlab({"fit", log}, dir.path());
    EXPECT_EQ(impostor.exit_code, 3) << impostor.output;
    EXPECT_EQ(impostor.output.find(cap), std::string::npos) << impostor.output;
}

}  // namespace
}  // namespace driftlab::e2e
