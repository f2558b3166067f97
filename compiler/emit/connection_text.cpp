// The text of `edsc connection`: one block per ConnectionN, each line a
// setting a scanner asks for, with the EDS field it comes from. The words
// are connections/summary.hpp's, which the datasheet and the hover show too.
#include <fmt/format.h>

#include "connections/summary.hpp"
#include "emit/connection_render.hpp"

namespace edsc::emit {

namespace {

using namespace connections;

// Long byte strings wrap at 16 bytes, aligned under the first.
std::string wrapped_hex(const cip::bytes& b, std::size_t indent) {
  std::string out;
  for (std::size_t i = 0; i < b.size(); i += 16) {
    if (i > 0) out += "\n" + std::string(indent, ' ');
    out += hex_bytes(cip::bytes(b.begin() + static_cast<std::ptrdiff_t>(i),
                                b.begin() + static_cast<std::ptrdiff_t>(std::min(b.size(), i + 16))));
  }
  return out;
}

void direction_text(std::string& out, std::string_view name, const direction_setting& d,
                    const direction_summary& words) {
  constexpr std::size_t indent = 16;
  out += fmt::format("  {:<13} {}\n", name, words.size);
  if (!d.used) return;
  const std::string pad(indent, ' ');
  out += fmt::format("{}{}\n", pad, words.point);
  out += fmt::format("{}{}\n", pad, words.types);
  out += pad + "network parameters ";
  out += d.word16 ? fmt::format("0x{:04X} (Forward_Open), ", *d.word16) : std::string("over 511 bytes: ");
  out += fmt::format("0x{:08X} (Large_Forward_Open)\n", d.word32);
  out += fmt::format("{}{}\n", pad, words.rpi);
}

void path_text(std::string& out, const connection_setting& s) {
  out += fmt::format("  {:<13} {} ({} bytes)\n", "path", wrapped_hex(s.app_path, 16), s.app_path.size());
  for (const auto& p : s.path) {
    std::string value = p.value ? fmt::format("{}", *p.value) : std::string("(the tool fills it in)");
    if (p.param != 0) value += fmt::format(" (Param{} default)", p.param);
    const auto role = role_words(p.role);
    out += fmt::format("    {:<14}{} {}{}{}\n", hex_bytes(p.bytes), segment_words(p.kind), value,
                       role.empty() ? "" : ": ", role);
  }
}

void key_text(std::string& out, const connection_setting& s) {
  if (!s.key) {
    out += fmt::format("  {:<13} none: [Device] lacks a number the key needs\n", "key");
    return;
  }
  const auto& k = *s.key;
  out += fmt::format("  {:<13} {}: vendor {}, device type {}, product code {}, revision {}.{}, {}\n", "key",
                     hex_bytes(s.key_bytes), k.vendor, k.device_type, k.product_code, k.major, k.minor,
                     k.compatible ? "compatible" : "exact");
}

void one_text(std::string& out, const connection_setting& s, const source_file& src) {
  const auto lc = src.position(s.at.begin);
  const auto words = summarize(s);
  out += fmt::format("Connection{} \"{}\" (line {})\n", s.number, s.name, lc.line);
  out += fmt::format("  {:<13} {}\n", "kind", words.kind);
  out += fmt::format("  {:<13} {}; transport byte 0x{:02X}\n", "transport", words.transport, s.transport);
  if (!words.owner_label.empty()) out += fmt::format("  {:<13} {}\n", words.owner_label, words.owners);
  if (!words.note.empty()) out += fmt::format("  {:<13} no request: {}\n", "note", words.note);
  path_text(out, s);
  key_text(out, s);
  direction_text(out, "O->T", s.ot, words.ot);
  direction_text(out, "T->O", s.to, words.to);
  if (!words.configuration.empty())
    out += fmt::format("  {:<13} {}: {}\n", "configuration", words.configuration,
                       s.config_data.empty() ? "none" : wrapped_hex(s.config_data, 16));
  if (s.config_instance != 0) out += config_field_lines(s, 4);
  if (!s.request.empty())
    out += fmt::format("  {:<13} {}, {} bytes:\n{}{}\n", "request",
                       s.large ? "Large_Forward_Open (a size over 511 bytes)" : "Forward_Open (no size over 511 bytes)",
                       s.request.size(), std::string(16, ' '), wrapped_hex(s.request, 16));
}

}  // namespace

std::string render_connections_text(const std::vector<connection_setting>& all, const source_file& src) {
  std::string out;
  for (const auto& s : all) {
    if (!out.empty()) out += "\n";
    one_text(out, s, src);
  }
  return out;
}

}  // namespace edsc::emit
