// The diagnosis accounts for the whole effect library: each effect is a candidate it fits, or is named as one a
// static log cannot identify, with the reason; and a candidate's parameters build the library's effect.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "host/gap/candidates.hpp"
#include "sim/effects/effect.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {
namespace {

TEST(Candidates, EveryLibraryEffectIsACandidateOrNamedNotIdentifiableNeverBoth) {
    std::set<std::string> library, candidates, unidentifiable;
    for (const sim::EffectInfo& e : sim::list_effects()) library.insert(e.name);
    for (const CandidateInfo& c : candidate_list()) EXPECT_TRUE(candidates.insert(c.effect).second) << c.effect << " twice";
    for (const NotIdentifiable& n : not_identifiable_list()) {
        EXPECT_TRUE(unidentifiable.insert(n.effect).second) << n.effect << " twice";
        EXPECT_FALSE(n.reason.empty()) << n.effect;
    }
    for (const std::string& name : library)
        EXPECT_NE(candidates.count(name), unidentifiable.count(name)) << name << ": a candidate, or not identifiable, exactly one";
    for (const std::string& name : candidates) EXPECT_TRUE(library.count(name)) << name << " is no library effect";
    for (const std::string& name : unidentifiable) EXPECT_TRUE(library.count(name)) << name << " is no library effect";
}

// Each candidate with fixed parameter keys, at plausible values on the gyro and on accel_y, builds its library effect
// (the registry validates every key), and the keys it reports are the channel's.
TEST(Candidates, ACandidatesParametersBuildItsLibraryEffectOnEitherKindOfChannel) {
    GapModel m;
    m.unit = sim::paper_model();
    for (const CandidateInfo& c : candidate_list()) {
        if (c.param_keys.empty()) continue;  // adc_dnl: one transition per code the log crosses
        const std::vector<double> p = c.effect == "ambient_cycle" ? std::vector<double>{0.01, 600.0, 0.3}
                                                                  : std::vector<double>(c.param_keys.size(), 0.5);
        for (const Channel ch : {Channel::gyro, Channel::accel_y}) {
            const sim::EffectSpec spec = make_candidate_effect(c.effect, ch, p, m);
            EXPECT_NO_THROW(sim::make_effect(spec.name, spec.table, "effects." + spec.name)) << c.effect;
            const auto names = candidate_param_names(c.effect, ch);
            ASSERT_EQ(names.size(), c.param_keys.size()) << c.effect;
            for (const std::string& n : names) EXPECT_EQ(n.find("_unit"), std::string::npos) << c.effect << ": " << n;
        }
    }
}

}  // namespace
}  // namespace driftlab::host::gap
