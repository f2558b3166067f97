// The libFuzzer entry point of every target: built once per target with
// EDSC_FUZZ_TARGET naming its body in fuzz_bodies.hpp (parse -> parse_body);
// see CMakeLists.txt here. Built with EDSC_FUZZ=ON.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_bodies.hpp"

#define EDSC_FUZZ_CAT2(a, b) a##b
#define EDSC_FUZZ_CAT(a, b) EDSC_FUZZ_CAT2(a, b)
#define EDSC_FUZZ_STR2(a) #a
#define EDSC_FUZZ_STR(a) EDSC_FUZZ_STR2(a)

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto broken = edsc::fuzz::EDSC_FUZZ_CAT(EDSC_FUZZ_TARGET, _body)({reinterpret_cast<const char*>(data), size});
  if (!broken.empty()) {
    std::fprintf(stderr, "fuzz_" EDSC_FUZZ_STR(EDSC_FUZZ_TARGET) ": %s\n", broken.c_str());
    std::abort();  // libFuzzer saves the input as a crash
  }
  return 0;
}
