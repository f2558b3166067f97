#pragma once
// `edsc connection`'s outputs: the settings of each ConnectionN
// (connections/settings.hpp) as text for a person, as JSON for a tool
// (docs/connection.md gives the JSON's fields) and as C.
#include <string>
#include <vector>

#include "connections/logix.hpp"
#include "connections/settings.hpp"
#include "source/source_file.hpp"

namespace edsc::emit {

[[nodiscard]] std::string render_connections_text(const std::vector<connections::connection_setting>& all,
                                                  const source_file& src);
[[nodiscard]] std::string render_connections_json(const std::vector<connections::connection_setting>& all,
                                                  const source_file& src);

// A C header for an originator of one's own: each request as bytes, the
// offsets it fills in, a struct of the settings (emit/connection_c.cpp).
[[nodiscard]] std::string render_connections_c(const std::vector<connections::connection_setting>& all,
                                               const source_file& src);

// C++ filling EIPScanner's ConnectionParameters, one function per
// connection (emit/connection_eipscanner.cpp).
[[nodiscard]] std::string render_connections_eipscanner(const std::vector<connections::connection_setting>& all,
                                                        const source_file& src);

// The rows of Studio 5000's Generic Ethernet Module dialog, one module per
// connection (`modules[i]` is `all[i]`'s; emit/connection_logix.cpp).
[[nodiscard]] std::string render_connections_logix(const std::vector<connections::connection_setting>& all,
                                                   const std::vector<connections::logix_module>& modules,
                                                   const source_file& src);

}  // namespace edsc::emit
