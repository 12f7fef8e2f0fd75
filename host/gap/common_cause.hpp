// Causes shared by channels: one slow process seen by several channels, each through its own coefficient, against
// each channel read alone. The channels' residuals (eq. 1 and the accepted mean shapes taken out) are differenced
// and transformed together; the multichannel Whittle likelihood of their cross-periodogram judges three readings:
//   separate        each channel its white floor and, where it pays, its own Gauss-Markov process (diagonal
//                   spectrum: the channels share nothing);
//   supply_coupling one Gauss-Markov supply wander reaching every channel ratiometrically, its loading the
//                   channel's DC level times the supply's relative deviation (one coefficient for all);
//   shared_process  one Gauss-Markov process with a free loading per channel (a temperature through each channel's
//                   coefficient, or supply pickup: a static log cannot tell them apart).
// The spectrum of a rank-1 shared part is S = D + g a a' (D diagonal), whose inverse and determinant are closed
// (Sherman-Morrison), so the cross terms a shared cause must explain enter the likelihood exactly. Chosen by the
// Schwarz criterion over every frequency of every channel, a shared reading by a margin of 2; a free one must also
// load two channels or more on their own (the ratiometric one loads them all through its one coefficient).
// Whittle, Ark. Mat. 2, 1953 (the multivariate form: Brillinger, Time Series, 1981, §7). docs/gap.md §Shared causes.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "host/gap/comparison.hpp"
#include "host/gap/gap_model.hpp"
#include "host/gap/statistics.hpp"
#include "sim/model/sim_model.hpp"

namespace driftlab::host::gap {

/// The readings, in the order they are fitted.
inline constexpr std::array<const char*, 3> kCommonReadings = {"separate", "supply_coupling", "shared_process"};

/// One reading of the channels' noise, fitted by the multichannel Whittle likelihood.
struct CommonFit {
    std::string reading;                          ///< one of kCommonReadings
    std::array<double, kChannelCount> white{};    ///< white floor per conversion [counts^2]
    std::array<double, kChannelCount> loading{};  ///< the shared process's std on each channel [counts], signed
    double relative_sd = 0.0;                     ///< supply_coupling: the supply's std over its nominal value [-]
    double tau_s = 0.0;                           ///< the shared process's correlation time [s]
    std::array<double, kChannelCount> own_sd{};   ///< separate: each channel's own process std [counts] (0: none)
    std::array<double, kChannelCount> own_tau{};  ///< ... and its correlation time [s]
    double nll = 0.0;                             ///< Whittle negative log-likelihood
    std::array<double, kChannelCount> channel_criterion{};  ///< separate: each channel's own criterion
    int parameters = 0;
    double criterion = 0.0;  ///< 2 nll + parameters x ln(observations) (Schwarz)
    /// Per channel: the criterion rises by more than one parameter's price when its loading is set to 0.
    std::array<bool, kChannelCount> loaded{};
};

/// A located coherence cell: where the channels share a band beyond the simulator.
struct SharedBand {
    std::string pair;  ///< "a~b"
    std::string band;  ///< the cell's band
    std::string part;  ///< fit or heldout
    double z = 0.0;
};

struct CommonFindings {
    bool compared = false;                  ///< two or more analysed channels and a gap located
    std::string not_compared;               ///< why not, when not
    std::vector<SharedBand> shared;         ///< located coherence cells
    double observations = 0.0;              ///< frequencies x channels in the likelihood
    std::vector<CommonFit> fits;            ///< kCommonReadings order
    std::optional<std::size_t> chosen;      ///< the shared reading that wins (index into fits), if one does
    std::vector<std::string> replaced;      ///< the per-channel processes it replaces ("gauss_markov on accel_x")
    std::optional<sim::EffectSpec> effect;  ///< the library effect that simulates the chosen reading

    const CommonFit* winner() const { return chosen ? &fits[*chosen] : nullptr; }
};

/// Channel `c`'s residual for the shared-cause likelihood: `y` less `shapes` (the accepted mean shapes, up to a
/// constant) and an eq. 1 fit [counts].
std::vector<double> common_residual(const std::vector<double>& t_s, const std::vector<double>& y,
                                    const std::vector<double>& shapes);

/// Fits the three readings to `residuals` (per channel; null for channels not analysed) of a log smoothed as `model`
/// says, whose channels sit at `dc_counts` (the DC level the ratiometric loading scales), the independent fits (a
/// channel alone, a start) on `threads` threads: the same result for any number. Needs >= 2 channels.
CommonFindings fit_common(const std::array<const std::vector<double>*, kChannelCount>& residuals,
                          const std::array<double, kChannelCount>& dc_counts, const GapModel& model, int threads);

/// The `separate` reading alone, and the price of one parameter (ln of the frequencies x channels): what a known
/// regressor (temperature_coupling.hpp) is judged against, channel by channel.
struct SeparateReading {
    CommonFit fit;
    double price = 0.0;
};
SeparateReading read_channels_alone(const std::array<const std::vector<double>*, kChannelCount>& residuals,
                                    const GapModel& model, int threads);

/// The located coherence cells of a comparison.
std::vector<SharedBand> shared_bands(const std::vector<LocatedCell>& located, const std::vector<Cell>& layout);

/// The library effect (supply_coupling with a wander) that simulates a shared reading `fit` on `model`'s unit.
sim::EffectSpec common_effect(const CommonFit& fit, const GapModel& model);

}  // namespace driftlab::host::gap
