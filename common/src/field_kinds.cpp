#include "impulse/field_kinds.h"

namespace impulse {

FieldBuild makeField(const FieldDef& def) {
  struct Maker {
    FieldBuild operator()(const GravitationDef& d) const { return makeGravitation(d); }
    FieldBuild operator()(const FluidDef& d) const { return makeFluidRegion(d); }
    FieldBuild operator()(const FanDef& d) const { return makeFan(d); }
  };
  return std::visit(Maker{}, def);
}

std::optional<FieldDef> describeField(const ForceField& field) {
  if (const auto* gravitation = dynamic_cast<const Gravitation*>(&field)) {
    return GravitationDef{gravitation->constant()};
  }
  if (const auto* fluid = dynamic_cast<const FluidRegion*>(&field)) return fluid->def();
  if (const auto* fan = dynamic_cast<const Fan*>(&field)) return fan->def();
  return std::nullopt;
}

}  // namespace impulse
