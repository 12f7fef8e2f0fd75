// help_formatter(); see commands.hpp.
#include <algorithm>

#include "host/cli/commands.hpp"

namespace driftlab::host::cli {
namespace {

// CLI11 joins an option's type and each check's description with ':' ("FLOAT:> 0", "INT:in [1, 64]"); a space
// makes them one phrase ("FLOAT > 0"). Everything else in the option column (default, REQUIRED, Excludes) is CLI11's.
class HelpFormatter : public CLI::Formatter {
public:
    std::string make_option_opts(const CLI::Option* opt) const override {
        std::string opts = CLI::Formatter::make_option_opts(opt);
        const std::string type = opt->get_type_name();
        const std::size_t at = opt->get_option_text().empty() ? opts.find(type) : std::string::npos;
        if (!type.empty() && at != std::string::npos) {
            std::string phrase = type;
            std::replace(phrase.begin(), phrase.end(), ':', ' ');
            opts.replace(at, type.size(), phrase);
        }
        return opts;
    }
};

}  // namespace

std::shared_ptr<CLI::Formatter> help_formatter() { return std::make_shared<HelpFormatter>(); }

}  // namespace driftlab::host::cli
