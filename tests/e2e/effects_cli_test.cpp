// `driftlab effects`: what it prints of an effect is a model file's table that builds that effect at its defaults,
// so a user can paste it and edit; the listing and the JSON hold the whole library; an unknown name is refused.
#include <algorithm>

#include <gtest/gtest.h>
#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"
#include "host/gap/candidates.hpp"
#include "sim/effects/effect.hpp"

namespace driftlab::e2e {
namespace {

TEST(EffectsCli, EachEffectsTableParsesAndBuildsTheEffectAtItsDefaults) {
    TempDir dir("effects");
    for (const sim::EffectInfo& info : sim::list_effects()) {
        const RunResult r = run_driftlab({"effects", info.name}, dir.path());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const std::size_t at = r.output.find("[effects." + info.name + "]\n");
        ASSERT_NE(at, std::string::npos) << r.output;
        EXPECT_NE(r.output.find("driftlab hil --model FILE"), std::string::npos) << r.output;  // how to use the table
        toml::table model;
        try {
            model = toml::parse(std::string_view(r.output).substr(at));
        } catch (const toml::parse_error& e) {
            FAIL() << info.name << ": " << e.description() << "\n" << r.output;
        }
        const toml::table* table = model["effects"][info.name].as_table();
        ASSERT_NE(table, nullptr) << r.output;
        EXPECT_EQ(table->size(), info.params.size()) << r.output;
        std::unique_ptr<sim::Effect> built;
        ASSERT_NO_THROW(built = sim::make_effect(info.name, *table, "effects." + info.name)) << r.output;
        EXPECT_EQ(built->parameters(), sim::make_effect(info.name)->parameters()) << r.output;
    }
}

TEST(EffectsCli, TheListAndTheJsonHoldTheWholeLibraryAndAnUnknownNameIsRefused) {
    TempDir dir("effects");
    const RunResult list = run_driftlab({"effects"}, dir.path());
    ASSERT_EQ(list.exit_code, 0) << list.output;
    const RunResult json = run_driftlab({"effects", "--json"}, dir.path());
    ASSERT_EQ(json.exit_code, 0) << json.output;
    const auto j = nlohmann::json::parse(json.output);
    const auto& library = sim::list_effects();
    ASSERT_EQ(j.size(), library.size());
    for (std::size_t k = 0; k < library.size(); ++k) {
        EXPECT_EQ(j[k]["name"], library[k].name);
        EXPECT_EQ(j[k]["stage"], sim::stage_name(library[k].stage));
        EXPECT_EQ(j[k]["params"].size(), library[k].params.size()) << library[k].name;
        // What the gap diagnosis does with it: a candidate it fits, or the reason a static log cannot identify it.
        const bool candidate = host::gap::find_candidate(library[k].name) != nullptr;
        EXPECT_EQ(j[k]["gap"]["candidate"], candidate) << library[k].name;
        EXPECT_FALSE(j[k]["gap"][candidate ? "fitted" : "reason"].get<std::string>().empty()) << library[k].name;
        // And in a gap --model file: a Gaussian process held, a mean shape refitted, anything else kept.
        const auto* c = host::gap::find_candidate(library[k].name);
        const std::string in_model = j[k]["gap"]["in_model"];
        const std::string expected = !c                                               ? "kept"
                                     : c->route == host::gap::FitRoute::spectral      ? "held"
                                     : c->route == host::gap::FitRoute::deterministic ? "refitted"
                                                                                      : "kept";
        EXPECT_EQ(in_model.rfind(expected, 0), 0u) << library[k].name << ": " << in_model;
        const auto lines = lines_of(list.output);
        EXPECT_TRUE(std::any_of(lines.begin(), lines.end(),
                                [&](const std::string& l) { return l.rfind(library[k].name + " ", 0) == 0; }))
            << library[k].name << "\n"
            << list.output;
    }
    const RunResult bad = run_driftlab({"effects", "spike"}, dir.path());
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("no effect 'spike'"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("spikes"), std::string::npos) << bad.output;
    // An empty name (a shell variable that expanded to nothing) had printed the whole list with exit 0.
    const RunResult empty = run_driftlab({"effects", ""}, dir.path());
    EXPECT_EQ(empty.exit_code, 2) << empty.output;
    EXPECT_NE(empty.output.find("NAME is empty"), std::string::npos) << empty.output;
}

}  // namespace
}  // namespace driftlab::e2e
