// A UTF-8 byte-order mark in front of an EDS file, through every command that
// reads one: the same answers as without it, and the mark written back by
// the commands that rewrite the file.
#include <regex>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"

namespace edsc::cli_test {
namespace {

const std::string bom = "\xEF\xBB\xBF";

// A file with a missing ';' on its first line and a missing ',' further
// down, so both the columns of line 1 and fix-its are compared.
const std::string findings_eds =
    "[File] DescText = \"t\" CreateDate = 07-30-2005; CreateTime = 12:00:00; Revision = 1.0;\n"
    "[Device]\n"
    "        VendCode = 65535; VendName = \"v\"; ProdType = 0; ProdTypeStr = \"t\"; ProdCode = 1;\n"
    "        MajRev = 0; MinRev = 1; ProdName = \"p\";\n"
    "[Device Classification]\n"
    "        Class1 = EtherNetIP;\n"
    "[Params]\n"
    "        Param1 = 0, , , 0x0000, 0xC7, 2, \"n\", \"\", \"\", 0, 10, 5 \"6\", , , , , , , , ;\n";

// SHA-256 digests of the input name the bytes, mark included.
std::string without_digests(std::string s) { return std::regex_replace(s, std::regex("[0-9a-f]{64}"), "<sha256>"); }

// Byte offsets (JSON's `offset`, SARIF's `byteOffset`) count the file's
// bytes, the mark's three included; lines and columns do not.
void unshift_offsets(nlohmann::json& j) {
  if (j.is_object()) {
    for (auto& [key, value] : j.items()) {
      if ((key == "offset" || key == "byteOffset") && value.is_number_unsigned() && value.get<unsigned>() >= 3)
        value = value.get<unsigned>() - 3;
      else
        unshift_offsets(value);
    }
  } else if (j.is_array()) {
    for (auto& v : j) unshift_offsets(v);
  }
}

class ByteOrderMark : public Cli {
 protected:
  // Runs `args` (where "IN" stands for the input) on the file without and
  // then with the mark, at the same path, and returns both results.
  std::pair<run_result, run_result> both(const std::string& text, std::vector<std::string> args) {
    const auto in = (dir_ / "dev.eds").string();
    for (auto& a : args)
      if (a == "IN") a = in;
    write_bytes(in, text);
    auto plain = run_edsc(args);
    write_bytes(in, bom + text);
    auto marked = run_edsc(args);
    return {std::move(plain), std::move(marked)};
  }
  void expect_same(const std::string& text, const std::vector<std::string>& args) {
    SCOPED_TRACE(args.front());
    const auto [plain, marked] = both(text, args);
    EXPECT_EQ(marked.status, plain.status);
    if (nlohmann::json::accept(plain.output)) {
      auto j = nlohmann::json::parse(marked.output, nullptr, false);
      unshift_offsets(j);
      EXPECT_EQ(j, nlohmann::json::parse(plain.output));
    } else {
      EXPECT_EQ(without_digests(marked.output), without_digests(plain.output));
    }
  }
};

TEST_F(ByteOrderMark, ReadingCommandsAnswerAsWithoutIt) {
  for (const auto* text : {&good_eds, &findings_eds}) {
    expect_same(*text, {"check", "IN", "--color", "never"});
    expect_same(*text, {"check", "IN", "--format", "json"});
    expect_same(*text, {"check", "IN", "--format", "sarif"});
    expect_same(*text, {"dump", "IN"});
    expect_same(*text, {"dump", "IN", "--json"});
    expect_same(*text, {"header", "IN", "-o", "-"});
    expect_same(*text, {"header", "IN", "-o", "-", "--stack", "opener"});
    expect_same(*text, {"fmt", "--check", "IN"});
  }
  const auto [plain, marked] = both(findings_eds, {"check", "IN", "--color", "never"});
  EXPECT_NE(plain.output.find("dev.eds:1:22: error: expected ';' at the end of entry"), std::string::npos)
      << plain.output;
  EXPECT_NE(plain.output.find("dev.eds:8:63: error: expected ','"), std::string::npos) << plain.output;
  EXPECT_EQ(marked.output.find(bom), std::string::npos) << "the mark is shown in a quoted line";
}

TEST_F(ByteOrderMark, DocAndDiffReadItAsText) {
  const auto old_file = file("old.eds", good_eds);
  auto [plain, marked] = both(good_eds, {"diff", old_file.string(), "IN"});
  EXPECT_EQ(plain.status, 0) << plain.output;
  EXPECT_EQ(marked.status, 0) << marked.output;
  EXPECT_EQ(marked.output, plain.output);
  const auto page = (dir_ / "dev.html").string();
  write_bytes(dir_ / "dev.eds", bom + findings_eds);
  const auto r = run_edsc({"doc", (dir_ / "dev.eds").string(), "-o", page});
  const auto html = read_bytes(page);
  EXPECT_EQ(html.find(bom), std::string::npos);
  EXPECT_EQ(html.find("syntax-stray"), std::string::npos) << r.output;
  EXPECT_NE(html.find("[File] DescText"), std::string::npos);
}

TEST_F(ByteOrderMark, WritersKeepItInFront) {
  const auto out = dir_ / "out.eds";
  const std::vector<std::vector<std::string>> commands = {
      {"fmt", "IN", "-o", out.string()},
      {"fix", "IN", "-o", out.string()},
      {"edit", "IN", "-o", out.string()},
      {"edit", "IN", "--set", "Device.MajRev=2", "--remove-section", "File", "-o", out.string()}};
  for (const auto& args : commands) {
    for (const auto* text : {&good_eds, &findings_eds}) {
      SCOPED_TRACE(args.front() + " " + std::to_string(args.size()) + (text == &good_eds ? " good" : " findings"));
      std::string written[2];
      run_result results[2];
      for (int marked = 0; marked < 2; ++marked) {
        fs::remove(out);
        write_bytes(dir_ / "dev.eds", marked == 1 ? bom + *text : *text);
        auto a = args;
        a[1] = (dir_ / "dev.eds").string();
        results[marked] = run_edsc(a);
        written[marked] = fs::exists(out) ? read_bytes(out) : "(not written)";
      }
      EXPECT_EQ(results[1].status, results[0].status) << results[1].output;
      EXPECT_EQ(results[1].output, results[0].output);
      if (written[0] != "(not written)")
        EXPECT_EQ(written[1], bom + written[0]);
      else
        EXPECT_EQ(written[1], written[0]);
    }
  }
}

TEST_F(ByteOrderMark, NetworkReadsANodeEdsWithIt) {
  const auto eds = fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-3byte.eds";
  const auto net = file("n.toml",
                        "[network]\nkind = \"devicenet\"\nname = \"t\"\nbaud = 125\n\n[scanner]\nprofile = "
                        "\"1769-SDN\"\nmac = 0\nslot = 5\n\n[[node]]\nmac = 2\nname = \"s\"\neds = \"dev.eds\"\n"
                        "connections = [\"cos\"]\ninput = 3\n");
  for (const auto* sub : {"check", "map"}) {
    SCOPED_TRACE(sub);
    write_bytes(dir_ / "dev.eds", read_bytes(eds));
    const auto plain = run_edsc({"net", sub, net.string()});
    write_bytes(dir_ / "dev.eds", bom + read_bytes(eds));
    const auto marked = run_edsc({"net", sub, net.string()});
    EXPECT_EQ(plain.status, 0) << plain.output;
    EXPECT_EQ(marked.status, plain.status) << marked.output;
    EXPECT_EQ(marked.output, plain.output);
  }
}

}  // namespace
}  // namespace edsc::cli_test
