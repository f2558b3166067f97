#include "model/device.hpp"

#include "cst/cst.hpp"

namespace edsc::model {

std::string_view device::raw(const value& v) const { return tree->text(v.from.where); }

}  // namespace edsc::model
