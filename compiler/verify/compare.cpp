#include "verify/compare.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "base/plural.hpp"
#include "facts/header_view.hpp"

namespace edsc::verify {

namespace {

constexpr const char* type_names[] = {"polled", "bit-strobed", "COS", "cyclic"};
constexpr std::uint8_t type_choice[] = {choice_poll, choice_strobe, choice_cos, choice_cyclic};

class comparer {
 public:
  comparer(const can_log& log, const conversation& conv, const model::device& dev, const source_file& eds)
      : log_(log), conv_(conv), dev_(dev), eds_(eds) {}

  verify_result run(std::optional<unsigned> only) {
    std::vector<emit::header_issue> issues;
    facts_ = emit::collect_facts(dev_, eds_, issues);
    for (const auto& i : issues)
      if (i.error) result_.eds_errors.push_back(i.message);
    if (!result_.eds_errors.empty()) return std::move(result_);
    if (facts_.devicenet) dn_ = *facts_.devicenet;
    for (const auto& p : log_.problems)
      result_.diags.push_back(make_diagnostic(diag_id::verify_log_line, p.where,
                                              fmt::format("capture line {} skipped: {}", p.line, p.message)));
    for (const auto& d : conv_.frames) {
      if (!d.undecodable || (only && d.group != 0 && d.mac != *only)) continue;
      const auto& f = log_.frames[d.frame];
      result_.diags.push_back(make_diagnostic(
          diag_id::verify_undecodable, f.where,
          fmt::format("frame {} [{}] {} not decoded: {}", id_text(f), f.data.size(), hex_bytes(f.data), d.why)));
    }
    std::vector<unsigned> nodes;
    for (const auto n : conv_.nodes)
      if (!only || n == *only) nodes.push_back(n);
    if (nodes.empty()) {
      const span where = log_.frames.empty() ? span{} : log_.frames.front().where;
      result_.diags.push_back(
          make_diagnostic(diag_id::verify_no_node, where,
                          only ? fmt::format("no frame from MAC {} in the capture; nothing to compare", *only)
                               : std::string("no DeviceNet slave answers in the capture; nothing to compare")));
    }
    for (const auto n : nodes) node(n);
    std::stable_sort(result_.diags.begin(), result_.diags.end(),
                     [](const diagnostic& a, const diagnostic& b) { return a.where.begin < b.where.begin; });
    return std::move(result_);
  }

 private:
  std::string id_text(const can_frame& f) const {
    return f.extended ? fmt::format("{:08X}", f.id) : fmt::format("0x{:03X}", f.id);
  }

  // "eds/x.eds:9:20", where the EDS states the value.
  std::string at(const model::value& v) const {
    const auto p = eds_.position(v.from.where.begin);
    return fmt::format("{}:{}:{}", eds_.path(), p.line, p.column);
  }

  void add(diag_id id, const exchange& x, std::string message) {
    auto d = make_diagnostic(id, log_.frames[*x.answer].where, std::move(message));
    d.notes.push_back({log_.frames[x.request].where,
                       fmt::format("the scanner asked for {} here", x.has_attr ? attribute_name(x.cls, x.inst, x.attr)
                                                                               : service_name(x.service, x.cls))});
    result_.diags.push_back(std::move(d));
  }

  void node(unsigned mac) {
    std::map<int, bool> reported_instance;  // once per connection instance
    for (const auto& x : conv_.exchanges) {
      if (x.mac != mac || !x.answer) continue;
      if (x.cls == 0x01 && x.inst == 1 && x.service == 0x0E && !x.error) identity(mac, x);
      if (x.cls == 0x05 && x.inst >= 2 && x.inst <= 4) connection(mac, x, reported_instance);
      if (x.service == 0x4B && x.cls == 0x03 && !x.value.empty()) allocation(mac, x);
    }
    io(mac);
  }

  void identity(unsigned mac, const exchange& x) {
    const auto& id = facts_.identity;
    const auto& dev = dev_.identity;
    const auto& d = x.data;
    auto code = [&](const char* what, const char* keyword, const model::value& v, std::uint16_t expected) {
      if (d.size() < 2) return short_answer(x);
      const unsigned got = d[0] | (d[1] << 8);
      if (got == expected) return;
      add(diag_id::verify_identity_mismatch, x,
          fmt::format("MAC {} answers {} {} where the EDS says {} ({} at {}); the scanner will show the node as "
                      "Mismatch",
                      mac, what, got, expected, keyword, at(v)));
    };
    switch (x.attr) {
      case 1: return code("vendor ID", "VendCode", dev.vend_code, id.vendor_id);
      case 2: return code("device type", "ProdType", dev.prod_type, id.device_type);
      case 3: return code("product code", "ProdCode", dev.prod_code, id.product_code);
      case 4: {
        if (d.size() < 2) return short_answer(x);
        const auto bus = fmt::format("{}.{}", d[0], d[1]);
        const auto eds = fmt::format("{}.{}", id.major_revision, id.minor_revision);
        if (d[0] != id.major_revision) {
          add(diag_id::verify_identity_mismatch, x,
              fmt::format("MAC {} answers revision {} where the EDS says {} (MajRev at {}); the major revision "
                          "differs, so the scanner will show the node as Mismatch",
                          mac, bus, eds, at(dev.maj_rev)));
        } else if (d[1] != id.minor_revision) {
          add(diag_id::verify_minor_revision, x,
              fmt::format("MAC {} answers revision {} where the EDS says {} (MinRev at {}); only the minor revision "
                          "differs, so the scanner still matches the node",
                          mac, bus, eds, at(dev.min_rev)));
        }
        return;
      }
      case 7: {
        if (d.empty() || d.size() < 1u + d[0]) return short_answer(x);
        const std::string name(d.begin() + 1, d.begin() + 1 + d[0]);
        if (name != id.product_name)
          add(diag_id::verify_product_name, x,
              fmt::format("MAC {} answers product name \"{}\" where the EDS says \"{}\" (ProdName at {})", mac, name,
                          id.product_name, at(dev.prod_name)));
        return;
      }
      default: return;
    }
  }

  void short_answer(const exchange& x) {
    result_.diags.push_back(make_diagnostic(
        diag_id::verify_undecodable, log_.frames[*x.answer].where,
        fmt::format("the answer to {} is too short: {}", attribute_name(x.cls, x.inst, x.attr), hex_bytes(x.data))));
  }

  // Instance 4 serves COS or cyclic: the one allocated, else the one the EDS has.
  int type_of_instance(unsigned inst, std::uint8_t allocated) const {
    if (inst == 2) return 0;
    if (inst == 3) return 1;
    if ((allocated & choice_cyclic) != 0) return 3;
    if ((allocated & choice_cos) != 0) return 2;
    return !dn_.types[2].supported && dn_.types[3].supported ? 3 : 2;
  }

  // Where the EDS states a connection type's produced or consumed size:
  // the Size of the InputN/OutputN its xxxInfo names.
  std::string size_source(int type, bool produced) const {
    for (const auto& c : dev_.io.connections) {
      if (static_cast<int>(c.type) != type) continue;
      const auto& ref = produced ? c.default_input : c.default_output;
      const auto* r = ref.as_ref();
      const auto& list = produced ? dev_.io.inputs : dev_.io.outputs;
      if (r != nullptr && r->resolved() && r->target < list.size())
        return fmt::format("{}{} Size at {}", produced ? "Input" : "Output", list[r->target].number,
                           at(list[r->target].size));
      return fmt::format("{} default {} at {}", type_names[type], produced ? "input" : "output", at(ref));
    }
    return "no xxxInfo entry";
  }

  void connection(unsigned mac, const exchange& x, std::map<int, bool>& reported) {
    const int type = type_of_instance(x.inst, x.allocated);
    const auto& t = dn_.types[type];
    const bool absent = x.error && x.general == 0x16;
    if (absent && t.supported && !reported[x.inst]) {
      reported[x.inst] = true;
      add(diag_id::verify_connection_missing, x,
          fmt::format("MAC {} has no {} connection (instance {}: object does not exist), but the EDS [IO_Info] "
                      "allows it ({}); a scanner configured for it will fail",
                      mac, type_names[type], x.inst, size_source(type, true)));
      return;
    }
    if (x.error) return;
    if (!t.supported) {
      if (reported[x.inst]) return;
      reported[x.inst] = true;
      add(diag_id::verify_connection_not_in_eds, x,
          fmt::format("MAC {} answers for {} connection instance {}, which the EDS [IO_Info] does not allow", mac,
                      type_names[type], x.inst));
      return;
    }
    if (x.service != 0x0E || (x.attr != 7 && x.attr != 8)) return;
    if (x.data.size() < 2) return short_answer(x);
    const bool produced = x.attr == 7;
    const unsigned got = x.data[0] | (x.data[1] << 8);
    const auto expected = produced ? t.produced_size : t.consumed_size;
    if (got == expected) return;
    add(diag_id::verify_connection_size, x,
        fmt::format("MAC {} {} {} on its {} connection where the EDS says {} ({}); the scanner will report "
                    "a size mismatch",
                    mac, produced ? "produces" : "consumes", plural(got, "byte"), type_names[type], expected,
                    size_source(type, produced)));
  }

  void allocation(unsigned mac, const exchange& x) {
    const auto asked = x.value[0];
    for (int type = 0; type < 4; ++type) {
      if ((asked & type_choice[type]) == 0) continue;
      const auto& t = dn_.types[type];
      if (x.error && t.supported) {
        add(diag_id::verify_connection_missing, x,
            fmt::format("MAC {} refuses to allocate its {} connection ({}), which the EDS [IO_Info] allows", mac,
                        type_names[type], status_name(x.general)));
      } else if (!x.error && !t.supported) {
        add(diag_id::verify_connection_not_in_eds, x,
            fmt::format("MAC {} allocates a {} connection, which the EDS [IO_Info] does not allow", mac,
                        type_names[type]));
      }
    }
  }

  // One diagnostic per connection and direction, counting the frames like it.
  void io(unsigned mac) {
    std::map<std::pair<int, bool>, std::pair<std::size_t, std::size_t>> wrong;  // -> first diag, count
    for (const auto& e : conv_.io) {
      if (e.mac != mac) continue;
      const int type = static_cast<int>(e.type);
      const auto& t = dn_.types[type];
      const auto expected = e.produced ? t.produced_size : t.consumed_size;
      // Longer data travels fragmented; the fragment protocol is not decoded.
      if (!t.supported || expected > 8 || e.length == expected) continue;
      const auto key = std::make_pair(type, e.produced);
      if (auto it = wrong.find(key); it != wrong.end()) {
        ++it->second.second;
        continue;
      }
      wrong[key] = {result_.diags.size(), 0};
      result_.diags.push_back(
          make_diagnostic(diag_id::verify_io_length, log_.frames[e.frame].where,
                          fmt::format("{} I/O frame {} MAC {} carries {} where the EDS says {} ({})", type_names[type],
                                      e.produced ? "from" : "to", mac, plural(e.length, "byte"), expected,
                                      size_source(type, e.produced))));
    }
    for (const auto& [key, v] : wrong)
      if (v.second > 0) result_.diags[v.first].message += fmt::format(" (and {} more frames like it)", v.second);
  }

  const can_log& log_;
  const conversation& conv_;
  const model::device& dev_;
  const source_file& eds_;
  emit::header_facts facts_;
  emit::devicenet_facts dn_;
  verify_result result_;
};

}  // namespace

verify_result compare(const can_log& log, const conversation& conv, const model::device& dev, const source_file& eds,
                      std::optional<unsigned> mac) {
  return comparer(log, conv, dev, eds).run(mac);
}

}  // namespace edsc::verify
