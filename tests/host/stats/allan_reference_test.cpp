// Allan-family deviations against published values: NBS14 (NIST SP 1065) and Stable32 tables, including the
// number of terms per tau (reference data: DRIFTLAB_SHARED_DIR/reference/allan, see its PROVENANCE.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "host/stats/deviation.hpp"
#include "host/stats/phase_record.hpp"
#include "reference_data.hpp"

namespace driftlab::host::stats {
namespace {

using test::allan_reference_dir;
using test::read_column;
using test::read_stable32;

#define SKIP_WITHOUT_REFERENCE()                                                  \
    if (!std::filesystem::exists(allan_reference_dir()))                          \
    GTEST_SKIP() << "Allan reference data not found at " << allan_reference_dir() \
                 << " (set DRIFTLAB_SHARED_DIR to the shared folder)"

constexpr double kRelTolerance = 1e-4;

struct Table {
    const char* folder;
    const char* data_file;
    InputKind kind;
    double tau0_s;
    const char* table_file;
    Deviation dev;
    double rel_tolerance = kRelTolerance;
};

// Stable32 ran the ocxo octave tables on "ocxo_frequency.001" (f / 1e7, about 1 + 1e-10 in a float format that
// keeps few digits of the deviation from 1); its all-tau tables ran on the offset-removed ".003" copy and match
// to 1e-4. allantools checks the .001 tables at 2e-3 for the same reason.
constexpr double kOcxoNormalisedTolerance = 2e-3;

PhaseRecord load_record(const Table& t) {
    std::vector<double> v = read_column(allan_reference_dir() / t.folder / t.data_file);
    if (std::string(t.folder) == "ocxo") {
        for (double& f : v) f = (f - 1.0e7) / 1.0e7;  // Stable32 ran on the normalised frequency
    }
    return t.kind == InputKind::rate ? PhaseRecord::from_rate(v, t.tau0_s) : PhaseRecord::from_phase(v, t.tau0_s);
}

void expect_matches_table(const Table& t) {
    const PhaseRecord record = load_record(t);
    const auto rows = read_stable32(allan_reference_dir() / t.folder / t.table_file);
    ASSERT_FALSE(rows.empty()) << t.table_file;
    std::vector<std::int64_t> ms;
    for (const auto& r : rows) ms.push_back(r.m);
    const DeviationCurve c = compute_deviation(record, t.dev, ms);
    ASSERT_EQ(c.m.size(), rows.size()) << t.table_file;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        SCOPED_TRACE(std::string(t.folder) + "/" + t.table_file + " AF " + std::to_string(rows[i].m));
        EXPECT_EQ(c.m[i], rows[i].m);
        EXPECT_EQ(c.n[i], rows[i].n);
        EXPECT_NEAR(c.tau_s[i] / rows[i].tau_s, 1.0, kRelTolerance);
        EXPECT_NEAR(c.dev[i] / rows[i].dev, 1.0, t.rel_tolerance);
    }
}

class Stable32Table : public ::testing::TestWithParam<Table> {};

TEST_P(Stable32Table, DeviationAndTermCountMatchEveryRow) {
    SKIP_WITHOUT_REFERENCE();
    expect_matches_table(GetParam());
}

constexpr auto R = InputKind::rate;
constexpr auto P = InputKind::phase;

const Table kTables[] = {
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_adev.txt", Deviation::adev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_oadev.txt", Deviation::oadev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_mdev.txt", Deviation::mdev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_hdev.txt", Deviation::hdev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_ohdev.txt", Deviation::ohdev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_adev_octave.txt", Deviation::adev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_oadev_octave.txt", Deviation::oadev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_mdev_octave.txt", Deviation::mdev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_hdev_octave.txt", Deviation::hdev},
    {"phasedat", "PHASE.DAT", P, 1.0, "phase_dat_ohdev_octave.txt", Deviation::ohdev},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "adev_octave.txt", Deviation::adev, kOcxoNormalisedTolerance},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "oadev_octave.txt", Deviation::oadev, kOcxoNormalisedTolerance},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "mdev_octave.txt", Deviation::mdev, kOcxoNormalisedTolerance},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "hdev_octave.txt", Deviation::hdev, kOcxoNormalisedTolerance},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "ohdev_octave.txt", Deviation::ohdev, kOcxoNormalisedTolerance},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "stable32_adev_alltau.txt", Deviation::adev},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "stable32_oadev_alltau.txt", Deviation::oadev},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "stable32_mdev_alltau.txt", Deviation::mdev},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "stable32_hdev_alltau.txt", Deviation::hdev},
    {"ocxo", "ocxo_frequency.txt", R, 1.0, "stable32_ohdev_alltau.txt", Deviation::ohdev},
    {"pink_frequency", "pink_frequency.txt", R, 42.0, "adev.txt", Deviation::adev},
    {"pink_frequency", "pink_frequency.txt", R, 42.0, "oadev.txt", Deviation::oadev},
    {"pink_frequency", "pink_frequency.txt", R, 42.0, "mdev.txt", Deviation::mdev},
    {"pink_frequency", "pink_frequency.txt", R, 42.0, "hdev.txt", Deviation::hdev},
    {"pink_frequency", "pink_frequency.txt", R, 42.0, "ohdev.txt", Deviation::ohdev},
    {"pink_frequency", "pink_frequency.txt", R, 1.0, "s32_oadev_octave.txt", Deviation::oadev},
    {"gps", "gps_1pps_phase_data.txt.gz", P, 1.0, "stable32_ADEV_decade.txt", Deviation::adev},
    {"gps", "gps_1pps_phase_data.txt.gz", P, 1.0, "stable32_OADEV_octave.txt", Deviation::oadev},
    {"gps", "gps_1pps_phase_data.txt.gz", P, 1.0, "stable32_MDEV_octave.txt", Deviation::mdev},
    {"gps", "gps_1pps_phase_data.txt.gz", P, 1.0, "stable32_HDEV_octave.txt", Deviation::hdev},
    {"gps", "gps_1pps_phase_data.txt.gz", P, 1.0, "stable32_OHDEV_octave.txt", Deviation::ohdev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", P, 1.0, "tic_adev.txt", Deviation::adev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", P, 1.0, "tic_oadev.txt", Deviation::oadev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", P, 1.0, "tic_mdev.txt", Deviation::mdev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", P, 1.0, "tic_hdev.txt", Deviation::hdev},
    {"Keysight53230A_ti_noise_floor", "tic_phase.txt", P, 1.0, "tic_ohdev.txt", Deviation::ohdev},
};

std::string table_name(const ::testing::TestParamInfo<Table>& info) {
    std::string s = std::string(info.param.folder) + "_" + info.param.table_file;
    for (char& ch : s) {
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    }
    return s;
}

INSTANTIATE_TEST_SUITE_P(AllanReference, Stable32Table, ::testing::ValuesIn(kTables), table_name);

// NBS14 published values (SP 1065): columns dataset,statistic,m,value,source,note.
struct Nbs14Value {
    std::string dataset;
    std::string statistic;
    std::int64_t m;
    double value;
};

std::vector<Nbs14Value> read_nbs14_expected() {
    std::ifstream in(allan_reference_dir() / "nbs14" / "nbs14_expected.csv");
    std::vector<Nbs14Value> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line.rfind("dataset", 0) == 0) continue;
        std::stringstream ss(line);
        std::string ds, st, m, val, src;
        std::getline(ss, ds, ',');
        std::getline(ss, st, ',');
        std::getline(ss, m, ',');
        std::getline(ss, val, ',');
        std::getline(ss, src, ',');
        if (src != "SP1065") continue;
        out.push_back({ds, st, std::stoll(m), std::stod(val)});
    }
    return out;
}

TEST(Nbs14, PublishedValuesFromPhaseAndFrequencyForms) {
    SKIP_WITHOUT_REFERENCE();
    const auto dir = allan_reference_dir() / "nbs14";
    const std::map<std::string, std::vector<PhaseRecord>> records = {
        {"10pt",
         {PhaseRecord::from_phase(read_column(dir / "nbs14_10point_phase.txt"), 1.0),
          PhaseRecord::from_rate(read_column(dir / "nbs14_10point_freq.txt"), 1.0)}},
        {"1000pt",
         {PhaseRecord::from_rate(read_column(dir / "nbs14_1000point_freq.txt"), 1.0),
          PhaseRecord::from_phase(read_column(allan_reference_dir() / "phasedat" / "PHASE.DAT"), 1.0)}},
    };
    int checked = 0;
    for (const Nbs14Value& e : read_nbs14_expected()) {
        Deviation dev;
        try {
            dev = parse_deviation(e.statistic);
        } catch (const std::invalid_argument&) {
            continue;  // statistics driftlab does not compute (tdev, totdev, ...)
        }
        for (const PhaseRecord& r : records.at(e.dataset)) {
            const std::int64_t m[] = {e.m};
            const DeviationCurve c = compute_deviation(r, dev, m);
            ASSERT_EQ(c.dev.size(), 1u);
            // SP 1065 prints 7 significant digits.
            EXPECT_NEAR(c.dev[0] / e.value, 1.0, 2e-6) << e.dataset << " " << e.statistic << " m=" << e.m;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 2 * (10 + 15));
}

}  // namespace
}  // namespace driftlab::host::stats
