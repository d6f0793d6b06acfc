// Saved world states: a world imported from another's exported state steps
// on bit-identically to it, and a state that is wrong anywhere is refused
// with a message, leaving the world exactly as it was.

#include "impulse/world_state.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "impulse/scenes/stress.h"
#include "impulse/world.h"
#include "joint_test_support.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

constexpr int kStepsAfterLoad = 300;

// FNV-1a over the exact bits of values, so any difference in any bit of
// the compared state shows.
class BitHash {
 public:
  template <class T>
  void add(const T& value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (unsigned char byte : bytes) hash_ = (hash_ ^ byte) * 1099511628211ull;
  }
  void add(const Vec2& v) {
    add(v.x());
    add(v.y());
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

// Everything in a state that later steps read: every body's motion, sleep
// timer and forces, every contact's manifold points, feature keys and
// warm-start impulses, every joint's impulses, the list orders, the trees.
std::uint64_t stateFingerprint(const WorldState& s) {
  BitHash h;
  for (const BodySlotState& b : s.bodies) {
    h.add(b.alive);
    h.add(b.generation);
    h.add(b.transform.p);
    h.add(b.transform.q.c);
    h.add(b.transform.q.s);
    h.add(b.linearVelocity);
    h.add(b.angularVelocity);
    h.add(b.sleepTime);
    h.add(b.awake);
    for (std::int32_t shape : b.shapes) h.add(shape);
    for (std::int32_t key : b.contactEdges) h.add(key);
    for (std::int32_t key : b.jointEdges) h.add(key);
  }
  for (const ShapeSlotState& shape : s.shapes) {
    h.add(shape.alive);
    h.add(shape.generation);
    h.add(shape.body);
    h.add(shape.proxyKey);
  }
  for (const ContactSlotState& c : s.contacts) {
    h.add(c.alive);
    h.add(c.shapeA);
    h.add(c.shapeB);
    h.add(c.bodyA);
    h.add(c.bodyB);
    h.add(c.touching);
    h.add(c.manifold.pointCount);
    for (const ManifoldPoint& p : c.manifold.points) {
      h.add(p.point);
      h.add(p.separation);
      h.add(p.id);
      h.add(p.normalImpulse);
      h.add(p.tangentImpulse);
    }
  }
  for (const JointSlotState& j : s.joints) {
    h.add(j.alive);
    h.add(j.impulses.point);
    h.add(j.impulses.axial);
    h.add(j.impulses.motor);
    h.add(j.reactionForce);
  }
  for (const DynamicTree::State& tree : s.broadPhase.trees) {
    for (const DynamicTree::Node& node : tree.nodes) {
      h.add(node.box.lower);
      h.add(node.box.upper);
      h.add(node.parent);
      h.add(node.userValue);
    }
  }
  for (std::int32_t slot : s.freeBodies) h.add(slot);
  for (std::int32_t slot : s.freeContacts) h.add(slot);
  for (std::int32_t slot : s.awakeBodies) h.add(slot);
  h.add(s.stepCount);
  h.add(s.time);
  return h.value();
}

// Saves `original` after its first steps, loads the state into a fresh
// world with the same limits and steps both kStepsAfterLoad more times: the body hash must agree
// after every step and the whole state at the end. A body created in both
// after the load must get the same id (slot reuse) and the same motion.
void expectBitIdenticalAfterLoad(World& original) {
  const WorldState saved = original.exportState();
  World loaded(original.settings());
  ASSERT_TRUE(loaded.importState(saved).ok());
  EXPECT_EQ(stateFingerprint(loaded.exportState()), stateFingerprint(saved));
  ASSERT_EQ(loaded.stateHash(), original.stateHash());
  for (int i = 1; i <= kStepsAfterLoad; ++i) {
    original.step(kDt);
    loaded.step(kDt);
    ASSERT_EQ(loaded.stateHash(), original.stateHash())
        << "diverged at step " << i << " after load";
    if (i == kStepsAfterLoad / 2) {
      const BodyId a = addCircle(original, {.center = Vec2(0, 12), .radius = Real(0.4)});
      const BodyId b = addCircle(loaded, {.center = Vec2(0, 12), .radius = Real(0.4)});
      ASSERT_EQ(a, b);
    }
  }
  EXPECT_EQ(stateFingerprint(loaded.exportState()), stateFingerprint(original.exportState()));
  EXPECT_EQ(loaded.stepCount(), original.stepCount());
  EXPECT_EQ(std::bit_cast<std::uint64_t>(loaded.simulatedTime()),
            std::bit_cast<std::uint64_t>(original.simulatedTime()));
}

TEST(WorldState, PyramidStepsOnBitIdentically_AfterLoadMidSettle) {
  World world;
  buildPyramid(world, 12);
  simulate(world, 0.5);
  ASSERT_GT(world.contactCount(), 100);
  expectBitIdenticalAfterLoad(world);
}

TEST(WorldState, RainOfCirclesStepsOnBitIdentically_AfterLoadMidFall) {
  World world;
  buildRain(world, 400);
  simulate(world, 1.5);
  ASSERT_GT(world.awakeBodyCount(), 300);
  ASSERT_GT(world.contactCount(), 100);
  expectBitIdenticalAfterLoad(world);
}

TEST(WorldState, JointsStepOnBitIdentically_AfterLoad) {
  World world;
  addGround(world);
  // A chain of boxes on revolute pins hanging from the world, a spring, a
  // rope, a motorised wheel on a prismatic cart, a weld and a mouse pull.
  BodyId previous{};
  for (int i = 0; i < 8; ++i) {
    const BodyId link = addBox(
        world,
        {.center = Vec2(Real(i) + Real(0.5), 10), .halfWidth = Real(0.5), .halfHeight = Real(0.1)});
    addJoint(world, link, previous, Vec2(Real(i), 10), Vec2(Real(i), 10), RevoluteJointSettings{});
    previous = link;
  }
  const BodyId weight = addCircle(world, {.center = Vec2(-4, 6), .radius = Real(0.5)});
  addJoint(world, weight, {}, Vec2(-4, 6), Vec2(-4, 9),
           DistanceJointSettings{.length = 2, .stiffness = 200, .damping = 2});
  const BodyId swing =
      addCircle(world, {.center = Vec2(-8, 6), .radius = Real(0.3), .velocity = Vec2(4, 0)});
  addJoint(world, swing, {}, Vec2(-8, 6), Vec2(-8, 9), RopeJointSettings{});
  const BodyId cart =
      addBox(world, {.center = Vec2(6, 1), .halfWidth = 1, .halfHeight = Real(0.3)});
  const BodyId wheel = addCircle(world, {.center = Vec2(6, Real(0.4)), .radius = Real(0.35)});
  addJoint(world, wheel, cart, Vec2(6, Real(0.4)), Vec2(6, Real(0.4)),
           WheelJointSettings{.stiffness = 300,
                              .damping = 5,
                              .enableMotor = true,
                              .motorSpeed = -3,
                              .maxMotorTorque = 50});
  addJoint(world, cart, {}, Vec2(6, 1), Vec2(6, 1), PrismaticJointSettings{.axis = Vec2(1, 0)});
  const BodyId glued = addBox(
      world, {.center = Vec2(7, Real(1.6)), .halfWidth = Real(0.3), .halfHeight = Real(0.3)});
  addJoint(world, glued, cart, Vec2(7, Real(1.3)), Vec2(7, Real(1.3)), WeldJointSettings{});
  const BodyId pulled = addBox(world, {.center = Vec2(-12, 1)});
  addJoint(world, pulled, {}, Vec2(-12, 1), Vec2(-10, 4),
           MouseJointSettings{.maxForce = 500, .stiffness = 100, .damping = 10});
  simulate(world, 1);
  ASSERT_GE(world.jointCount(), 13);
  expectBitIdenticalAfterLoad(world);
}

// Fields are saved by the numbers they were made from and made again under
// their ids: a liquid, a fan and gravitation act on a falling rain the same
// after the load, and the next field gets the same id in both worlds.
TEST(WorldState, FieldsStepOnBitIdentically_AfterLoad_AndKeepTheirIds) {
  World world;
  buildRain(world, 200);
  const Real width = 12;
  ASSERT_TRUE(world.addField(makeField(FluidDef{.polygon = {Vec2(-width, 0), Vec2(width, 0), Vec2(width, 3),
                                                             Vec2(-width, 3)}})
                                 .field)
                  .value != 0);
  const FieldId fan = world.addField(makeField(FanDef{.position = Vec2(0, 1), .direction = Vec2(0, 1)}).field);
  ASSERT_TRUE(world.addField(makeField(GravitationDef{.constant = 0.5}).field).value != 0);
  ASSERT_TRUE(world.removeField(fan));  // a gap in the ids
  simulate(world, 1);
  const WorldState saved = world.exportState();
  ASSERT_EQ(saved.fields.size(), 2u);
  expectBitIdenticalAfterLoad(world);

  World loaded(world.settings());
  ASSERT_TRUE(loaded.importState(saved).ok());
  const std::vector<FieldId> savedIds{saved.fields[0].id, saved.fields[1].id};
  EXPECT_EQ(loaded.fieldIds(), savedIds);
  EXPECT_EQ(loaded.addField(makeField(GravitationDef{}).field).value, saved.nextFieldId);
}

TEST(WorldState, SleepingPileStepsOnBitIdentically_WhenWokenAfterLoad) {
  World world;
  const Pyramid pyramid = buildPyramid(world, 6);
  ASSERT_GT(simulateUntilAsleep(world, 20), 0);
  // A body mid-way to sleep beside the sleeping pile: its sleep timer must
  // carry over for both to fall asleep on the same step.
  addCircle(world, {.center = Vec2(12, Real(0.5)), .radius = Real(0.5)});
  simulate(world, 0.2);
  const WorldState saved = world.exportState();
  World loaded;
  ASSERT_TRUE(loaded.importState(saved).ok());
  EXPECT_EQ(loaded.awakeBodyCount(), 1);
  for (World* w : {&world, &loaded}) {
    ASSERT_TRUE(w->applyImpulse(pyramid.top, Vec2(3, 0)).ok());
  }
  int mostAwake = 0;
  for (int i = 1; i <= kStepsAfterLoad; ++i) {
    world.step(kDt);
    loaded.step(kDt);
    mostAwake = std::max(mostAwake, world.awakeBodyCount());
    ASSERT_EQ(loaded.stateHash(), world.stateHash()) << "diverged at step " << i << " after load";
    ASSERT_EQ(loaded.awakeBodyCount(), world.awakeBodyCount()) << "step " << i;
  }
  EXPECT_GT(mostAwake, 10);  // the push woke the pile's island
  EXPECT_NE(stateOf(world, pyramid.top).position, pyramid.topStart);
  EXPECT_EQ(stateFingerprint(loaded.exportState()), stateFingerprint(world.exportState()));
}

TEST(WorldState, RemovedSlotsAreReusedInTheSavedOrder) {
  World world;
  std::vector<BodyId> ids;
  for (int i = 0; i < 6; ++i) ids.push_back(addCircle(world, {.center = Vec2(Real(2 * i), 5)}));
  world.destroyBody(ids[4]);
  world.destroyBody(ids[1]);
  World loaded;
  ASSERT_TRUE(loaded.importState(world.exportState()).ok());
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(addCircle(loaded, {.center = Vec2(0, 9)}), addCircle(world, {.center = Vec2(0, 9)}));
  }
  EXPECT_FALSE(loaded.isValid(ids[1]));  // the old id of a reused slot stays stale
}

// A pile with contacts and a joint, to corrupt in the refusal tests.
WorldState pileState(World& world) {
  buildPyramid(world, 4);
  const BodyId ball = addCircle(world, {.center = Vec2(8, 3)});
  addJoint(world, ball, {}, Vec2(8, 3), Vec2(8, 6), DistanceJointSettings{});
  simulate(world, 0.3);
  return world.exportState();
}

std::int32_t firstDynamicSlot(const WorldState& state) {
  for (std::size_t slot = 0; slot < state.bodies.size(); ++slot) {
    if (state.bodies[slot].alive && !state.bodies[slot].properties.isStatic) return std::int32_t(slot);
  }
  return -1;
}

// The refusal names the problem; the target world is exactly as it was.
void expectRefused(const WorldState& bad, const std::string& expected) {
  World target;
  buildTower(target, 3);
  simulate(target, 0.2);
  const std::uint64_t before = stateFingerprint(target.exportState());
  const InputResult result = target.importState(bad);
  EXPECT_FALSE(result.ok());
  EXPECT_NE(result.error.find(expected), std::string::npos) << result.error;
  EXPECT_EQ(stateFingerprint(target.exportState()), before);
  EXPECT_EQ(target.bodyCount(), 4);
}

TEST(WorldState, RefusesNonFiniteBody_WorldUnchanged) {
  World source;
  WorldState state = pileState(source);
  state.bodies[std::size_t(firstDynamicSlot(state))].linearVelocity.x() =
      std::numeric_limits<Real>::quiet_NaN();
  expectRefused(state, "velocity is not a finite number");
}

TEST(WorldState, RefusesBodyOutOfRange_WorldUnchanged) {
  World source;
  WorldState state = pileState(source);
  state.bodies[std::size_t(firstDynamicSlot(state))].angularVelocity = 5000;
  expectRefused(state, "angular velocity");
  state = source.exportState();
  state.bodies[std::size_t(firstDynamicSlot(state))].transform.p = Vec2(1e6f, 0);
  expectRefused(state, "position");
}

TEST(WorldState, RefusesBadPolygon_WorldUnchanged) {
  World source;
  WorldState state = pileState(source);
  const std::int32_t shape = state.bodies[std::size_t(firstDynamicSlot(state))].shapes.front();
  Polygon& polygon = std::get<Polygon>(state.shapes[std::size_t(shape)].shape.geometry);
  ASSERT_EQ(polygon.count, 4);
  polygon.vertices[2] = Vec2(Real(0.1), Real(0.1));  // a dent: not convex
  expectRefused(state, "polygon");
}

TEST(WorldState, RefusesJointOnMissingBody_WorldUnchanged) {
  World source;
  WorldState state = pileState(source);
  ASSERT_EQ(state.joints.size(), 1u);
  state.joints[0].bodyA = std::int32_t(state.bodies.size());  // no such slot
  expectRefused(state, "bodyA must be a live body");
}

TEST(WorldState, RefusesBrokenLinks_WorldUnchanged) {
  World source;
  WorldState state = pileState(source);
  state.freeBodies.push_back(0);  // a live slot on the free list
  expectRefused(state, "free list");
  state = source.exportState();
  state.broadPhase.trees[1].nodes[std::size_t(state.broadPhase.trees[1].root)].parent = 0;
  expectRefused(state, "broad phase");
  state = source.exportState();
  state.bodies[std::size_t(firstDynamicSlot(state))].contactEdges.push_back(1 << 20);
  expectRefused(state, "contact edge");
  state = source.exportState();
  state.awakeBodies.clear();
  expectRefused(state, "awake");
}

TEST(WorldState, RefusesFieldOutOfRange_WorldUnchanged) {
  World source;
  buildTower(source, 2);
  source.addField(makeField(GravitationDef{}).field);
  WorldState bad = source.exportState();
  ASSERT_EQ(bad.fields.size(), 1u);
  bad.fields[0].def = GravitationDef{.constant = 1e9};
  expectRefused(bad, "field 0: ");
  WorldState reused = source.exportState();
  reused.fields.push_back(reused.fields[0]);
  expectRefused(reused, "id used twice");
}

}  // namespace
}  // namespace impulse
