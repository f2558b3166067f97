#pragma once
// A -verify style harness: an EDS test file states the diagnostics it must
// produce in comments on the offending line,
//     Input1 = 1, 6 "20 04";   $ expected-error{{expected ','}}
// and `expected-warning@+1{{...}}` / `@-2` address a nearby line. The text in
// braces must occur in "message [id]". Every diagnostic must be expected and
// every expectation met. A line `$ verify-only: syntax structure` limits the
// comparison to diagnostics of those groups (for files that test one family);
// `$ verify-flags: pedantic` passes -W flags (tests/check/test_cases.cpp).
#include <string>
#include <vector>

#include "diag/diagnostic.hpp"
#include "source/source_file.hpp"

namespace edsc::testing {

struct expectation {
  std::uint32_t line;
  severity level;
  std::string text;
};

[[nodiscard]] std::vector<expectation> read_expectations(const source_file& src);

// Empty when diagnostics and expectations agree; otherwise one line per
// mismatch, ready for a test failure message.
[[nodiscard]] std::vector<std::string> verify(const source_file& src, const diagnostics& diags);

}  // namespace edsc::testing
