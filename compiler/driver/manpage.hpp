#pragma once
#include <string>
#include <utility>
#include <vector>

#include "driver/cli_model.hpp"

namespace edsc::driver {

// The man pages of the command line: edsc(1) and edsc-COMMAND(1) for every
// command ("edsc-net-map"), as (file name, roff text) pairs. Options come from
// the CLI definitions, the rule list of edsc-rules(1) from the catalogue.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> man_pages(const cli_command& top,
                                                                         const std::string& version);

}  // namespace edsc::driver
