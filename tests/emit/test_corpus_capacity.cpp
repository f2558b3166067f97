// [Capacity] of every file of both corpora: limits_of keeps exactly the
// well-formed TSpecs a plain reading of the text finds, and no stated rate
// rises with the connection size. The figures of the full corpora are
// asserted where every file is walked.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "connections/capacity.hpp"
#include "corpus_dirs.hpp"
#include "opener_support.hpp"

namespace edsc::test {
namespace {

using connections::io_direction;

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// TSpecN entries the text writes as a direction word and two unsigned
// integers, counted apart from the parser: comments dropped, then a regex.
std::size_t well_formed_tspecs(const std::string& text) {
  static const std::regex comment(R"(\$[^\n]*)");
  static const std::regex tspec(
      R"(\bTSpec\d+\s*=\s*(TxRx|Tx|Rx)\s*,\s*(0[xX][0-9A-Fa-f]+|\d+)\s*,\s*(0[xX][0-9A-Fa-f]+|\d+)\s*;)",
      std::regex::icase);
  const auto bare = std::regex_replace(text, comment, "");
  return static_cast<std::size_t>(
      std::distance(std::sregex_iterator(bare.begin(), bare.end(), tspec), std::sregex_iterator()));
}

// Sizes where the rule could change its answer: each stated size, one on
// either side, and 0.
std::set<std::uint64_t> probe_sizes(const connections::capacity_limits& l) {
  std::set<std::uint64_t> out{0};
  for (const auto& t : l.tspecs) out.insert({t.size == 0 ? 0 : t.size - 1, t.size, t.size + 1});
  return out;
}

struct corpus_figures {
  std::size_t files = 0, with_tspec = 0, tspecs = 0;
  std::size_t io = 0, msg = 0, overhead = 0, per_mcast = 0, cip = 0;
  std::vector<std::string> rising;  // files where a larger size is allowed more packets
};

void walk(const std::filesystem::path& f, corpus_figures& fig) {
  const auto text = read(f);
  const auto c = plan_eds(text);
  connections::capacity_limits l;
  ASSERT_NO_THROW(l = connections::limits_of(c->dev)) << f;
  ++fig.files;
  EXPECT_EQ(l.tspecs.size(), well_formed_tspecs(text)) << f;
  fig.with_tspec += l.tspecs.empty() ? 0 : 1;
  fig.tspecs += l.tspecs.size();
  fig.io += l.max_io_connections ? 1 : 0;
  fig.msg += l.max_msg_connections ? 1 : 0;
  fig.overhead += l.conn_overhead ? 1 : 0;
  fig.per_mcast += l.max_consumers_per_mcast ? 1 : 0;
  fig.cip += l.max_cip_connections ? 1 : 0;
  for (const auto dir : {io_direction::tx, io_direction::rx}) {
    std::optional<std::uint64_t> last;
    for (const auto size : probe_sizes(l)) {
      const auto b = connections::pps_limit(l, dir, size);
      if (!b) continue;
      if (last && b->pps > *last) fig.rising.push_back(f.filename().string());
      last = b->pps;
    }
  }
}

TEST(CorpusCapacity, TSpecsReadAndRatesNeverRiseWithSize) {
  corpus_figures fig;
  for (const auto& f : corpora::sample()) walk(f, fig);
  EXPECT_GE(fig.files, corpora::sample_size());
  EXPECT_TRUE(fig.rising.empty()) << fig.rising.front();
  if (corpora::sample_stride() != 1) return;
  // The full corpora, counted by hand with grep: 95 files state 185 TSpecs
  // (167 TxRx, 9 Tx, 9 Rx), all well-formed.
  EXPECT_EQ(fig.with_tspec, 95u);
  EXPECT_EQ(fig.tspecs, 185u);
  EXPECT_EQ(fig.io, 80u);
  EXPECT_EQ(fig.msg, 93u);
  EXPECT_EQ(fig.overhead, 72u);
  EXPECT_EQ(fig.per_mcast, 19u);
  EXPECT_EQ(fig.cip, 3u);
}

}  // namespace
}  // namespace edsc::test
