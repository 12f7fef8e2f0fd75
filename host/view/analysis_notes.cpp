// Notes and warnings of the analyses' text views; see analysis_notes.hpp.
#include "host/view/analysis_notes.hpp"

#include <iostream>

namespace driftlab::host::view {

void print_note(const std::string& note, bool json) {
    if (!note.empty()) (json ? std::cerr : std::cout) << "note: " << note << "\n";
}

void print_file_notes(const fit::FileAnalysis& file, bool json) {
    for (const auto& note : file.notes) print_note(note, json);
}

void print_analysis_warnings(const fit::DriftAnalysis& analysis) {
    for (const auto& warning : analysis.warnings) std::cout << "  warning: " << warning << "\n";
}

}  // namespace driftlab::host::view
