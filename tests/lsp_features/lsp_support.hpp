#pragma once
// Analyses EDS text held by a test and finds offsets by the text around them.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "check/check_file.hpp"
#include "io/read_file.hpp"
#include "lsp/features.hpp"

namespace edsc::test {

inline std::unique_ptr<analysis> analyze_text(std::string text) {
  return analyze(std::make_unique<source_file>("test.eds", std::move(text)), check_options{});
}

// A file of the corpus or the project; null (and a failure) when unreadable.
inline std::unique_ptr<analysis> analyze_path(const std::string& path) {
  auto r = io::read_source(path);
  if (auto* src = (r ? &r.value() : nullptr)) return analyze(std::move(*src), check_options{});
  ADD_FAILURE() << r.error().message;
  return nullptr;
}

// Offset of the `n`th (0-based) occurrence of `needle`, plus `shift`.
inline std::uint32_t offset_of(const analysis& a, std::string_view needle, std::uint32_t shift = 0, int n = 0) {
  std::size_t at = a.text().find(needle);
  while (n-- > 0 && at != std::string_view::npos) at = a.text().find(needle, at + 1);
  EXPECT_NE(at, std::string_view::npos) << needle;
  return static_cast<std::uint32_t>(at) + shift;
}

inline std::string_view text_at(const analysis& a, span s) { return a.text().substr(s.begin, s.size()); }

// The line (1-based) a span starts on, so span lists read as `line:text`.
inline std::string where(const analysis& a, span s) {
  return std::to_string(a.source->position(s.begin).line) + ":" + std::string(text_at(a, s));
}

// `line:text` of each span, to compare span lists.
inline std::vector<std::string> lines(const analysis& a, const std::vector<span>& spans) {
  std::vector<std::string> out;
  for (auto s : spans) out.push_back(where(a, s));
  return out;
}

// Edits applied back to front (they do not overlap).
inline std::string apply(std::string_view text, std::vector<lsp::text_edit> edits) {
  std::sort(edits.begin(), edits.end(), [](const auto& x, const auto& y) { return x.range.begin > y.range.begin; });
  std::string out(text);
  for (const auto& e : edits) out.replace(e.range.begin, e.range.size(), e.new_text);
  return out;
}

// A small file with one of each kind of reference.
inline constexpr std::string_view sample = R"([File]
        DescText = "Sample";
        CreateDate = 01-02-2020;
        CreateTime = 10:00:00;
        Revision = 1.0;

[Device]
        VendCode = 65535;
        VendName = "Sample Vendor";
        ProdType = 12;
        ProdTypeStr = "Communications Adapter";
        ProdCode = 7;
        MajRev = 1;
        MinRev = 1;
        ProdName = "Sample";
        Catalog = "S-1";

[Device Classification]
        Class1 = EtherNetIP;

[IO_Info]
        Default = 0x0001;
        PollInfo = 0x0001, 1, 1;
        Input1 = 2, 16, 0x0001, "Status", 6, "20 04 24 64 30 03", "Status word";
        Output1 = 2, 16, 0x0001, "Command", 6, "20 04 24 96 30 03", "Command word";

[Params]
        Param1 = 0, 6, "20 04 24 01 30 [Param2]", 0x0012, 0xC7, 2, "Speed", "rpm", "Motor speed",
                0, 3000, 1500, 1, 1, 1, 0, , , , , 0;
        Param2 = 0, , , 0x0002, 0xC6, 1, "Mode", "", "Operating mode", 0, 2, 0, , , , , , , , , ;
        Enum2 = 0, "Off", 1, "Run", 2, "Test";
        Param3 = 0, , , 0x0000, 0xC8, 4, "RPI", "us", "", 1000, 100000, 10000, , , , , , , , , ;

[Groups]
        Group1 = "Motor", 2, 1, 2;

[Assembly]
        Assem100 = "Input", "20 04 24 64 30 03", 4, 0x0000, , , 16, Param1, 16, Param2;
        Assem150 = "Output", "", 2, 0x0000, , , 16, Param1;

[Connection Manager]
        Connection1 = 0x04010002, 0x44640405, Param3, 2, Assem150, Param3, 4, Assem100, , , , ,
                "Exclusive Owner", "", "20 04 24 01 2C 96 2C 64";
)";

}  // namespace edsc::test
