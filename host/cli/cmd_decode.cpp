// `driftlab decode`: rebuilds a recording's log from its raw capture, through the same assembler the recorder
// used, so the result equals the recorded log (host/io/capture, host/io/log_assembler).
#include <cstdio>
#include <memory>

#include "host/cli/commands.hpp"
#include "host/io/capture.hpp"
#include "host/io/log_assembler.hpp"
#include "host/io/status_line.hpp"
#include "host/util/error.hpp"
#include "host/util/output_file.hpp"

namespace driftlab::host::cli {
namespace {

struct DecodeOptions {
    std::string capture;
    std::string output;
};

void run_decode(const DecodeOptions& o) {
    refuse_writing_over_input(o.output, "-o", o.capture, "capture");
    io::CaptureReader reader(o.capture);
    io::LogAssembler assembler(o.output, reader.header());
    bool started = false;
    while (auto rec = reader.next()) {
        if (rec->kind == io::CaptureKind::rx) {
            assembler.on_rx(rec->t_us, rec->payload.data(), rec->payload.size());
        } else if (rec->kind == io::CaptureKind::event) {
            try {
                assembler.on_event(rec->t_us, rec->text());
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
    if (!started) {
        throw DataError(o.capture, 0, "the capture holds no recording start (the recorder stopped during the "
                                      "handshake), so there is no log to rebuild");
    }
    assembler.finish();
    for (const auto& d : reader.damaged())
        std::fprintf(stderr, "driftlab: warning: %s: byte offsets %llu..%llu: damaged, %llu bytes skipped to the next whole "
                             "records (frames in them count as lost)\n",
                     o.capture.c_str(), static_cast<unsigned long long>(d.offset),
                     static_cast<unsigned long long>(d.offset + d.bytes), static_cast<unsigned long long>(d.bytes));
    for (const std::uint64_t offset : reader.retimed())
        std::fprintf(stderr, "driftlab: warning: %s: byte offset %llu: a record's time is damaged (it is after the next "
                             "record's); read at the previous record's time\n",
                     o.capture.c_str(), static_cast<unsigned long long>(offset));
    if (reader.truncated_at()) {
        std::fprintf(stderr, "driftlab: warning: %s: byte offset %llu: last record cut (recorder killed while "
                             "writing); decoded up to it\n",
                     o.capture.c_str(), static_cast<unsigned long long>(*reader.truncated_at()));
    }
    const io::AssemblyStats& s = assembler.stats();
    std::printf("decoded %llu rows to %s; frames %llu, lost %llu (%.3f %%), gaps %llu\n",
                static_cast<unsigned long long>(s.rows), o.output.c_str(), static_cast<unsigned long long>(s.frames),
                static_cast<unsigned long long>(s.lost_frames), io::loss_percent(s),
                static_cast<unsigned long long>(s.gaps));
    if (const std::string skipped = io::skipped_samples(s); !skipped.empty()) std::printf("%s\n", skipped.c_str());
}

}  // namespace

void register_decode(CLI::App& app) {
    auto o = std::make_shared<DecodeOptions>();
    CLI::App* cmd = app.add_subcommand("decode", "Rebuild a recorded log from its raw capture (LOG.csv.cap)");
    cmd->add_option("capture", o->capture, "Capture file written by `driftlab record`")->required();
    cmd->add_option("-o,--output", o->output, "Log file to write")->required();
    cmd->callback([o] { run_decode(*o); });
}

}  // namespace driftlab::host::cli
