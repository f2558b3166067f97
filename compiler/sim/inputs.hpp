#pragma once
// Input data chosen by the user instead of the counter pattern: whole
// assemblies in hex, or named fields of the EDS's assembly members sized and
// encoded by the member, from a JSON or TOML file (`--inputs`) or a line on
// standard input while the simulator runs (docs/sim.md).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "diag/catalogue.hpp"
#include "sim/state.hpp"

namespace edsc::sim {

// The assembly a key names: "100" (the instance) or "Assem5" (the instance AssemN describes).
[[nodiscard]] assembly_instance* find_assembly(device& d, std::string_view key);

using field_number = connections::number;
// A number as written on a control line: 12, -3, 0x1F, 1.5.
using connections::parse_number;

// Why a value or a line is refused: the rule it breaks (sim-inputs-*,
// docs/rules.md) and the message for the user.
struct input_refusal {
  diag_id id{};
  std::string message;
};

// Each sets the data and fixes it (the counter pattern leaves it alone from
// then on); the refusal, or nullopt.
[[nodiscard]] std::optional<input_refusal> set_bytes(assembly_instance& a, std::string_view hex);
// A name several members share (one ParamN in each) sets every one of
// them; a name two parameters share is refused as ambiguous.
[[nodiscard]] std::optional<input_refusal> set_field(assembly_instance& a, std::string_view name, field_number v);
// The ParamN a field name stands for, when it names exactly one parameter.
[[nodiscard]] std::optional<std::uint32_t> field_param(const assembly_instance& a, std::string_view name);

struct input_error {
  diag_id id{};
  std::uint32_t line = 0, column = 0;  // 1-based; 0 when the error has no place in the file
  std::string message;
};
// `--inputs FILE`: TOML when the name ends in .toml, else JSON. Top-level keys
// name assemblies; a value is a hex string or a table of field = number.
[[nodiscard]] std::optional<input_error> load_inputs(device& d, const std::string& path, std::string_view text);

// One control line ("set 100 01 02 03", "set Assem100 speed=5 mode=2"):
// applied whole or not at all; the JSON line that answers it.
[[nodiscard]] std::string control(state& s, std::string_view line);

}  // namespace edsc::sim
