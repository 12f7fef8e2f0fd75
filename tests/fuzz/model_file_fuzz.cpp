// libFuzzer harness: the model-file parser (sim/model/model_file) on any text. A file it refuses must be refused
// with a ModelFileError (file, line, key); a model it takes must come back the same through write_model, the text
// gap writes for a user to edit and read again.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "sim/model/model_file.hpp"
#include "sim/sim_error.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace driftlab::sim;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    SimModel model;
    try {
        model = parse_model(text, "fuzz.toml");
    } catch (const ModelFileError&) {
        return 0;  // a refusal naming the file and key
    }
    // write_model's text reads back to the same model, so writing that again gives the same text.
    const std::string written = write_model(model);
    SimModel again;
    try {
        again = parse_model(written, "written.toml");
    } catch (const ModelFileError& e) {
        std::fprintf(stderr, "write_model wrote a file parse_model refuses: %s\n%s\n", e.what(), written.c_str());
        std::abort();
    }
    DRIFTLAB_FUZZ_CHECK(write_model(again) == written);
    return 0;
}
