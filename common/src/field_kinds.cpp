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

}  // namespace impulse
