#include "network/layout.hpp"

#include <algorithm>

namespace edsc::network {

namespace {

std::uint32_t align_up(std::uint32_t at, alignment a) {
  const auto n = static_cast<std::uint32_t>(a);
  return (at + n - 1) / n * n;
}

struct mapper {
  const plan& p;
  bool input;
  image_layout image;
  std::vector<layout_problem>& problems;

  std::uint32_t size_of(const planned_connection& c) const { return input ? c.input : c.output; }

  const block* overlapping(std::uint32_t at, std::uint32_t size) const {
    for (const auto& b : image.blocks)
      if (at < b.end() && b.offset < at + size) return &b;
    return nullptr;
  }

  // A node's data at a fixed DWord: its connections one after the other.
  void place_fixed(std::size_t n, std::uint32_t dword) {
    std::uint32_t at = dword * 4;
    for (const auto& c : p.nodes[n].connections) {
      const auto size = size_of(c);
      if (size == 0) continue;
      at = align_up(at, p.align);
      if (std::uint64_t{at} + size > image.capacity) {
        problems.push_back({input, n, false, 0, at, size});
        return;
      }
      if (const auto* b = overlapping(at, size)) problems.push_back({input, n, true, b->node, at, size});
      image.blocks.push_back({n, c.type, at, size, true});
      at += size;
    }
  }

  void place_auto(std::size_t n, std::uint32_t& cursor) {
    for (const auto& c : p.nodes[n].connections) {
      const auto size = size_of(c);
      if (size == 0) continue;
      std::uint32_t at = align_up(cursor, p.align);
      while (const auto* b = overlapping(at, size)) at = align_up(b->end(), p.align);
      if (std::uint64_t{at} + size > image.capacity) {
        problems.push_back({input, n, false, 0, at, size});
        return;
      }
      image.blocks.push_back({n, c.type, at, size, false});
      cursor = at + size;
    }
  }

  image_layout run() {
    image.input = input;
    image.capacity = (input ? p.profile->input : p.profile->output).slave_bytes();
    for (std::size_t n = 0; n < p.nodes.size(); ++n) {
      const auto& fixed = input ? p.nodes[n].input_dword : p.nodes[n].output_dword;
      if (fixed) place_fixed(n, *fixed);
    }
    const auto start = input ? p.input_start : p.output_start;
    std::uint32_t cursor = start * 4;
    for (std::size_t n = 0; n < p.nodes.size(); ++n) {
      const auto& fixed = input ? p.nodes[n].input_dword : p.nodes[n].output_dword;
      if (!fixed) place_auto(n, cursor);
    }
    std::stable_sort(image.blocks.begin(), image.blocks.end(),
                     [](const block& a, const block& b) { return a.offset < b.offset; });
    return std::move(image);
  }
};

}  // namespace

std::uint32_t image_layout::used() const {
  std::uint32_t n = 0;
  for (const auto& b : blocks) n += b.size;
  return n;
}

layout automap(const plan& p) {
  layout l;
  if (p.profile == nullptr) return l;
  l.input = mapper{p, true, {}, l.problems}.run();
  l.output = mapper{p, false, {}, l.problems}.run();
  return l;
}

}  // namespace edsc::network
