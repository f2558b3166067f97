// The Parameter and File objects over every file of both corpora, as pure
// functions (no network): each ParamN answers every attribute, Get_Attributes_All
// is attributes 1-21 in order, a settable number takes its own value back
// (or 0x09 when the EDS's default lies outside its own limits), and the
// upload returns the file byte for byte.
#include <gtest/gtest.h>

#include <fstream>

#include "cip/message.hpp"
#include "corpus_dirs.hpp"
#include "edit/analyze.hpp"
#include "sim/state.hpp"

namespace edsc::sim {
namespace {

cip::reply ask(state& s, std::uint8_t service, std::uint32_t cls, std::uint32_t instance,
               std::optional<std::uint32_t> attr, cip::byte_view data = {}) {
  const link l{0x0100007F, 0};
  const auto r = handle_cip(s, l, cip::encode_request(service, cip::logical_path(cls, instance, attr), data).value(),
                            clock::time_point{});
  auto rep = cip::decode_reply(r, 0);
  EXPECT_TRUE(rep.ok());
  return rep.ok() ? rep.value() : cip::reply{0, 0xFF, {}, {}};
}

TEST(sim_corpus_objects, every_parameter_and_every_file_is_served) {
  std::size_t files = 0, params = 0, settable = 0, default_outside = 0;
  for (const auto& path : corpora::sample()) {
    SCOPED_TRACE(path.filename().string());
    std::ifstream in(path, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const auto a = edit::analyze(path.string(), text);
    state s;
    s.dev = build_device(a->dev, 1);
    s.dev.file.content.assign(text.begin(), text.end());
    ++files;
    if (!s.dev.params.empty()) {
      EXPECT_EQ(ask(s, 0x0E, 0x0F, 0, 3).data.size(), 2u);
      for (const auto& p : std::vector<parameter_instance>(s.dev.params)) {
        ++params;
        const auto all = ask(s, 0x01, 0x0F, p.number, std::nullopt);
        ASSERT_EQ(all.general, 0) << "Param" << p.number;
        cip::bytes joined;
        for (std::uint32_t attr = 1; attr <= 21; ++attr) {
          const auto r = ask(s, 0x0E, 0x0F, p.number, attr);
          ASSERT_EQ(r.general, 0) << "Param" << p.number << " attribute " << attr;
          joined.insert(joined.end(), r.data.begin(), r.data.end());
        }
        EXPECT_EQ(joined, all.data) << "Param" << p.number;
        if (p.type == nullptr || p.read_only) continue;
        ++settable;
        EXPECT_EQ(p.value.size(), p.type->size) << "Param" << p.number;
        const auto set = ask(s, 0x10, 0x0F, p.number, 1, p.value).general;
        EXPECT_TRUE(set == 0 || set == 0x09) << "Param" << p.number << " status " << int(set);
        if (set == 0x09) ++default_outside;
      }
    }
    ASSERT_EQ(ask(s, 0x4B, 0x37, 0xC8, std::nullopt, cip::bytes{0xFF}).general, 0);
    cip::bytes got;
    for (std::size_t n = 0; n <= text.size(); ++n) {
      const auto r = ask(s, 0x4F, 0x37, 0xC8, std::nullopt, cip::bytes{static_cast<std::uint8_t>(n)});
      ASSERT_EQ(r.general, 0);
      const bool last = r.data[1] == 2 || r.data[1] == 4;
      got.insert(got.end(), r.data.begin() + 2, r.data.end() - (last ? 2 : 0));
      if (last) break;
    }
    EXPECT_TRUE(got == s.dev.file.content);  // bytes, not chars: files with Windows-1252 text compare right
  }
  EXPECT_EQ(files, corpora::sample().size());
  std::printf(
      "Parameter object over %zu files: %zu parameters, %zu settable numbers, %zu with a default outside "
      "their own limits\n",
      files, params, settable, default_outside);
}

}  // namespace
}  // namespace edsc::sim
