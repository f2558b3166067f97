// `edsc new`: a complete EDS from a few facts about the device. The text is
// generated plainly and then laid out by the formatter, so a new file is
// already `fmt`-clean.
#include <ctime>

#include <fmt/format.h>

#include "edit/format.hpp"
#include "edit/locate.hpp"
#include "edit/new_device.hpp"
#include "edit/value_check.hpp"
#include "model/decode.hpp"
#include "parse/parser.hpp"

namespace edsc::edit {

namespace {

std::string type_name(std::uint32_t type) {
  switch (type) {
    case 0: return "Generic Device (deprecated)";
    case 7: return "General Purpose Discrete I/O";
    case 12: return "Communications Adapter";
    case 43: return "Generic Device";
    case 100: return "Vendor Specific";
    default: throw edit_error(fmt::format("no usual name for product type {}; give --product-type-name", type));
  }
}

std::uint16_t connection_bit(const std::string& c) {
  if (c == "poll") return 0x0001;
  if (c == "strobe") return 0x0002;
  if (c == "cos") return 0x0004;
  if (c == "cyclic") return 0x0008;
  throw edit_error(fmt::format("unknown DeviceNet connection '{}'; choose poll, strobe, cos or cyclic", c));
}

void now(std::string& date, std::string& time) {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  if (date.empty()) date = fmt::format("{:02}-{:02}-{:04}", tm.tm_mon + 1, tm.tm_mday, tm.tm_year + 1900);
  if (time.empty()) time = fmt::format("{:02}:{:02}:{:02}", tm.tm_hour, tm.tm_min, tm.tm_sec);
}

void devicenet_io(const device_spec& s, std::string& out) {
  auto conns = s.connections.empty() ? std::vector<std::string>{"poll", "cos"} : s.connections;
  std::uint16_t all = 0;
  for (const auto& c : conns) all |= connection_bit(c);
  if ((all & 0x0004) && (all & 0x0008))
    throw edit_error("cos and cyclic share one DeviceNet connection; choose one of them");
  if (s.input == 0 && s.output == 0)
    throw edit_error("a DeviceNet node has data one way at least: give --input-bytes or --output-bytes");
  out += "[IO_Info]\n";
  out += fmt::format("Default = 0x{:04X};\n", connection_bit(conns.front()));
  const std::pair<const char*, std::uint16_t> infos[] = {
      {"PollInfo", 0x0001}, {"StrobeInfo", 0x0002}, {"COSInfo", 0x0004}, {"CyclicInfo", 0x0008}};
  // Strobe carries one bit to the node: outputs of more than a byte are not strobed.
  const std::uint16_t out_mask = s.output <= 1 ? all : static_cast<std::uint16_t>(all & ~0x0002);
  for (const auto& [name, bit] : infos) {
    if (!(all & bit)) continue;
    const bool out_ok = s.output > 0 && (out_mask & bit);
    out += fmt::format("{} = 0x{:04X}, {}, {};\n", name, all, s.input > 0 ? 1 : 0, out_ok ? 1 : 0);
  }
  // Assembly instances 100 (input) and 150 (output): vendor-specific range.
  if (s.input > 0)
    out += fmt::format("Input1 = {}, 0, 0x{:04X}, {}, 6, \"20 04 24 64 30 03\", {};\n", s.input, all,
                       quote(s.input_name), quote(s.input_help));
  if (s.output > 0)
    out += fmt::format("Output1 = {}, 0, 0x{:04X}, {}, 6, \"20 04 24 96 30 03\", {};\n", s.output, out_mask,
                       quote(s.output_name), quote(s.output_help));
}

void ethernetip_io(const device_spec& s, std::string& out) {
  if (s.input == 0 || s.output == 0)
    throw edit_error(
        "an EtherNet/IP device made by edsc new has an exclusive-owner connection: give "
        "--input-bytes and --output-bytes (1 byte or more each)");
  out += "[Assembly]\n";
  out += fmt::format("Assem100 = {}, \"\", {}, 0x0000,,;\n", quote(s.input_name), s.input);
  out += fmt::format("Assem150 = {}, \"\", {}, 0x0000,,;\n", quote(s.output_name), s.output);
  out += "[Connection Manager]\n";
  // Exclusive owner, cyclic, class 1; O->T point-to-point with run/idle
  // header, T->O multicast or point-to-point; config 151, points 150 / 100.
  out += fmt::format(
      "Connection1 = 0x04010002, 0x44640405, , {}, Assem150, , {}, Assem100, , , , , \"Exclusive Owner\", \"\", "
      "\"20 04 24 97 2C 96 2C 64\";\n",
      s.output, s.input);
  out += "[Port]\n";
  out += "Port1 = TCP, \"EtherNet/IP Port\", \"20 F5 24 01\", 2;\n";
  out += "[Capacity]\n";
  out += "MaxIOConnections = 1;\nMaxMsgConnections = 2;\n";
  out += fmt::format("TSpec1 = TxRx, {}, 1000;\n", std::max(s.input, s.output));
}

std::string eds_text(const device_spec& spec, const std::string& eol) {
  auto s = spec;
  if (s.name.empty()) throw edit_error("--name is empty; a device needs a product name");
  if (s.vendor > 0xFFFF || s.product_type > 0xFFFF || s.product_code > 0xFFFF)
    throw edit_error("vendor, product type and product code are 16-bit numbers (0 to 65535)");
  if (s.vendor_name.empty()) s.vendor_name = fmt::format("Vendor {}", s.vendor);
  if (s.product_type_name.empty()) s.product_type_name = type_name(s.product_type);
  if (s.network != "devicenet" && s.network != "ethernetip")
    throw edit_error(fmt::format("unknown network '{}'; choose devicenet or ethernetip", s.network));
  if (!s.date.empty() && s.time.empty()) s.time = "00:00:00";
  now(s.date, s.time);
  model::date d{};
  model::time_of_day t{};
  model::revision r{};
  bool lexed = false;
  if (!model::decode::date(s.date, d, lexed)) throw edit_error(fmt::format("date '{}' is not mm-dd-yyyy", s.date));
  if (!model::decode::time(s.time, t, lexed)) throw edit_error(fmt::format("time '{}' is not hh:mm:ss", s.time));
  if (!model::decode::revision(s.revision, r, lexed) || r.major > 255 || r.minor > 255 || r.major == 0)
    throw edit_error(fmt::format("revision '{}' is not major.minor (1..255 each)", s.revision));

  std::string out = fmt::format("$ {}: electronic data sheet created by edsc new.\n", s.name);
  out += "[File]\n";
  out += fmt::format("DescText = {};\n", quote(s.description.empty() ? s.name + " EDS file" : s.description));
  out += fmt::format("CreateDate = {};\nCreateTime = {};\n", s.date, s.time);
  out += fmt::format("ModDate = {};\nModTime = {};\n", s.date, s.time);
  out += "Revision = 1.0;\n";
  out += "[Device]\n";
  out += fmt::format("VendCode = {};\nVendName = {};\n", s.vendor, quote(s.vendor_name));
  out += fmt::format("ProdType = {};\nProdTypeStr = {};\n", s.product_type, quote(s.product_type_name));
  out += fmt::format("ProdCode = {};\nMajRev = {};\nMinRev = {};\n", s.product_code, r.major, r.minor);
  out += fmt::format("ProdName = {};\n", quote(s.name));
  if (!s.catalog.empty()) out += fmt::format("Catalog = {};\n", quote(s.catalog));
  out += "[Device Classification]\n";
  out += fmt::format("Class1 = {};\n", s.network == "devicenet" ? "DeviceNet" : "EtherNetIP");
  if (s.network == "devicenet")
    devicenet_io(s, out);
  else
    ethernetip_io(s, out);

  const source_file src("<new>", out);
  const auto parsed = parse(src);
  if (!parsed.diags.empty())
    throw edit_error(fmt::format("internal: generated text does not parse: {}", parsed.diags.front().message));
  auto formatted = format(parsed.tree, format_options{eol});
  if (!formatted) throw edit_error("internal: " + formatted.error().why);
  return *formatted;
}

}  // namespace

edit_result<std::string> make_eds(const device_spec& spec, const std::string& eol) {
  return as_edit_result([&] { return eds_text(spec, eol); });
}

}  // namespace edsc::edit
