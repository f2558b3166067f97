#pragma once
// `edsc doc`: a datasheet is the model of one EDS as plain text tables and bit
// maps (built here, from edsc::analysis), then written as HTML or Markdown
// (render_*.cpp). Every string is UTF-8 text, never markup: the renderers
// escape it.
#include <cstdint>
#include <string>
#include <vector>

#include "check/check_file.hpp"

namespace edsc::doc {

// One table cell: text (newlines are line breaks), the source line it is
// about (0: none) and a style hint.
enum class cell_style : std::uint8_t { plain, number, code, muted, flags };

struct cell {
  std::string text;
  std::uint32_t line = 0;
  cell_style style = cell_style::plain;
};

struct table {
  std::vector<std::string> head;
  std::vector<std::vector<cell>> rows;
  [[nodiscard]] bool empty() const { return rows.empty(); }
};

// A run of bits of an assembly or I/O data set. `first` counts from bit 0 of
// byte 0; padding blocks have no parameter behind them.
struct bit_block {
  std::string label;   // parameter name (or what the member names)
  std::string detail;  // "Param5, UINT": for the tooltip and the legend
  std::uint32_t first = 0, bits = 0;
  bool padding = false;
  std::uint32_t color = 0;  // palette index; neighbours differ
  std::uint32_t line = 0;
};

struct bit_map {
  std::string id;       // anchor and SVG file stem: "assem100", "input1"
  std::string title;    // "Assem100: Output Data"
  std::string caption;  // size, path, connection types
  std::uint32_t bytes = 0;
  std::vector<bit_block> blocks;  // in bit order, gaps filled with padding
  std::uint32_t line = 0;
  std::string note;  // a disagreement worth saying (members vs. size)
};

struct finding {
  severity level = severity::note;
  std::string id, message;
  std::uint32_t line = 0, column = 0;                        // 0: the whole file
  std::vector<std::pair<std::uint32_t, std::string>> notes;  // line, text
};

// What the library index needs of a file.
struct summary {
  std::string vendor, product, type, catalog, networks, file;
  std::uint32_t vendor_id = 0, type_id = 0, product_code = 0, major = 0, minor = 0;
  bool identified = false;  // the five numbers are all there
  std::string revision;     // "1.4", or what is known
  std::string sha256;       // of the bytes, to tell a collision from a copy
  std::size_t errors = 0, warnings = 0, notes = 0;
};

struct sheet {
  std::string title, subtitle;  // product name; vendor and product type
  summary sum;
  table identity;           // field, value
  table file_info;          // [File]
  table devicenet_io;       // one row per predefined connection type
  table io_data;            // InputN/OutputN
  table connections;        // EtherNet/IP ConnectionN
  table proxy_connections;  // ProxyConnectN / ProxiedConnectN, apart from the real ones
  std::vector<bit_map> maps;
  table params, groups, ports, capacity;
  std::vector<finding> findings;
};

// Everything the page says about one analysed file.
[[nodiscard]] sheet build_sheet(const analysis& a);

// The file name the VVVVTTTTPPPPMM00.eds convention gives the identity, or
// empty when the numbers are missing.
[[nodiscard]] std::string conventional_name(const summary& s);

}  // namespace edsc::doc
