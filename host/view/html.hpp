// Small HTML building blocks for the self-contained report: escaping and number formatting.
#pragma once

#include <string>

namespace driftlab::host::view {

/// Text with &, <, >, " escaped for HTML element and attribute content.
std::string html_escape(const std::string& text);

/// printf("%.*g") of `value` with `digits` significant digits; "-" when not finite.
std::string sig(double value, int digits = 4);

/// printf("%.*f"); "-" when not finite.
std::string fixed(double value, int decimals);

}  // namespace driftlab::host::view
