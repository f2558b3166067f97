// The one place where rule families are listed. Each family lives in its own
// file of this folder and reports through the context.
#include "check/context.hpp"

namespace edsc {

void check_structure(const check_context& ctx);
void check_values(const check_context& ctx);
void check_identity(const check_context& ctx);
void check_io_info(const check_context& ctx);
void check_params(const check_context& ctx);
void check_connection_family(const check_context& ctx);
void check_schema(const check_context& ctx);
void check_enums(const check_context& ctx);

void run_checks(const check_context& ctx) {
  check_structure(ctx);
  check_values(ctx);
  check_identity(ctx);
  check_io_info(ctx);
  check_params(ctx);
  check_connection_family(ctx);
  check_schema(ctx);
  check_enums(ctx);
}

}  // namespace edsc
