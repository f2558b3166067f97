#pragma once
// `edsc diff`: what changed between two EDS files, compared on their models
// (layout, comments and entry order are no difference), and what each change
// does to a network already configured with the old file (docs/diff.md).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check/check_file.hpp"

namespace edsc::diff {

// How a difference affects an existing configuration.
enum class impact : std::uint8_t {
  cosmetic,  // nothing a scanner or a configuration relies on
  additive,  // something new; what was configured still works
  breaking,  // the device no longer matches the configuration, or data moves
};

enum class group : std::uint8_t { identity, io, parameters, connections, other };

// Which keying a scanner uses when it checks the revision: exact match wants
// the configured major.minor; compatible revision accepts the same major and
// a minor revision at least as high.
enum class keying : std::uint8_t { exact, compatible };

// One side of a difference: where it is in that file and what it says there.
struct side {
  std::uint32_t offset = 0xFFFFFFFFu;  // byte offset in the file; none: not in it
  std::string value;                   // shown value; empty when none applies
  [[nodiscard]] bool present() const { return offset != 0xFFFFFFFFu; }
};

struct difference {
  group in = group::other;
  impact level = impact::cosmetic;
  std::string kind;         // stable id: "io-size", "param-renumbered", ... (docs/diff.md)
  std::string subject;      // what it is about: "[IO_Info] Input1"
  std::string message;      // what changed
  std::string consequence;  // what it does to a configured network
  side before, after;
};

struct identity_key {
  std::optional<std::uint64_t> vendor, device_type, product_code, major, minor;
};

struct verdicts {
  identity_key before, after;
  bool exact_match = true;       // a scanner keyed to exact match accepts the new device
  bool compatible_match = true;  // ... keyed to compatible revision
};

struct options {
  keying assumed = keying::compatible;  // what a minor revision step counts as
};

struct result {
  verdicts keys;
  std::vector<difference> differences;  // grouped, then in the new file's order
  [[nodiscard]] std::size_t count(impact i) const;
  [[nodiscard]] bool breaking() const { return count(impact::breaking) > 0; }
};

[[nodiscard]] result compare(const model::device& before, const model::device& after, const options& opt = {});
[[nodiscard]] inline result compare(const analysis& before, const analysis& after, const options& opt = {}) {
  return compare(before.dev, after.dev, opt);
}

[[nodiscard]] std::string_view to_string(impact i);
[[nodiscard]] std::string_view to_string(group g);
[[nodiscard]] std::string_view title(group g);  // "identity and keying"

struct text_options {
  bool color = false;
};
[[nodiscard]] std::string render_text(const result& r, const analysis& before, const analysis& after,
                                      const text_options& style);
[[nodiscard]] std::string render_json(const result& r, const analysis& before, const analysis& after);

inline constexpr int json_format_version = 1;

}  // namespace edsc::diff
