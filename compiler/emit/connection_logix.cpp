// `edsc connection --format logix`: each connection as the rows of Studio
// 5000's Generic Ethernet Module dialog (connections/logix.hpp decides
// them), with the configuration bytes its configuration tag must hold. The
// heading and owner words are connections/summary.hpp's, as in the text.
#include <fmt/format.h>

#include "connections/summary.hpp"
#include "emit/connection_render.hpp"

namespace edsc::emit {

namespace {

using namespace connections;

std::string instance_words(const logix_row& r) {
  return r.instance ? fmt::format("instance {}", *r.instance) : std::string("instance (none in the EDS path)");
}

std::string unicast_words(logix_unicast u) {
  switch (u) {
    case logix_unicast::yes: return "yes: the device offers point-to-point T->O only";
    case logix_unicast::no: return "no: the device offers multicast T->O only";
    case logix_unicast::either: return "either: the device offers point-to-point and multicast T->O";
  }
  return "";
}

void rows(std::string& out, const connection_setting& s, const logix_module& m) {
  const auto type = type_name(m.type);
  out += fmt::format("  {:<15}{}\n", "Comm Format", m.comm_format);
  out += fmt::format("  {:<15}{}, size {} ({}; {} bytes T->O)\n", "Input", instance_words(m.input), m.input.size, type,
                     m.input.bytes);
  if (m.input_only)
    out += fmt::format("  {:<15}{}, size 0 (the {} connection's O->T point: no data)\n", "Output",
                       instance_words(m.output), kind_words(s.kind));
  else
    out += fmt::format("  {:<15}{}, size {} ({}; {} bytes O->T)\n", "Output", instance_words(m.output), m.output.size,
                       type, m.output.bytes);
  if (s.config_instance != 0)
    out += fmt::format("  {:<15}{}, size {} (8-bit)\n", "Configuration", instance_words(m.configuration),
                       m.configuration.size);
  else
    out += fmt::format("  {:<15}none in the EDS path: size 0\n", "Configuration");
  const auto& d = s.to.used ? s.to : s.ot;
  // The row is named RPI already: the words without their own "RPI ".
  auto rpi = rpi_words(d.rpi, s.to.used ? "O->T" : "T->O");
  if (rpi.starts_with("RPI ")) rpi.erase(0, 4);
  out += fmt::format("  {:<15}{}\n", "RPI", rpi);
  out += fmt::format("  {:<15}{}\n", "Unicast", unicast_words(m.unicast));
}

void configuration_tag(std::string& out, const connection_setting& s) {
  if (s.config_data.empty()) return;
  out += fmt::format("  {:<15}{} bytes for the module's configuration tag, element 0 first:\n", "Config data",
                     s.config_data.size());
  for (std::size_t i = 0; i < s.config_data.size(); i += 16) {
    std::string line;
    for (std::size_t j = i; j < std::min(s.config_data.size(), i + 16); ++j)
      line += fmt::format("{}{:02X}", j == i ? "" : " ", s.config_data[j]);
    out += fmt::format("  {:<15}{}\n", "", line);
  }
  out += config_field_lines(s, 4);
}

void one_module(std::string& out, const connection_setting& s, const logix_module& m, const source_file& src) {
  const auto words = summarize(s);
  out +=
      fmt::format("Connection{} \"{}\" (line {}): {}\n", s.number, s.name, src.position(s.at.begin).line, words.kind);
  if (!words.owner_label.empty()) out += fmt::format("  {:<15}{}\n", words.owner_label, words.owners);
  if (!m.refusal.empty()) {
    out += fmt::format("  {:<15}{}\n", "Not possible", m.refusal);
    return;
  }
  rows(out, s, m);
  configuration_tag(out, s);
}

}  // namespace

std::string render_connections_logix(const std::vector<connection_setting>& all,
                                     const std::vector<logix_module>& modules, const source_file& src) {
  std::string out = fmt::format(
      "Generic Ethernet Module settings for {} (one module per connection; sizes in the comm format's unit)\n",
      src.path());
  for (std::size_t i = 0; i < all.size() && i < modules.size(); ++i) {
    out += "\n";
    one_module(out, all[i], modules[i], src);
  }
  return out;
}

}  // namespace edsc::emit
