// Gilbert–Elliott loss; see gilbert_elliott.hpp.
#include "sim/link/gilbert_elliott.hpp"

#include <algorithm>

namespace driftlab::sim {

bool GilbertElliott::step_lost() {
    const double u_transition = rng_.uniform();
    bad_ = bad_ ? !(u_transition < params_.p_bad_to_good) : (u_transition < params_.p_good_to_bad);
    return rng_.uniform() < (bad_ ? params_.loss_in_bad : params_.loss_in_good);
}

void GilbertElliott::process(Packet& packet, LinkCounters& counters) {
    if (params_.p_good_to_bad == 0.0 && params_.loss_in_good == 0.0) return;  // never leaves a lossless G
    if (params_.unit == LossUnit::frame) {
        if (!step_lost()) return;
        counters.bytes_lost += packet.bytes.size();
        ++counters.packets_lost;
        packet.bytes.clear();
        packet.damaged = true;
        return;
    }
    const auto before = packet.bytes.size();
    std::erase_if(packet.bytes, [this](const TimedByte&) { return step_lost(); });
    const auto lost = before - packet.bytes.size();
    counters.bytes_lost += lost;
    if (lost > 0) packet.damaged = true;
}

}  // namespace driftlab::sim
