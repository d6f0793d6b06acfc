#pragma once
// Contact events (contact_events.cpp): begin and end of touch, and hits,
// gathered as the narrow phase finds them and published sorted after the
// step.

#include "world_data.h"

namespace impulse {

/// The contact began (touching now) or stopped touching; a contact whose
/// shapes asked for no events reports nothing.
void reportTouchChange(WorldData& world, const Contact& contact);

/// A hit when a point of the touching contact closes faster than the
/// world's threshold and meets within the next `dt`.
void reportHit(WorldData& world, const Contact& contact, Real dt);

}  // namespace impulse
