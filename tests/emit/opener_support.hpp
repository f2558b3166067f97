#pragma once
// Shared by the unit tests of `edsc header --stack opener` (test_opener_plan.cpp,
// test_opener_render.cpp): an EDS text planned in memory, no OpENer build, and
// small builders for the [Device], [Assembly] and ConnectionN text they feed.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "emit/opener_plan.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

namespace edsc::test {

// An EDS planned for OpENer: the source, its model and what plan_opener said.
struct opener_case {
  std::unique_ptr<source_file> src;
  parse_result parsed;
  model::device dev;
  diagnostics diags;  // plan_opener's only (lowering's own findings are not OpENer's)
  std::vector<emit::header_issue> issues;
  emit::opener_plan plan;

  // The span of the `nth` occurrence of `needle` in the source (an empty
  // span at the end when it is not there, which no diagnostic points at).
  [[nodiscard]] span at(std::string_view needle, int nth = 0) const {
    const auto text = src->text();
    std::size_t pos = text.find(needle);
    while (nth-- > 0 && pos != std::string_view::npos) pos = text.find(needle, pos + 1);
    if (pos == std::string_view::npos) return span{src->size(), src->size()};
    return span{static_cast<std::uint32_t>(pos), static_cast<std::uint32_t>(pos + needle.size())};
  }
  // `inner` within the first occurrence of `around` (a field told apart by its neighbours).
  [[nodiscard]] span in(std::string_view around, std::string_view inner) const {
    const auto outer = at(around);
    const auto pos = around.find(inner);
    if (outer.empty() || pos == std::string_view::npos) return span{src->size(), src->size()};
    const auto begin = outer.begin + static_cast<std::uint32_t>(pos);
    return span{begin, begin + static_cast<std::uint32_t>(inner.size())};
  }
};

inline std::unique_ptr<opener_case> plan_eds(std::string text) {
  auto c = std::make_unique<opener_case>();
  c->src = std::make_unique<source_file>("opener-unit.eds", std::move(text));
  c->parsed = parse(*c->src);
  diagnostics lowering;
  c->dev = lower(c->parsed.tree, lowering);
  c->plan = emit::plan_opener(c->dev, *c->src, c->diags, c->issues);
  return c;
}

// VendCode 1234, ProdType 12, ProdCode 4321, revision 2.7, "Widget".
inline std::string device_section(std::string_view prod_name = "\"Widget\"") {
  return fmt::format(
      "[Device]\n"
      "    VendCode = 1234;\n"
      "    VendName = \"Acme\";\n"
      "    ProdType = 12;\n"
      "    ProdTypeStr = \"Communications Adapter\";\n"
      "    ProdCode = 4321;\n"
      "    MajRev = 2;\n"
      "    MinRev = 7;\n"
      "    ProdName = {};\n"
      "    Catalog = \"W-1\";\n\n",
      prod_name);
}

// Output (O->T) 100 of 16 bytes, configuration 120 of 10, input (T->O) 130
// of 32: sizes stated, no members.
inline std::string assembly_section(std::string_view extra = "") {
  return fmt::format(
      "[Assembly]\n"
      "    Assem100 = \"Out\", \"\", 16, 0x0001, , ;\n"
      "    Assem120 = \"Cfg\", \"\", 10, 0x0001, , ;\n"
      "    Assem130 = \"In\", \"\", 32, 0x0000, , ;\n"
      "{}\n",
      extra);
}

// One ConnectionN line; the RPIs are 10 ms each way.
struct conn {
  int number = 1;
  std::string trigger = "0x84010002";  // server, cyclic, exclusive owner, class 1
  std::string params = "0x44640405";   // O->T 32-bit run/idle header (format 4), T->O modeless (0)
  std::string ot_size = "", ot_format = "Assem100";
  std::string to_size = "", to_format = "Assem130";
  std::string config_size = "", config_format = "Assem120";
  std::string name = "Owner";
  std::string path = "\"20 04 24 78 2C 64 2C 82\"";  // config 120, O->T 100, T->O 130
  [[nodiscard]] std::string text() const {
    return fmt::format("    Connection{} = {}, {}, 10000, {}, {}, 10000, {}, {}, , , {}, {}, \"{}\", \"\", {};\n",
                       number, trigger, params, ot_size, ot_format, to_size, to_format, config_size, config_format,
                       name, path);
  }
};

// Connection1 an owner (conn{}); Connection2 and Connection4 input only
// (0x82010002, bit 25) and Connection3 listen only (0x81010002, bit 24), whose
// O->T is a heartbeat (format 2 in bits 8-10) to instance 198 or 199 with no
// data. Connection4 names configuration 120 without a size or format.
inline std::vector<conn> four_connections() {
  conn in1{.number = 2,
           .trigger = "0x82010002",
           .params = "0x44640205",
           .ot_format = "",
           .name = "In1",
           .path = "\"20 04 24 78 2C C6 2C 82\""};
  conn listen = in1;
  listen.number = 3;
  listen.trigger = "0x81010002";
  listen.name = "Listen";
  listen.path = "\"20 04 24 78 2C C7 2C 82\"";
  conn in2 = in1;
  in2.number = 4;
  in2.name = "In2";
  in2.config_format = "";
  return {conn{}, in1, listen, in2};
}

inline std::string connection_manager(const std::vector<conn>& cs) {
  std::string s = "[Connection Manager]\n    Object_Class_Code = 0x06;\n";
  for (const auto& c : cs) s += c.text();
  return s;
}

inline std::unique_ptr<opener_case> plan_connections(const std::vector<conn>& cs, std::string_view assemblies = "") {
  return plan_eds(device_section() + assembly_section(assemblies) + connection_manager(cs));
}

}  // namespace edsc::test
