// The notes and warnings every analysis's text view prints the same way: "note: ..." (on the error output beside
// JSON, so the standard output stays one document) and a series' "  warning: ..." lines.
#pragma once

#include <string>

#include "host/fit/file_analysis.hpp"

namespace driftlab::host::view {

/// "note: ...": on the standard output, or on the error output beside JSON; nothing for "".
void print_note(const std::string& note, bool json);

/// The file's notes (an option it does not use, a cut last line dropped), with print_note().
void print_file_notes(const fit::FileAnalysis& file, bool json);

/// A series' analysis warnings, one "  warning: ..." line each, as fit and whiteness print them.
void print_analysis_warnings(const fit::DriftAnalysis& analysis);

}  // namespace driftlab::host::view
