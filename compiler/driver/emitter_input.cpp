#include "driver/emitter_input.hpp"

#include <string>

#include "diag/render_text.hpp"
#include "driver/output.hpp"
#include "parse/not_text.hpp"

namespace edsc::driver {

namespace {

void show(const source_file& src, const diagnostics& diags) {
  std::string out;
  for (const auto& d : diags) render_text(src, d, text_style{use_color(color_mode::auto_detect, stderr)}, out);
  write_all(stderr, out);
}

}  // namespace

std::unique_ptr<analysis> analyse_eds_text(std::unique_ptr<source_file> source) {
  if (auto d = not_text(source->text())) {
    show(*source, {std::move(*d)});
    return nullptr;
  }
  return analyze(std::move(source), check_options{});
}

bool show_errors_touching(const analysis& a, emit::emitter who) {
  const auto errors = emit::errors_touching(a.tree, a.diags, who);
  show(*a.source, errors);
  return !errors.empty();
}

}  // namespace edsc::driver
