#pragma once
// Time limits inside the tests, multiplied by the build's EDSC_TEST_TIME_SCALE
// (1 in Release, 10 under ASan + UBSan; tests/CMakeLists.txt), so a verdict
// never hangs on how slow the instrumented build or a loaded machine is. A
// limit only catches hangs; the real checks are on what a run produced.
#ifndef EDSC_TEST_TIME_SCALE
#define EDSC_TEST_TIME_SCALE 1
#endif

namespace edsc::test_time {

inline constexpr int scale = EDSC_TEST_TIME_SCALE;

// `limit` (a std::chrono duration or a plain count) times the scale.
template <class T>
constexpr T scaled(T limit) {
  return limit * scale;
}

// The size of an input whose point is its size (a million fields, 10^5
// sections): whole in Release, where a quadratic step would show, and
// divided by the scale under the sanitizers, which find a memory error in the
// same code paths at a tenth of the size and would otherwise spend minutes on it.
template <class T>
constexpr T shrunk(T size) {
  return size / scale;
}

}  // namespace edsc::test_time
