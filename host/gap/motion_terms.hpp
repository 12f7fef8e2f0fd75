// The errors only motion shows, as candidates of `gap --truth`: scale factor, cross-axis coupling (misalignment) and
// the gyro's g-sensitivity. Each is a known regressor times an unknown size, so each is estimated by least squares
// on the log less its known input (beside a constant and the eq. 1 exponential), and judged against the same
// estimate on replicates of the calibrated unit at rest: a parametric bootstrap of its null distribution.
// docs/gap.md §A log in motion.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "host/gap/gap_model.hpp"
#include "host/gap/known_input.hpp"
#include "host/log/log_data.hpp"

namespace driftlab::host::gap {

struct GapOptions;

/// One coefficient of a motion effect, as the effect library's model file names it.
struct MotionTerm {
    std::string effect;                               ///< scale_factor, cross_axis or g_sensitivity
    Channel channel = Channel::gyro;                  ///< the channel it acts on
    MotionQuantity input = MotionQuantity::yaw_rate;  ///< the quantity it scales
    std::string parameter;                            ///< the model-file key with its index, e.g. matrix_pct[0][1]
    std::string unit;                                 ///< of the parameter
    double per_coefficient = 1.0;                     ///< the parameter per unit regression coefficient
};

struct MotionTermFit {
    MotionTerm term;
    bool tested = false;     ///< false: the trajectory does not excite it, or it moves with a term before it
    std::string not_tested;  ///< why not
    double value = 0.0;      ///< estimate [the parameter's unit]
    double null_sd = 0.0;    ///< its spread on replicates of the unit at rest [the parameter's unit]
    double z = 0.0;          ///< (value - null mean) / null_sd
    bool accepted = false;   ///< |z| beyond the family-wise threshold
};

struct MotionFindings {
    std::string truth_path;
    std::string input_source;  ///< KnownInput::source
    int newest_channel = 3;
    bool newest_estimated = false;
    int replicates = 0;
    double z_threshold = 0.0;  ///< Student t, R - 1 degrees of freedom, level alpha over the tested terms
    std::vector<MotionTermFit> terms;

    /// The accepted term of largest |z|, or nullptr.
    const MotionTermFit* strongest() const;
};

/// The terms that can act on the channels selected, in the order they are tested (a channel's own scale factor
/// first).
std::vector<MotionTerm> motion_terms(const std::array<bool, kChannelCount>& channels);

/// Estimates and judges every term on `rest` (the log less its known input) against `options.replicates`
/// replicates of `base`, at family-wise level `options.alpha`.
MotionFindings fit_motion_terms(const LogData& rest, const KnownInput& known, const GapModel& base,
                                const std::array<bool, kChannelCount>& channels, const GapOptions& options);

/// `rest` less the accepted terms' contributions: what the diagnosis at rest goes on with.
LogData without_accepted(const LogData& rest, const KnownInput& known, const MotionFindings& findings);

}  // namespace driftlab::host::gap
