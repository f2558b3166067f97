#include "network/network.hpp"

namespace edsc::network {

const char* name_of(conn_type t) {
  constexpr const char* names[] = {"poll", "strobe", "cos", "cyclic"};
  return names[static_cast<std::size_t>(t)];
}

const char* label_of(conn_type t) {
  constexpr const char* names[] = {"Poll", "Strobe", "COS", "Cyclic"};
  return names[static_cast<std::size_t>(t)];
}

const char* name_of(keying k) {
  switch (k) {
    case keying::exact: return "exact";
    case keying::compatible: return "compatible";
    case keying::none: return "none";
  }
  return "exact";
}

const char* name_of(alignment a) {
  switch (a) {
    case alignment::byte: return "byte";
    case alignment::word: return "word";
    case alignment::dword: return "dword";
  }
  return "dword";
}

const char* name_of(cable c) {
  switch (c) {
    case cable::unspecified: return "unspecified";
    case cable::thick: return "thick";
    case cable::thin: return "thin";
    case cable::flat: return "flat";
  }
  return "unspecified";
}

}  // namespace edsc::network
