// The message a reader refuses its input with, for the tests that check what a bad line is called.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "host/util/error.hpp"

namespace driftlab::test_support {

/// The DataError message `read()` throws; a test failure (naming `input`, when given) and "" when it throws none.
template <class Read>
std::string data_error_of(Read read, std::string_view input = {}) {
    try {
        read();
    } catch (const host::DataError& e) {
        return e.what();
    }
    ADD_FAILURE() << "accepted" << (input.empty() ? "" : ":\n") << input;
    return {};
}

}  // namespace driftlab::test_support
