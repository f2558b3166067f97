#include "source/source_file.hpp"

#include <algorithm>

#include "base/utf8.hpp"
#include "source/line_starts.hpp"

namespace edsc {

source_file::source_file(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)), view_(text_) {}

source_file::source_file(std::string path, std::unique_ptr<char[]> bytes, std::size_t size)
    : path_(std::move(path)), view_(bytes.get(), size) {
  owner_ = std::shared_ptr<const char[]>(std::move(bytes));
}

source_file::source_file(std::string path, std::shared_ptr<const void> owner, std::string_view bytes,
                         const std::atomic<bool>* changed)
    : path_(std::move(path)), owner_(std::move(owner)), view_(bytes), changed_(changed) {}

void source_file::index_lines() const {
  std::call_once(indexed_, [this] { line_starts_ = line_starts(view_); });
}

std::uint32_t source_file::line_count() const {
  index_lines();
  return static_cast<std::uint32_t>(line_starts_.size());
}

line_col source_file::position(std::uint32_t offset) const {
  index_lines();
  offset = std::min<std::uint32_t>(offset, size());
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<std::uint32_t>(it - line_starts_.begin());
  // A byte-order mark is no column: the first line's text starts after it.
  const std::uint32_t begin = line == 1 ? std::min(utf8::bom_length(view_), offset) : line_starts_[line - 1];
  return {line, offset - begin + 1};
}

std::string_view source_file::line_text(std::uint32_t line) const {
  index_lines();
  if (line == 0 || line > line_starts_.size()) return {};
  const std::uint32_t begin = line == 1 ? utf8::bom_length(view_) : line_starts_[line - 1];
  std::uint32_t end = line < line_starts_.size() ? line_starts_[line] : size();
  while (end > begin && (view_[end - 1] == '\n' || view_[end - 1] == '\r')) --end;
  return view_.substr(begin, end - begin);
}

}  // namespace edsc
