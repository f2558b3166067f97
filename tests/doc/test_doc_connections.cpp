// The datasheet and `edsc connection` say the same of every connection: each
// line of a ConnectionN row of the page is a line (or the end of one, after
// its label) of the command's text for that connection, on every corpus file.
// A second rendering of the settings on either side fails here.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "connections/settings.hpp"
#include "corpus_dirs.hpp"
#include "doc/sheet.hpp"
#include "doc_support.hpp"
#include "emit/connection_render.hpp"

namespace edsc::doc_test {
namespace {

// The command's block for ConnectionN: from its heading to the blank line.
std::string block_of(const std::string& text, std::uint32_t number) {
  const auto head = fmt::format("Connection{} \"", number);
  auto at = text.rfind(head, 0) == 0 ? 0 : text.find("\n" + head);
  if (at == std::string::npos) return {};
  const auto end = text.find("\n\n", at + 1);
  return text.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// The lines of a cell; the owner line drops its label, which the command
// prints in its own column ("needs one of ..." against "needs         one of ...").
std::vector<std::string> cell_lines(const std::string& cell) {
  std::vector<std::string> out;
  std::istringstream in(cell);
  for (std::string line; std::getline(in, line);) {
    for (const std::string_view label : {"needs ", "shares "})
      if (line.starts_with(label)) line.erase(0, label.size());
    if (!line.empty()) out.push_back(line);
  }
  return out;
}

// Columns of a connection row: entry, name, kind and transport, O->T, T->O,
// configuration, path (the path is the file's, in words; the command gives bytes).
constexpr std::size_t said_columns[] = {2, 3, 4, 5};

std::size_t check_file(const fs::path& path) {
  const auto a = analyse_file(path);
  const auto sheet = doc::build_sheet(*a);
  const auto text = emit::render_connections_text(connections::describe_connections(a->dev), *a->source);
  std::size_t checked = 0;
  for (const auto& c : a->dev.connections) {
    const auto name = fmt::format("Connection{}", c.number);
    const auto row = std::find_if(sheet.connections.rows.begin(), sheet.connections.rows.end(),
                                  [&](const auto& r) { return !r.empty() && r[0].text == name; });
    if (!c.decoded || row == sheet.connections.rows.end()) continue;
    const auto block = block_of(text, c.number);
    EXPECT_FALSE(block.empty()) << path.filename() << " " << name;
    for (const auto column : said_columns)
      for (const auto& line : cell_lines((*row)[column].text))
        EXPECT_NE(block.find(line), std::string::npos)
            << path.filename() << " " << name << ": the page says '" << line << "', the command says\n"
            << block;
    ++checked;
  }
  return checked;
}

TEST(DocConnections, EveryConnectionReadsAsTheCommandSaysIt) {
  std::size_t checked = 0;
  for (const auto& path : corpora::sample()) checked += check_file(path);
  // Both corpora hold hundreds of ConnectionN; a sample of them still dozens.
  EXPECT_GT(checked, corpora::sample_stride() == 1 ? 200u : 10u);
}

}  // namespace
}  // namespace edsc::doc_test
