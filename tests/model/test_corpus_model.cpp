// Every corpus file lowers; the model's counts agree with an independent
// scanner; golden dumps of a reviewed handful do not drift.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "corpus_dirs.hpp"
#include "emit/emit_json.hpp"
#include "golden.hpp"
#include "model_support.hpp"
#include "test_paths.hpp"

namespace fs = std::filesystem;
using namespace edsc;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<fs::path> corpus_files() { return edsc::corpora::sample(); }

std::string lower_ascii(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The independent count: no parser, just a scanner that skips comments and
// strings, tracks `[section]` headers and counts `StemN =` per section.
// Keys are "section|stem" in lower case.
std::map<std::string, int> scan_counts(const std::string& t) {
  std::map<std::string, int> n;
  std::string section;
  std::size_t i = 0;
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  while (i < t.size()) {
    const char c = t[i];
    if (c == '$') {
      while (i < t.size() && t[i] != '\n' && t[i] != '\r') ++i;
    } else if (c == '"') {
      for (++i; i < t.size() && t[i] != '"' && t[i] != '\n'; ++i)
        if (t[i] == '\\') ++i;
      ++i;
    } else if (c == '[') {
      const auto close = t.find(']', i);
      if (close == std::string::npos) break;
      section = lower_ascii(t.substr(i + 1, close - i - 1));
      while (!section.empty() && section.back() == ' ') section.pop_back();
      while (!section.empty() && section.front() == ' ') section.erase(0, 1);
      i = close + 1;
    } else if (is_word(c) && (i == 0 || !is_word(t[i - 1]))) {
      std::size_t j = i;
      while (j < t.size() && is_word(t[j])) ++j;
      std::string word = t.substr(i, j - i);
      std::size_t k = j;
      while (k < t.size() && (t[k] == ' ' || t[k] == '\t' || t[k] == '\r' || t[k] == '\n')) ++k;
      if (k < t.size() && t[k] == '=') {
        std::size_t d = word.size();
        while (d > 0 && std::isdigit(static_cast<unsigned char>(word[d - 1]))) --d;
        if (d < word.size()) ++n[section + "|" + lower_ascii(word.substr(0, d))];
      }
      i = j;
    } else {
      ++i;
    }
  }
  return n;
}

int sum(const std::map<std::string, int>& n, const std::string& section_prefix,
        std::initializer_list<const char*> stems) {
  int total = 0;
  for (const auto& [key, count] : n) {
    const auto bar = key.find('|');
    const auto sec = key.substr(0, bar);
    if (sec.rfind(section_prefix, 0) != 0) continue;
    // `connection manager` also covers the per-port `connection manager2`
    if (sec != section_prefix && !std::isdigit(static_cast<unsigned char>(sec.back()))) continue;
    for (const auto* s : stems)
      if (key.substr(bar + 1) == s) total += count;
  }
  return total;
}

}  // namespace

TEST(CorpusModel, EveryFileLowersAndCountsAgree) {
  const auto files = corpus_files();
  ASSERT_GE(files.size(), edsc::corpora::sample_size());
  std::chrono::nanoseconds lower_time{0};
  std::size_t bytes = 0;
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    auto text = slurp(f);
    bytes += text.size();
    const auto counts = scan_counts(text);
    auto src = std::make_unique<source_file>(f.string(), std::move(text));
    const auto parsed = parse(*src);
    diagnostics diags;
    const auto t0 = std::chrono::steady_clock::now();
    const auto dev = lower(parsed.tree, diags);
    lower_time += std::chrono::steady_clock::now() - t0;
    EXPECT_FALSE(dev.incomplete);
    EXPECT_NO_THROW((void)emit::to_json(dev, *src).dump());

    int params = 0, proxies = 0;
    for (const auto& p : dev.params) (p.kind == model::param_kind::param ? params : proxies)++;
    EXPECT_EQ(params, sum(counts, "params", {"param"}));
    EXPECT_EQ(proxies, sum(counts, "params", {"proxyparam", "proxiedparam", "constructedparam"}));
    EXPECT_EQ(static_cast<int>(dev.enums.size()), sum(counts, "params", {"enum", "proxyenum", "proxiedenum"}));
    EXPECT_EQ(static_cast<int>(dev.enum_pars.size()), sum(counts, "enumpar", {"param"}));
    EXPECT_EQ(static_cast<int>(dev.groups.size()), sum(counts, "groups", {"group"}));
    EXPECT_EQ(static_cast<int>(dev.assemblies.size()),
              sum(counts, "assembly",
                  {"assem", "assemexa", "proxyassem", "proxiedassem", "proxyassemexa", "proxiedassemexa"}));
    EXPECT_EQ(static_cast<int>(dev.variants.size()),
              sum(counts, "assembly", {"variant", "variantexa", "bitstringvariant"}));
    EXPECT_EQ(static_cast<int>(dev.connections.size()), sum(counts, "connection manager", {"connection"}));
    EXPECT_EQ(static_cast<int>(dev.io.inputs.size()), sum(counts, "io_info", {"input"}));
    EXPECT_EQ(static_cast<int>(dev.io.outputs.size()), sum(counts, "io_info", {"output"}));
    EXPECT_EQ(static_cast<int>(dev.io.input_exas.size() + dev.io.output_exas.size()),
              sum(counts, "io_info", {"inputexa", "outputexa"}));
    EXPECT_EQ(static_cast<int>(dev.proxy_connections.size()),
              sum(counts, "connection manager", {"proxyconnect", "proxiedconnect"}));
    EXPECT_EQ(static_cast<int>(dev.variant_io.inputs.size() + dev.variant_io.outputs.size()),
              sum(counts, "variant_io_info", {"input", "output"}));
    EXPECT_EQ(static_cast<int>(dev.ports.size()), sum(counts, "port", {"port"}));
    EXPECT_EQ(static_cast<int>(dev.cap.tspecs.size()), sum(counts, "capacity", {"tspec"}));
  }
  const double ms = std::chrono::duration<double, std::milli>(lower_time).count();
  std::cout << "[ lowering ] " << files.size() << " files, " << bytes << " bytes in " << ms << " ms\n";
}

// Golden dumps: regenerate with EDSC_UPDATE_GOLDEN=1, then review the diff.
class GoldenDump : public testing::TestWithParam<const char*> {};

TEST_P(GoldenDump, MatchesCheckedInJson) {
  const fs::path eds = fs::path(EDSC_CORPUS_DIR) / GetParam();
  const fs::path golden = fs::path(EDSC_TESTS_DIR) / "model" / "golden" / (std::string(GetParam()) + ".json");
  auto src = std::make_unique<source_file>(eds.filename().string(), slurp(eds));
  const auto parsed = parse(*src);
  diagnostics diags;
  const auto dev = lower(parsed.tree, diags);
  const std::string out = emit::to_json(dev, *src).dump(1) + "\n";
  if (edsc::test::update_golden()) {
    std::ofstream(golden, std::ios::binary) << out;
    GTEST_SKIP() << "golden rewritten: " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden;
  const auto expected = slurp(golden);
  if (out != expected) {
    // Point at the first differing line rather than printing megabytes.
    std::size_t line = 1, i = 0;
    while (i < out.size() && i < expected.size() && out[i] == expected[i]) line += out[i++] == '\n';
    FAIL() << "dump differs from " << golden << " at line " << line;
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, GoldenDump,
                         testing::Values("EIPStackGroup__OpENer__opener_sample_app.eds",
                                         "sbb777__a_2025_pc_w_dnet__HILSCHER_NETX90_DN_DNS.eds",
                                         "sbb777__a_2025_pc_w_dnet__476297.eds",
                                         "ME-Catalyst__iodd-manager__54611_MVK_Pro_ME_DIO8_IOL8_5P_AB.eds",
                                         "SerafinTech__node-st-eds-parse__00010003028B0100.eds"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           return "file" + std::to_string(info.index);
                         });
