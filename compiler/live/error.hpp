#pragma once
// The client's result type: a value, or the error that stopped it with its
// id (net/socket.hpp: live-timeout, live-malformed-reply, ...) and words
// for the user.
#include <string_view>

#include <fmt/format.h>

#include "cip/bytes.hpp"
#include "net/socket.hpp"

namespace edsc::live {

using clock = net::clock;
using error = net::error;
template <class T>
using result = net::result<T>;

// A request of ours that the codec refuses to encode (a length over its
// field): nothing is sent.
inline error refused_to_encode(std::string_view what, const cip::encode_error& e) {
  return error{net::error_id::too_large, fmt::format("{}: {}", what, e.what())};
}

}  // namespace edsc::live
