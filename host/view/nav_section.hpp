// The navigation section of `driftlab report --nav NAV.json` (docs/nav.md §Report): what `nav --json` printed, as a
// table per variant and the figures of `nav --plot`.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "host/view/nav_view.hpp"

namespace driftlab::host::view {

struct NavSection {
    std::string html;
    std::vector<NamedPlot> plots;  ///< with their captions as titles
};

/// The section for `nav` (read from `path`). Throws DataError naming `path` when it is not what nav --json prints.
NavSection nav_section(const nlohmann::json& nav, const std::string& path);

}  // namespace driftlab::host::view
