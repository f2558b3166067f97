// Explicit writes in a capture held to the parameters they set: ParamN's
// value through the Parameter object (class 0x0F, instance N, attribute 1),
// or the attribute a parameter's link path names (EDS_FORMAT.md's [Params]
// link path: where the value lives in the device's objects).
#include <fmt/format.h>

#include "cip/request.hpp"
#include "cip/status.hpp"
#include "connections/fields.hpp"
#include "verify/enip_judge.hpp"

namespace edsc::verify {

namespace {

// The class, instance and attribute a link path names: those three logical
// segments with their numbers written out, nothing else. A port segment
// routes elsewhere (a module behind the device), so a write to the device
// itself is not to it; a [ParamN] standing for a number is not known here.
std::optional<cip::object_address> link_target(const model::device& dev, const model::param& p) {
  const auto* path = dev.path_of(p.link_path);
  if (path == nullptr || !path->complete || path->segments.size() != 3) return std::nullopt;
  const auto& s = path->segments;
  using k = model::segment_kind;
  if (s[0].kind != k::class_id || s[1].kind != k::instance || s[2].kind != k::attribute) return std::nullopt;
  for (const auto& seg : s)
    if (!seg.value_known()) return std::nullopt;
  return cip::object_address{s[0].value, s[1].value, s[2].value};
}

// Whether `w` sets ParamN's value: through the Parameter object, or at its link path.
bool sets(const model::device& dev, const model::param& p, const capture::write_seen& w, bool& by_link) {
  by_link = false;
  if (w.class_id == cip::code(cip::class_id::parameter) && w.instance == p.number && w.attribute == 1u) return true;
  const auto t = link_target(dev, p);
  by_link = t && t->class_id == w.class_id && t->instance == w.instance && t->attribute == w.attribute;
  return by_link;
}

// The value `data` holds for a parameter of its type: none when the sizes differ.
std::optional<connections::number> value_of(const model::device& dev, const model::param& p,
                                            const std::vector<std::uint8_t>& data) {
  const auto size = std::size_t{p.type->size};
  if (data.size() != size || size == 0 || size > 8) return std::nullopt;
  connections::data_field f;
  f.param = p.number;
  f.param_index = static_cast<std::uint32_t>(&p - dev.params.data());
  f.bits = static_cast<std::uint32_t>(size * 8);
  f.is_signed = p.type->cls == schema::type_class::signed_int;
  f.is_real = p.type->cls == schema::type_class::real;
  return connections::decode_field(f, connections::get_bits(data, 0, f.bits));
}

std::string answer_text(const capture::write_seen& w) {
  return w.reply_general ? fmt::format("the device answered 0x{:02X}", *w.reply_general)
                         : std::string("the capture holds no reply");
}

}  // namespace

// Set_Attributes_All carries every settable attribute, not the value alone:
// only Set_Attribute_Single is judged. When several parameters name the
// attribute written (views of one value), a value any of them accepts is
// not a finding; otherwise the first one's limit is the site.
std::vector<capture_finding> judge_writes(const capture::tracker& t, std::span<const capture_device> devices,
                                          std::span<const capture_eds> files) {
  std::vector<capture_finding> out;
  for (const auto& w : t.writes()) {
    if (w.service != cip::code(cip::service::set_attribute_single) || !w.attribute) continue;
    const capture_device* d = nullptr;
    for (const auto& x : devices)
      if (x.address == w.target.address && x.eds) d = &x;
    if (d == nullptr) continue;
    const auto& dev = *files[*d->eds].dev;
    std::optional<capture_finding> first;
    bool accepted = false;
    for (const auto& p : dev.params) {
      bool by_link = false;
      if (p.kind != model::param_kind::param || p.type == nullptr || !sets(dev, p, w, by_link)) continue;
      const auto value = value_of(dev, p, w.data);
      if (!value) continue;
      auto ok = connections::check_value(dev, p, *value);
      if (ok) {
        accepted = true;
        break;
      }
      if (first) continue;
      const auto via = by_link ? fmt::format(" (its link path: class 0x{:02X}, instance {}, attribute {})", w.class_id,
                                             w.instance, *w.attribute)
                               : std::string();
      first = capture_finding{
          *d->eds, make_diagnostic(diag_id::capture_write_limits, ok.error().at.empty() ? p.from.where : ok.error().at,
                                   fmt::format("frame {}: {} writes {} to Param{}{}: {}; {}", w.frame,
                                               address_text(w.originator.address), connections::number_text(*value),
                                               p.number, via, ok.error().why, answer_text(w)))};
    }
    if (first && !accepted) out.push_back(std::move(*first));
  }
  return out;
}

}  // namespace edsc::verify
