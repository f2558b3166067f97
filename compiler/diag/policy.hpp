#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "diag/diagnostic.hpp"

namespace edsc {

// What the user's -W flags make of the catalogue's default severities,
// following the compiler conventions: later flags win.
//   -W<id|group>             enable (rules of group `pedantic` start disabled)
//   -Wno-<id|group>          disable (syntax and input errors cannot be disabled)
//   -Werror                  every warning becomes an error
//   -Werror=<id|group>       that warning becomes an error
//   -Wno-error=<id|group>    that warning stays a warning under -Werror
class diag_policy {
 public:
  diag_policy();

  // Takes one flag without its leading "-W"; returns an error message for an
  // unknown id or group, or a flag that may not be used.
  [[nodiscard]] std::optional<std::string> add_flag(std::string_view flag);

  // Drops disabled diagnostics and maps severities, in place.
  void apply(diagnostics& ds) const;

  [[nodiscard]] bool enabled(diag_id id) const;
  [[nodiscard]] severity level_of(diag_id id) const;

 private:
  enum class to_error : unsigned char { unset, yes, no };
  struct rule_state {
    bool enabled = true;
    to_error promote = to_error::unset;
  };
  std::vector<rule_state> rules_;
  bool werror_ = false;
};

}  // namespace edsc
