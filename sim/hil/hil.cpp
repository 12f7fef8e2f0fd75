// The host-in-the-loop event loop; see hil.hpp.
#include "sim/hil/hil.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "driftlab/proto/messages.hpp"
#include "driftlab/proto/wire.hpp"
#include "sim/hil/native_target.hpp"
#include "sim/model/sensor_model.hpp"
#include "sim/motion/trajectories.hpp"
#include "sim/sim_error.hpp"

namespace driftlab::sim {

namespace {

// The sensor model seen from the board: eq. 1 runs on the sensor's own power-on time.
class SensorSource final : public ConversionSource {
public:
    explicit SensorSource(const HilOptions& options)
        : sensor_(options.model, options.seed, options.warm_up_s), observer_(options.on_conversion) {
        if (options.trajectory) sensor_.set_motion(motion_source(options.trajectory));
    }
    std::uint16_t code(Channel c, double t_s) override {
        const std::uint16_t code = sensor_.convert(c, t_s).code;
        if (observer_) observer_(c, t_s, code);
        return code;
    }

private:
    SensorModel sensor_;
    const std::function<void(Channel, double, std::uint16_t)>& observer_;
};

std::unique_ptr<EmulatedBoard> make_target(TargetKind kind, std::span<const std::uint8_t> eeprom,
                                           const DieTemperature& die) {
    switch (kind) {
    case TargetKind::native: return std::make_unique<NativeTarget>(eeprom, die);
    }
    return nullptr;
}

// One link packet per protocol frame, so frame-unit losses take whole frames as a radio packet would.
void send_frames(LinkDirection& link, const TxChunk& chunk) {
    const auto& b = chunk.bytes;
    std::size_t i = 0;
    while (i < b.size()) {
        std::size_t size = b.size() - i;
        if (size > proto::kOffsetLen && b[i] == proto::kSync0 && b[i + 1] == proto::kSync1)
            size = std::min(size, proto::frame_size(b[i + proto::kOffsetLen]));
        link.send(chunk.t_s, std::span(b.data() + i, size));
        i += size;
    }
}

double earliest(std::initializer_list<std::optional<double>> times) {
    double t = std::numeric_limits<double>::infinity();
    for (const auto& x : times)
        if (x) t = std::min(t, *x);
    return t;
}

}  // namespace

// The firmware's output must fit the link: the model's UART sends 10 bits per byte, so a configuration whose
// frames per output need more than the baud rate would queue without end, arrive ever later, and end the run's
// time before most of them arrive (a short log with nothing lost).
std::optional<std::string> link_capacity_refusal(const SimModel& model) {
    const proto::ConfigPayload& fw = model.firmware;
    const std::size_t bytes =
        proto::frame_size(proto::kSamplePayloadSize) + (fw.raw ? proto::frame_size(proto::kRawPayloadSize) : 0);
    const double needed_baud = 10.0 * static_cast<double>(bytes) / (fw.output_period_ms / 1000.0);
    if (needed_baud <= model.link.baud) return std::nullopt;
    char text[320];
    std::snprintf(text, sizeof text,
                  "the link (link.baud %g, %g bytes/s) cannot carry %zu bytes (SAMPLE%s) every %u ms (%g bytes/s): "
                  "outputs would queue without end; lengthen the output period%s, or raise link.baud",
                  model.link.baud, model.link.baud / 10.0, bytes, fw.raw ? " + RAW" : "", fw.output_period_ms,
                  needed_baud / 10.0, fw.raw ? ", drop raw" : "");
    return std::string(text);
}

HilSummary run_hil(const HilOptions& options, const RecordSink& sink) {
    SensorSource source(options);
    Link link(options.model.link, options.seed);
    HostPlan plan;
    plan.config = options.model.firmware;
    plan.duration_s = options.duration_s;
    plan.reply_timeout_s = options.reply_timeout_s;
    plan.key = options.key;
    HostEndpoint host(plan, sink, options.on_ready);
    const std::unique_ptr<EmulatedBoard> board =
        options.make_board ? options.make_board()
                           : make_target(options.target, options.eeprom, options.die_temperature);

    std::vector<TxChunk> tx;
    std::vector<std::uint8_t> rx;
    std::vector<std::vector<std::uint8_t>> requests;
    double next_report_s = 0.0;
    const double report_step_s = std::max(options.duration_s / 200.0, 1e-3);
    // Handshake and closing take a few round trips; each request may be retried max_tries times.
    const double give_up_s = options.duration_s + 4.0 * plan.max_tries * plan.reply_timeout_s + 60.0;
    double t = 0.0;
    bool interrupted = false;
    while (!host.done()) {
        if (options.stop && options.stop->load()) {
            interrupted = true;
            break;
        }
        t = earliest({board->next_conversion_s(), link.to_firmware().next_arrival_s(), link.to_host().next_arrival_s(),
                      host.next_action_s()});
        if (t == std::numeric_limits<double>::infinity())
            throw BoardError("the run stalled: nothing left to happen in virtual time");
        if (t > give_up_s)
            throw BoardError("the session did not finish within " + std::to_string(give_up_s) + " s of virtual time");

        // Same-instant order: conversions due, then bytes reaching the firmware, then bytes reaching the host,
        // then whatever the host decides at that instant.
        board->advance_to(t, source, tx);
        rx.clear();
        link.to_firmware().deliver_until(t, rx);
        if (!rx.empty()) board->receive(rx, tx);
        for (const TxChunk& chunk : tx) send_frames(link.to_host(), chunk);
        tx.clear();

        rx.clear();
        link.to_host().deliver_until(t, rx);
        if (!rx.empty()) host.receive(t, rx);

        requests.clear();
        host.act(t, requests);
        for (const auto& frame : requests) link.to_firmware().send(t, frame);

        // The end is reported once, after the loop: a stream run awaiting its last RAW runs past the duration.
        if (options.progress && t >= next_report_s && t < options.duration_s) {
            options.progress(std::min(t / options.duration_s, 1.0));
            next_report_s = t + report_step_s;
        }
    }

    HilSummary s;
    s.host = host.counters();
    s.decoder = host.decoder_counters();
    s.to_host = link.to_host().counters();
    s.to_firmware = link.to_firmware().counters();
    s.version = host.version();
    s.status = host.status();
    s.conversions = board->conversions();
    s.simulated_s = t;
    s.interrupted = interrupted;
    if (options.progress && !interrupted) options.progress(1.0);
    return s;
}

}  // namespace driftlab::sim
