#include "diag/policy.hpp"

#include <fmt/format.h>

namespace edsc {

namespace {

bool protected_group(std::string_view group) { return group == "syntax" || group == "input"; }

// The rules a flag names: one id, or every rule of a group.
std::vector<diag_id> rules_named(std::string_view name) {
  std::vector<diag_id> out;
  for (const auto& r : all_rules()) {
    if (r.name == name || r.group == name) out.push_back(r.id);
  }
  return out;
}

}  // namespace

// Pedantic rules flag what the format allows but a careful author may still
// want to know; they are off until -Wpedantic (or their own -W<id>).
diag_policy::diag_policy() : rules_(all_rules().size()) {
  for (const auto& r : all_rules()) {
    if (r.group == "pedantic") rules_[static_cast<std::size_t>(r.id)].enabled = false;
  }
}

result<void, std::string> diag_policy::add_flag(std::string_view flag) {
  // The global forms set every rule they speak of, so that a later -Werror
  // overrides an earlier -Wno-error=ID and the other way round.
  if (flag == "error" || flag == "no-error") {
    const bool on = flag == "error";
    for (const auto& r : all_rules()) {
      auto& st = rules_[static_cast<std::size_t>(r.id)];
      if (!on)
        st.promote = to_error::no;
      else if (r.default_level == severity::warning)
        st.promote = to_error::yes;
    }
    return {};
  }
  bool enable = true;
  auto promote = to_error::unset;
  std::string_view name = flag;
  if (name.starts_with("error=")) {
    promote = to_error::yes;
    name.remove_prefix(6);
  } else if (name.starts_with("no-error=")) {
    promote = to_error::no;
    name.remove_prefix(9);
  } else if (name.starts_with("no-")) {
    enable = false;
    name.remove_prefix(3);
  }
  const auto ids = rules_named(name);
  if (ids.empty()) {
    return fail(fmt::format("unknown diagnostic or group '{}' in -W{} (see `edsc rules`)", name, flag));
  }
  for (const auto id : ids) {
    const auto& info = rule_of(id);
    auto& st = rules_[static_cast<std::size_t>(id)];
    if (promote != to_error::unset) {
      st.promote = promote;
      if (promote == to_error::yes) st.enabled = true;  // as -Werror=ID does in compilers
    } else if (!enable && protected_group(info.group)) {
      return fail(fmt::format("-W{}: {} errors cannot be disabled", flag, info.group));
    } else {
      st.enabled = enable;
    }
  }
  return {};
}

bool diag_policy::enabled(diag_id id) const { return rules_[static_cast<std::size_t>(id)].enabled; }

severity diag_policy::level_of(diag_id id) const {
  const auto& st = rules_[static_cast<std::size_t>(id)];
  return st.promote == to_error::yes ? severity::error : rule_of(id).default_level;
}

void diag_policy::apply(diagnostics& ds) const {
  std::erase_if(ds, [this](const diagnostic& d) { return !enabled(d.id); });
  for (auto& d : ds) {
    if (d.level == rule_of(d.id).default_level) d.level = level_of(d.id);
  }
}

}  // namespace edsc
