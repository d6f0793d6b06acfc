#include "impulse/wire/query_convert.h"

#include "impulse/wire/convert.h"

namespace impulse::wire {

QueryFilter queryFilterFromWire(const v1::QueryFilter& filter) {
  QueryFilter result;
  if (filter.has_category_bits()) result.categoryBits = filter.category_bits();
  if (filter.has_mask_bits()) result.maskBits = filter.mask_bits();
  return result;
}

void toWire(const QueryFilter& filter, v1::QueryFilter* out) {
  out->set_category_bits(filter.categoryBits);
  out->set_mask_bits(filter.maskBits);
}

void toWire(const CastHit& hit, v1::QueryHit* out) {
  out->set_shape_id(hit.shape.value);
  out->set_body_id(hit.body.value);
  toWire(hit.point, out->mutable_point());
  toWire(hit.normal, out->mutable_normal());
  out->set_fraction(hit.fraction);
}

}  // namespace impulse::wire
