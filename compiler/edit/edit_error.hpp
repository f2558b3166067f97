#pragma once
// What the edit room's operations return: done, or refused with the reason
// and nothing changed. The checks deep inside a request throw edit_error;
// each public operation turns it into its result (as_edit_result), so no
// exception leaves the room.
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "base/result.hpp"

namespace edsc::edit {

// A request that cannot be carried out: bad address, bad value, a missing
// entry. The message names the valid choices; nothing has been written.
struct edit_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class T>
using edit_result = result<T, edit_error>;
using edited = edit_result<void>;

// Runs `f`, the room's throwing implementation of an operation, and returns
// what it made or the edit_error that stopped it.
template <class F>
[[nodiscard]] auto as_edit_result(F&& f) -> edit_result<std::invoke_result_t<F>> {
  try {
    if constexpr (std::is_void_v<std::invoke_result_t<F>>) {
      std::forward<F>(f)();
      return {};
    } else {
      return std::forward<F>(f)();
    }
  } catch (const edit_error& e) {
    return fail(e);
  }
}

}  // namespace edsc::edit
