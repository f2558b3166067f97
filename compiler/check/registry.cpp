// The one place where rule families are listed. Each family lives in its own
// file of this folder and reports through the context.
#include "check/context.hpp"

namespace edsc {

void check_structure(const check_context& ctx);

void run_checks(const check_context& ctx) {
  check_structure(ctx);
}

}  // namespace edsc
