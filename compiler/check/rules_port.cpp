// [Port], [Capacity], [Modular] and the embedded icon (EDS_FORMAT.md §3.12-3.14,
// §8.2, §7 rules 43-46). [Capacity] needs nothing here: TSpecN direction
// keywords and non-negative sizes/rates are enforced by value typing.
#include <array>
#include <unordered_map>

#include <fmt/format.h>

#include "check/context.hpp"
#include "schema/text.hpp"

namespace edsc {

namespace {

// Public port type keywords all name networks; vendor-specific types
// (`65535_Chassis`) may well be the backplane, so they are left alone.
bool network_port_type(std::string_view type) {
  static constexpr std::array<std::string_view, 5> networks{"TCP", "DeviceNet", "ControlNet", "CompoNet", "EtherNetIP"};
  for (const auto n : networks)
    if (schema::iequals(n, type)) return true;
  return false;
}

void check_ports(const check_context& ctx) {
  std::unordered_map<std::uint64_t, const model::port*> first;
  for (const auto& p : ctx.dev.ports) {
    if (!p.port_number.is_integer()) continue;
    const auto n = p.port_number.as_uint();
    const auto [it, fresh] = first.try_emplace(n, &p);
    if (!fresh) {
      ctx.report_with_note(
          diag_id::port_number_duplicate, ctx.where(p.port_number),
          fmt::format("Port{} uses port number {}, already used by Port{}", p.number, n, it->second->number),
          ctx.where(it->second->port_number), fmt::format("Port{} uses it here", it->second->number));
    }
    if (n == 1 && p.type.ok() && network_port_type(p.type.text)) {
      ctx.report(diag_id::port_one_not_backplane, ctx.where(p.port_number),
                 fmt::format("Port{} is a {} port but uses port number 1, which is by convention the backplane",
                             p.number, p.type.text));
    }
  }
}

void check_modular(const check_context& ctx) {
  const auto& slots = ctx.dev.mod.define_slots_in_rack;
  if (slots.is_integer() && slots.as_uint() == 0) {
    ctx.report(diag_id::modular_zero_slots, ctx.where(slots), "DefineSlotsInRack is 0: the rack has no slot");
  }
}

void check_icon(const check_context& ctx) {
  const auto& id = ctx.dev.identity;
  if (!id.icon_contents.present()) return;
  if (!id.icon.present()) {
    ctx.report(diag_id::icon_contents_without_icon, ctx.entry_keyword(id.icon_contents.from),
               "IconContents is given but Icon (the icon's file name) is not");
  }
  const auto& data = id.icon_data;
  if (!id.icon_contents.ok() || data.empty()) return;  // invalid Base64 is reported by the value rules
  static constexpr std::array<std::uint8_t, 4> ico{0x00, 0x00, 0x01, 0x00};
  if (data.size() >= ico.size() && std::equal(ico.begin(), ico.end(), data.begin())) return;
  // A BMP is a vendor's deliberate choice (a whole product line writes it), so
  // only a note; anything else is probably a damaged copy.
  if (data.size() >= 2 && data[0] == 'B' && data[1] == 'M') {
    ctx.report(diag_id::icon_bmp, ctx.where(id.icon_contents),
               "IconContents decodes to a BMP image, not an ICO icon (00 00 01 00)");
    return;
  }
  ctx.report(diag_id::icon_not_ico, ctx.where(id.icon_contents),
             fmt::format("IconContents decodes to data starting {:02X} {:02X}, not an ICO icon (00 00 01 00)", data[0],
                         data.size() > 1 ? data[1] : 0));
}

}  // namespace

void check_ports_and_icon(const check_context& ctx) {
  check_ports(ctx);
  check_modular(ctx);
  check_icon(ctx);
}

}  // namespace edsc
