#pragma once
// `edsc header`: the facts of a device (header_view.hpp) rendered through the
// mustache templates (header_render.cpp).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "facts/header_view.hpp"

namespace edsc::emit {

struct header_options {
  std::string prefix = "EDS_";
  std::optional<std::uint32_t> serial;  // unset: the build defines it (#ifndef guard)
  std::string template_dir;             // empty: the built-in templates only
  std::string output_name = "eds.h";    // base name of the header, for the include guard
};

struct header_result {
  std::string text;                    // the header, when no error
  std::vector<header_issue> issues;    // EDS problems
  std::optional<std::string> failure;  // template or option problem (exit 2)
  [[nodiscard]] bool has_error() const;
};

[[nodiscard]] header_result generate_header(const model::device& dev, const source_file& src,
                                            const header_options& options);

}  // namespace edsc::emit
