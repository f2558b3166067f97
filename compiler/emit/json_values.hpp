#pragma once
// Internal to the JSON emitter: how one value, path or origin is written.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cst/cst.hpp"
#include "model/device.hpp"
#include "source/source_file.hpp"

namespace edsc::emit::detail {

using json = nlohmann::ordered_json;

struct writer {
  const model::device& dev;
  const source_file& src;

  [[nodiscard]] std::uint32_t line(std::uint32_t offset) const { return src.position(offset).line; }
  [[nodiscard]] std::uint32_t line(const model::origin& o) const { return line(o.where.begin); }
  // Entity header: keyword as written and its line.
  void head(json& j, const model::origin& o) const;
  [[nodiscard]] json value(const model::value& v) const;
  [[nodiscard]] json path(const model::epath& p) const;
  [[nodiscard]] json values(const std::vector<model::value>& vs) const;
  [[nodiscard]] std::string ref_name(const model::reference& r) const;
};

// EDS text is 8-bit (often Windows-1252); JSON needs UTF-8. Valid UTF-8 is
// kept, anything else is read as Windows-1252.
[[nodiscard]] std::string to_utf8(std::string_view s);
[[nodiscard]] std::string_view to_string(model::invalid_reason r);
[[nodiscard]] json mask_names(std::uint64_t mask, std::initializer_list<std::string_view> names);

}  // namespace edsc::emit::detail
