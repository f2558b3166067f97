#include "io/collect_inputs.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

namespace edsc::io {

namespace fs = std::filesystem;

namespace {

bool has_eds_extension(const fs::path& p) {
  auto ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".eds";
}

}  // namespace

collected_inputs collect_inputs(const std::vector<std::string>& args) {
  collected_inputs out;
  for (const auto& arg : args) {
    if (is_stdin(arg)) {
      out.files.push_back(arg);
      continue;
    }
    std::error_code ec;
    const auto status = fs::status(arg, ec);
    if (ec || !fs::exists(status)) {
      out.errors.push_back({fmt::format("{}: no such file or directory", arg)});
      continue;
    }
    if (!fs::is_directory(status)) {
      out.files.push_back(arg);
      continue;
    }
    std::vector<std::string> found;
    fs::recursive_directory_iterator it(arg, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      std::error_code fec;
      if (it->is_regular_file(fec) && has_eds_extension(it->path())) found.push_back(it->path().string());
    }
    if (ec) {
      out.errors.push_back({fmt::format("{}: cannot read directory: {}", arg, ec.message())});
      continue;
    }
    if (found.empty()) {
      out.errors.push_back({fmt::format("{}: directory holds no .eds files", arg)});
      continue;
    }
    std::sort(found.begin(), found.end());
    out.files.insert(out.files.end(), found.begin(), found.end());
  }
  return out;
}

}  // namespace edsc::io
