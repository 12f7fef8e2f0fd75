// `driftlab fleet` on a simulated batch: 20 boards whose eq. 1 parameters scatter around Table 1 (seeded), two of
// them planted outliers (one gyro with 3.5 x T, one accel_y with 4 x the noise). Each board's C1, C2 and T come back
// within their stated errors, the two planted boards are the ones named and for the planted parameter, a file that
// is no log is named while the rest are reported and the exit is not 0; a second run reads every board back from the
// cache and prints the same; the fleet in three shards merges to the one-process output.
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "e2e_support.hpp"

namespace driftlab::e2e {
namespace {

struct Drift {
    double c1, c2, tau;
};

constexpr const char* kChannels[] = {"gyro", "accel_x", "accel_y", "accel_z"};
constexpr Drift kTable1[] = {{3, 505, 411}, {2, 470, 953}, {23, 474, 937}, {28, 622, 1050}};
constexpr int kBoards = 20;
constexpr int kSlowGyro = 5;     // T x 3.5
constexpr int kNoisyAccel = 13;  // accel_y's noise x 4

std::string board_name(int i) { return (i < 10 ? "b0" : "b") + std::to_string(i); }

// Writes board i's model file and log into `dir`; returns its planted drift per channel.
std::vector<Drift> make_board(const TempDir& dir, int i, std::mt19937_64& rng) {
    std::normal_distribution<double> z;
    std::vector<Drift> planted;
    std::ofstream model(dir.file(board_name(i) + ".toml"));
    for (int c = 0; c < 4; ++c) {
        Drift d{kTable1[c].c1 * (1 + 0.1 * z(rng)), kTable1[c].c2 + 2 * z(rng), kTable1[c].tau * (1 + 0.1 * z(rng))};
        if (i == kSlowGyro && c == 0) d.tau = 3.5 * kTable1[c].tau;
        model << "[channels." << kChannels[c] << "]\ndrift_c1_counts = " << d.c1 << "\ndrift_c2_counts = " << d.c2
              << "\ndrift_tau_s = " << d.tau << "\n";
        if (i == kNoisyAccel && c == 2) model << "raw_noise_std_g = " << 4 * 0.0141 << "\n";
        planted.push_back(d);
    }
    model.close();
    const RunResult r = run_driftlab({"hil", "--preset", "fig3", "--model", dir.file(board_name(i) + ".toml"), "--seed",
                                      std::to_string(100 + i), "-o", dir.file("logs/" + board_name(i) + ".csv")},
                                     dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return planted;
}

TEST(FleetCli, TwentyBoardsGiveBackTheirParametersAndTheTwoPlantedOutliers) {
    TempDir dir("fleet");
    std::filesystem::create_directories(dir.path() / "logs");
    std::mt19937_64 rng(2026);
    std::vector<std::vector<Drift>> planted;
    for (int i = 0; i < kBoards; ++i) planted.push_back(make_board(dir, i, rng));
    std::ofstream(dir.file("logs/notes.csv")) << "t,gyro\n1,2\n";  // sorts after the boards
    const std::vector<std::string> fleet = {"fleet", dir.file("logs"), "--cache", dir.file("cache"), "--json"};
    const SplitRun run = run_driftlab_split(fleet, dir.path());
    EXPECT_EQ(run.exit_code, 3) << run.err;
    EXPECT_NE(run.err.find(dir.file("logs/notes.csv") + ": not analysed; the other 20 boards are reported"),
              std::string::npos)
        << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out);
    ASSERT_EQ(j["boards"].size(), kBoards + 1u);
    EXPECT_NE(j["boards"][kBoards]["error"].get<std::string>().find("not a driftlab log"), std::string::npos);
    // Each parameter within 4.5 of its standard errors of the planted value, and the errors honest over all 240.
    double sum_z2 = 0.0;
    int n = 0;
    for (int i = 0; i < kBoards; ++i)
        for (int c = 0; c < 4; ++c) {
            const nlohmann::json& ch = j["boards"][i]["channels"][kChannels[c]];
            const double truth[] = {planted[i][c].c1, planted[i][c].c2, planted[i][c].tau};
            const char* names[] = {"C1", "C2", "T"};
            for (int p = 0; p < 3; ++p) {
                ASSERT_TRUE(ch[names[p]].is_object()) << board_name(i) << " " << kChannels[c] << " " << names[p];
                const double z =
                    (ch[names[p]]["value"].get<double>() - truth[p]) / ch[names[p]]["std_error"].get<double>();
                EXPECT_LT(std::fabs(z), 4.5) << board_name(i) << " " << kChannels[c] << " " << names[p];
                sum_z2 += z * z;
                ++n;
            }
        }
    const double rms = std::sqrt(sum_z2 / n);
    EXPECT_GT(rms, 0.7);
    EXPECT_LT(rms, 1.4);
    // The two planted boards, each for what was planted, and no other.
    ASSERT_EQ(j["standouts"].size(), 2u) << j["standouts"].dump(2);
    EXPECT_EQ(j["standouts"][0]["log"], dir.file("logs/" + board_name(kSlowGyro) + ".csv"));
    EXPECT_EQ(j["standouts"][0]["channel"], "gyro");
    EXPECT_EQ(j["standouts"][0]["parameter"], "T");
    EXPECT_EQ(j["standouts"][1]["log"], dir.file("logs/" + board_name(kNoisyAccel) + ".csv"));
    EXPECT_EQ(j["standouts"][1]["channel"], "accel_y");
    EXPECT_EQ(j["standouts"][1]["parameter"], "N");
    EXPECT_GT(j["standouts"][1]["z"].get<double>(), j["batch"]["channels"]["accel_y"]["N"]["limit"].get<double>());
    const double noisy = j["boards"][kNoisyAccel]["channels"]["accel_y"]["N"]["value"].get<double>();
    const double usual = j["batch"]["channels"]["accel_y"]["N"]["median"].get<double>();
    EXPECT_NEAR(noisy / usual, 4.0, 0.4);

    // Again: every board read back, the same document.
    const SplitRun again = run_driftlab_split(fleet, dir.path());
    EXPECT_EQ(again.exit_code, 3);
    EXPECT_NE(again.err.find("20 of 21 boards read back"), std::string::npos) << again.err;
    EXPECT_EQ(again.out, run.out);

    // In three shards without the cache, merged: the one-process document.
    std::vector<std::string> merge = {"merge", "--json"};
    for (int k = 0; k < 3; ++k) {
        merge.push_back(dir.file("f" + std::to_string(k) + ".part"));
        const RunResult r = run_driftlab(
            {"fleet", dir.file("logs"), "--no-cache", "--shard", std::to_string(k) + "/3", "-o", merge.back()},
            dir.path());
        EXPECT_EQ(r.exit_code, 0) << r.output;
    }
    const SplitRun merged = run_driftlab_split(merge, dir.path());
    EXPECT_EQ(merged.exit_code, 3) << merged.err;
    EXPECT_EQ(merged.out, run.out);
}

}  // namespace
}  // namespace driftlab::e2e
