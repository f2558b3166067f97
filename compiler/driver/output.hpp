#pragma once
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "source/source_file.hpp"

namespace edsc::driver {

enum class color_mode { auto_detect, always, never };
enum class report_format { text, json, sarif };

[[nodiscard]] bool use_color(color_mode mode, std::FILE* stream);

// Writes all of `s`; returns false when the stream failed (a closed pipe).
bool write_all(std::FILE* stream, std::string_view s);

void print_error(std::string_view message);  // "edsc: error: ..." on stderr

// --color=auto|always|never.
void add_color_option(CLI::App* cmd, color_mode& color);

// --color, --format and -W, shared by every command that reports diagnostics.
void add_report_options(CLI::App* cmd, color_mode& color, report_format& format,
                        std::vector<std::string>& warning_flags);

// Reads an input file; on failure prints why and returns null.
[[nodiscard]] std::unique_ptr<source_file> read_or_report(const std::string& path);

}  // namespace edsc::driver
