// A body's shapes: checking a shape definition, attaching a shape to a body
// (slot, body list, broad-phase proxy), detaching it, and the body's mass,
// centre of mass and sizes from the union of its shapes.

#include "body_shapes.h"

#include <algorithm>
#include <array>
#include <string>

#include "input_limits.h"

namespace impulse {

namespace {

std::int32_t allocateShape(WorldData& world) {
  std::int32_t slot = world.freeShapes.acquire(world.shapes.size());
  if (slot == static_cast<std::int32_t>(world.shapes.size())) world.shapes.emplace_back();
  return slot;
}

BroadPhase::ProxyKind proxyKindOf(const Body& body) {
  return body.isStatic ? BroadPhase::ProxyKind::Static : BroadPhase::ProxyKind::Movable;
}

// Moves every shape of the body by `offset` in its frame.
void translateShapes(WorldData& world, std::int32_t body, const Vec2& offset) {
  world.forEachShape(body, [&](std::int32_t s) {
    ShapeSlot& slot = world.shapes[s];
    world.shapeGeometries.store(slot, translated(shapeOf(slot.ref()), offset));
  });
}

// The union's mass properties in the body's frame, each shape weighed with
// its own density.
MassProperties unionMass(WorldData& world, std::int32_t body) {
  // Only shapes with mass count: a body of segments alone (a static chain)
  // keeps its origin. A single part comes back unchanged, so a circle or
  // polygon centred on the origin keeps its origin bit for bit.
  std::vector<MassProperties>& parts = world.massParts;
  parts.clear();
  world.forEachShape(body, [&](std::int32_t s) {
    const ShapeSlot& slot = world.shapes[s];
    if (isSolid(slot.type()))
      parts.push_back(computeMassProperties(slot.ref(), slot.coefficients.density));
  });
  if (parts.empty()) return {};
  return combineMassProperties(parts);
}

bool hasArea(const WorldData& world, std::int32_t body) {
  bool area = false;
  world.forEachShape(body, [&](std::int32_t s) { area = area || isSolid(world.shapes[s].type()); });
  return area;
}

}  // namespace

Real rollingRadiusOf(const Shape& shape) {
  switch (shape.type()) {
    case ShapeType::Circle: return shape.circle().radius;
    case ShapeType::Capsule: return shape.capsule().radius;
    case ShapeType::Segment:
    case ShapeType::Polygon:
    case ShapeType::ChainSegment: return 0;
  }
  return 0;
}

std::string checkShapeDef(const WorldData& world, const ShapeDef& def) {
  if (ShapeError error = validateShape(def.shape, world.settings.shapeLimits); error != ShapeError::None) {
    return std::string(describe(error));
  }
  if (static_cast<int>(def.material) >= kMaterialCount) return "unknown material";
  return validateMaterialOverride(def.materialOverride);
}

std::int32_t attachShape(WorldData& world, std::int32_t body, const ShapeDef& def) {
  const std::int32_t s = allocateShape(world);
  ShapeSlot& slot = world.shapes[s];
  const std::uint32_t generation = slot.generation;
  slot = ShapeSlot{};
  slot.generation = generation;
  slot.alive = true;
  world.shapeGeometries.store(slot, def.shape);
  slot.material = def.material;
  slot.coefficients = resolveCoefficients(def.material, def.materialOverride);
  slot.rollingRadius = rollingRadiusOf(def.shape);
  slot.interaction = def.interaction;
  slot.body = body;
  // Appended, so a body's shapes keep the order they were given in.
  std::int32_t* link = &world.bodies[body].shapeHead;
  while (*link != kNullIndex) link = &world.shapes[*link].nextInBody;
  *link = s;
  ++world.bodies[body].shapeCount;
  ++world.liveShapes;
  if (def.interaction.isSensor) addSensor(world, s);
  return s;
}

void changeShapeInteraction(WorldData& world, std::int32_t s, const ShapeInteraction& interaction) {
  ShapeSlot& slot = world.shapes[s];
  const bool wasSensor = slot.interaction.isSensor;
  slot.interaction = interaction;
  if (interaction.isSensor && !wasSensor) addSensor(world, s);
  if (!interaction.isSensor && wasSensor) removeSensor(world, s);
  refilterShapeContacts(world, s);
  world.broadPhase.touchProxy(slot.proxyKey);
  wakeIsland(world, slot.body);
}

void createShapeProxy(WorldData& world, std::int32_t s) {
  ShapeSlot& slot = world.shapes[s];
  slot.proxyKey = world.broadPhase.createProxy(shapeAABB(world, s), s, proxyKindOf(world.bodies[slot.body]),
                                               shapeRoom(world, s));
}

void detachShape(WorldData& world, std::int32_t s) {
  ShapeSlot& slot = world.shapes[s];
  Body& body = world.bodies[slot.body];
  std::int32_t* link = &body.shapeHead;
  while (*link != s) link = &world.shapes[*link].nextInBody;
  *link = slot.nextInBody;
  --body.shapeCount;
  if (slot.proxyKey != kNullIndex) world.broadPhase.destroyProxy(slot.proxyKey);
  if (slot.interaction.isSensor) removeSensor(world, s);
  world.shapeGeometries.release(slot);
  slot.alive = false;
  ++slot.generation;
  world.freeShapes.release(s);
  --world.liveShapes;
}

std::string checkShapesSuitType(const WorldData& world, std::int32_t body, BodyType type) {
  if (type == BodyType::Dynamic && !hasArea(world, body)) {
    return "a dynamic body needs a shape with area (circle, capsule or polygon): segments and chains have none";
  }
  // A moving body's shapes stay together; static scenery (terrain, a long
  // floor) may reach as far as its shapes do.
  const Real extent = world.bodies[body].extent;
  if (type == BodyType::Static || extent <= kMaxBodyExtent) return {};
  return "the body's shapes reach " + describeNumber(extent) + " m from its centre of mass: they must stay within " +
         describeNumber(kMaxBodyExtent) + " m of it";
}

// The centre of mass moved with the shapes, so the velocity is the same
// material motion's at the new centre, and the contacts' cached frames are
// stale.
std::string reshapeBody(WorldData& world, std::int32_t slot) {
  Body& body = world.bodies[slot];
  const Vec2 shift = updateBodyMass(world, slot);
  const Vec2 arm = body.transform.q.apply(shift);
  body.linearVelocity += body.angularVelocity * Vec2(-arm.y(), arm.x());
  body.center0 = body.transform.p;
  body.rotation0 = body.transform.q;
  forgetManifoldFrames(world, slot);
  moveBodyProxies(world, slot);
  wakeIsland(world, slot);
  return checkShapesSuitType(world, slot, body.type());
}

void wakeBodiesUnder(WorldData& world, const AABB& box) {
  world.broadPhase.query(box, [&](std::int32_t shape) {
    wakeIsland(world, world.shapes[shape].body);
    return true;
  });
}

Vec2 updateBodyMass(WorldData& world, std::int32_t b) {
  Body& body = world.bodies[b];
  const Vec2 shift = unionMass(world, b).center;
  if (shift != Vec2::Zero()) {
    translateShapes(world, b, -shift);
    body.transform.p += body.transform.q.apply(shift);
  }
  // From the shapes as they are kept, as a saved world's bodies get it.
  setMassFromShapes(world, b);
  return shift;
}

Vec2 setMassFromShapes(WorldData& world, std::int32_t b) {
  Body& body = world.bodies[b];
  const MassProperties total = unionMass(world, b);
  body.mass = total;
  body.mass.center = Vec2::Zero();
  body.invMass = 0;
  body.invInertia = 0;
  if (body.isStatic) {
    body.mass.mass = 0;
    body.mass.inertia = 0;
  } else if (body.isDynamic()) {
    body.invMass = body.mass.mass > 0 ? 1 / body.mass.mass : 0;
    body.invInertia = body.mass.inertia > 0 ? 1 / body.mass.inertia : 0;
  }
  body.extent = 0;
  body.innerRadius = 0;
  bool anySolid = false;
  world.forEachShape(b, [&](std::int32_t s) {
    const ShapeRef shape = world.shapes[s].ref();
    body.extent = std::max(body.extent, computeExtent(shape));
    if (!isSolid(shape.type)) return;
    const Real inner = computeInnerRadius(shape);
    body.innerRadius = anySolid ? std::min(body.innerRadius, inner) : inner;
    anySolid = true;
  });
  return total.center;
}

}  // namespace impulse
