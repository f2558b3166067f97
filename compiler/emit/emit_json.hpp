#pragma once
#include <nlohmann/json.hpp>

#include "model/device.hpp"
#include "source/source_file.hpp"

namespace edsc::emit {

// The model as JSON (docs/dump-json.md, schema docs/dump-json.schema.json).
// Deterministic: keys in a fixed order, arrays in file order, no timestamps
// or absolute paths (the file is named by its base name only).
[[nodiscard]] nlohmann::ordered_json to_json(const model::device& dev, const source_file& src);

inline constexpr int dump_format_version = 1;

}  // namespace edsc::emit
