#pragma once
// The one result type of fallible operations: a value or the error that
// stopped it. The shape of C++23's std::expected (has_value, value, error,
// and `fail(e)` for std::unexpected), written here because the clang of the
// fuzz build cannot compile <expected>; when it can, this becomes an alias.
// It depends on the standard library alone, so every room may include it.
#include <cassert>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

namespace edsc {

// The error half, spelled at the return site: `return fail(decode_error{...});`
template <class E>
struct failure {
  E error;
};

template <class E>
[[nodiscard]] failure<std::decay_t<E>> fail(E&& e) {
  return {std::forward<E>(e)};
}

template <class T, class E>
class [[nodiscard]] result {
  static_assert(!std::is_same_v<T, E>, "a result's value and error types must differ");

 public:
  using value_type = T;
  using error_type = E;

  result() requires std::is_default_constructible_v<T>
  = default;
  result(T v) : v_(std::in_place_index<0>, std::move(v)) {}  // NOLINT: implicit by design
  result(E e) : v_(std::in_place_index<1>, std::move(e)) {}  // NOLINT: implicit by design
  template <class F>
  requires std::is_constructible_v<E, F> result(failure<F> f)
      : v_(std::in_place_index<1>, std::move(f.error)) {}  // NOLINT: implicit by design

  [[nodiscard]] bool has_value() const { return v_.index() == 0; }
  [[nodiscard]] bool ok() const { return has_value(); }
  explicit operator bool() const { return has_value(); }

  [[nodiscard]] const T& value() const& {
    assert(has_value());
    return *std::get_if<0>(&v_);
  }
  [[nodiscard]] T& value() & {
    assert(has_value());
    return *std::get_if<0>(&v_);
  }
  [[nodiscard]] T&& value() && {
    assert(has_value());
    return std::move(*std::get_if<0>(&v_));
  }
  [[nodiscard]] const T& operator*() const& { return value(); }
  [[nodiscard]] T& operator*() & { return value(); }
  [[nodiscard]] const T* operator->() const { return &value(); }
  [[nodiscard]] T* operator->() { return &value(); }

  [[nodiscard]] const E& error() const& {
    assert(!has_value());
    return *std::get_if<1>(&v_);
  }
  [[nodiscard]] E& error() & {
    assert(!has_value());
    return *std::get_if<1>(&v_);
  }

  template <class U>
  [[nodiscard]] T value_or(U&& other) const& {
    return has_value() ? value() : static_cast<T>(std::forward<U>(other));
  }

 private:
  std::variant<T, E> v_;
};

// An operation that yields nothing but may fail.
template <class E>
class [[nodiscard]] result<void, E> {
 public:
  using value_type = void;
  using error_type = E;

  result() = default;
  result(E e) : e_(std::move(e)) {}  // NOLINT: implicit by design
  template <class F>
  requires std::is_constructible_v<E, F> result(failure<F> f) : e_(std::move(f.error)) {}  // NOLINT: implicit by design

  [[nodiscard]] bool has_value() const { return !e_.has_value(); }
  [[nodiscard]] bool ok() const { return has_value(); }
  explicit operator bool() const { return has_value(); }
  [[nodiscard]] const E& error() const& {
    assert(e_.has_value());
    return *e_;
  }

 private:
  std::optional<E> e_;  // the error; E need not be default-constructible
};

}  // namespace edsc
