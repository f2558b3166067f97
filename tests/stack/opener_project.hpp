#pragma once
// Building a device from an EDS the way a user would: `edsc header --stack
// opener FILE -o DIR`, then `cmake -S DIR -B BUILD` against the shared,
// unmodified OpENer tree. One build folder per device, kept between runs
// and compiled through ccache, so a rerun rebuilds only what changed.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "netns/live_support.hpp"
#include "netns/run_edsc.hpp"
#include "test_paths.hpp"

namespace edsc::stack_test {

using live_test::quoted;
using live_test::run_edsc;
using live_test::shell;

struct device_build {
  bool ok = false;
  int generate_status = -1;  // `edsc header --stack opener`'s exit status
  std::string log, binary;
  double generate_s = 0, build_s = 0;
};

inline std::string stack_root() { return EDSC_STACK_BUILD_DIR; }

// Generates into <root>/<name>/gen and builds in <root>/<name>/build (warnings
// in the generated application are errors there).
inline device_build build_device(const std::string& name, const std::string& eds) {
  namespace fs = std::filesystem;
  device_build b;
  const auto dir = fs::path(stack_root()) / name;
  const auto gen = (dir / "gen").string(), build = (dir / "build").string();
  fs::create_directories(dir);
  const auto g = run_edsc("header --stack opener " + quoted(eds) + " -o " + quoted(gen));
  b.generate_s = g.seconds;
  b.generate_status = g.status;
  b.log = g.output;
  if (g.status != 0) return b;
  const auto start = std::chrono::steady_clock::now();
  const auto ccache = shell("command -v ccache").status == 0 ? " -DCMAKE_C_COMPILER_LAUNCHER=ccache" : "";
  // Every device's folders lie alike under the root: with paths relative to
  // a base folder above them (the caller's, else the root), ccache serves one
  // device's OpENer objects to the next, whose sources preprocess the same.
  const char* caller = std::getenv("CCACHE_BASEDIR");
  const auto base = "CCACHE_BASEDIR=" + quoted(caller != nullptr && *caller != 0 ? caller : stack_root()) +
                    "; export CCACHE_BASEDIR; ";
  // One job: the suite runs beside other builds on a shared machine.
  const auto r = shell(base + "cmake -S " + quoted(gen) + " -B " + quoted(build) +
                       " -DOPENER_SOURCE_DIR=" + quoted(EDSC_OPENER_SOURCE_DIR) +
                       " -DCMAKE_BUILD_TYPE=Release -DEDSC_OPENER_WERROR=ON" + ccache + " >" + quoted(build + ".log") +
                       " 2>&1 && cmake --build " + quoted(build) + " -j1 >>" + quoted(build + ".log") + " 2>&1");
  b.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  b.log += shell("tail -c 4000 " + quoted(build + ".log")).out;
  b.binary = build + "/opener/src/ports/POSIX/OpENer";
  b.ok = r.status == 0 && fs::exists(b.binary);
  return b;
}

}  // namespace edsc::stack_test
