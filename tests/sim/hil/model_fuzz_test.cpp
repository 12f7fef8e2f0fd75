// Model files with damaged values, through the loader and a host-in-the-loop run: each must be refused with a
// ConfigError that names the file and a line, or run to its end with finite records in time order. A file whose
// every value the loader accepted had ended runs in an internal error (NaN at the converter input from a span_g of
// 1e-308, from a flicker b_dps of 1e308); these sweeps are what found both, kept so that a new key or effect meets
// them too. Every key of every shipped model and every effect parameter meets each value that breaks arithmetic;
// then random models of one to three effects with many values changed at once (deterministic seeds).
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "sim/effects/effect.hpp"
#include "sim/hil/hil.hpp"
#include "sim/model/model_file.hpp"
#include "sim/sim_error.hpp"

namespace driftlab::sim {
namespace {

// Zero, signs, both ends of a double's range, the non-finite, integer-width edges, and the wrong types.
const std::vector<std::string> kExtremes = {"0",     "-1",    "-0.0",       "0.5",    "1e-12", "5e-324", "1e-308",
                                            "1e9",   "1e100", "1e308",      "-1e308", "nan",   "inf",    "-inf",
                                            "65535", "65536", "4294967296", "\"x\"",  "true",  "[]"};

constexpr double kRunS = 10.0;

struct Tally {
    int refused = 0;
    int ran = 0;
};

// The `key = value` lines of a model file: where each value starts and ends (before any comment).
struct ValueSpan {
    std::size_t begin;
    std::size_t end;
};

std::vector<ValueSpan> value_spans(const std::string& text) {
    std::vector<ValueSpan> spans;
    std::size_t line = 0;
    while (line < text.size()) {
        std::size_t eol = text.find('\n', line);
        if (eol == std::string::npos) eol = text.size();
        const std::size_t eq = text.find('=', line);
        if (text[line] != '#' && text[line] != '[' && eq < eol) {
            std::size_t end = std::min(text.find('#', eq), eol);
            std::size_t begin = eq + 1;
            while (begin < end && text[begin] == ' ') ++begin;
            while (end > begin && text[end - 1] == ' ') --end;
            spans.push_back({begin, end});
        }
        line = eol + 1;
    }
    return spans;
}

std::string replaced(const std::string& text, ValueSpan at, const std::string& value) {
    return text.substr(0, at.begin) + value + text.substr(at.end);
}

// Refused with a ConfigError naming m.toml and a line, or run for kRunS with every record finite and later than
// the one before; the host-in-the-loop may also refuse it as documented (the firmware's NAK, a board that stops
// answering). Anything else fails the test with the file that caused it.
void load_and_run(const std::string& text, std::uint64_t seed, Tally& tally) {
    SimModel model;
    try {
        model = parse_model(text, "m.toml");
    } catch (const ModelFileError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("m.toml:", 0), 0u) << what << "\n" << text;
        EXPECT_TRUE(what.size() > 7 && std::isdigit(static_cast<unsigned char>(what[7]))) << what << "\n" << text;
        ++tally.refused;
        return;
    }
    if (link_capacity_refusal(model)) {
        ++tally.refused;
        return;
    }
    HilOptions options;
    options.model = model;
    options.duration_s = kRunS;
    options.seed = seed;
    double last_t = -1.0;
    bool ordered = true, finite = true;
    try {
        run_hil(options, [&](const HilRecord& r) {
            ordered = ordered && r.t_s > last_t;
            last_t = r.t_s;
            for (double v : r.value_counts) finite = finite && std::isfinite(v);
        });
    } catch (const ConfigRefused&) {
        ++tally.refused;
        return;
    } catch (const BoardError&) {
        ++tally.refused;
        return;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "the run ended in " << e.what() << "\n" << text;
        return;
    }
    EXPECT_TRUE(ordered) << text;
    EXPECT_TRUE(finite) << text;
    EXPECT_GT(last_t, 0.0) << "no record\n" << text;
    ++tally.ran;
}

std::string read_all(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// An effect's model-file table with its documented defaults.
std::string default_table(const EffectInfo& effect) {
    std::string text = "[effects." + effect.name + "]\n";
    for (const ParamInfo& p : effect.params) text += p.key + " = " + p.default_text + "\n";
    return text;
}

// Both outcomes must occur, or a sweep that refuses (or accepts) everything would pass without testing either side.
void expect_both_outcomes(const Tally& tally) {
    EXPECT_GT(tally.refused, 20);
    EXPECT_GT(tally.ran, 20);
}

TEST(ModelFuzz, EveryKeyOfEveryShippedModelMeetsEachExtremeValue) {
    Tally tally;
    std::uint64_t seed = 1;
    for (const auto& entry : std::filesystem::directory_iterator(DRIFTLAB_MODELS_DIR)) {
        if (entry.path().extension() != ".toml") continue;
        const std::string text = read_all(entry.path());
        for (const ValueSpan& at : value_spans(text))
            for (const std::string& value : kExtremes) load_and_run(replaced(text, at, value), ++seed, tally);
    }
    expect_both_outcomes(tally);
}

TEST(ModelFuzz, EveryEffectParameterMeetsEachExtremeValue) {
    Tally tally;
    std::uint64_t seed = 1;
    for (const EffectInfo& effect : list_effects()) {
        const std::string text = "name = \"fz\"\n" + default_table(effect);
        for (const ValueSpan& at : value_spans(text)) {
            if (at.begin < text.find('[')) continue;  // the model's name
            for (const std::string& value : kExtremes) load_and_run(replaced(text, at, value), ++seed, tally);
        }
    }
    expect_both_outcomes(tally);
}

TEST(ModelFuzz, RandomModelsOfSeveralEffectsWithManyValuesChanged) {
    std::mt19937_64 rng(20261203);
    const std::vector<EffectInfo>& effects = list_effects();
    auto random_value = [&]() -> std::string {
        const double r = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        auto magnitude = [&] { return std::pow(10.0, std::uniform_real_distribution<double>(-6.0, 6.0)(rng)); };
        std::ostringstream v;
        v.precision(17);
        if (r < 0.2) return kExtremes[rng() % kExtremes.size()];
        if (r < 0.85) {
            v << (rng() % 2 ? -1.0 : 1.0) * magnitude();
        } else {
            v << '[';
            for (std::uint64_t k = rng() % 4; k > 0; --k) v << magnitude() << (k > 1 ? ", " : "");
            v << ']';
        }
        return v.str();
    };
    Tally tally;
    for (std::uint64_t it = 1; it <= 400; ++it) {
        std::string text = "name = \"fz\"\n";
        for (std::uint64_t n = 1 + rng() % 3; n > 0; --n) text += default_table(effects[rng() % effects.size()]);
        // Replaced from the end, so that the spans before each replacement still hold.
        const std::vector<ValueSpan> spans = value_spans(text);
        for (std::size_t k = spans.size(); k-- > 1;)
            if (rng() % 3 == 0) text = replaced(text, spans[k], random_value());
        load_and_run(text, it, tally);
    }
    expect_both_outcomes(tally);
}

}  // namespace
}  // namespace driftlab::sim
