#include "lsp/documents.hpp"

#include "edit/analyze.hpp"

namespace edsc::lsp {

void apply_change(std::string& text, const content_change& change, const line_index& lines) {
  if (!change.where) {
    text = change.text;
    return;
  }
  const auto s = lines.to_span(*change.where);
  text.replace(s.begin, s.size(), change.text);
}

void apply_change(std::string& text, const content_change& change) {
  if (!change.where) {
    text = change.text;
    return;
  }
  apply_change(text, change, line_index(text));
}

std::string uri_to_path(std::string_view uri) {
  constexpr std::string_view scheme = "file://";
  if (uri.substr(0, scheme.size()) != scheme) return std::string(uri);
  uri.remove_prefix(scheme.size());
  // file://host/path: the host (usually empty or localhost) is not part of the path.
  if (const auto slash = uri.find('/'); slash != std::string_view::npos) uri.remove_prefix(slash);
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    const auto hex = [](char c) {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      return -1;
    };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2])));
      i += 2;
    } else {
      out.push_back(uri[i]);
    }
  }
  return out;
}

std::string& document::text_to_edit() {
  if (text_in_analysis_) {
    text_ = analysed->text();
    text_in_analysis_ = false;
  }
  return text_;
}

void document::analyse(const check_options& options) {
  if (analysed) return;
  lines.reset();
  analysed = edit::analyze(path, std::move(text_), options);
  text_.clear();
  text_in_analysis_ = true;
  lines = std::make_unique<line_index>(analysed->text());
}

void document::drop_analysis() {
  (void)text_to_edit();
  lines.reset();
  analysed.reset();
}

document& document_store::open(std::string uri, std::int64_t version, std::string text) {
  document d;
  d.uri = uri;
  d.path = uri_to_path(uri);
  d.version = version;
  d.replace_text(std::move(text));
  auto& slot = docs_[std::move(uri)];
  slot = std::move(d);
  return slot;
}

document* document_store::find(std::string_view uri) {
  const auto it = docs_.find(uri);
  return it == docs_.end() ? nullptr : &it->second;
}

void document_store::close(std::string_view uri) {
  if (const auto it = docs_.find(uri); it != docs_.end()) docs_.erase(it);
}

}  // namespace edsc::lsp
