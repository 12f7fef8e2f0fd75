// Text and JSON of a fleet; see fleet_view.hpp.
#include "host/view/fleet_view.hpp"

#include <cmath>
#include <cstdio>

#include "host/fleet/standout_limit.hpp"
#include "host/gap/diagnose.hpp"
#include "host/util/format_number.hpp"
#include "host/view/json_out.hpp"

namespace driftlab::host::view {

using fleet::BoardEntry;
using fleet::kParameters;

namespace {

void print_boards(std::ostream& out, const std::vector<BoardEntry>& boards) {
    out << "per board (eq. 1 in counts and s; noise terms of the drift-removed ADEV, counts s^k):\n";
    char line[512];
    std::snprintf(line, sizeof line, "  %-24s %-8s %-16s %-18s %-16s %-20s %-20s %-20s %s\n", "log", "channel", "C1",
                  "C2", "T", "N", "B", "K", "gap");
    out << line;
    for (const BoardEntry& b : boards) {
        if (!b.result) continue;
        for (std::size_t c = 0; c < b.result->channels.size(); ++c) {
            const std::vector<std::string> cells = channel_cells(*b.result, c, "+-", "-");
            std::snprintf(line, sizeof line, "  %-24s %-8s %-16s %-18s %-16s %-20s %-20s %-20s %s\n",
                          c == 0 ? b.log.c_str() : "", b.result->channels[c].channel.c_str(), cells[0].c_str(),
                          cells[1].c_str(), cells[2].c_str(), cells[3].c_str(), cells[4].c_str(), cells[5].c_str(),
                          c == 0 ? cells[6].c_str() : "");
            out << line;
        }
    }
}

void print_batch(std::ostream& out, const fleet::Batch& batch) {
    out << "batch (median and robust spread over the boards whose log determines the value; x/ a factor):\n";
    char line[256];
    std::snprintf(line, sizeof line, "  %-8s %-3s %-14s %6s %12s %10s  %s\n", "channel", "", "unit", "boards", "median",
                  "spread", "range");
    out << line;
    for (const fleet::Distribution& d : batch.distributions) {
        const std::string range = significant_plain(d.low, 4) + " .. " + significant_plain(d.high, 4);
        std::snprintf(line, sizeof line, "  %-8s %-3s %-14s %6zu %12s %10s  %s\n", d.channel.c_str(),
                      kParameters[d.parameter].name, kParameters[d.parameter].unit, d.boards,
                      significant_plain(d.median, 5).c_str(), spread_cell(d, "x/").c_str(), range.c_str());
        out << line;
    }
}

}  // namespace

std::string estimate_cell(const fleet::Estimate& e, const std::string& plus_minus, const std::string& unknown) {
    if (!e.known) return unknown;
    return std::isfinite(e.std_error) ? value_with_error(e.value, e.std_error, plus_minus)
                                      : significant_plain(e.value, 5);
}

std::vector<std::string> channel_cells(const fleet::BoardResult& r, std::size_t channel, const std::string& plus_minus,
                                       const std::string& unknown) {
    std::vector<std::string> cells;
    for (const fleet::Estimate& e : r.channels.at(channel).parameters)
        cells.push_back(estimate_cell(e, plus_minus, unknown));
    cells.push_back(!r.gap_run ? unknown : r.gap_error.empty() ? r.gap_verdict : "failed");
    return cells;
}

std::string spread_cell(const fleet::Distribution& d, const std::string& factor_sign) {
    return kParameters[d.parameter].log_scale ? factor_sign + significant_plain(d.factor, 3)
                                              : significant_plain(d.spread, 3);
}

void print_fleet_text(std::ostream& out, const FleetView& v) {
    const std::vector<BoardEntry>& boards = *v.boards;
    out << "fleet: " << counted(v.batch.boards, "log") << ", " << v.batch.analysed << " analysed\n";
    print_boards(out, boards);
    print_batch(out, v.batch);
    if (v.batch.standouts.empty()) {
        out << "no board stands out (every robust z within its limit, every analysis done)\n";
    } else {
        out << "boards that stand out (a robust z beyond its limit, an analysis that failed):\n";
        for (const fleet::Standout& s : v.batch.standouts)
            out << "  " << boards[s.board].log << ": " << s.reason << "\n";
    }
    if (!v.batch.verdicts.empty()) out << "gap verdicts: " << verdict_summary(v) << "\n";
    for (const BoardEntry& b : boards)
        if (!b.result) out << "not analysed: " << b.error << "\n";
}

std::string verdict_summary(const FleetView& v) {
    std::string text;
    for (const auto& [verdict, boards] : v.batch.verdicts) {
        text += (text.empty() ? "" : "; ") + verdict + " " + std::to_string(boards.size());
        if (verdict == "none") continue;
        std::string logs;
        for (const std::size_t b : boards) logs += (logs.empty() ? "" : ", ") + (*v.boards)[b].log;
        text += " (" + logs + ")";
    }
    const double alpha = gap::GapOptions{}.alpha;
    return text + ". The diagnosis names an effect on a clean log about " + significant_plain(100 * alpha, 2) +
           " % of the time: " + significant_plain(alpha * static_cast<double>(v.batch.diagnosed), 2) + " of " +
           std::to_string(v.batch.diagnosed) + " boards by chance";
}

nlohmann::json fleet_json(const FleetView& v) {
    nlohmann::json boards = nlohmann::json::array();
    for (const BoardEntry& b : *v.boards) {
        nlohmann::json j = {{"log", b.log}, {"error", b.error.empty() ? nlohmann::json() : nlohmann::json(b.error)}};
        if (b.result) {
            const fleet::BoardResult& r = *b.result;
            j["rows"] = r.rows;
            j["duration_s"] = json_number(r.duration_s);
            j["gap"] =
                r.gap_run
                    ? nlohmann::json{{"verdict", r.gap_verdict}, {"located", r.gap_located}, {"error", r.gap_error}}
                    : nlohmann::json();
            nlohmann::json channels = nlohmann::json::object();
            for (const fleet::ChannelResult& c : r.channels) {
                nlohmann::json ch = {{"error", c.error}, {"fit_status", c.fit_status}};
                for (std::size_t p = 0; p < fleet::kParameterCount; ++p)
                    ch[kParameters[p].name] =
                        c.parameters[p].known ? nlohmann::json{{"value", json_number(c.parameters[p].value)},
                                                               {"std_error", json_number(c.parameters[p].std_error)}}
                                              : nlohmann::json();
                channels[c.channel] = ch;
            }
            j["channels"] = channels;
        }
        boards.push_back(j);
    }
    nlohmann::json distributions = nlohmann::json::object();
    for (const fleet::Distribution& d : v.batch.distributions)
        distributions[d.channel][kParameters[d.parameter].name] = {
            {"unit", kParameters[d.parameter].unit}, {"boards", d.boards},
            {"median", json_number(d.median)},       {"spread", json_number(d.spread)},
            {"factor", json_number(d.factor)},       {"low", json_number(d.low)},
            {"high", json_number(d.high)},           {"limit", json_number(d.limit)}};
    nlohmann::json verdicts = nlohmann::json::object();
    for (const auto& [verdict, given] : v.batch.verdicts)
        for (const std::size_t b : given) verdicts[verdict].push_back((*v.boards)[b].log);
    nlohmann::json standouts = nlohmann::json::array();
    for (const fleet::Standout& s : v.batch.standouts)
        standouts.push_back({{"log", (*v.boards)[s.board].log},
                             {"channel", s.channel},
                             {"parameter", s.parameter},
                             {"z", json_number(s.z)},
                             {"reason", s.reason}});
    return {{"boards", boards},
            {"batch",
             {{"boards", v.batch.boards},
              {"analysed", v.batch.analysed},
              {"channels", distributions},
              {"verdicts", verdicts}}},
            {"false_standout", fleet::kFalseStandout},
            {"standouts", standouts}};
}

}  // namespace driftlab::host::view
