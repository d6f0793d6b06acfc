// The large-world origin: every float position is relative to it, so a scene
// far from (0, 0) keeps float's micrometres near the origin. Moving it moves
// every stored position by the difference, in double, rounded once.

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "impulse/field_kinds.h"
#include "impulse/world.h"
#include "input_limits.h"
#include "world_data.h"

namespace impulse {

namespace {

Vec2 shifted(const Vec2& position, const Vec2d& offset) {
  return Vec2(Real(double(position.x()) - offset.x()), Real(double(position.y()) - offset.y()));
}

// Every body stays where the step guard keeps bodies: within the bounds
// grown by the escape margin.
std::string checkBodiesStayInRange(const WorldData& world, const Vec2d& offset) {
  const Real margin = world.settings.inputLimits.escapeMargin;
  const AABB range = world.settings.bounds.expanded(margin);
  for (std::size_t slot = 0; slot < world.bodies.size(); ++slot) {
    const Body& body = world.bodies[slot];
    if (!body.alive) continue;
    const Vec2d centre = body.transform.p.cast<double>() - offset;
    if (centre.x() < range.lower.x() || centre.x() > range.upper.x() ||
        centre.y() < range.lower.y() || centre.y() > range.upper.y()) {
      return "origin would leave body " + std::to_string(world.idOf(std::int32_t(slot)).value) +
             " more than the escape margin (" + describeNumber(margin) +
             " m) outside the bounds, where the step removes bodies";
    }
  }
  return {};
}

// The definition of a built-in field at its new place; a gravitation pulls
// between bodies and has no place.
FieldDef shiftedDef(FieldDef def, const Vec2d& offset) {
  std::visit(
      [&](auto& kind) {
        using Kind = std::decay_t<decltype(kind)>;
        if constexpr (std::is_same_v<Kind, FluidDef>) {
          for (Vec2& point : kind.polygon) point = shifted(point, offset);
        } else if constexpr (std::is_same_v<Kind, FanDef>) {
          kind.position = shifted(kind.position, offset);
        }
      },
      def);
  return def;
}

// Every field at its new place, made before anything changes so a field
// that cannot be made there refuses the whole shift. Fields of a kind of
// one's own stay as they are.
std::string shiftedFields(const WorldData& world, const Vec2d& offset,
                          std::vector<FieldSlot>& fields) {
  fields = world.fields;
  for (FieldSlot& slot : fields) {
    const std::optional<FieldDef> def = describeField(*slot.field);
    if (!def) continue;
    FieldBuild build = makeField(shiftedDef(*def, offset));
    if (!build.ok()) {
      return "field " + std::to_string(slot.id.value) + " at the new origin: " + build.error;
    }
    slot.field = std::move(build.field);
  }
  return {};
}

void shiftBodies(WorldData& world, const Vec2d& offset) {
  for (std::size_t slot = 0; slot < world.bodies.size(); ++slot) {
    Body& body = world.bodies[slot];
    if (!body.alive) continue;
    body.transform.p = shifted(body.transform.p, offset);
    body.center0 = shifted(body.center0, offset);
    world.changes.mark(BodyChange::Moved, world.idOf(std::int32_t(slot)));
  }
}

// A side held by the world keeps its anchor as a world point, and every
// joint keeps its creation anchor B as its target (a mouse joint's).
void shiftJoints(WorldData& world, const Vec2d& offset) {
  for (Joint& joint : world.joints) {
    if (!joint.alive) continue;
    if (joint.edges.bodyB == kNullIndex) joint.localAnchorB = shifted(joint.localAnchorB, offset);
    joint.target = shifted(joint.target, offset);
  }
}

void shiftContactPoints(WorldData& world, const Vec2d& offset) {
  for (Contact& contact : world.contacts) {
    for (int i = 0; i < contact.manifold.pointCount; ++i) {
      ManifoldPoint& point = contact.manifold.points[std::size_t(i)];
      point.point = shifted(point.point, offset);
    }
  }
}

void shiftHits(StepEvents& events, const Vec2d& offset) {
  for (ContactHitEvent& hit : events.contactHits) hit.point = shifted(hit.point, offset);
}

}  // namespace

Vec2d World::origin() const { return impl_->origin; }

Vec2 World::toLocal(const Vec2d& point) const {
  return Vec2(Real(point.x() - impl_->origin.x()), Real(point.y() - impl_->origin.y()));
}

Vec2d World::toGlobal(const Vec2& position) const {
  return impl_->origin + position.cast<double>();
}

InputResult World::shiftOrigin(const Vec2d& origin) {
  if (std::string error = checkOrigin(origin); !error.empty()) return {error};
  WorldData& world = *impl_;
  const Vec2d offset = origin - world.origin;
  if (std::string error = checkBodiesStayInRange(world, offset); !error.empty()) return {error};
  std::vector<FieldSlot> fields;
  if (std::string error = shiftedFields(world, offset, fields); !error.empty()) return {error};
  world.fields = std::move(fields);
  shiftBodies(world, offset);
  shiftJoints(world, offset);
  shiftContactPoints(world, offset);
  shiftHits(world.events, offset);
  shiftHits(world.pendingEvents, offset);
  world.broadPhase.shift(offset);
  world.origin = origin;
  world.changes.mark(WorldChange::Origin);
  return {};
}

}  // namespace impulse
