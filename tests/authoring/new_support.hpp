#pragma once
// `edsc new` run with its standard output (the new file) and standard error
// apart, and a reader of the fields of one entry of the result.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "authoring_support.hpp"
#include "test_paths.hpp"

namespace authoring {

struct new_run {
  int status = -1;
  std::string out;  // standard output: the new file
  std::string err;  // standard error: diagnostics and messages
};

class NewOptions : public scratch_test {
 protected:
  // `edsc args...` with standard output and standard error apart.
  new_run run(const std::vector<std::string>& args) {
    std::string cmd = quote_arg(EDSC_BINARY);
    for (const auto& a : args) {
      cmd += ' ';
      cmd += quote_arg(a);
    }
    const auto out = dir_ / "stdout", err = dir_ / "stderr";
    const int raw = std::system((cmd + " >" + quote_arg(out.string()) + " 2>" + quote_arg(err.string())).c_str());
    new_run r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128;
    r.out = read_bytes(out);
    r.err = read_bytes(err);
    return r;
  }

  // The flags that give the input and output sizes in bytes, as this edsc
  // names them (--input/--output, or --input-bytes/--output-bytes).
  std::vector<std::string> io_bytes(int in, int out) {
    static const bool bytes_suffix = run({"new", "--help"}).out.find("--input-bytes") != std::string::npos;
    const std::string suffix = bytes_suffix ? "-bytes" : "";
    std::vector<std::string> args;
    if (in > 0) args.insert(args.end(), {"--input" + suffix, std::to_string(in)});
    if (out > 0) args.insert(args.end(), {"--output" + suffix, std::to_string(out)});
    return args;
  }

  // `edsc new` for a DeviceNet node (2 bytes in, 1 out) with `extra` options.
  new_run make(std::vector<std::string> extra, int in = 2, int out = 1) {
    std::vector<std::string> args{"new", "--vendor", "65535", "--product-type", "7", "--product-code",
                                  "5",   "--name",   "Node"};
    if (std::find(extra.begin(), extra.end(), "--date") == extra.end())
      args.insert(args.end(), {"--date", "01-02-2024"});
    for (auto& a : io_bytes(in, out)) args.push_back(std::move(a));
    for (auto& a : extra) args.push_back(std::move(a));
    return run(args);
  }
};

// The fields of `keyword`'s entry (first occurrence, case as written), comments
// and layout removed, quotes kept: a reader of the format's syntax, not of
// fmt's layout.
inline std::vector<std::string> fields(const std::string& text, const std::string& keyword) {
  std::size_t at = 0;
  for (;;) {
    at = text.find(keyword, at);
    if (at == std::string::npos) return {};
    const bool line_start = at == 0 || text[at - 1] == '\n' || text[at - 1] == ' ' || text[at - 1] == '\t';
    const auto eq = text.find_first_not_of(" \t", at + keyword.size());
    if (line_start && eq != std::string::npos && text[eq] == '=') {
      at = eq + 1;
      break;
    }
    at += keyword.size();
  }
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = at; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') quoted = !quoted;
    if (!quoted && c == '$') {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
      continue;
    }
    if (!quoted && c == ';') return out;
    if (!quoted && c == ',') {
      out.emplace_back();
      continue;
    }
    if (!quoted && (c == ' ' || c == '\t' || c == '\r' || c == '\n')) continue;
    out.back() += c;
  }
  return {};
}

using strings = std::vector<std::string>;

// Each keyword of `want` names a one-field entry of `text` with that value.
inline void expect_values(const std::string& text, const std::vector<std::pair<std::string, std::string>>& want) {
  for (const auto& [keyword, value] : want) EXPECT_EQ(fields(text, keyword), strings{value}) << keyword;
}

}  // namespace authoring
