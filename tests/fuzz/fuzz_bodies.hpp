#pragma once
// The bodies of the libFuzzer targets, shared with the regression replay in
// tests/reliability so a crash found by fuzzing is re-run by the normal (g++)
// build forever after. Each body returns an empty string when the input
// passed, else a description of the broken invariant; a crash, leak or
// sanitizer report is the other way to fail.
#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "capture/reader.hpp"
#include "capture/trace.hpp"
#include "check/check_file.hpp"
#include "cip/connection_manager.hpp"
#include "cip/encap.hpp"
#include "cip/file_transfer.hpp"
#include "cip/io_frame.hpp"
#include "cip/message.hpp"
#include "cst/cst.hpp"
#include "diff/diff.hpp"
#include "edit/analyze.hpp"
#include "edit/editor.hpp"
#include "edit/fingerprint.hpp"
#include "edit/format.hpp"
#include "emit/emit_json.hpp"
#include "emit/header.hpp"
#include "live/session.hpp"
#include "lower/lower.hpp"
#include "lsp/jsonrpc.hpp"
#include "lsp/server.hpp"
#include "lsp/transport.hpp"
#include "network/layout.hpp"
#include "network/plan.hpp"
#include "network/render_map.hpp"
#include "parse/parser.hpp"
#include "sim/inputs.hpp"
#include "sim/state.hpp"
#include "source/line_starts.hpp"
#include "source/source_file.hpp"
#include "verify/enip_capture.hpp"

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
  const auto out = edit::format(a->tree, {});
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

// The language server on an EDS document: input that is neither a framed
// stream nor JSON lines is opened as a document, and every feature is asked
// for at positions spread over it, then once more after an edit, so the
// fuzzer's EDS mutations reach hover, navigation, completion, rename,
// symbols, formatting and code actions.
inline std::vector<std::string> lsp_document_session(std::string_view text) {
  using nlohmann::json;
  std::vector<std::string> out;
  int id = 0;
  const auto dump = [](const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); };
  const auto request = [&](const char* method, json params) {
    out.push_back(dump({{"jsonrpc", "2.0"}, {"id", ++id}, {"method", method}, {"params", std::move(params)}}));
  };
  const auto notify = [&](const char* method, json params) {
    out.push_back(dump({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}}));
  };
  const json doc = {{"uri", "file:///fuzz.eds"}};
  request("initialize", {{"capabilities", json::object()}});
  notify("initialized", json::object());
  notify("textDocument/didOpen",
         {{"textDocument", {{"uri", "file:///fuzz.eds"}, {"languageId", "eds"}, {"version", 1}, {"text", text}}}});
  // Lines as the server counts them (LF, CRLF and a lone CR).
  const auto starts = line_starts(text);
  const std::size_t lines = starts.size();
  const std::size_t probes = std::min<std::size_t>(lines, 12);
  // Per probe two cursors: on the line's first word (a keyword or section
  // name: definitions and renames start there) and at a column taken from
  // the text itself, so the fuzzer steers it (past the line's end included).
  const auto at = [&](std::size_t k, bool first_word) {
    const std::size_t line = k * lines / probes;
    const std::size_t len = (line + 1 < lines ? starts[line + 1] - 1 : text.size()) - starts[line];
    std::size_t column = 0;
    if (first_word) {
      while (column < len && (text[starts[line] + column] == ' ' || text[starts[line] + column] == '\t')) ++column;
    } else {
      column = static_cast<unsigned char>(text.empty() ? 0 : text[(starts[line] + k) % text.size()]) % (len + 2);
    }
    return json{{"line", line}, {"character", column}};
  };
  const auto everything_at = [&](const json& pos) {
    const json tp = {{"textDocument", doc}, {"position", pos}};
    request("textDocument/hover", tp);
    request("textDocument/definition", tp);
    request("textDocument/references",
            {{"textDocument", doc}, {"position", pos}, {"context", {{"includeDeclaration", true}}}});
    request("textDocument/completion", tp);
    request("textDocument/prepareRename", tp);
    request("textDocument/documentHighlight", tp);
    // Renames within the family of the word under the cursor (Param7 ->
    // Param1, likely taken, and Param1007, likely free), and across families.
    const std::size_t line = pos["line"], column = pos["character"];
    std::size_t b = starts[line] + column, e = b;
    while (e < text.size() && std::isalpha(static_cast<unsigned char>(text[e]))) ++e;
    const std::size_t digits = e;
    while (e < text.size() && e < digits + 6 && std::isdigit(static_cast<unsigned char>(text[e]))) ++e;
    std::vector<std::string> names{"Param2", "Assem9999"};
    if (b < digits && digits < e) {
      const std::string stem(text.substr(b, digits - b));
      names = {stem + "1", stem + std::to_string(std::stoul(std::string(text.substr(digits, e - digits))) + 1000)};
    }
    for (const auto& name : names)
      request("textDocument/rename", {{"textDocument", doc}, {"position", pos}, {"newName", name}});
    request("textDocument/codeAction", {{"textDocument", doc},
                                        {"range", {{"start", pos}, {"end", pos}}},
                                        {"context", {{"diagnostics", json::array()}}}});
  };
  for (std::size_t k = 0; k < probes; ++k)
    for (const bool first_word : {true, false}) everything_at(at(k, first_word));
  request("textDocument/documentSymbol", {{"textDocument", doc}});
  request("textDocument/foldingRange", {{"textDocument", doc}});
  // A query cut from the middle of the text, so the fuzzer steers it too.
  request("workspace/symbol", {{"query", std::string(text.substr(text.size() / 2, 4))}});
  request("textDocument/formatting", {{"textDocument", doc}, {"options", {{"tabSize", 4}, {"insertSpaces", true}}}});
  request("textDocument/codeAction",
          {{"textDocument", doc},
           {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", lines}, {"character", 0}}}}},
           {"context", {{"diagnostics", json::array()}, {"only", {"source.fixAll"}}}}});
  // An incremental edit: a line from the middle copied to the start, then the
  // features once more on the changed text.
  const std::size_t mid = lines / 2;
  const auto mid_text = text.substr(starts[mid], (mid + 1 < lines ? starts[mid + 1] : text.size()) - starts[mid]);
  const json origin = {{"line", 0}, {"character", 0}};
  json change = {{"range", {{"start", origin}, {"end", origin}}}, {"text", mid_text}};
  notify("textDocument/didChange", {{"textDocument", {{"uri", "file:///fuzz.eds"}, {"version", 2}}},
                                    {"contentChanges", json::array({std::move(change)})}});
  everything_at(at(probes / 2, true));
  everything_at(at(probes / 2, false));
  request("shutdown", nullptr);
  notify("exit", nullptr);
  return out;
}

// The language server on a message stream: input starting with "Content-"
// is the raw byte stream (framing included); input starting with "{" is one
// message body per line after an initialize, so mutations reach the
// handlers; anything else is an EDS document (lsp_document_session). Every
// request and every broken message gets exactly one answer, every answer is
// JSON, nothing throws, and no handler fails inside (InternalError, a log
// line).
inline std::string lsp_body(std::string_view input) {
  std::vector<std::string> bodies;
  bool document = false;
  if (input.substr(0, 8) == "Content-") {
    std::size_t at = 0;
    lsp::frame_reader reader([&](char* buf, std::size_t n) {
      const auto take = std::min(n, input.size() - at);
      std::copy_n(input.data() + at, take, buf);
      at += take;
      return take;
    });
    for (auto f = reader.next(); f.what != lsp::frame::kind::end; f = reader.next()) {
      if (f.what == lsp::frame::kind::message) bodies.emplace_back(f.body);
    }
  } else if (input.substr(0, 1) == "{") {
    bodies.emplace_back(R"({"jsonrpc":"2.0","id":0,"method":"initialize","params":{"capabilities":{}}})");
    for (std::size_t at = 0; at <= input.size();) {
      auto eol = input.find('\n', at);
      if (eol == std::string_view::npos) eol = input.size();
      bodies.emplace_back(input.substr(at, eol - at));
      at = eol + 1;
    }
  } else {
    bodies = lsp_document_session(input);
    document = true;
  }
  std::size_t answers = 0, expected = 0;
  std::string broken;
  const auto fail = [&](std::string why) {
    if (broken.empty()) broken = std::move(why);
  };
  lsp::server srv(
      {},
      [&](const std::string& body) {
        const auto j = lsp::json::parse(body, nullptr, false);
        if (j.is_discarded() || !j.is_object()) return fail("the server sent a message that is not a JSON object");
        if (!j.contains("id") || j.contains("method")) return;
        ++answers;
        if (j.contains("error") && j["error"].value("code", 0) == static_cast<int>(lsp::error_code::internal_error))
          fail("internal error: " + j["error"].value("message", std::string()));
      },
      // The server logs what went wrong in a handler. With well-formed
      // messages (the document mode) any such line is a bug; with fuzzed
      // ones only an internal error or a failed analysis is.
      [&](std::string_view line) {
        if (document || line.find("internal error") != std::string_view::npos ||
            line.find(": diagnostics of ") != std::string_view::npos)
          fail(std::string(line));
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

// `edsc diff` on two files: the input up to its first NUL byte is the old
// file, the rest the new one (no NUL: the input against itself). Both
// renderings work on any pair and the JSON parses; a file diffed against an
// identical copy shows no difference (diff refuses files with syntax errors,
// so those only have to survive).
inline std::string diff_body(std::string_view input) {
  const auto nul = input.find('\0');
  const auto old_text = input.substr(0, nul);
  const auto new_text = nul == std::string_view::npos ? input : input.substr(nul + 1);
  const auto a = edit::analyze("old.eds", std::string(old_text));
  const auto b = edit::analyze("new.eds", std::string(new_text));
  const auto r = diff::compare(*a, *b);
  (void)diff::render_text(r, *a, *b, {});
  if (!nlohmann::json::accept(diff::render_json(r, *a, *b))) return "diff JSON does not parse";
  const auto same = edit::analyze("new.eds", std::string(old_text));
  if (!a->has_syntax_errors() && !diff::compare(*a, *same).differences.empty())
    return "a file differs from an identical copy";
  return {};
}

// The EtherNet/IP reply decoders on any bytes (what a hostile device may
// send): no crash, no read out of bounds (the sanitizers watch), every error
// located inside the input, and what decodes accounts for its bytes.
inline std::string cip_body(std::string_view input) {
  const cip::byte_view b(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  constexpr std::size_t base = 24;
  auto inside = [&](const cip::decode_error& e) { return e.offset >= base && e.offset <= base + b.size(); };
  std::string broken;
  auto judge = [&](const char* what, const auto& r) {
    if (!r.ok() && !inside(r.error()) && broken.empty())
      broken = std::string(what) + ": error located outside the input";
  };
  if (cip::decode_encap_header(b).ok() && b.size() < cip::encap_header_size)
    return "a header decoded from fewer than 24 bytes";
  judge("CPF", cip::decode_cpf(b, base));
  judge("RegisterSession", cip::decode_register_session(b, base));
  judge("SendRRData", cip::decode_send_rr_data(b, base));
  judge("SendUnitData", cip::decode_send_unit_data(b, base));
  judge("ListIdentity", cip::decode_list_identity(b, base));
  judge("ListServices", cip::decode_list_services(b, base));
  judge("Identity", cip::decode_identity_all(b, base));
  judge("Forward_Open reply", cip::decode_forward_open_ok(b, base));
  judge("Forward_Close reply", cip::decode_forward_close(b, base));
  judge("Initiate_Upload reply", cip::decode_upload_offer(b, base));
  if (const auto p = cip::decode_upload_packet(b, base); p.ok()) {
    if (2 + p->data.size() + (p->checksum ? 2 : 0) != b.size())
      return "an upload packet's parts do not add up to its bytes";
  } else {
    judge("Upload_Transfer reply", p);
  }
  if (const auto r = cip::decode_reply(b, base); r.ok()) {
    if (4 + 2 * r->additional.size() + r->data.size() != b.size()) return "a reply's parts do not add up to its bytes";
  } else {
    judge("reply", r);
  }
  for (const bool run_idle : {false, true}) {
    const auto f = cip::decode_io_frame(b, run_idle);
    if (f.ok() && f->data.size() > b.size()) return "an I/O frame with more data than bytes";
  }
  return broken;
}

// A small device for the simulator's fuzz body: one exclusive owner with
// configuration and one input-only connection.
inline constexpr std::string_view sim_fuzz_eds = R"eds([File]
DescText = "edsc sim fuzz device";
CreateDate = 11-26-2026;
CreateTime = 00:00:00;
Revision = 1.0;

[Device]
VendCode = 65535;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 7;
MajRev = 1;
MinRev = 2;
ProdName = "edsc sim fuzz";

[Device Classification]
Class1 = EtherNetIP;

[Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","","",1000,100000,20000,,,,,,,,,;
Param2 = 0,,,0x0000,0xC3,2,"Speed","","",-100,100,-5,,,,,,,,,;
Param3 = 0,,,0x0002,0xC6,1,"Mode","","",0,9,1,,,,,,,,,;
Enum3 = 1,"one",4,"four";
Param4 = 0,,,0x0000,0xCA,4,"Gain","","",,,1.5,,,,,,,,,;

[Assembly]
Assem100 = "Input",,8,0x0000,,,16,Param2,8,Param3,32,Param4;
Assem150 = "Output",,4,0x0000,,,;
Assem151 = "Config",,2,0x0000,,,;

[Connection Manager]
Connection1 = 0x84010002,0x44640405,Param1,,Assem150,Param1,,Assem100,,,,Assem151,"Owner","","20 04 24 97 2C 96 2C 64";
Connection2 = 0x02010002,0x44640305,Param1,0,,Param1,,Assem100,,,,,"Input only","","20 04 24 97 2C 98 2C 64";
)eds";

// The simulator's request handling on any bytes (what a hostile scanner may
// send): the first byte picks the door (TCP or UDP encapsulation, a bare CIP
// request, a class 1 frame, a control line, CIP requests in a row each after
// its length byte), the rest is the message. No crash, no stall, and every
// encapsulation reply's length field counts its bytes.
inline std::string sim_body(std::string_view input) {
  static const auto model = edit::analyze("fuzz.eds", std::string(sim_fuzz_eds));
  static const auto prototype = [] {
    auto d = sim::build_device(model->dev, 1);
    d.file.name = "fuzz.eds";  // the File object serves the EDS
    d.file.content.assign(sim_fuzz_eds.begin(), sim_fuzz_eds.end());
    return d;
  }();
  if (input.empty()) return {};
  sim::state s;
  s.dev = prototype;
  sim::link l{0x0100007F, 0};
  const auto now = sim::clock::time_point{} + std::chrono::hours(1);
  const cip::byte_view b(reinterpret_cast<const std::uint8_t*>(input.data()) + 1, input.size() - 1);
  // A registered session and an open owner connection first, so deeper paths are reached.
  (void)sim::handle_encap(
      s, l, cip::encode_encap(cip::command::register_session, 0, {}, cip::register_session_data()).value(), true, now);
  switch (static_cast<std::uint8_t>(input[0]) % 6) {
    case 0:
    case 1: {
      const auto out = sim::handle_encap(s, l, b, input[0] % 4 == 0, now);
      if (out.reply && (out.reply->size() < cip::encap_header_size ||
                        ((*out.reply)[2] | ((*out.reply)[3] << 8)) + cip::encap_header_size != out.reply->size()))
        return "an encapsulation reply whose length field does not count its bytes";
      break;
    }
    case 2: {
      const auto r = sim::handle_cip(s, l, b, now);
      if (!cip::decode_reply(r, 0).ok()) return "a CIP reply the client cannot decode";
      break;
    }
    case 3: sim::consume_io(s, b, l.peer_ip, now); break;
    case 4: {
      const auto reply = sim::control(s, input.substr(1));
      if (!reply.empty() && !nlohmann::json::accept(reply)) return "a control answer that is not JSON";
      break;
    }
    default:  // an upload or a parameter change reaches its later states only after earlier requests
      for (std::size_t at = 0; at < b.size();) {
        const std::size_t n = std::min<std::size_t>(b[at], b.size() - at - 1);
        if (!cip::decode_reply(sim::handle_cip(s, l, b.subspan(at + 1, n), now), 0).ok())
          return "a CIP reply the client cannot decode";
        at += 1 + n;
      }
      break;
  }
  (void)sim::produce_io(s, now + std::chrono::hours(1000));  // past the longest timeout (512 x 2^32 us)
  if (!s.connections.empty()) return "a connection outlived its timeout";
  return {};
}

// The client's session machine (live/session.hpp) fed a device's side of a
// conversation: each step is a byte, below 0xF0 the length of the chunk of
// bytes that follows it, 0xF0 the deadline passing, 0xF1 the peer closing,
// 0xF2 a reset, 0xF3 the client closing. The session registers first; each
// time it is idle again it asks the next of ListIdentity, ListServices and a
// Get_Attribute_Single, so replies that pass every check reach the next request.
inline std::string session_check_transmit(const live::session& s, const cip::bytes& out) {
  const auto h = cip::decode_encap_header(out);
  if (!h || h->length + cip::encap_header_size != out.size())
    return "a request whose length field does not count its bytes";
  if (h->session != s.handle() && s.handle() != 0)
    return "a request carrying another session handle than the one granted";
  return {};
}

inline std::string session_check_event(const live::session& s, const live::event& ev) {
  if (const auto* r = std::get_if<live::registered>(&ev); r && (r->handle == 0 || r->handle != s.handle()))
    return "a session registered with a handle it does not hold";
  if (const auto* c = std::get_if<live::cip_reply>(&ev); c && c->reply.service != 0x8E)
    return "a reply to another service taken as the answer";
  if (const auto* e = std::get_if<live::error>(&ev); e && (e->id.empty() || e->message.empty()))
    return "an error without an id or words";
  return {};
}

inline std::string session_body(std::string_view input) {
  using namespace std::chrono_literals;
  live::session s(1000ms);
  auto now = live::clock::time_point{} + std::chrono::hours(1);
  // What the session has to send and to say, checked as soon as it has it.
  auto drain = [&s]() -> std::string {
    while (auto out = s.poll_transmit())
      if (auto broken = session_check_transmit(s, *out); !broken.empty()) return broken;
    while (auto ev = s.poll_event())
      if (auto broken = session_check_event(s, *ev); !broken.empty()) return broken;
    const bool waiting =
        s.current() == live::session::state::registering || s.current() == live::session::state::awaiting;
    if (waiting != s.next_deadline().has_value()) return "a deadline without a request under way, or the reverse";
    return {};
  };
  s.register_session(now);
  if (auto broken = drain(); !broken.empty()) return broken;
  unsigned asked = 0;
  const auto b = reinterpret_cast<const std::uint8_t*>(input.data());
  for (std::size_t at = 0; at < input.size();) {
    const auto op = b[at++];
    if (op < 0xF0) {
      const std::size_t n = std::min<std::size_t>(op, input.size() - at);
      s.handle_bytes(cip::byte_view(b + at, n), now);
      at += n;
    } else if (op == 0xF0) {
      if (const auto d = s.next_deadline()) now = *d;
      s.handle_timeout(now);
    } else if (op == 0xF1) {
      s.handle_closed({});
    } else if (op == 0xF2) {
      s.handle_closed("Connection reset by peer");
    } else if (op == 0xF3) {
      s.close();
    }
    if (auto broken = drain(); !broken.empty()) return broken;
    if (s.current() != live::session::state::idle || s.handle() == 0) continue;
    switch (asked++ % 3) {
      case 0: s.list_identity(now); break;
      case 1: s.list_services(now); break;
      default:
        s.request(
            cip::service::get_attribute_single,
            cip::encode_request(cip::service::get_attribute_single, cip::logical_path(cip::class_id::identity, 1, 7))
                .value(),
            now);
    }
    if (auto broken = drain(); !broken.empty()) return broken;
  }
  return {};
}
// The EDS a fuzzed capture is judged against: one class 1 connection with
// configuration, run/idle O->T, RPI limits from a parameter.
inline constexpr const char* capture_eds = R"eds([File]
DescText = "fuzz";
CreateDate = 01-01-2020;
CreateTime = 00:00:00;
Revision = 1.0;

[Device]
VendCode = 1;
VendName = "edsc";
ProdType = 12;
ProdTypeStr = "Communications Adapter";
ProdCode = 2;
MajRev = 1;
MinRev = 1;
ProdName = "simulator objects";
Catalog = "s";

[Params]
Param1 = 0,,,0x0000,0xC8,4,"RPI","us","",10000,50000,20000,,,,,,,,,;
Param2 = 0,,,0x0000,0xC7,2,"Speed","","",0,100,50,,,,,,,,,;

[Assembly]
Assem100 = "In","20 04 24 64 30 03",8,0x0000,,,64,;
Assem150 = "Out","20 04 24 96 30 03",4,0x0000,,,,;
Assem151 = "Cfg","20 04 24 97 30 03",2,0x0000,,,16,Param2;

[Connection Manager]
Connection1 = 0x04010002,0x44640405,Param1,4,Assem150,Param1,8,Assem100,,,2,Assem151,"io","","20 04 24 97 2C 96 2C 64";
)eds";

// A capture file (pcap, pcapng) read from memory, every message tracked and
// judged against capture_eds, the timeline rendered: whatever the bytes, the
// reading ends, nothing throws, and what the reader holds stays within its
// limits (fragments, TCP bytes held ahead of gaps, open directions).
inline std::string capture_body(std::string_view input) {
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  const capture::reassembly_limits fragments{8, 64 * 1024, 30'000'000'000};
  capture::tcp_limits tcp;
  tcp.max_streams = 16;
  tcp.max_held_per_stream = 4096;
  tcp.max_held_total = 16 * 1024;
  auto r = capture::reader::open_memory(bytes, fragments, tcp);
  if (!r) return r.error().message.empty() ? "a refused capture without a reason" : "";
  capture::tracker t;
  std::int64_t last = 0;
  for (;;) {
    auto m = r->next();
    if (!m || !m->has_value()) break;
    last = std::max(last, (*m)->time.total_ns());
    t.add(**m);
    if (r->fragments().pending_bytes() > fragments.max_bytes) return "fragments held past their cap";
    if (r->streams().open_streams() > tcp.max_streams) return "TCP directions open past their cap";
    // Each held segment counts 64 bytes more for its bookkeeping (tcp_stream.hpp).
    if (r->streams().held_bytes() > tcp.max_held_total + 64) return "TCP bytes held past their cap";
  }
  t.finish(last);
  static const auto eds = edit::analyze("fuzz.eds", capture_eds);
  const verify::capture_eds files[] = {{&eds->dev, eds->source.get()}};
  const auto v = verify::judge_capture(t, files);
  const std::string names[] = {"fuzz.eds"};
  (void)verify::render_timeline(t, v, names);
  for (const auto& f : v.findings)
    if (f.d.message.empty()) return "a finding without words";
  return {};
}

}  // namespace edsc::fuzz
