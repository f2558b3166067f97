#pragma once
// What the simulated device holds, read once from the typed model: its
// identity from [Device], its assembly instances, and one connection point
// per ConnectionN it can serve (paths, sizes and formats from the same
// collector `edsc header` and `verify --live` use). No second model of the
// EDS: every number here comes from model::device through connections::plan_connections.
#include <cstdint>
#include <string>
#include <vector>

#include "cip/encap.hpp"
#include "cip/request.hpp"
#include "connections/fields.hpp"
#include "connections/plan.hpp"
#include "connections/served_points.hpp"
#include "model/device.hpp"
#include "schema/cip_types.hpp"

namespace edsc::sim {

enum class assembly_role : std::uint8_t { input, output, config, other };

// A member of an AssemN that names a ParamN: what `--inputs` and the
// control on standard input set by name (inputs.cpp).
using input_field = connections::data_field;

struct assembly_instance {
  std::uint32_t instance = 0;
  assembly_role role = assembly_role::other;
  cip::bytes data;               // its size is the EDS's
  bool fixed = false;            // input data given by --inputs: the counter pattern leaves it alone
  std::uint32_t eds_number = 0;  // N of the AssemN describing it, 0 when none does
  std::vector<input_field> fields;
};

using connections::connection_point;
using connections::default_rpi_max_us;
using connections::default_rpi_min_us;
using connections::rpi_limits;
using connections::unserved;

// One ParamN served as Parameter object (class 0x0F) instance N, its
// attributes as the EDS gives them (parameter_object.cpp).
struct parameter_instance {
  std::uint32_t number = 0;
  // A fixed-size number type (integer, bit string, real): value, min, max
  // and default are encoded in it and Set_Attribute_Single is checked
  // against them. nullptr: a string or other type, served read-only.
  const schema::cip_type_info* type = nullptr;
  bool read_only = false;  // descriptor bit 4
  std::uint16_t descriptor = 0;
  std::uint8_t data_type = 0, data_size = 0;
  std::string name, units, help;
  cip::bytes value, min, max, def, link_path;
  std::vector<cip::bytes> allowed;  // enumerated with an EnumN: its values; else empty (min..max)
  std::uint16_t multiplier = 1, divisor = 1, base = 1, offset = 0;  // attributes 13-16 (offset an INT)
  std::uint16_t links[4] = {0, 0, 0, 0};                            // attributes 17-20
  std::uint8_t precision = 0;                                       // attribute 21
};

// The EDS itself, served by the File object (class 0x37, instance 0xC8).
struct eds_file {
  std::string name;  // the file name without directories
  cip::bytes content;
  std::uint8_t major = 1, minor = 0;  // [File] Revision
};

struct device {
  const model::device* eds = nullptr;  // what the points' plans point into; outlives the simulator
  cip::identity id;                    // attributes 1-7; serial from the command line
  std::vector<assembly_instance> assemblies;
  std::vector<connection_point> points;
  std::vector<unserved> skipped;
  std::vector<parameter_instance> params;  // sorted by number
  std::uint16_t param_class_descriptor = 0x0003, cfg_assembly = 0;
  eds_file file;

  [[nodiscard]] parameter_instance* param(std::uint32_t number);
  [[nodiscard]] const parameter_instance* param(std::uint32_t number) const;

  [[nodiscard]] assembly_instance* assembly(std::uint32_t instance);
  [[nodiscard]] const assembly_instance* assembly(std::uint32_t instance) const;
};

[[nodiscard]] device build_device(const model::device& dev, std::uint32_t serial);
// Named fields of the assemblies an AssemN describes (inputs.cpp).
void add_fields(const model::device& dev, device& d);
// The Parameter object's instances and class attributes from [Params] and [ParamClass].
void add_parameters(const model::device& dev, device& d);

}  // namespace edsc::sim
