#pragma once
// The bodies of the libFuzzer targets, shared with the regression replay in
// tests/reliability so a crash found by fuzzing is re-run by the normal (g++)
// build forever after. Each body returns an empty string when the input
// passed, else a description of the broken invariant; a crash, leak or
// sanitizer report is the other way to fail.
#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "check/check_file.hpp"
#include "cst/cst.hpp"
#include "edit/analyze.hpp"
#include "edit/editor.hpp"
#include "edit/fingerprint.hpp"
#include "edit/format.hpp"
#include "emit/emit_json.hpp"
#include "emit/header_view.hpp"
#include "lower/lower.hpp"
#include "lsp/jsonrpc.hpp"
#include "lsp/server.hpp"
#include "lsp/transport.hpp"
#include "network/layout.hpp"
#include "network/plan.hpp"
#include "network/render_map.hpp"
#include "parse/parser.hpp"
#include "source/source_file.hpp"

namespace edsc::fuzz {

inline constexpr const char* fuzz_path = "fuzz.eds";

// Parsing never throws, and the tree is lossless: printing it gives back
// every input byte.
inline std::string parse_body(std::string_view input) {
  const source_file src(fuzz_path, std::string(input));
  const auto parsed = parse(src);
  if (cst::print(parsed.tree) != input) return "cst::print does not reproduce the input";
  return {};
}

// The whole front end (parse, lower, every rule, the severity policy) plus
// the JSON dump, which sees every string of the model.
inline std::string check_body(std::string_view input) {
  const auto a = edit::analyze(fuzz_path, std::string(input));
  const auto j = emit::to_json(a->dev, *a->source);
  (void)j.dump();
  return {};
}

// `edsc fmt` changes layout only: when it formats, the model is unchanged.
inline std::string fmt_body(std::string_view input) {
  const std::string text(input);
  const auto a = edit::analyze(fuzz_path, text);
  if (a->has_syntax_errors()) return {};  // fmt refuses these files
  std::string why;
  const auto out = edit::format(a->tree, {}, why);
  if (!out) return {};
  if (*out == text) return {};
  if (edit::model_fingerprint(fuzz_path, *out) != edit::model_fingerprint(fuzz_path, text))
    return "formatting changed the model";
  return {};
}

// An editor given no operation hands back the bytes it was given.
inline std::string edit_body(std::string_view input) {
  const std::string text(input);
  const edit::editor ed(fuzz_path, text);
  if (ed.text() != text) return "edit with no operations changed the bytes";
  return {};
}

// Header generation renders with the built-in templates whatever the model
// holds: a template failure is a bug; EDS problems only withhold the header.
inline std::string header_body(std::string_view input) {
  const source_file src(fuzz_path, std::string(input));
  const auto parsed = parse(src);
  diagnostics diags;
  const auto dev = lower(parsed.tree, diags);
  const auto result = emit::generate_header(dev, src, emit::header_options{});
  if (result.failure) return "header template failed: " + *result.failure;
  if (!result.has_error() && result.text.empty()) return "header rendered empty";
  return {};
}

// The language server on a message stream: input starting with "Content-"
// is the raw byte stream (framing included); any other input is one message
// body per line after an initialize, so mutations reach the handlers. Every
// request and every broken message gets exactly one answer, every answer is
// JSON, and nothing throws.
inline std::string lsp_body(std::string_view input) {
  std::vector<std::string> bodies;
  if (input.substr(0, 8) == "Content-") {
    std::size_t at = 0;
    lsp::frame_reader reader([&](char* buf, std::size_t n) {
      const auto take = std::min(n, input.size() - at);
      std::copy_n(input.data() + at, take, buf);
      at += take;
      return take;
    });
    for (auto f = reader.next(); f.what != lsp::frame::kind::end; f = reader.next()) {
      if (f.what == lsp::frame::kind::message) bodies.push_back(std::move(f.body));
    }
  } else {
    bodies.emplace_back(R"({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}})");
    for (std::size_t at = 0; at <= input.size();) {
      auto eol = input.find('\n', at);
      if (eol == std::string_view::npos) eol = input.size();
      bodies.emplace_back(input.substr(at, eol - at));
      at = eol + 1;
    }
  }
  std::size_t answers = 0, expected = 0;
  std::string broken;
  lsp::server srv({}, [&](const std::string& body) {
    const auto j = lsp::json::parse(body, nullptr, false);
    if (j.is_discarded() || !j.is_object()) broken = "the server sent a message that is not a JSON object";
    else if (j.contains("id") && !j.contains("method")) ++answers;
  });
  for (const auto& b : bodies) {
    if (srv.exited()) break;
    const auto kind = lsp::parse_incoming(b).what;
    expected += kind == lsp::incoming::kind::request || kind == lsp::incoming::kind::invalid ? 1 : 0;
    srv.handle(b);
    srv.idle();
  }
  if (!broken.empty()) return broken;
  if (answers != expected) return "answers: " + std::to_string(answers) + ", expected " + std::to_string(expected);
  return {};
}

// A network file: read, checked and, when it plans, laid out and rendered in
// every map format. EDS files are not read (a fuzzed path could name any
// file); nodes with one are reported unreadable, the rest are planned.
inline std::string network_body(std::string_view input) {
  const network::eds_reader no_files = [](const std::string& path) -> io::read_result {
    return io::io_error{path + " is not read while fuzzing"};
  };
  auto c = network::check_network(std::make_unique<source_file>("fuzz.toml", std::string(input)), {}, no_files);
  if (!c.result) return {};
  const auto l = network::automap(*c.result);
  for (const auto* image : {&l.input, &l.output}) {
    for (std::size_t i = 0; i < image->blocks.size(); ++i) {
      if (image->blocks[i].end() > image->capacity) return "a block past the slave area";
      if (i > 0 && image->blocks[i - 1].end() > image->blocks[i].offset && l.problems.empty())
        return "blocks overlap without a reported problem";
    }
  }
  const network::map_input m{*c.result, l, "fuzz.toml"};
  if (!nlohmann::json::accept(network::render_map_json(m))) return "map JSON does not parse";
  (void)network::render_map_text(m);
  (void)network::render_map_svg(m);
  (void)network::render_map_csv(m);
  (void)network::render_map_c(m);
  (void)network::render_map_modbus(m);
  return {};
}

}  // namespace edsc::fuzz
