#pragma once
#include <cstdint>
#include <vector>

#include "model/value.hpp"

namespace edsc::model {

// [File] (EDS_FORMAT.md §3.1).
struct file_info {
  std::uint32_t section = none;  // CST section index, none when the section is missing
  value desc_text, create_date, create_time, mod_date, mod_time, revision, home_url, exclude, eds_file_crc;
};

// [Device] (§3.2). `icon_data` holds IconContents decoded when it is valid Base64.
struct device_info {
  std::uint32_t section = none;
  value vend_code, vend_name, prod_type, prod_type_str, prod_code, maj_rev, min_rev, prod_name, catalog, icon,
      icon_contents, application_profiles_assembly;
  std::vector<std::uint8_t> icon_data;
};

// Network bits, derived from [Device Classification] or from the sections present.
enum network : std::uint8_t {
  net_devicenet = 1,
  net_controlnet = 2,
  net_ethernetip = 4,
  net_componet = 8,
  net_modbus = 16,
};

struct class_entry {
  std::uint32_t number = 0;  // N of ClassN
  value network;             // keyword (public or vendor-specific)
  std::vector<value> more;   // `Class2 = 1_Tool_A, 1_Tool_B;` lists more keywords
};

struct classification {
  std::uint32_t section = none;
  std::vector<class_entry> classes;
  std::uint8_t networks = 0;         // bit set of `network`
  bool from_classification = false;  // false: inferred from the sections present
  bool safety = false;               // ClassN = Safety
};

}  // namespace edsc::model
