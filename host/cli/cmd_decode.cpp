// `driftlab decode`: rebuilds a recording's log from its raw capture, through the same assembler the recorder
// used, so the result equals the recorded log (host/io/capture, host/io/log_assembler).
#include <algorithm>
#include <bitset>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/io/capture.hpp"
#include "host/io/crc_failures.hpp"
#include "host/io/log_assembler.hpp"
#include "host/io/status_line.hpp"
#include "host/util/error.hpp"
#include "host/util/output_file.hpp"
#include "host/util/output_folder.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::cli {
namespace {

struct DecodeOptions {
    std::string capture;
    std::string output;
    bool overwrite = false;
    bool json = false;
    bool strict = false;
};

/// True when `text` is "start" with one bit flipped.
bool one_bit_from_start(const std::string& text) {
    static const std::string start = "start";
    if (text.size() != start.size()) return false;
    int bits = 0;
    for (std::size_t i = 0; i < text.size(); ++i)
        bits += std::bitset<8>(static_cast<unsigned char>(text[i] ^ start[i])).count();
    return bits == 1;
}

/// `text` with bytes that are not printable ASCII written as \xNN (a flipped high bit makes invalid UTF-8).
std::string printable(const std::string& text) {
    std::string out;
    for (const unsigned char c : text) {
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        }
    }
    return out;
}

/// In a capture that holds no start, the offset of the event to read as one: events carry no checksum, so one
/// flipped bit in the start's text (a disk or copy fault) had left the whole capture undecodable. Only where exactly
/// one event is a bit from it; else nullopt.
std::optional<std::uint64_t> damaged_start(const std::string& capture) {
    io::CaptureReader scan(capture);
    std::optional<std::uint64_t> found;
    int near = 0;
    while (const auto rec = scan.next())
        if (rec->kind == io::CaptureKind::event && one_bit_from_start(rec->text())) found = rec->offset, ++near;
    return near == 1 ? found : std::nullopt;
}

/// Feeds every record of `reader` to `assembler`, the event at `rescued_start` read as the start; true when the
/// log started.
bool feed(const DecodeOptions& o, io::CaptureReader& reader, io::LogAssembler& assembler,
          std::optional<std::uint64_t> rescued_start, io::CrcFailures& crc_failures) {
    bool started = false;
    while (auto rec = reader.next()) {
        if (rec->kind == io::CaptureKind::rx) {
            assembler.on_rx(rec->t_us, rec->payload.data(), rec->payload.size());
            crc_failures.after_record(assembler.decoder_counters().bad_crc, rec->offset);
        } else if (rec->kind == io::CaptureKind::event) {
            const bool rescued = rec->offset == rescued_start;
            if (rescued)
                std::fprintf(stderr,
                             "driftlab: warning: %s: byte offset %llu: event '%s' read as the recording's start "
                             "(one bit from 'start'; the capture holds no other)\n",
                             o.capture.c_str(), static_cast<unsigned long long>(rec->offset),
                             printable(rec->text()).c_str());
            try {
                assembler.on_event(rec->t_us, rescued ? "start" : rec->text());
            } catch (const DataError& e) {
                // The assembler names the capture its header names; the file decoded here, and where, are what help.
                const std::string what = e.what();
                const std::size_t colon = what.find(": ");
                throw DataError(o.capture, 0,
                                "byte offset " + std::to_string(rec->offset) + ": " +
                                    (colon == std::string::npos ? what : what.substr(colon + 2)));
            }
            started = started || assembler.started();
        }
    }
    return started;
}

/// The capture's damage that cost bytes (a frame failing its CRC, a damaged stretch, a cut last record), for
/// --strict: "" when none.
std::string bytes_not_decoded(const io::CaptureReader& reader, const io::CrcFailures& crc_failures) {
    std::string what;
    const auto add = [&what](const std::string& part) { what += (what.empty() ? "" : ", ") + part; };
    if (const std::uint32_t n = crc_failures.frames())
        add(std::to_string(n) + (n == 1 ? " frame failed its CRC check" : " frames failed their CRC check"));
    std::uint64_t skipped = 0;
    for (const auto& d : reader.damaged()) skipped += d.bytes;
    if (skipped > 0)
        add(std::to_string(skipped) + " damaged bytes skipped in " + std::to_string(reader.damaged().size()) +
            (reader.damaged().size() == 1 ? " stretch" : " stretches"));
    if (reader.truncated_at()) add("the last record is cut");
    return what;
}

/// The summary as one JSON object (docs/recording.md lists the keys).
nlohmann::json summary_json(const DecodeOptions& o, const io::CaptureReader& reader, const io::LogAssembler& assembler,
                            const io::CrcFailures& crc_failures, std::optional<std::uint64_t> rescued_start) {
    const io::AssemblyStats& s = assembler.stats();
    const proto::DecoderCounters& d = assembler.decoder_counters();
    nlohmann::json damaged = nlohmann::json::array();
    for (const auto& stretch : reader.damaged())
        damaged.push_back({{"offset", stretch.offset}, {"bytes", stretch.bytes}});
    const auto offset_or_null = [](const std::optional<std::uint64_t>& v) {
        return v ? nlohmann::json(*v) : nlohmann::json();
    };
    return {{"capture", o.capture},
            {"log", o.output},
            {"rows", s.rows},
            {"frames_received", s.frames},
            {"frames_lost", s.lost_frames},
            {"loss_percent", io::loss_percent(s)},
            {"duplicate_frames", s.duplicate_frames},
            {"reordered_frames", s.reordered_frames},
            {"gaps", s.gaps},
            {"firmware_restarts", s.firmware_restarts},
            {"rows_missing_raw", s.raw_missing},
            {"skipped_samples",
             {{"repeated", s.stale_samples},
              {"beyond_converter", s.unreachable_samples},
              {"empty_window", s.empty_samples}}},
            {"untrusted_frames",
             {{"conflicting", s.conflicting_frames},
              {"conflicting_rows", s.conflicting_rows},
              {"unexpected_versions", s.unexpected_versions},
              {"unexpected_configs", s.unexpected_configs},
              {"foreign_config_acks", s.foreign_config_acks},
              {"other_window_samples", s.other_window_samples},
              {"other_calibration_samples", s.other_calibration_samples}}},
            {"crc_errors", d.bad_crc},
            {"bad_length", d.bad_length},
            {"resync_bytes", d.resync_bytes},
            {"crc_failures", crc_failures.json()},
            {"damaged", damaged},
            {"retimed", reader.retimed()},
            {"truncated_at", offset_or_null(reader.truncated_at())},
            {"start_read_at", offset_or_null(rescued_start)}};
}

void run_decode(const DecodeOptions& o) {
    // Two documents cannot share one stream.
    if (o.output == "-" && o.json)
        throw UsageError("--json: the log goes to standard output (-o -); write it to a file");
    refuse_writing_over_input(o.output, "-o", o.capture, "capture");
    // The recorded log usually sits beside its capture: `decode run.csv.cap -o run.csv` of a damaged capture had
    // replaced an intact recording with fewer rows.
    refuse_replacing(o.output, "log", "-o", o.overwrite);
    auto reader = std::make_unique<io::CaptureReader>(o.capture);
    NewFolders folders;  // taken away again, when empty, if no log can be rebuilt
    folders.make_folder_of(o.output, "log");
    auto assembler = std::make_unique<io::LogAssembler>(o.output, reader->header());
    auto crc_failures = std::make_unique<io::CrcFailures>();
    bool started = feed(o, *reader, *assembler, std::nullopt, *crc_failures);
    // Only a capture without a start is read again, for a damaged one (the assembler wrote nothing without it).
    const std::optional<std::uint64_t> rescued_start = started ? std::nullopt : damaged_start(o.capture);
    if (rescued_start) {
        reader = std::make_unique<io::CaptureReader>(o.capture);
        assembler = std::make_unique<io::LogAssembler>(o.output, reader->header());
        crc_failures = std::make_unique<io::CrcFailures>();
        started = feed(o, *reader, *assembler, rescued_start, *crc_failures);
    }
    if (!started) {
        throw DataError(o.capture, 0,
                        "the capture holds no recording start (the recorder stopped during the "
                        "handshake), so there is no log to rebuild");
    }
    assembler->finish();
    folders.keep();
    for (const auto& d : reader->damaged())
        std::fprintf(stderr,
                     "driftlab: warning: %s: byte offsets %llu..%llu: damaged, %llu bytes skipped to the next whole "
                     "records (frames in them count as lost)\n",
                     o.capture.c_str(), static_cast<unsigned long long>(d.offset),
                     static_cast<unsigned long long>(d.offset + d.bytes), static_cast<unsigned long long>(d.bytes));
    for (const std::uint64_t offset : reader->retimed())
        std::fprintf(stderr,
                     "driftlab: warning: %s: byte offset %llu: a record's time is damaged (it is after the next "
                     "record's); read at the previous record's time\n",
                     o.capture.c_str(), static_cast<unsigned long long>(offset));
    crc_failures->warn(o.capture);
    if (reader->truncated_at()) {
        std::fprintf(stderr,
                     "driftlab: warning: %s: byte offset %llu: last record cut (recorder killed while "
                     "writing); decoded up to it\n",
                     o.capture.c_str(), static_cast<unsigned long long>(*reader->truncated_at()));
    }
    const io::AssemblyStats& s = assembler->stats();
    if (o.json) {
        view::write_json(std::cout, summary_json(o, *reader, *assembler, *crc_failures, rescued_start));
    } else {
        // With the log on standard output, the summary goes beside the warnings rather than after its last row.
        std::FILE* summary = o.output == "-" ? stderr : stdout;
        std::fprintf(summary, "decoded %llu rows to %s; frames %llu, lost %llu (%.3f %%; crc errors %u), gaps %llu\n",
                     static_cast<unsigned long long>(s.rows), o.output == "-" ? "standard output" : o.output.c_str(),
                     static_cast<unsigned long long>(s.frames), static_cast<unsigned long long>(s.lost_frames),
                     io::loss_percent(s), static_cast<unsigned>(assembler->decoder_counters().bad_crc),
                     static_cast<unsigned long long>(s.gaps));
        if (const std::string skipped = io::skipped_samples(s); !skipped.empty())
            std::fprintf(summary, "%s\n", skipped.c_str());
        if (const std::string untrusted = io::untrusted_frames(s); !untrusted.empty())
            std::fprintf(summary, "%s\n", untrusted.c_str());
    }
    // After the log and the summary are written: a script is told, and no good row is lost for it.
    if (const std::string lost = o.strict ? bytes_not_decoded(*reader, *crc_failures) : ""; !lost.empty())
        throw DataError(o.capture, 0, "--strict: " + lost + " (the log holds every good row)");
}

}  // namespace

void register_decode(CLI::App& app) {
    auto o = std::make_shared<DecodeOptions>();
    CLI::App* cmd = app.add_subcommand("decode", "Rebuild a recorded log from its raw capture (LOG.csv.cap)");
    cmd->add_option("capture", o->capture, "Capture file written by `driftlab record`")
        ->required()
        ->check(non_empty_path());
    cmd->add_option("-o,--output", o->output, "Log file to write (its folder is made; - for standard output)")
        ->required()
        ->check(non_empty_path());
    cmd->add_flag("--overwrite", o->overwrite, "Replace a file already at -o (refused otherwise)");
    cmd->add_flag("--json", o->json,
                  "Print the summary as JSON (keys: rows, frames_received, frames_lost, crc_errors, crc_failures, "
                  "damaged, truncated_at, ...; docs/recording.md)");
    cmd->add_flag("--strict", o->strict,
                  "Exit 3 when bytes were not decoded (frames failing their CRC, damaged stretches skipped, a cut last "
                  "record); the log still holds every good row");
    cmd->footer(
        "Damage in the capture (a cut last record, skipped stretches, frames failing their CRC) is warned of "
        "with byte offsets on standard error; the log is still written, and the exit code is 0 (3 with "
        "--strict). Exit 3: no log can be rebuilt (not a capture, no recording start).");
    cmd->callback([o] { run_decode(*o); });
}

}  // namespace driftlab::host::cli
