// `packet_loss`: bursty loss by the Gilbert–Elliott model (Gilbert 1960, Elliott 1963). A two-state Markov
// chain (good G, bad B) steps once per unit (a whole packet, or one byte); in state s the unit is lost with
// probability loss_in_s. With p = P(G->B), r = P(B->G): P(B) = p/(p+r), mean loss rate
// = (r·loss_in_good + p·loss_in_bad)/(p+r); for the Gilbert case (loss_in_good 0, loss_in_bad 1) loss bursts
// are geometric with mean length 1/r. docs/sim.md §Link.
#pragma once

#include "sim/link/link.hpp"
#include "sim/model/rng.hpp"

namespace driftlab::sim {

class GilbertElliott final : public LinkStage {
public:
    GilbertElliott(const PacketLossParams& params, Rng rng) : params_(params), rng_(rng) {}
    void process(Packet& packet, LinkCounters& counters) override;

    /// Steps the chain once and says whether this unit is lost (exposed for the loss-statistics test).
    bool step_lost();

private:
    PacketLossParams params_;
    Rng rng_;
    bool bad_ = false;  // starts in G
};

}  // namespace driftlab::sim
