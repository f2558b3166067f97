#include "model/capacity.hpp"

#include "schema/text.hpp"

namespace edsc::model {

const setting* capacity::find(std::string_view canonical) const {
  for (const auto& s : settings)
    if (schema::iequals(s.canonical, canonical)) return &s;
  return nullptr;
}

}  // namespace edsc::model
