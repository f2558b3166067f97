#pragma once
// The client's result type: a value, or the error that stopped it with its
// id (net/socket.hpp: live-timeout, live-malformed-reply, ...) and words
// for the user.
#include "net/socket.hpp"

namespace edsc::live {

using clock = net::clock;
using error = net::error;
template <class T>
using result = net::result<T>;

}  // namespace edsc::live
