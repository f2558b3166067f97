#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <utility>

#include "source/span.hpp"

namespace edsc::cst {

inline constexpr std::uint32_t npos = std::numeric_limits<std::uint32_t>::max();

enum class token_kind : std::uint8_t {
  blank,         // run of spaces and tabs
  newline,       // CR, LF or CRLF
  comment,       // `$` to end of line
  bom,           // a UTF-8 byte-order mark, only ever the file's first token
  lbracket,      // `[` of a section header
  section_name,  // the name between the brackets (trimmed)
  rbracket,      // `]`
  keyword,       // entry keyword before `=`
  equals,
  comma,
  semicolon,
  string,  // one quoted piece, quotes and `L` prefix included
  bare,    // unquoted value: number, date, reference, keyword...
  lbrace,
  rbrace,
  skipped,  // bytes the parser stepped over while recovering from an error
};

// The trivia kinds come first: one comparison per token.
[[nodiscard]] constexpr bool is_trivia(token_kind k) { return k <= token_kind::bom; }

// Tokens tile the input: token i ends where token i+1 begins, the first starts
// at 0 and the last ends at the end of the file. That is what makes the tree
// lossless.
struct token {
  span where;
  token_kind kind;
};

// The tokens of a file, five bytes each: because they tile the input, a token
// begins where the previous one ends, so only ends and kinds are stored (the
// token array would otherwise be the largest part of the tree). Elements are
// read by value.
class token_list {
 public:
  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = token;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = token;
    iterator(const token_list* l, std::size_t i) : list_(l), i_(i) {}
    token operator*() const { return (*list_)[i_]; }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    iterator operator++(int) {
      auto old = *this;
      ++i_;
      return old;
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.i_ == b.i_; }

   private:
    const token_list* list_;
    std::size_t i_;
  };

  token_list() = default;
  token_list(token_list&& other) noexcept { *this = std::move(other); }
  token_list& operator=(token_list&& other) noexcept {
    bounds_ = std::move(other.bounds_);
    kinds_ = std::move(other.kinds_);
    size_ = std::exchange(other.size_, 0);
    capacity_ = std::exchange(other.capacity_, 0);
    gap_ = std::exchange(other.gap_, npos);
    return *this;
  }
  token_list(const token_list& other) { *this = other; }
  token_list& operator=(const token_list& other) {
    if (this != &other) {
      size_ = 0;
      regrow(other.size_);
      std::copy_n(other.bounds_.get(), other.size_ + 1, bounds_.get());
      std::copy_n(other.kinds_.get(), other.size_, kinds_.get());
      size_ = other.size_;
      gap_ = other.gap_;
    }
    return *this;
  }

  void reserve(std::size_t n) {
    if (n > capacity_) regrow(n);
  }
  // Pushing is most of what the parser does per token: one capacity check
  // for both arrays, and the previous end is read without a test.
  void push_back(token t) {
    if (size_ == capacity_) regrow(std::max<std::size_t>(16, 2 * capacity_));
    const std::uint32_t last = bounds_[size_];
    // A token that does not start where the last one ended cannot be stored
    // faithfully; remember the first such offset for first_structure_violation.
    if (t.where.begin != last && gap_ == npos) gap_ = last;
    kinds_[size_] = t.kind;
    bounds_[++size_] = t.where.end;
  }
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  [[nodiscard]] token operator[](std::size_t i) const { return {span{bounds_[i], bounds_[i + 1]}, kinds_[i]}; }
  [[nodiscard]] token back() const { return (*this)[size() - 1]; }
  [[nodiscard]] iterator begin() const { return {this, 0}; }
  [[nodiscard]] iterator end() const { return {this, size()}; }
  // Where the last token ends (0 when there is none).
  [[nodiscard]] std::uint32_t end_offset() const { return size_ == 0 ? 0 : bounds_[size_]; }
  [[nodiscard]] std::uint32_t first_gap() const { return gap_; }

 private:
  // Capacity for n tokens, keeping the first size_. Allocated uninitialised:
  // a generous reservation costs address space only until it is written.
  void regrow(std::size_t n) {
    auto bounds = std::make_unique_for_overwrite<std::uint32_t[]>(n + 1);
    auto kinds = std::make_unique_for_overwrite<token_kind[]>(n);
    if (bounds_) {
      std::copy_n(bounds_.get(), size_ + 1, bounds.get());
      std::copy_n(kinds_.get(), size_, kinds.get());
    } else {
      bounds[0] = 0;
    }
    bounds_ = std::move(bounds);
    kinds_ = std::move(kinds);
    capacity_ = n;
  }

  // bounds_[0] is 0 and bounds_[i + 1] is where token i ends, so token i is
  // bounds_[i]..bounds_[i + 1] with no special case for the first one.
  std::unique_ptr<std::uint32_t[]> bounds_;
  std::unique_ptr<token_kind[]> kinds_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
  std::uint32_t gap_ = npos;
};

}  // namespace edsc::cst
