// `edsc header` as a user runs it, and the text helpers it relies on.
#include <gtest/gtest.h>

#include "emit_support.hpp"
#include "facts/c_text.hpp"
#include "facts/sha256.hpp"
#include "test_paths.hpp"

using namespace edsc;
using namespace edsc::test;

namespace {

const auto diffuse = fs::path(EDSC_PROJECT_DIR) / "eds" / "rightsight-42ef-diffuse.eds";

command_result header(const std::string& args) { return run_shell(edsc_command() + " header " + args); }

}  // namespace

TEST(HeaderText, StringLiteralsEscapeEverythingOutsidePrintableAscii) {
  EXPECT_EQ(emit::c_string_literal("Sensor"), "\"Sensor\"");
  EXPECT_EQ(emit::c_string_literal("a\"b\\c?"), "\"a\\\"b\\\\c\\?\"");
  EXPECT_EQ(emit::c_string_literal("\xE9t\xC3\xA9\n1"), "\"\\351t\\303\\251\\0121\"");
  EXPECT_EQ(emit::comment_text("a*/b\x01"), "a* /b?");
}

TEST(HeaderText, Identifiers) {
  EXPECT_EQ(emit::upper_snake("MaxIOConnections"), "MAX_IO_CONNECTIONS");
  EXPECT_EQ(emit::upper_snake("MaxCIPConnections"), "MAX_CIP_CONNECTIONS");
  EXPECT_EQ(emit::upper_snake("rightsight-42ef.h"), "RIGHTSIGHT_42EF_H");
  EXPECT_TRUE(emit::is_c_identifier("EDS_"));
  EXPECT_FALSE(emit::is_c_identifier("1X"));
  EXPECT_FALSE(emit::is_c_identifier("A-B"));
}

TEST(HeaderText, Sha256) {
  EXPECT_EQ(emit::sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(emit::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // Two blocks of padding: 56 bytes leave no room for the length.
  EXPECT_EQ(emit::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(HeaderCli, WritesAReproducibleHeaderNamingItsSource) {
  temp_dir dir("header-cli");
  const auto a = dir.path() / "a.h";
  const auto b = dir.path() / "sub.h";
  ASSERT_EQ(header(quoted(diffuse) + " -o " + quoted(a)).status, 0);
  fs::create_directory(dir.path() / "other");
  fs::copy_file(diffuse, dir.path() / "other" / diffuse.filename());
  ASSERT_EQ(header(quoted(dir.path() / "other" / diffuse.filename()) + " -o " + quoted(b)).status, 0);
  const auto text = read_text(a);
  auto other = read_text(b);
  // Same bytes wherever the EDS lives; only the guard follows the output name.
  for (auto pos = other.find("EDS_SUB_H_INCLUDED"); pos != std::string::npos; pos = other.find("EDS_SUB_H_INCLUDED"))
    other.replace(pos, 18, "EDS_A_H_INCLUDED");
  EXPECT_EQ(text, other);
  EXPECT_NE(text.find("from rightsight-42ef-diffuse.eds"), std::string::npos);
  EXPECT_NE(text.find("SHA-256: " + emit::sha256_hex(read_text(diffuse))), std::string::npos);
  EXPECT_NE(text.find("#define EDS_PRODUCT_NAME \"RightSight Standard Diffuse\""), std::string::npos);
  EXPECT_NE(text.find("#define EDS_COS_PRODUCED_SIZE 1u"), std::string::npos);
  EXPECT_NE(text.find("#define EDS_ALLOCATION_CHOICE_MASK 0x15u"), std::string::npos);
  EXPECT_NE(text.find("#ifndef EDS_SERIAL_NUMBER"), std::string::npos);
  EXPECT_EQ(text.find("{{"), std::string::npos);
  EXPECT_EQ(text.find("&quot;"), std::string::npos);  // no HTML escaping
}

TEST(HeaderCli, PrefixSerialAndStdout) {
  const auto r = header(quoted(diffuse) + " -o - --prefix RS_ --serial 0x500AF52B");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("#define RS_SERIAL_NUMBER 0x500AF52Bu"), std::string::npos);
  EXPECT_NE(r.output.find("#define RS_VENDOR_ID 1u"), std::string::npos);
  EXPECT_NE(r.output.find("rs_param_info"), std::string::npos);
  EXPECT_EQ(r.output.find("EDS_"), std::string::npos);
  EXPECT_NE(header(quoted(diffuse) + " -o - --serial 1234567").output.find("SERIAL_NUMBER 0x0012D687u"),
            std::string::npos);
}

TEST(HeaderCli, UsageAndInputErrors) {
  EXPECT_EQ(header(quoted(diffuse) + " -o - --prefix 9X").status, 2);
  EXPECT_EQ(header(quoted(diffuse) + " -o - --serial 0x100000000").status, 2);
  EXPECT_EQ(header(quoted(diffuse) + " -o - --serial twelve").status, 2);
  EXPECT_EQ(header(quoted(diffuse)).status, 2);  // -o is required
  EXPECT_EQ(header("/nonexistent/x.eds -o -").status, 2);
  EXPECT_EQ(header(quoted(diffuse) + " -o - --template-dir /nonexistent").status, 2);
  temp_dir dir("header-errors");
  const auto out = dir.path() / "none.h";
  const auto r = header(quoted(fs::path(EDSC_CORPUS_DIR) / "kh-ko__NVM__eds_sample.txt.eds") + " -o " + quoted(out));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("VendCode is missing"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(HeaderCli, LongProductNamesAreShortenedWithAWarning) {
  const auto r = header(quoted(fs::path(EDSC_CORPUS_DIR) /
                               "KamWisa__ABB_Mitsubishi-PLC-Interface-Configuration-via-EtherNetIP__ENIP_FA.eds") +
                        " -o -");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("warning: [Device] ProdName is 37 bytes"), std::string::npos);
  EXPECT_NE(r.output.find("#define EDS_PRODUCT_NAME \"ABB EtherNet/IP Anybus Adapter D\""), std::string::npos);
}

// Identity attribute 7 holds 32 bytes: a UTF-8 name is cut before the
// character that would not fit whole, a Latin-1 one at byte 32.
TEST(HeaderCli, LongProductNamesAreCutBetweenCharacters) {
  temp_dir dir("prodname-cut");
  std::string text = read_text(diffuse);
  const auto at = text.find("ProdName");
  const auto end = text.find(';', at);
  const auto with_name = [&](const std::string& name) {
    auto t = text;
    t.replace(at, end - at, "ProdName = \"" + name + "\"");
    const auto path = dir.path() / "named.eds";
    write_text(path, t);
    return header(quoted(path) + " -o -");
  };
  const std::string ascii31(31, 'a');
  auto r = with_name(ascii31 + "\xC3\xA9");  // 33 bytes, 32 characters
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("#define EDS_PRODUCT_NAME \"" + ascii31 + "\"\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("#define EDS_PRODUCT_NAME_LENGTH 31u"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("ProdName is 33 bytes; the Identity object's Product Name holds at most 32, so the header "
                          "carries its first 31 (32 would cut a character in two)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("\\303\""), std::string::npos) << r.output;
  r = with_name(ascii31 + "a\xE9");  // Latin-1: every byte a character
  EXPECT_NE(r.output.find("#define EDS_PRODUCT_NAME \"" + ascii31 + "a\"\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("carries its first 32\n"), std::string::npos) << r.output;
  r = with_name(std::string(30, 'a') + "\xC3\xA9");  // 32 bytes: fits
  EXPECT_EQ(r.output.find("ProdName is"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("#define EDS_PRODUCT_NAME_LENGTH 32u"), std::string::npos) << r.output;
}

TEST(HeaderCli, TemplateDirOverridesOnlyTheFilesItHolds) {
  temp_dir dir("templates");
  write_text(dir.path() / "header_cip.mustache", "/* no CIP codes, {{prefix}} */\n");
  const auto r = header(quoted(diffuse) + " -o - --template-dir " + quoted(dir.path()));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("/* no CIP codes, EDS_ */"), std::string::npos);
  EXPECT_EQ(r.output.find("EDS_CLASS_IDENTITY"), std::string::npos);
  EXPECT_NE(r.output.find("#define EDS_VENDOR_ID 1u"), std::string::npos);  // built-in identity part
  write_text(dir.path() / "header.h.mustache", "{{#broken}}\n");
  EXPECT_EQ(header(quoted(diffuse) + " -o - --template-dir " + quoted(dir.path())).status, 2);
}
