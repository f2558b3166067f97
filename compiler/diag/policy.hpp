#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.hpp"
#include "diag/diagnostic.hpp"

namespace edsc {

// What the user's -W flags make of the catalogue's default severities,
// following the compiler conventions. Flags apply in order, so where two
// flags speak of the same rule the later one wins.
//   -W<id|group>             enable (rules of group `pedantic` start disabled)
//   -Wno-<id|group>          disable (syntax and input errors cannot be disabled)
//   -Werror                  every warning becomes an error (notes stay notes)
//   -Wno-error               no warning or note becomes an error
//   -Werror=<id|group>       enable it and make it an error, a note as well as
//                            a warning (a CI run can fail on a note it cares about)
//   -Wno-error=<id|group>    it keeps its own severity
class diag_policy {
 public:
  diag_policy();

  // Takes one flag without its leading "-W"; refused with an error message
  // for an unknown id or group, or a flag that may not be used.
  [[nodiscard]] result<void, std::string> add_flag(std::string_view flag);

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
};

}  // namespace edsc
