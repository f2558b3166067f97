#pragma once
#include <cstddef>
#include <map>
#include <string>

#include "base/result.hpp"

namespace edsc::emit {

// The templates of templates/, compiled in (cmake/embed_templates.cmake).
struct embedded_template {
  const char* name;  // file name, e.g. "header.h.mustache"
  const char* text;
};
extern const embedded_template embedded_templates[];
extern const std::size_t embedded_template_count;

using template_set = std::map<std::string, std::string>;  // file name -> text

// The built-in templates, each replaced by `dir`/<name> when that file exists
// (an empty `dir` means built-ins only); on I/O failure, the sentence that
// says what could not be read.
struct templates_unreadable {
  std::string message;
};
[[nodiscard]] result<template_set, templates_unreadable> load_templates(const std::string& dir);

}  // namespace edsc::emit
