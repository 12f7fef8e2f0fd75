// The views of a host-in-the-loop run; see hil_view.hpp.
#include "host/view/hil_view.hpp"

#include <cmath>
#include <iomanip>

#include "host/util/format_number.hpp"

namespace driftlab::host::view {
namespace {

nlohmann::json link_json(const sim::LinkCounters& c) {
    return {{"packets_sent", c.packets_sent},       {"packets_lost", c.packets_lost},
            {"packets_damaged", c.packets_damaged}, {"bytes_sent", c.bytes_sent},
            {"bytes_lost", c.bytes_lost},           {"bytes_dropped", c.bytes_dropped},
            {"bytes_corrupted", c.bytes_corrupted}, {"bytes_delivered", c.bytes_delivered}};
}

}  // namespace

void print_hil_summary(std::ostream& out, const HilRun& run) {
    if (!run.effects.empty()) out << "effects simulated: " << run.effects << "\n";
    out << "wrote " << run.summary.host.rows << " rows to " << run.log_path;
    if (run.summary.host.rows_missing_raw > 0)
        out << " (" << counted(run.summary.host.rows_missing_raw, "sample") << " not logged: their RAW frame was lost)";
    if (run.summary.host.empty_samples > 0)
        out << " (" << counted(run.summary.host.empty_samples, "sample")
            << " not logged: n_window 0, no estimate behind their values)";
    out << "\n"
        << "frames: sent " << run.summary.to_host.packets_sent << ", received " << run.summary.host.frames_received
        << ", lost " << run.summary.host.frames_lost << " (crc errors " << run.summary.decoder.bad_crc << ")\n"
        << "link to host: " << run.summary.to_host.packets_damaged << " frames damaged ("
        << run.summary.to_host.packets_lost << " lost whole), " << run.summary.to_host.bytes_dropped
        << " bytes dropped, " << run.summary.to_host.bytes_corrupted
        << " corrupted; to firmware: " << run.summary.to_firmware.packets_damaged << " frames damaged\n"
        << "simulated " << std::setprecision(6) << run.summary.simulated_s << " s in " << std::setprecision(3)
        << run.wall_s << " s wall (" << std::lround(run.real_time_factor()) << "x real time)\n";
}

nlohmann::json hil_json(const HilRun& run) {
    return {
        {"log", run.log_path},
        {"preset", run.preset},
        {"model", run.model_name},
        {"seed", run.seed},
        {"duration_s", run.duration_s},
        {"simulated_s", run.summary.simulated_s},
        {"wall_s", run.wall_s},
        {"real_time_factor", run.real_time_factor()},
        {"conversions", run.summary.conversions},
        {"frames_sent", run.summary.to_host.packets_sent},
        {"frames_received", run.summary.host.frames_received},
        {"frames_lost", run.summary.host.frames_lost},
        {"crc_errors", run.summary.decoder.bad_crc},
        {"bad_length", run.summary.decoder.bad_length},
        {"resync_bytes", run.summary.decoder.resync_bytes},
        {"polls_sent", run.summary.host.polls_sent},
        {"samples_received", run.summary.host.samples_received},
        {"rows", run.summary.host.rows},
        {"rows_missing_raw", run.summary.host.rows_missing_raw},
        {"empty_samples", run.summary.host.empty_samples},
        {"retries", run.summary.host.retries},
        {"link", {{"to_host", link_json(run.summary.to_host)}, {"to_firmware", link_json(run.summary.to_firmware)}}},
        {"firmware",
         {{"rx_frames", run.summary.status.rx_frames},
          {"rx_bad_crc", run.summary.status.rx_bad_crc},
          {"rx_bad_length", run.summary.status.rx_bad_length},
          {"rx_unknown_type", run.summary.status.rx_unknown_type},
          {"rx_resync_bytes", run.summary.status.rx_resync_bytes},
          {"rx_overflow", run.summary.status.rx_overflow},
          {"tx_overflow", run.summary.status.tx_overflow},
          {"dropped", run.summary.status.dropped}}}};
}

}  // namespace driftlab::host::view
