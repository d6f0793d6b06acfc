#pragma once
// Union-find forests kept as parent arrays (a root is its own parent),
// found with unionFindRoot: the stacks of the support pass and the joint
// tree pass's groups, whose roots name them.

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
