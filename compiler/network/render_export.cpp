// `edsc net map` exports: RSLogix 5000 alias tags (CSV), the C scanlist of a
// scanner firmware, and the register map of the 2012 Modbus/TCP scanner.
// docs/network.md states which layouts are confirmed and which assumed.
#include <cctype>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "network/render_map.hpp"

namespace edsc::network {

namespace {

// Connection-type codes of the Modbus paper's active-device table.
constexpr std::uint8_t type_code[] = {0x3C, 0x03, 0xB7, 0xC4};  // poll, strobe, cos, cyclic
constexpr const char* type_macro[] = {"POLL", "STROBE", "COS", "CYCLIC"};

std::string csv_quote(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"')
      out += "\"\"";
    else
      out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  }
  return out + "\"";
}

// A Logix tag name: letters, digits and single underscores, starting with a letter.
std::string tag_name(std::string_view name, std::uint32_t mac) {
  std::string out;
  for (const char c : name) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) != 0;
    if (ok)
      out += c;
    else if (!out.empty() && out.back() != '_')
      out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || std::isalpha(static_cast<unsigned char>(out.front())) == 0)
    out = fmt::format("Node{}_{}", mac, out);
  if (out.size() > 36) out.resize(36);
  return out;
}

// Text safe inside a C block comment, on one line.
std::string c_comment(std::string_view s) {
  std::string out;
  for (const char c : s) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F)
      out += ' ';
    else if (c == '/' && !out.empty() && out.back() == '*')
      out += " /";
    else
      out += c;
  }
  return out;
}

std::string c_ident(std::string_view s) {
  std::string out;
  for (const char c : s)
    out += std::isalnum(static_cast<unsigned char>(c)) != 0 ? static_cast<char>(std::toupper(c)) : '_';
  return out;
}

}  // namespace

std::string render_map_csv(const map_input& m) {
  const auto& p = m.p;
  std::string out = "remark,\"CSV-Import-Export\"\n";
  out +=
      fmt::format("remark,{}\n", csv_quote(fmt::format("Alias tags of network {}, written by edsc net map", p.name)));
  out += "0.3\nTYPE,SCOPE,NAME,DESCRIPTION,DATATYPE,SPECIFIER,ATTRIBUTES\n";
  for (std::size_t n = 0; n < p.nodes.size(); ++n) {
    const auto& node = p.nodes[n];
    for (const auto* image : {&m.l.input, &m.l.output}) {
      const block* first = nullptr;
      std::uint32_t bytes = 0;
      for (const auto& b : image->blocks)
        if (b.node == n) {
          if (first == nullptr) first = &b;
          bytes += b.size;
        }
      if (first == nullptr) continue;
      const auto at = place_of(p, *image, *first);
      const auto name = tag_name(node.name, node.mac) + (image->input ? "_I" : "_O");
      const auto desc = fmt::format("MAC {} {}{}: {} {}", node.mac, node.name,
                                    node.product.empty() ? "" : fmt::format(" ({})", node.product),
                                    plural(bytes, "byte"), image->input ? "in" : "out");
      // An alias names the DINT holding the node's first byte.
      const auto spec = fmt::format("Local:{}:{}.Data[{}]", p.slot, image->input ? "I" : "O", at.first_dword);
      out += fmt::format("ALIAS,,{},{},\"\",{},\"(RADIX := Hex, ExternalAccess := Read/Write)\"\n", csv_quote(name),
                         csv_quote(desc), csv_quote(spec));
    }
  }
  return out;
}

std::string render_map_c(const map_input& m) {
  const auto& p = m.p;
  const auto guard = "EDSC_NET_" + c_ident(p.name) + "_H";
  std::size_t entries = 0;
  for (const auto& n : p.nodes) entries += n.connections.size();
  std::string out = fmt::format(
      "/* Scanlist of DeviceNet network \"{}\" ({}), written by edsc net map.\n"
      " * Active devices: one entry per node and connection (MAC, connection type,\n"
      " * input and output bytes). Data tables: where each connection's data sits,\n"
      " * as a byte offset into the slave data area of the {} image (alignment {}). */\n"
      "#ifndef {}\n#define {}\n\n#include <stdint.h>\n\n",
      c_comment(p.name), c_comment(m.source_name), c_comment(p.profile->name), name_of(p.align), guard, guard);
  for (std::size_t t = 0; t < conn_type_count; ++t)
    out += fmt::format("#define EDSC_NET_CONN_{} 0x{:02X}u\n", type_macro[t], type_code[t]);
  out += fmt::format(
      "\n#define EDSC_NET_SCANNER_MAC {}u\n#define EDSC_NET_INPUT_AREA_BYTES {}u\n"
      "#define EDSC_NET_OUTPUT_AREA_BYTES {}u\n#define EDSC_NET_ACTIVE_DEVICE_COUNT {}u\n"
      "#define EDSC_NET_INPUT_TABLE_COUNT {}u\n#define EDSC_NET_OUTPUT_TABLE_COUNT {}u\n\n",
      p.scanner_mac, m.l.input.capacity, m.l.output.capacity, entries, m.l.input.blocks.size(),
      m.l.output.blocks.size());
  out +=
      "struct edsc_net_device {\n  uint8_t mac;\n  uint8_t conn_type;\n  uint16_t input_size;\n"
      "  uint16_t output_size;\n};\n\nstruct edsc_net_data {\n  uint8_t mac;\n  uint8_t conn_type;\n"
      "  uint16_t byte_count;\n  uint16_t offset;\n};\n\n";
  out += fmt::format("static const struct edsc_net_device edsc_net_active_devices[{}] = {{\n",
                     std::max<std::size_t>(entries, 1));
  for (const auto& n : p.nodes)
    for (const auto& c : n.connections)
      out += fmt::format("  {{{}u, EDSC_NET_CONN_{}, {}u, {}u}}, /* {} */\n", n.mac,
                         type_macro[static_cast<std::size_t>(c.type)], c.input, c.output, c_comment(n.name));
  if (entries == 0) out += "  {0u, 0u, 0u, 0u}, /* no node */\n";
  out += "};\n";
  for (const auto* image : {&m.l.input, &m.l.output}) {
    const char* dir = image->input ? "input" : "output";
    out += fmt::format("\nstatic const struct edsc_net_data edsc_net_{}_table[{}] = {{\n", dir,
                       std::max<std::size_t>(image->blocks.size(), 1));
    for (const auto& b : image->blocks)
      out +=
          fmt::format("  {{{}u, EDSC_NET_CONN_{}, {}u, {}u}}, /* {} */\n", p.nodes[b.node].mac,
                      type_macro[static_cast<std::size_t>(b.type)], b.size, b.offset, c_comment(p.nodes[b.node].name));
    if (image->blocks.empty()) out += "  {0u, 0u, 0u, 0u}, /* no data */\n";
    out += "};\n";
  }
  out += fmt::format("\n#endif /* {} */\n", guard);
  return out;
}

std::string render_map_modbus(const map_input& m) {
  const auto& p = m.p;
  std::string out = fmt::format(
      "Modbus/TCP register map of network {} for a DeviceNet scanner served as in the 2012 paper.\n"
      "Packing (assumed, UNCONFIRMED): the one-byte fields of each table are packed two per 16-bit holding\n"
      "register, first byte in the high byte, from the table's first register on; byte k of a table is in\n"
      "register base + k/2, high byte when k is even. 'address' is the byte offset of the data in the\n"
      "scanner's slave data area as laid out by net map (alignment {}). Read with function 03,\n"
      "write with 06 or 16. Fields wider than one byte do not fit and are marked.\n\n",
      p.name, name_of(p.align));
  auto regs = [](std::uint32_t base, std::uint32_t first_byte, std::uint32_t bytes) {
    const auto a = base + first_byte / 2, b = base + (first_byte + bytes - 1) / 2;
    return fmt::format("0x{:04X}{}-0x{:04X}{}", a, first_byte % 2 == 0 ? "H" : "L", b,
                       (first_byte + bytes - 1) % 2 == 0 ? "H" : "L");
  };
  auto byte = [](std::uint32_t v) { return v > 255 ? fmt::format("{} (>255!)", v) : std::to_string(v); };
  out += "active devices (0x04FD-0x06FC; 4 bytes per connection: MAC, type, input size, output size)\n";
  out += fmt::format("  {:>5}  {:>3}  {:<20}  {:<6}  {:>4}  {:>5}  {:>6}  {}\n", "entry", "MAC", "node", "conn", "code",
                     "in", "out", "registers");
  std::uint32_t k = 0;
  for (const auto& n : p.nodes)
    for (const auto& c : n.connections) {
      out += fmt::format("  {:>5}  {:>3}  {:<20}  {:<6}  0x{:02X}  {:>5}  {:>6}  {}\n", k, n.mac, n.name,
                         label_of(c.type), type_code[static_cast<std::size_t>(c.type)], byte(c.input), byte(c.output),
                         regs(0x04FD, k * 4, 4));
      ++k;
    }
  for (const auto* image : {&m.l.input, &m.l.output}) {
    const std::uint32_t base = image->input ? 0x0800 : 0x0B00;
    out += fmt::format(
        "\n{} data table (0x{:04X}-0x{:04X}; 5 bytes per connection: MAC, type, byte count, address "
        "high, address low)\n",
        image->input ? "input" : "output", base, base + 0x2FF);
    out += fmt::format("  {:>5}  {:>3}  {:<20}  {:<6}  {:>4}  {:>5}  {:>7}  {}\n", "entry", "MAC", "node", "conn",
                       "code", "bytes", "address", "registers");
    k = 0;
    for (const auto& b : image->blocks) {
      const auto& n = p.nodes[b.node];
      out += fmt::format("  {:>5}  {:>3}  {:<20}  {:<6}  0x{:02X}  {:>5}  0x{:04X}  {}\n", k, n.mac, n.name,
                         label_of(b.type), type_code[static_cast<std::size_t>(b.type)], byte(b.size), b.offset,
                         regs(base, k * 5, 5));
      ++k;
    }
  }
  return out;
}

}  // namespace edsc::network
