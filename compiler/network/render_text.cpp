// The text table and the JSON document of `edsc net map`.
#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "base/plural.hpp"
#include "network/render_map.hpp"

namespace edsc::network {

namespace {

const image_profile& profile_of(const plan& p, const image_layout& image) {
  return image.input ? p.profile->input : p.profile->output;
}

std::string word_range(std::uint32_t a, std::uint32_t b) {
  return a == b ? std::to_string(a) : fmt::format("{}-{}", a, b);
}

void text_image(const plan& p, const image_layout& image, std::string& out) {
  const auto& ip = profile_of(p, image);
  const auto slave_words = ip.words - ip.reserved_words;
  out += fmt::format("{} image Local:{}:{} ({}): words 0-{} {}; slave data words {}-{} (DWords 0-{})\n",
                     image.input ? "input" : "output", p.slot, ip.tag, plural(ip.words, "word"), ip.reserved_words - 1,
                     ip.reserved_name, ip.reserved_words, ip.words - 1, slave_words / 2 - 1);
  std::size_t name_w = 4;
  for (const auto& b : image.blocks) name_w = std::max(name_w, p.nodes[b.node].name.size());
  out += fmt::format("  {:>3}  {:<{}}  {:<10}  {:>5}  {:<7}  {:<7}  {:<6}  {}\n", "MAC", "node", name_w, "connection",
                     "bytes", "byte", "words", "DWords", "tag");
  for (const auto& b : image.blocks) {
    const auto& n = p.nodes[b.node];
    const auto at = place_of(p, image, b);
    out += fmt::format("  {:>3}  {:<{}}  {:<10}  {:>5}  {:<7}  {:<7}  {:<6}  {}{}\n", n.mac, n.name, name_w,
                       label_of(b.type), b.size, word_range(b.offset, b.end() - 1),
                       word_range(at.first_word, at.last_word), word_range(at.first_dword, at.last_dword), at.tag,
                       b.fixed ? "  (fixed)" : "");
  }
  if (image.blocks.empty()) out += "  (no node has data in this image)\n";
  out += fmt::format("  {} of {} slave data bytes used, {} free\n\n", image.used(), image.capacity,
                     image.capacity - image.used());
}

}  // namespace

block_place place_of(const plan& p, const image_layout& image, const block& b) {
  const auto& ip = profile_of(p, image);
  block_place at;
  at.first_word = ip.reserved_words + b.offset / 2;
  at.last_word = ip.reserved_words + (b.end() - 1) / 2;
  at.first_dword = b.offset / 4;
  at.last_dword = (b.end() - 1) / 4;
  at.tag = fmt::format("Local:{}:{}.Data[{}]", p.slot, ip.tag, at.first_dword);
  if (b.offset % 4 != 0) at.tag += fmt::format(".{}", (b.offset % 4) * 8);
  if (at.last_dword != at.first_dword) at.tag += fmt::format("..Data[{}]", at.last_dword);
  return at;
}

std::string render_map_text(const map_input& m) {
  const auto& p = m.p;
  std::string out = fmt::format(
      "network {}: {} scanner at MAC {}, slot {}; {}; alignment {}, start DWord {} "
      "(input) and {} (output)\n\n",
      p.name, p.profile->name, p.scanner_mac, p.slot, plural(p.nodes.size(), "node"), name_of(p.align), p.input_start,
      p.output_start);
  text_image(p, m.l.input, out);
  text_image(p, m.l.output, out);
  out += fmt::format("  {:>3}  {:<24}  {:<10}  {}\n", "MAC", "node", "keying",
                     "identity (vendor/type/code/revision) and product");
  for (const auto& n : p.nodes) {
    std::string id = "(not stated)";
    if (n.identity)
      id = fmt::format("{}/{}/{}/{}.{}", n.identity->vendor, n.identity->device_type, n.identity->product_code,
                       n.identity->major, n.identity->minor);
    out += fmt::format("  {:>3}  {:<24}  {:<10}  {} {}{}\n", n.mac, n.name, name_of(n.key), id,
                       n.product.empty() ? "" : fmt::format("\"{}\"", n.product), n.has_eds ? "" : " (no EDS)");
  }
  return out;
}

std::string render_map_json(const map_input& m) {
  using json = nlohmann::ordered_json;
  const auto& p = m.p;
  json out;
  out["format"] = "edsc-network-map";
  out["version"] = 1;
  out["network"] = p.name;
  out["scanner"] = {{"profile", p.profile->name}, {"mac", p.scanner_mac}, {"slot", p.slot}};
  out["alignment"] = name_of(p.align);
  json nodes = json::array();
  for (const auto& n : p.nodes) {
    json j{{"mac", n.mac},
           {"name", n.name},
           {"product", n.product},
           {"eds", n.has_eds ? json(n.eds) : json(nullptr)},
           {"keying", name_of(n.key)}};
    if (n.identity)
      j["identity"] = {{"vendor", n.identity->vendor},
                       {"device_type", n.identity->device_type},
                       {"product_code", n.identity->product_code},
                       {"major", n.identity->major},
                       {"minor", n.identity->minor}};
    else
      j["identity"] = nullptr;
    json conns = json::array();
    for (const auto& c : n.connections)
      conns.push_back({{"type", name_of(c.type)}, {"input", c.input}, {"output", c.output}});
    j["connections"] = std::move(conns);
    nodes.push_back(std::move(j));
  }
  out["nodes"] = std::move(nodes);
  json images = json::array();
  for (const auto* image : {&m.l.input, &m.l.output}) {
    const auto& ip = profile_of(p, *image);
    json blocks = json::array();
    for (const auto& b : image->blocks) {
      const auto at = place_of(p, *image, b);
      blocks.push_back({{"mac", p.nodes[b.node].mac},
                        {"node", p.nodes[b.node].name},
                        {"connection", name_of(b.type)},
                        {"byte", b.offset},
                        {"bytes", b.size},
                        {"words", {at.first_word, at.last_word}},
                        {"dwords", {at.first_dword, at.last_dword}},
                        {"tag", at.tag},
                        {"fixed", b.fixed}});
    }
    images.push_back({{"direction", image->input ? "input" : "output"},
                      {"tag", fmt::format("Local:{}:{}", p.slot, ip.tag)},
                      {"words", ip.words},
                      {"reserved", {{"words", {0, ip.reserved_words - 1}}, {"content", ip.reserved_name}}},
                      {"slave_words", {ip.reserved_words, ip.words - 1}},
                      {"slave_bytes", image->capacity},
                      {"used_bytes", image->used()},
                      {"blocks", std::move(blocks)}});
  }
  out["images"] = std::move(images);
  return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace edsc::network
