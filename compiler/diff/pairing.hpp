#pragma once
// Internal to the diff: pairs the entries of two lists by a key (kind and
// number). The k-th entry with a key in the old list pairs with the k-th
// with that key in the new one, so a repeated number (check's
// duplicate-entry) pairs in order, never crosswise, and a file always
// matches an identical copy. One hash lookup an entry: linear, not quadratic,
// in the length of the lists.
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace edsc::diff::detail {

template <class T>
struct pairing {
  std::vector<const T*> partner;  // per old entry: the new one it pairs with, or null
  std::vector<bool> paired;       // per new entry: whether an old one pairs with it
};

template <class T, class Key>
[[nodiscard]] pairing<T> pair_by_key(const std::vector<T>& before, const std::vector<T>& after, Key key) {
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> in_after;
  for (std::size_t j = 0; j < after.size(); ++j) in_after[key(after[j])].push_back(j);
  std::unordered_map<std::uint64_t, std::size_t> seen;
  pairing<T> out{std::vector<const T*>(before.size(), nullptr), std::vector<bool>(after.size(), false)};
  for (std::size_t i = 0; i < before.size(); ++i) {
    const auto k = key(before[i]);
    const auto rank = seen[k]++;
    const auto it = in_after.find(k);
    if (it == in_after.end() || rank >= it->second.size()) continue;
    out.partner[i] = &after[it->second[rank]];
    out.paired[it->second[rank]] = true;
  }
  return out;
}

}  // namespace edsc::diff::detail
