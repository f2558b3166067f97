// One rule (model::classify) says what a ConnectionN is, exclusive owner,
// input only or listen only, with or without configuration: the simulator
// serves the point as that kind, the client plans it so, and the OpENer
// generator configures that kind of point, over every connection of both
// corpora. Where field 1 names none or several kinds, the generator refuses
// the connection (OpENer configures one kind per point) and the simulator
// and client take the rule's precedence.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "connections/plan.hpp"
#include "corpus_dirs.hpp"
#include "edit/analyze.hpp"
#include "emit/opener_plan.hpp"
#include "sim/device.hpp"

namespace edsc {
namespace {

using model::app_type;

TEST(connection_kind, the_rule_names_one_kind_with_precedence_owner_input_listen) {
  model::trigger_transport tt;
  EXPECT_EQ(model::classify(tt, false).type, app_type::exclusive_owner);  // none named
  EXPECT_EQ(model::classify(tt, false).named, 0u);
  tt.listen_only = true;
  EXPECT_EQ(model::classify(tt, false).type, app_type::listen_only);
  EXPECT_TRUE(model::classify(tt, false).unambiguous());
  tt.input_only = true;
  EXPECT_EQ(model::classify(tt, false).type, app_type::input_only);
  EXPECT_FALSE(model::classify(tt, false).unambiguous());
  tt.exclusive_owner = true;
  EXPECT_EQ(model::classify(tt, true).type, app_type::exclusive_owner);
  EXPECT_EQ(model::classify(tt, true).named, 3u);
  EXPECT_TRUE(model::classify(tt, true).configured);
}

TEST(connection_kind, simulator_client_and_generator_agree_over_both_corpora) {
  std::size_t connections = 0;
  std::vector<std::string> ambiguous;
  for (const auto& path : corpora::sample()) {
    SCOPED_TRACE(path.filename().string());
    std::ifstream in(path, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const auto a = edit::analyze(path.string(), text);
    const auto plans = connections::plan_connections(a->dev);
    const auto dev = sim::build_device(a->dev, 1);
    diagnostics diags;
    std::vector<emit::header_issue> issues;
    const auto opener = emit::plan_opener(a->dev, *a->source, diags, issues);
    for (const auto& p : plans) {
      if (!p.conn->decoded) continue;
      ++connections;
      const auto k = model::classify(p.conn->tt, p.facts.config_size > 0 && p.facts.config_instance != 0);
      EXPECT_EQ(p.kind.type, k.type) << "Connection" << p.conn->number;
      EXPECT_EQ(p.kind.configured, k.configured) << "Connection" << p.conn->number;
      if (!k.unambiguous())
        ambiguous.push_back(path.filename().string() + " Connection" + std::to_string(p.conn->number));
      for (const auto& cp : dev.points) {
        if (cp.number == p.conn->number) {
          EXPECT_EQ(cp.kind, k.type) << "simulator, Connection" << cp.number;
        }
      }
      for (const auto& op : opener.points) {
        if (op.connection != p.conn->number) continue;
        EXPECT_TRUE(k.unambiguous()) << "generator, Connection" << op.connection;
        EXPECT_EQ(op.kind, k.type) << "generator, Connection" << op.connection;
      }
    }
  }
  // The one connection of both corpora that names no kind has field 1 0 (a
  // "ping to the ID object": no transport class either): the generator refuses
  // it and neither the simulator nor the client opens a class 1 connection to it.
  if (EDSC_CORPUS_SAMPLE == 1) {
    EXPECT_GT(connections, 1000u);
    EXPECT_EQ(ambiguous, std::vector<std::string>{"SerafinTech__node-st-eds-parse__0001000E00C42000.eds Connection2"});
  }
}

}  // namespace
}  // namespace edsc
