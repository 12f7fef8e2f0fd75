// A plain numeric table made in memory, as read_numeric_table() would make it from a file of that name.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "host/log/numeric_table.hpp"

namespace driftlab::test_support {

inline host::NumericTable numeric_table(std::string source_name, std::vector<std::string> names,
                                        std::vector<std::vector<double>> columns) {
    host::NumericTable t;
    t.source_name = std::move(source_name);
    t.names = std::move(names);
    t.columns = std::move(columns);
    return t;
}

}  // namespace driftlab::test_support
