// `driftlab effects [NAME]`: the simulator's effect library as the registry knows it (sim/effects), so a model file's
// keys and a gap verdict's effect can be looked up without the source; docs/effects.md says more of each.
#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "host/cli/commands.hpp"
#include "host/gap/candidates.hpp"
#include "host/util/error.hpp"
#include "sim/effects/effect.hpp"

namespace driftlab::host::cli {
namespace {

struct EffectsOptions {
    std::string name;
    bool json = false;
};

// What the gap diagnosis does with the effect: how it fits a candidate, or why a static log cannot identify it.
struct GapUse {
    bool candidate = false;
    std::string text;
    std::string
        in_model;  ///< what gap does with it when `gap --model FILE` holds it (docs/gap.md, the model's own effects)
};

GapUse gap_use(const std::string& name) {
    const std::string kept = "kept as the file gives it";
    if (const gap::CandidateInfo* c = gap::find_candidate(name)) {
        const std::string not_tried = kept + "; not tried again on any channel";
        switch (c->route) {
        case gap::FitRoute::deterministic:
            return {true, "as a mean shape, by variable projection beside eq. 1",
                    "refitted to the log with eq. 1 on each analysed channel where the file gives it a size (its "
                    "timing is the power-on's)"};
        case gap::FitRoute::spectral:
            return {true, "as a Gaussian process, by its spectral likelihood",
                    "held at the file's values (the unit's stated noise), in every spectrum fitted on the channel; its "
                    "candidate "
                    "is fitted in place of it, not beside it"};
        case gap::FitRoute::simulated: return {true, "by simulation against the statistics battery", not_tried};
        case gap::FitRoute::code_density: return {true, "to a raw-mode log's raw codes", not_tried};
        }
    }
    for (const gap::NotIdentifiable& n : gap::not_identifiable_list())
        if (n.effect == name) return {false, n.reason, kept};
    return {false, "not tried", kept};
}

nlohmann::json to_json(const sim::EffectInfo& e) {
    nlohmann::json params = nlohmann::json::array();
    for (const sim::ParamInfo& p : e.params)
        params.push_back({{"key", p.key}, {"unit", p.unit}, {"default", p.default_text}, {"doc", p.doc}});
    const GapUse use = gap_use(e.name);
    return {
        {"name", e.name},
        {"stage", sim::stage_name(e.stage)},
        {"equation", e.equation},
        {"summary", e.summary},
        {"params", params},
        {"gap",
         {{"candidate", use.candidate}, {use.candidate ? "fitted" : "reason", use.text}, {"in_model", use.in_model}}}};
}

// The effect's parameters as a model file's table at their defaults (an effect at its defaults changes nothing),
// each with its unit and meaning, ready to edit.
void print_one(const sim::EffectInfo& e) {
    const GapUse use = gap_use(e.name);
    std::cout
        << e.name << " (" << sim::stage_name(e.stage) << " stage): " << e.summary << "\n  " << e.equation
        << "\n  gap diagnosis: " << (use.candidate ? "a candidate, fitted " : "not a candidate: ") << use.text
        << "\n  in a gap --model file: " << use.in_model
        << "\n\n# At these defaults it changes nothing: set its sizes, put the table in a model file (TOML) and run\n"
        << "# driftlab hil --model FILE (docs/effects.md, sim/models/ for examples).\n[effects." << e.name << "]\n";
    std::size_t width = 0;
    for (const sim::ParamInfo& p : e.params) width = std::max(width, p.key.size() + 3 + p.default_text.size());
    for (const sim::ParamInfo& p : e.params) {
        const std::string line = p.key + " = " + p.default_text;
        std::cout << line << std::string(width - line.size(), ' ') << "  # "
                  << (p.unit.empty() ? "" : "[" + p.unit + "] ") << p.doc << "\n";
    }
}

}  // namespace

void register_effects(CLI::App& app) {
    auto opts = std::make_shared<EffectsOptions>();
    CLI::App* cmd =
        app.add_subcommand("effects", "List the simulator's effect library, or show one effect's model-file table");
    CLI::Option* name =
        cmd->add_option("name", opts->name, "An effect: its equation and its parameters at their defaults, as TOML");
    cmd->add_flag(
        "--json", opts->json,
        "Print JSON (an array of: name, stage, equation, summary, params[], gap{candidate, fitted|reason, in_model})");
    cmd->callback([opts, name] {
        // An empty name given (a variable that expanded to nothing) is a mistake, not a request for the whole list.
        if (name->count() > 0 && opts->name.empty())
            throw UsageError("effects: NAME is empty (omit it to list the library)");
        const auto& all = sim::list_effects();
        std::vector<const sim::EffectInfo*> shown;
        for (const sim::EffectInfo& e : all)
            if (opts->name.empty() || e.name == opts->name) shown.push_back(&e);
        if (shown.empty()) {
            std::string names;
            for (const sim::EffectInfo& e : all) names += (names.empty() ? "" : ", ") + e.name;
            throw UsageError("effects: no effect '" + opts->name + "' (the library has " + names + ")");
        }
        if (opts->json) {
            nlohmann::json out = nlohmann::json::array();
            for (const sim::EffectInfo* e : shown) out.push_back(to_json(*e));
            std::cout << out.dump(2) << "\n";
        } else if (!opts->name.empty()) {
            print_one(*shown.front());
        } else {
            std::size_t width = 0;
            for (const sim::EffectInfo* e : shown) width = std::max(width, e->name.size());
            for (const sim::EffectInfo* e : shown)
                std::cout << e->name << std::string(width - e->name.size(), ' ') << "  " << sim::stage_name(e->stage)
                          << std::string(10 - std::string(sim::stage_name(e->stage)).size(), ' ') << "  "
                          << (gap_use(e->name).candidate ? "gap  " : "     ") << e->summary << "\n";
            std::cout << "(in application order within each stage; gap: a candidate of the gap diagnosis, the others a "
                         "static "
                         "log cannot identify; `driftlab effects NAME` gives an effect's model-file table and why)\n";
        }
    });
}

}  // namespace driftlab::host::cli
