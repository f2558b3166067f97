#include "verify/decode.hpp"

#include <algorithm>
#include <array>
#include <set>

#include <fmt/format.h>

#include "base/plural.hpp"

namespace edsc::verify {

namespace {

constexpr std::uint8_t svc_get = 0x0E, svc_set = 0x10, svc_allocate = 0x4B, svc_release = 0x4C, svc_error = 0x94;

// What the decoder remembers of one node between frames.
struct node_state {
  std::optional<std::size_t> pending;  // exchange awaiting its answer
  std::uint8_t allocated = 0;
  std::vector<std::uint8_t> fragments;  // a fragmented answer being reassembled
  bool fragmenting = false;
};

std::uint16_t le16(const std::vector<std::uint8_t>& d, std::size_t at) {
  return static_cast<std::uint16_t>(d[at] | (d[at + 1] << 8));
}

class decoder {
 public:
  explicit decoder(const can_log& log) : log_(log) {}

  conversation run() {
    for (std::size_t i = 0; i < log_.frames.size(); ++i) conv_.frames.push_back(frame(i));
    conv_.nodes.assign(heard_.begin(), heard_.end());
    // A MAC that only sent a duplicate MAC check is a node when someone talks to it
    // (the scanner checks its own MAC too, and is no slave).
    for (const auto mac : dup_only_)
      if (addressed_.contains(mac) && !heard_.contains(mac)) conv_.nodes.push_back(mac);
    std::sort(conv_.nodes.begin(), conv_.nodes.end());
    return std::move(conv_);
  }

 private:
  decoded_frame frame(std::size_t i) {
    const auto& f = log_.frames[i];
    decoded_frame d;
    d.frame = i;
    d.dir = f.dir != 0 ? f.dir : '?';
    if (f.extended || f.remote) {
      d.undecodable = true;
      d.why = f.extended ? "a 29-bit identifier; DeviceNet uses 11-bit ones" : "a remote frame; DeviceNet sends none";
      d.label = f.extended ? "29-bit" : "remote";
      return d;
    }
    if (f.id < 0x400) {
      d.group = 1;
      d.message = f.id >> 6;
      d.mac = f.id & 0x3F;
      group1(i, d);
    } else if (f.id < 0x600) {
      d.group = 2;
      d.mac = (f.id >> 3) & 0x3F;
      d.message = f.id & 0x7;
      group2(i, d);
    } else {
      d.group = f.id < 0x7C0 ? 3 : 4;
      d.message = f.id < 0x7C0 ? (f.id >> 6) & 0x7 : f.id & 0x3F;
      d.mac = f.id < 0x7C0 ? f.id & 0x3F : 0;
      d.label = fmt::format("G{} msg {}", d.group, d.message);
      d.undecodable = true;
      d.why = f.id >= 0x7F0 ? "an identifier DeviceNet does not use (0x7F0-0x7FF)"
                            : fmt::format("group {} is outside the Predefined Master/Slave Connection Set", d.group);
    }
    return d;
  }

  void group1(std::size_t i, decoded_frame& d) {
    d.dir = 'S';
    const auto& f = log_.frames[i];
    auto& node = nodes_[d.mac];
    heard_.insert(d.mac);
    io_event e{i, d.mac, true, conn_type::cos, node.allocated, f.data.size()};
    switch (d.message) {
      case 0xC:
        d.label = "G1 msg 12: multicast poll response";
        d.meaning = plural(f.data.size(), "byte");
        return;
      case 0xD:
        e.type = (node.allocated & choice_cyclic) != 0 ? conn_type::cyclic : conn_type::cos;
        d.label = "G1 msg 13: COS/cyclic data";
        break;
      case 0xE:
        e.type = conn_type::strobe;
        d.label = "G1 msg 14: bit-strobe response";
        break;
      case 0xF:
        if ((node.allocated & choice_poll) == 0 && (node.allocated & (choice_cos | choice_cyclic)) != 0) {
          d.label = "G1 msg 15: COS/cyclic acknowledge";
          d.meaning = "the slave acknowledges the master's COS/cyclic data";
          return;
        }
        e.type = conn_type::poll;
        d.label = "G1 msg 15: poll response";
        break;
      default:
        d.label = fmt::format("G1 msg {}", d.message);
        d.undecodable = true;
        d.why = "a group 1 message id the predefined set does not use";
        return;
    }
    d.meaning = fmt::format("{}: {}", plural(f.data.size(), "data byte"), hex_bytes(f.data));
    conv_.io.push_back(e);
  }

  void group2(std::size_t i, decoded_frame& d) {
    const auto& f = log_.frames[i];
    auto& node = nodes_[d.mac];
    static constexpr std::array<const char*, 8> names{
        "bit-strobe command", "multicast poll command",  "COS/cyclic acknowledge", "explicit response",
        "explicit request",   "poll/COS/cyclic command", "unconnected request",    "duplicate MAC ID check"};
    d.label = fmt::format("G2 msg {}: {}", d.message, names[d.message]);
    switch (d.message) {
      case 0:
      case 1:
        d.dir = 'M';
        d.meaning = fmt::format("master MAC {}, {}", d.mac, plural(f.data.size(), "byte"));
        return;
      case 2:
        d.dir = 'M';
        d.meaning = fmt::format("to MAC {}", d.mac);
        addressed_.insert(d.mac);
        return;
      case 3:
        d.dir = 'S';
        heard_.insert(d.mac);
        answer(i, d, node);
        return;
      case 4:
      case 6:
        d.dir = 'M';
        addressed_.insert(d.mac);
        request(i, d, node);
        return;
      case 5: {
        d.dir = 'M';
        addressed_.insert(d.mac);
        const auto type = (node.allocated & choice_poll) != 0     ? conn_type::poll
                          : (node.allocated & choice_cyclic) != 0 ? conn_type::cyclic
                                                                  : conn_type::cos;
        conv_.io.push_back({i, d.mac, false, type, node.allocated, f.data.size()});
        d.meaning = fmt::format("to MAC {}: {}: {}", d.mac, plural(f.data.size(), "data byte"), hex_bytes(f.data));
        return;
      }
      default:
        if (f.data.size() != 7) {
          d.undecodable = true;
          d.why = fmt::format("a duplicate MAC ID check has 7 data bytes, not {}", f.data.size());
          return;
        }
        dup_only_.insert(d.mac);
        d.meaning = fmt::format("MAC {} is on line: vendor {}, serial 0x{:08X}{}", d.mac, le16(f.data, 1),
                                static_cast<std::uint32_t>(f.data[3] | (f.data[4] << 8) | (f.data[5] << 16)) |
                                    (static_cast<std::uint32_t>(f.data[6]) << 24),
                                (f.data[0] & 0x80) != 0 ? " (response)" : "");
        return;
    }
  }

  void request(std::size_t i, decoded_frame& d, node_state& node) {
    const auto& b = log_.frames[i].data;
    if (b.size() >= 2 && (b[0] & 0x80) != 0 && (b[1] & 0xC0) == 0xC0) {
      d.meaning = fmt::format("acknowledges fragment {}", b[1] & 0x3F);
      return;
    }
    if (b.size() < 4 || (b[0] & 0x80) != 0 || (b[1] & 0x80) != 0) {
      d.undecodable = true;
      d.why = (b.size() >= 1 && (b[0] & 0x80) != 0) ? "a fragmented request (not decoded)"
                                                    : "too short or not a request body (hdr svc class inst)";
      return;
    }
    exchange x;
    x.mac = d.mac;
    x.request = i;
    x.service = b[1];
    x.cls = b[2];
    x.inst = b[3];
    x.allocated = node.allocated;
    const bool path_attr = x.service == svc_get || x.service == svc_set;
    if (path_attr && b.size() < 5) {
      d.undecodable = true;
      d.why = fmt::format("{} without an attribute", service_name(x.service, x.cls));
      return;
    }
    x.has_attr = path_attr;
    if (path_attr) x.attr = b[4];
    x.value.assign(b.begin() + (path_attr ? 5 : 4), b.end());
    d.meaning = fmt::format("{} {}/{}", service_name(x.service, x.cls), x.cls, x.inst);
    if (x.has_attr) d.meaning += fmt::format("/{} ({})", x.attr, attribute_name(x.cls, x.inst, x.attr));
    if ((x.service == svc_allocate || x.service == svc_release) && !x.value.empty())
      d.meaning += ": " + choice_names(x.value[0]);
    else if (!x.value.empty())
      d.meaning += " = " + hex_bytes(x.value);
    node.pending = conv_.exchanges.size();
    node.fragmenting = false;
    conv_.exchanges.push_back(std::move(x));
  }

  void answer(std::size_t i, decoded_frame& d, node_state& node) {
    const auto& b = log_.frames[i].data;
    std::vector<std::uint8_t> body;
    if (b.size() >= 2 && (b[0] & 0x80) != 0) {
      const unsigned type = b[1] >> 6;
      if (type == 0) node.fragments.clear(), node.fragmenting = true;
      if (!node.fragmenting) {
        d.undecodable = true;
        d.why = "a fragment without its first fragment";
        return;
      }
      node.fragments.insert(node.fragments.end(), b.begin() + 2, b.end());
      d.meaning = fmt::format("fragment {} ({})", b[1] & 0x3F, type == 0 ? "first" : type == 2 ? "last" : "middle");
      if (type != 2) return;
      node.fragmenting = false;
      body = node.fragments;
    } else if (b.size() >= 2) {
      body.assign(b.begin() + 1, b.end());
    } else {
      d.undecodable = true;
      d.why = "an explicit response needs a header and a service byte";
      return;
    }
    if (!node.pending) {
      d.undecodable = true;
      d.why = "a response to no request in the capture";
      return;
    }
    auto& x = conv_.exchanges[*node.pending];
    node.pending.reset();
    x.answer = i;
    if (body[0] == svc_error) {
      x.error = true;
      x.general = body.size() > 1 ? body[1] : 0xFF;
      x.additional = body.size() > 2 ? body[2] : 0xFF;
      d.meaning += fmt::format("{}error: {}", d.meaning.empty() ? "" : ", ", status_name(x.general));
      return;
    }
    if (body[0] != (x.service | 0x80)) {
      d.undecodable = true;
      d.why = fmt::format("answers service 0x{:02X}, the request was 0x{:02X}", body[0] & 0x7F, x.service);
      return;
    }
    x.data.assign(body.begin() + 1, body.end());
    if (x.service == svc_allocate && !x.value.empty()) node.allocated |= x.value[0];
    if (x.service == svc_release && !x.value.empty()) node.allocated &= static_cast<std::uint8_t>(~x.value[0]);
    d.meaning += fmt::format("{}{} ok{}", d.meaning.empty() ? "" : ", ", service_name(x.service, x.cls),
                             x.data.empty() ? "" : ": " + hex_bytes(x.data));
  }

  const can_log& log_;
  conversation conv_;
  std::array<node_state, 64> nodes_{};
  std::set<unsigned> heard_, addressed_, dup_only_;
};

}  // namespace

conversation decode(const can_log& log) { return decoder(log).run(); }

}  // namespace edsc::verify
