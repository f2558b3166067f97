// Neovim as a real client (tests/lsp/nvim_client.lua): it opens an EDS with
// defects, waits for the diagnostics, asks for hover, definition, a code
// action and formatting, and writes what it got. Skipped without nvim.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "lsp/lsp_client.hpp"
#include "test_paths.hpp"
#include "time_scale.hpp"

namespace edsc::lsp_test {
namespace {

namespace fs = std::filesystem;

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST(LspNeovim, HeadlessClientSession) {
  if (std::system("command -v nvim >/dev/null 2>&1") != 0) GTEST_SKIP() << "nvim is not installed (Debian: neovim)";
  const fs::path dir = fs::temp_directory_path() / ("edsc-nvim-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto eds = dir / "defect.eds";
  fs::copy_file(fs::path(EDSC_TESTS_DIR) / "lsp" / "data" / "defect.eds", eds, fs::copy_options::overwrite_existing);
  const auto out = dir / "transcript.txt";
  const std::string cmd = "cd '" + dir.string() + "' && EDSC_BIN='" + EDSC_BINARY + "' EDSC_EDS='" + eds.string() +
                          "' EDSC_OUT='" + out.string() + "' HOME='" + dir.string() +
                          "' EDSC_TIME_SCALE=" + std::to_string(edsc::test_time::scale) + " timeout " +
                          std::to_string(edsc::test_time::scaled(120)) +
                          " nvim --headless --clean -n -u NONE -i NONE -c 'luafile " + EDSC_TESTS_DIR +
                          "/lsp/nvim_client.lua' >/dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const auto transcript = read_bytes(out.string());
  SCOPED_TRACE(transcript);
  // Diagnostics as edsc check reports them. Neovim turns the UTF-16 character
  // back into a byte column: 39 units before the missing ';' are 41 bytes (an emoji).
  EXPECT_TRUE(has_line(transcript,
                       "diagnostic 3:41 error syntax-missing-semicolon expected ';' at the end of entry 'DescText'"));
  EXPECT_TRUE(
      has_line(transcript, "diagnostic 6:18 warning moddate-before-createdate ModDate is earlier than CreateDate"));
  EXPECT_TRUE(has_line(transcript,
                       "diagnostic 19:8 error duplicate-entry entry 'ProdName' appears more than once in [Device]"));
  EXPECT_NE(transcript.find("hover ProdType: "), std::string::npos);
  EXPECT_EQ(transcript.find("hover ProdType: none"), std::string::npos);
  EXPECT_TRUE(has_line(transcript, "definition of Group1 member: line 26 character 8"));
  EXPECT_TRUE(has_line(transcript, "code action: Insert ';' [syntax-missing-semicolon] (quickfix, preferred)"));
  EXPECT_TRUE(has_line(transcript, "diagnostics after the fix: 2"));
  EXPECT_TRUE(has_line(transcript, "stopped: true"));
  EXPECT_EQ(transcript.find("lua error"), std::string::npos);
  // Formatting applied in the editor gives what edsc fmt writes for the fixed file.
  const auto fixed = dir / "fixed.eds";
  ASSERT_EQ(
      std::system((std::string(EDSC_BINARY) + " fix -q '" + eds.string() + "' -o '" + fixed.string() + "' 2>/dev/null")
                      .c_str()) >>
          8,
      1);
  EXPECT_EQ(read_bytes(out.string() + ".formatted"), run_edsc_stdout("fmt '" + fixed.string() + "'"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace edsc::lsp_test
