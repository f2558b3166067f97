// Every corpus file's header compiles as strict C99 and C++17, and what it
// states agrees with the model: each translation unit re-states the model's
// values (computed here, not by the generator) as static assertions, and the
// C++ build runs to compare the parameter table.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "corpus_dirs.hpp"
#include "emit/header.hpp"
#include "emit_support.hpp"
#include "facts/c_text.hpp"
#include "io/read_file.hpp"
#include "lower/lower.hpp"
#include "parse/parser.hpp"

using namespace edsc;
using namespace edsc::test;

namespace {

// The one corpus file without identity values (every [Device] entry empty):
// edsc refuses to write a header that would state a made-up identity.
constexpr const char* no_identity = "kh-ko__NVM__eds_sample.txt.eds";

std::string check(const std::string& cond, std::size_t& n) {
  return fmt::format("EDS_STATIC_ASSERT({}, model_{});\n", cond, n++);
}

// Static assertions re-stating the model: identity, DeviceNet sizes, connections, capacity.
std::string model_checks(const model::device& dev) {
  std::string s;
  std::size_t n = 0;
  const auto& id = dev.identity;
  s += check(fmt::format("EDS_VENDOR_ID == {}u", id.vend_code.as_uint()), n);
  s += check(fmt::format("EDS_DEVICE_TYPE == {}u", id.prod_type.as_uint()), n);
  s += check(fmt::format("EDS_PRODUCT_CODE == {}u", id.prod_code.as_uint()), n);
  s += check(
      fmt::format("EDS_MAJOR_REVISION == {}u && EDS_MINOR_REVISION == {}u", id.maj_rev.as_uint(), id.min_rev.as_uint()),
      n);
  s += check(fmt::format("EDS_PRODUCT_NAME_LENGTH == {}u", std::min<std::size_t>(id.prod_name.text.size(), 32)), n);
  if (id.catalog.ok()) s += "#ifndef EDS_CATALOG\n#error catalog\n#endif\n";
  if (dev.io.section != model::none) {
    static const char* names[] = {"POLL", "STROBE", "COS", "CYCLIC"};
    std::vector<bool> seen(4);
    for (const auto& c : dev.io.connections) {
      const auto t = static_cast<std::size_t>(c.type);
      if (seen[t]) continue;
      seen[t] = true;
      for (const bool out : {false, true}) {
        const auto& v = out ? c.default_output : c.default_input;
        std::uint64_t size = 0;
        if (v.is_ref && v.ref.resolved()) size = (out ? dev.io.outputs : dev.io.inputs)[v.ref.target].size.as_uint();
        s += check(fmt::format("EDS_{}_{}_SIZE == {}u", names[t], out ? "CONSUMED" : "PRODUCED", size), n);
      }
    }
    s += check(fmt::format("EDS_DEFAULT_CONNECTIONS == {}u", dev.io.default_mask.as_uint()), n);
  }
  if (!dev.connections.empty()) {
    std::vector<std::uint32_t> numbers;
    for (const auto& c : dev.connections) {
      if (std::find(numbers.begin(), numbers.end(), c.number) != numbers.end()) continue;
      numbers.push_back(c.number);
      const auto p = fmt::format("EDS_CONNECTION{}_", c.number);
      s += check(fmt::format("{}TRIGGER_TRANSPORT == {}u", p, c.trigger.as_uint()), n);
      s += check(fmt::format("{}OUTPUT_RUN_IDLE == {}", p, c.cp.ot.real_time_format == 4 ? 1 : 0), n);
      s += check(fmt::format("{}INPUT_RUN_IDLE == {}", p, c.cp.to.real_time_format == 4 ? 1 : 0), n);
      if (c.ot_size.is_integer()) s += check(fmt::format("{}OUTPUT_SIZE == {}u", p, c.ot_size.as_uint()), n);
      if (c.to_size.is_integer()) s += check(fmt::format("{}INPUT_SIZE == {}u", p, c.to_size.as_uint()), n);
    }
    s += check(fmt::format("EDS_CONNECTION_COUNT == {}u", numbers.size()), n);
    for (const auto& st : dev.cap.settings)
      if (st.canonical == "MaxIOConnections" && st.first() != nullptr && st.first()->is_integer())
        s += check(fmt::format("EDS_MAX_IO_CONNECTIONS == {}u", st.first()->as_uint()), n);
  }
  return s;
}

// A main() comparing the parameter table with the model, entry by entry.
std::string param_checks(const model::device& dev) {
  std::string rows;
  std::size_t count = 0;
  for (const auto& p : dev.params) {
    if (p.kind != model::param_kind::param) continue;
    ++count;
    std::uint64_t def = 0;
    int has_def = 0;
    if (p.type != nullptr && p.default_value.is_integer() && p.type->size > 0 && p.type->size <= 8 &&
        p.type->cls != schema::type_class::real) {
      const auto mask = p.type->size == 8 ? ~0ull : (1ull << (8 * p.type->size)) - 1;
      def = static_cast<std::uint64_t>(p.default_value.as_int()) & mask;
      has_def = 1;
    }
    rows += fmt::format("  {{ {}u, {}, {}u, {}, UINT64_C({}), {} }},\n", p.number,
                        emit::c_string_literal(p.name.ok() ? p.name.text : ""), p.type ? p.type->code : 0,
                        p.descriptor.is_integer() && (p.descriptor.as_uint() & 0x10) ? 1 : 0, def, has_def);
  }
  return fmt::format(
      "#include <stdio.h>\n#include <string.h>\n"
      "static const struct {{ uint32_t number; const char *name; unsigned type; unsigned ro; uint64_t def; int "
      "has_def; }}"
      " expect[] = {{\n{}  {{ 0, \"\", 0, 0, 0, 0 }}\n}};\n"
      "int main(void) {{\n  unsigned i; int bad = 0;\n"
      "  if (EDS_PARAM_COUNT != {}u) {{ printf(\"count\\n\"); return 1; }}\n"
      "  for (i = 0; i + 1u < sizeof expect / sizeof expect[0]; ++i) {{\n"
      "    const eds_param_info *p = &eds_params[i];\n"
      "    if (p->number != expect[i].number || strcmp(p->name, expect[i].name) != 0 || p->data_type != expect[i].type "
      "||\n"
      "        p->read_only != expect[i].ro || (expect[i].has_def && p->default_value != expect[i].def)) {{\n"
      "      printf(\"Param%u differs\\n\", (unsigned)expect[i].number); bad = 1; }}\n  }}\n  return bad;\n}}\n",
      rows, count);
}

struct job {
  std::string name;
  fs::path tu;
};

}  // namespace

TEST(CorpusHeaders, CompileStrictlyAndAgreeWithTheModel) {
  temp_dir dir("corpus-headers");
  const auto files = edsc::corpora::sample();
  ASSERT_GE(files.size(), edsc::corpora::sample_size());

  std::vector<job> jobs;
  for (std::size_t i = 0; i < files.size(); ++i) {
    auto read = io::read_source(files[i].string());
    ASSERT_TRUE(read.ok()) << files[i];
    const auto& src = *read.value();
    const auto parsed = parse(src);
    diagnostics d;
    const auto dev = lower(parsed.tree, d);
    emit::header_options opt;
    opt.output_name = fmt::format("h{}.h", i);
    const auto r = emit::generate_header(dev, src, opt);
    ASSERT_FALSE(r.failure) << files[i] << ": " << *r.failure;
    if (files[i].filename() == no_identity) {
      EXPECT_TRUE(r.has_error());
      continue;
    }
    ASSERT_FALSE(r.has_error()) << files[i];
    write_text(dir.path() / opt.output_name, r.text);
    const auto tu = dir.path() / fmt::format("t{}.c", i);
    write_text(tu, fmt::format("#define EDS_PARAM_TABLE\n#include \"{}\"\n{}{}", opt.output_name, model_checks(dev),
                               param_checks(dev)));
    jobs.push_back({files[i].filename().string(), tu});
  }
  EXPECT_EQ(jobs.size(), files.size() - 1);

  // Two compilers per file, spread over the cores.
  std::atomic<std::size_t> next{0};
  std::mutex m;
  std::vector<std::string> failures;
  auto worker = [&] {
    for (std::size_t i; (i = next++) < jobs.size();) {
      const auto& j = jobs[i];
      const auto exe = fs::path(j.tu).replace_extension(".cpp.exe");
      auto c = run_shell("gcc -std=c99 -Wall -Wextra -Werror -pedantic -fsyntax-only " + quoted(j.tu));
      auto cxx = run_shell("g++ -std=c++17 -Wall -Wextra -Werror -x c++ " + quoted(j.tu) + " -o " + quoted(exe) +
                           " && " + quoted(exe));
      if (c.status != 0 || cxx.status != 0) {
        std::lock_guard lock(m);
        failures.push_back(j.name + ":\n" + c.output + cxx.output);
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(2u, std::thread::hardware_concurrency()); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  EXPECT_TRUE(failures.empty()) << failures.size() << " headers failed; first:\n"
                                << (failures.empty() ? "" : failures[0])
                                << (failures.size() > 1 ? failures.back() : "");
}
