// Harness errors: every failure the harness detects is a HarnessError whose message says what and where.
#pragma once

#include <stdexcept>
#include <string>

namespace harness {

class HarnessError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace harness
