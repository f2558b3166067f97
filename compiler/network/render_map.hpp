#pragma once
// `edsc net map` formats (docs/network.md): the laid-out images as a text
// table, JSON, an SVG picture, RSLogix 5000 alias tags (CSV), a C scanlist
// header and the Modbus/TCP register map of the 2012 scanner.
#include <string>

#include "network/layout.hpp"
#include "network/plan.hpp"

namespace edsc::network {

struct map_input {
  const plan& p;
  const layout& l;
  std::string source_name;  // the network file's name, for generated headers
};

[[nodiscard]] std::string render_map_text(const map_input& m);
[[nodiscard]] std::string render_map_json(const map_input& m);
[[nodiscard]] std::string render_map_svg(const map_input& m);
[[nodiscard]] std::string render_map_csv(const map_input& m);
[[nodiscard]] std::string render_map_c(const map_input& m);
[[nodiscard]] std::string render_map_modbus(const map_input& m);

// Shared by the formats: where a block sits, in the profile's words.
struct block_place {
  std::uint32_t first_word = 0, last_word = 0;    // of the whole image
  std::uint32_t first_dword = 0, last_dword = 0;  // of the slave data area (Data[n])
  std::string tag;                                // Local:5:I.Data[0]
};
[[nodiscard]] block_place place_of(const plan& p, const image_layout& image, const block& b);

}  // namespace edsc::network
