// What the authoring commands tell a user to run next, and where they point:
// a command that is suggested does what it is suggested for, and a location
// names the text it quotes.
#include <regex>

#include "authoring_support.hpp"

namespace authoring {
namespace {

class Hints : public scratch_test {};

const std::string head =
    "[File]\n        DescText = \"t\"; CreateDate = 07-30-2005; CreateTime = 12:00:00; Revision = 1.0;\n"
    "        HomeURL = \"http://example.com\";\n"
    "[Device]\n        VendCode = 1; VendName = \"v\"; ProdType = 7; ProdTypeStr = \"t\"; ProdCode = 1;\n"
    "        MajRev = 1; MinRev = 1; ProdName = \"p\";\n";

TEST_F(Hints, FixIsSuggestedOnlyWhenItRepairsSomething) {
  // A stray word has no fix-it: `edsc fix` would change nothing.
  const auto stray = file("stray.eds", head + "        !oops\n");
  for (const auto& cmd :
       std::vector<std::vector<std::string>>{{"fmt", stray.string()}, {"diff", stray.string(), stray.string()}}) {
    const auto r = edsc(cmd);
    EXPECT_EQ(r.status, cmd[0] == "fmt" ? 1 : 2) << r.output;
    EXPECT_NE(r.output.find("syntax-stray"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("edsc fix"), std::string::npos) << r.output;
  }
  // A missing ';' has one, and fix does repair it.
  const auto semi = file("semi.eds", head + "[Device Classification]\n        Class1 = EtherNetIP\n");
  for (const auto& cmd :
       std::vector<std::vector<std::string>>{{"fmt", semi.string()}, {"diff", semi.string(), semi.string()}}) {
    const auto r = edsc(cmd);
    EXPECT_NE(r.output.find("edsc fix"), std::string::npos) << r.output;
  }
  EXPECT_EQ(edsc({"fix", "--in-place", semi.string()}).status, 0);
  EXPECT_EQ(edsc({"fmt", semi.string()}).status, 0);
  // Both kinds at once: fix repairs part of it, and says so.
  const auto both = file("both.eds", head + "        oops\n[Device Classification]\n        Class1 = EtherNetIP\n");
  const auto r = edsc({"fmt", both.string()});
  EXPECT_NE(r.output.find("edsc fix repairs 1 of them"), std::string::npos) << r.output;
}

TEST_F(Hints, FmtCheckSuggestsTheLineEndingsItChecked) {
  const auto lf = file("lf.eds", head);
  auto r = edsc({"fmt", "--check", "--eol", "crlf", lf.string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("edsc fmt --in-place --eol crlf " + lf.string() + " formats it"), std::string::npos)
      << r.output;
  // The suggested command does make the file pass the same check.
  EXPECT_EQ(edsc({"fmt", "--in-place", "--eol", "crlf", lf.string()}).status, 0);
  r = edsc({"fmt", "--check", "--eol", "crlf", lf.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  // Without --eol the suggestion has none.
  const auto other = file("other.eds", "[File]\n    DescText = \"t\";\n");
  r = edsc({"fmt", "--check", other.string()});
  EXPECT_NE(r.output.find("(edsc fmt --in-place " + other.string() + " formats it)"), std::string::npos) << r.output;
}

// path:line:col of the first finding in `output`, and the quoted line under it.
struct located {
  std::string path;
  int line = 0;
  std::string quoted;
};
located first_finding(const std::string& output) {
  std::smatch m;
  located l;
  if (std::regex_search(output, m,
                        std::regex(R"(([^\n]+):(\d+):\d+: (?:error|warning|note): [^\n]*\n +\d+ \| ([^\n]*))")))
    l = {m[1].str(), std::stoi(m[2].str()), m[3].str()};
  return l;
}

std::string line_of(const std::string& text, int n) {
  std::size_t at = 0;
  for (int i = 1; i < n; ++i) at = text.find('\n', at) + 1;
  return text.substr(at, text.find('\n', at) - at);
}

TEST_F(Hints, EditFindingsNameTheTextTheyQuote) {
  const auto in = file("in.eds", head);
  const auto out = dir_ / "out.eds";
  // The removed entry moves MajRev up a line: the finding about it is in the
  // edited text, which is the output's, not the input's.
  auto r =
      edsc({"edit", in.string(), "--remove-entry", "File.HomeURL", "--set", "Device.MajRev=0", "-o", out.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  auto f = first_finding(r.output);
  EXPECT_EQ(f.path, out.string()) << r.output;
  EXPECT_EQ(f.quoted, "        MajRev = 0; MinRev = 1; ProdName = \"p\";") << r.output;
  EXPECT_EQ(line_of(read_bytes(out), f.line), f.quoted) << r.output;

  r = edsc({"edit", in.string(), "--remove-entry", "File.HomeURL", "--set", "Device.MajRev=0", "--in-place"});
  EXPECT_EQ(r.status, 0) << r.output;
  f = first_finding(r.output);
  EXPECT_EQ(f.path, in.string()) << r.output;
  EXPECT_EQ(line_of(read_bytes(in), f.line), f.quoted) << r.output;

  r = edsc({"edit", file("third.eds", head).string(), "--set", "Device.MajRev=0"});
  EXPECT_EQ(first_finding(r.output).path, "<stdout>") << r.output;
}

TEST_F(Hints, FixFindingsLeftNameTheRepairedText) {
  // The inserted ';' moves the rest of its line: what is left is located in
  // the repaired text.
  auto text = head;
  text.replace(text.find("MajRev = 1;"), 11, "MajRev = 1");
  text.replace(text.find("\"p\""), 3, "\"A product name longer than thirty-two bytes\"");
  const auto in = file("in.eds", text + "[Device Classification]\n        Class1 = EtherNetIP;\n");
  const auto out = dir_ / "out.eds";
  const auto r = edsc({"fix", in.string(), "-o", out.string()});
  const auto f = first_finding(r.output.substr(r.output.find("fixed:")));
  EXPECT_EQ(f.path, out.string()) << r.output;
  EXPECT_EQ(line_of(read_bytes(out), f.line), f.quoted) << r.output;
}

TEST_F(Hints, ADoubledBracketHeaderIsOneFindingWhereItStands) {
  const auto in = file("in.eds", head + "[[Foo]]\n        Bar = 1;\n");
  const auto r = edsc({"check", in.string(), "--color", "never"});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_EQ(r.output.find("unknown section"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("syntax-stray"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("in.eds:7:2: error: invalid section name; names are letters, digits, single spaces and "
                          "'_' '.' '/' '\\' '-', found '[' [syntax-section-header]"),
            std::string::npos)
      << r.output;
  // Neither does any other malformed header add a section named nothing.
  const auto more = file("more.eds", head + "[Fo$o]\n[ ]\n[Foo\n[A*]\n");
  const auto m = edsc({"check", more.string(), "--color", "never"});
  EXPECT_EQ(m.output.find("unknown section"), std::string::npos) << m.output;
}

}  // namespace
}  // namespace authoring
