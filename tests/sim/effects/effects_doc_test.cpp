// docs/effects.md stays true: every TOML example in it builds its effect, every effect has an example, the table
// gives each effect the stage it is applied at, and every parameter key the registry knows appears in the document.
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "effect_test_support.hpp"

namespace driftlab::sim {
namespace {

std::string read_doc() {
    std::ifstream in(std::string(DRIFTLAB_SOURCE_DIR) + "/docs/effects.md");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(EffectsDoc, EveryExampleParsesAndEveryEffectHasOne) {
    const std::string doc = read_doc();
    ASSERT_FALSE(doc.empty()) << "docs/effects.md not found under " << DRIFTLAB_SOURCE_DIR;
    std::set<std::string> covered;
    std::size_t pos = 0;
    while ((pos = doc.find("```toml\n", pos)) != std::string::npos) {
        const std::size_t start = pos + 8;
        const std::size_t end = doc.find("```", start);
        ASSERT_NE(end, std::string::npos);
        const toml::table t = toml::parse(std::string_view(doc).substr(start, end - start));
        const toml::table* effects = t["effects"].as_table();
        ASSERT_NE(effects, nullptr);
        for (const auto& [name, body] : *effects) {
            const std::string n(name.str());
            EXPECT_NO_THROW(make_effect(n, *body.as_table(), "effects." + n)) << n;
            covered.insert(n);
        }
        pos = end + 3;
    }
    for (const EffectInfo& info : list_effects()) {
        EXPECT_TRUE(covered.count(info.name)) << "no example for " << info.name;
        EXPECT_NE(doc.find("### " + info.name + "\n"), std::string::npos) << "no section for " << info.name;
    }
}

// The table's Stage cell starts with the effect's default stage (saturation and spikes name a second one after it).
TEST(EffectsDoc, TheTableNamesEachEffectsStage) {
    const std::string doc = read_doc();
    for (const EffectInfo& info : list_effects()) {
        const std::string cell = "| `" + info.name + "` | ";
        const std::size_t at = doc.find(cell);
        ASSERT_NE(at, std::string::npos) << "no table row for " << info.name;
        EXPECT_EQ(doc.compare(at + cell.size(), std::string(stage_name(info.stage)).size(), stage_name(info.stage)), 0)
            << info.name << ": " << doc.substr(at + cell.size(), 24);
    }
}

TEST(EffectsDoc, EveryParameterKeyIsDocumented) {
    const std::string doc = read_doc();
    for (const EffectInfo& info : list_effects()) {
        for (const ParamInfo& p : info.params) {
            EXPECT_NE(doc.find("`" + p.key + "`"), std::string::npos) << info.name << "." << p.key;
        }
    }
}

}  // namespace
}  // namespace driftlab::sim
