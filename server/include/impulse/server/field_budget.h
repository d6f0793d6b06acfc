#pragma once
/// What a room's force fields cost per step, so that no field, and no body
/// spawned under fields, can make one room's step take seconds (issue 30:
/// one gravitation field over 9 990 bodies cost about 300 ms a step).
///
/// The cost is counted in body interactions per step: a gravitation field
/// acts between every pair of bodies, n (n - 1) / 2; a fan or fluid region
/// looks at each body once, n.

#include <cstdint>
#include <string>

#include "impulse/field_kinds.h"
#include "impulse/world.h"

namespace impulse::server {

struct FieldLimits {
  /// Fields a room may hold (--max-fields).
  int maxFields = 64;
  /// Body interactions per step all the room's fields may cost
  /// (--max-field-cost); about 6 ms of gravitation on one core.
  std::uint64_t maxCost = 1'000'000;
};

/// The cost of one field of kind `def` over `bodies` bodies.
std::uint64_t fieldCost(const FieldDef& def, std::uint64_t bodies);
/// The cost of every field of `world` were it to hold `bodies` bodies.
std::uint64_t fieldsCost(const World& world, std::uint64_t bodies);

/// Why `def` may not be added to `world` (count or cost), or "".
std::string fieldRefusal(const World& world, const FieldDef& def, const FieldLimits& limits);
/// Why `world` may not take one more body under its fields, or "".
std::string bodyRefusal(const World& world, const FieldLimits& limits);
/// Why a whole world (a loaded scene) is over the limits, or "".
std::string worldRefusal(const World& world, const FieldLimits& limits);

}  // namespace impulse::server
