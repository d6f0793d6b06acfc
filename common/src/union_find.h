#pragma once
// The root of an item in a union-find forest kept as a parent array (a
// root is its own parent), halving the path on the way: the stacks of the
// support pass and the joint tree pass's groups.

#include <cstdint>
#include <vector>

namespace impulse {

inline std::int32_t unionFindRoot(std::vector<std::int32_t>& parent, std::int32_t item) {
  while (parent[std::size_t(item)] != item) {
    parent[std::size_t(item)] = parent[std::size_t(parent[std::size_t(item)])];
    item = parent[std::size_t(item)];
  }
  return item;
}

}  // namespace impulse
