#pragma once
/// Queries (impulse/query.h) on the wire: filters in, hits out.

#include "impulse.pb.h"
#include "impulse/query.h"

namespace impulse::wire {

/// Any bits are valid; unset fields take QueryFilter's defaults.
QueryFilter queryFilterFromWire(const v1::QueryFilter& filter);
void toWire(const QueryFilter& filter, v1::QueryFilter* out);
void toWire(const CastHit& hit, v1::QueryHit* out);

}  // namespace impulse::wire
