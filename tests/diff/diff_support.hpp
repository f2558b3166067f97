#pragma once
// Helpers of the diff tests: analysing text in memory, picking differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "diff/diff.hpp"
#include "edit/analyze.hpp"
#include "test_paths.hpp"

namespace diff_test {

namespace fs = std::filesystem;
using edsc::diff::difference;
using edsc::diff::impact;

inline std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string project_file(const std::string& rel) { return read_bytes(fs::path(EDSC_PROJECT_DIR) / rel); }

struct compared {
  std::unique_ptr<edsc::analysis> before, after;
  edsc::diff::result r;
  [[nodiscard]] const difference* find(std::string_view kind) const {
    for (const auto& d : r.differences)
      if (d.kind == kind) return &d;
    return nullptr;
  }
  [[nodiscard]] std::vector<std::string> kinds() const {
    std::vector<std::string> out;
    for (const auto& d : r.differences) out.push_back(d.kind);
    return out;
  }
  [[nodiscard]] std::string dump() const { return edsc::diff::render_text(r, *before, *after, {}); }
};

inline compared compare(const std::string& old_text, const std::string& new_text, const edsc::diff::options& opt = {},
                        const std::string& old_name = "old.eds", const std::string& new_name = "new.eds") {
  compared c;
  c.before = edsc::edit::analyze(old_name, old_text);
  c.after = edsc::edit::analyze(new_name, new_text);
  c.r = edsc::diff::compare(*c.before, *c.after, opt);
  return c;
}

// A small EtherNet/IP device the diff tests change piece by piece.
inline const std::string device_eds = R"($ A small EtherNet/IP device for the diff tests
[File]
        DescText = "diff test device";
        CreateDate = 01-15-2024;
        CreateTime = 10:30:00;
        Revision = 1.0;

[Device]
        VendCode = 65535;
        VendName = "edsc tests";
        ProdType = 12;
        ProdTypeStr = "Communications Adapter";
        ProdCode = 7;
        MajRev = 2;
        MinRev = 3;
        ProdName = "Diff Device";
        Catalog = "D-1";

[Device Classification]
        Class1 = EtherNetIP;

[Params]
        Param1 = 0, , , 0x0000, 0xC7, 2, "Speed", "rpm", "Motor speed", 0, 3000, 1500, , , , , , , , , 0;
        Param2 = 0, , , 0x0000, 0xC6, 1, "Mode", "", "Operating mode", 0, 2, 0, , , , , , , , , 0;
        Enum2 = 0, "Off", 1, "Run", 2, "Jog";
        Param3 = 0, , , 0x0010, 0xC7, 2, "Status", "", "Status word", 0, 65535, 0, , , , , , , , , 0;

[Assembly]
        Assem100 = "Output", "20 04 24 64 30 03", 4, 0x0000, , , 16, Param1, 8, Param2, 8, ;
        Assem101 = "Input", "20 04 24 65 30 03", 2, , , , 16, Param3;
)";

// `text` with the first occurrence of `from` replaced by `to` (which must exist).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace diff_test
