#pragma once
/// The kinds of force field a user can ask for by numbers (the wire's
/// AddField), and the one call that checks them and makes the field.

#include <optional>
#include <variant>

#include "impulse/fan.h"
#include "impulse/fluid_region.h"
#include "impulse/gravitation.h"

namespace impulse {

using FieldDef = std::variant<GravitationDef, FluidDef, FanDef>;

/// The field, or the error naming the refused number and its range.
FieldBuild makeField(const FieldDef& def);
/// The numbers a field made by makeField was made from; nothing for a field
/// of another kind.
std::optional<FieldDef> describeField(const ForceField& field);

}  // namespace impulse
