#include "emit/templates.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace edsc::emit {

result<template_set, templates_unreadable> load_templates(const std::string& dir) {
  template_set set;
  for (std::size_t i = 0; i < embedded_template_count; ++i)
    set.emplace(embedded_templates[i].name, embedded_templates[i].text);
  if (dir.empty()) return set;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    return fail(templates_unreadable{"template directory '" + dir + "' does not exist"});
  }
  // Only the names edsc knows are read: a stray file cannot change the output.
  for (auto& [name, text] : set) {
    const auto path = std::filesystem::path(dir) / name;
    if (!std::filesystem::exists(path, ec)) continue;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    if (!in) return fail(templates_unreadable{"cannot read template '" + path.string() + "'"});
    text = s.str();
  }
  return set;
}

}  // namespace edsc::emit
