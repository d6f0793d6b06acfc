// Editing live bodies: the type changed at run time, bodies created asleep,
// teleports and material changes, with what each must keep (contacts,
// sleeping, save/load, determinism) and what each refuses.

#include <gtest/gtest.h>

#include <string>

#include "impulse/body.h"
#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using test::addBox;
using test::addCircle;
using test::addGround;
using test::kDt;
using test::simulate;
using test::stateOf;

// Bodies that land here settle instead of bouncing (metal on metal
// restitution is 0.1).
constexpr Material kDull = Material::Metal;

BodyId addDullGround(World& world) {
  return addBox(world, {.center = Vec2(0, -1), .halfWidth = 20, .halfHeight = 1, .material = kDull, .isStatic = true});
}

bool mentions(const std::string& text, const std::string& word) { return text.find(word) != std::string::npos; }

BodyType typeOf(const World& world, BodyId id) {
  return world.bodyDescription(id).value().properties.type();
}

// Three unit boxes stacked on the box at `base`.
std::vector<BodyId> stackOn(World& world, const Vec2& base) {
  std::vector<BodyId> stack;
  for (int i = 1; i <= 3; ++i) stack.push_back(addBox(world, {.center = base + Vec2(0, Real(i))}));
  return stack;
}

TEST(BodyType, StaticBoxTurnedDynamicFalls) {
  World world;
  addDullGround(world);
  const BodyId box = addBox(world, {.center = Vec2(0, 5), .material = kDull, .isStatic = true});
  simulate(world, 0.5);
  EXPECT_EQ(stateOf(world, box).position.y(), 5) << "a static box hangs where it was made";
  EXPECT_EQ(world.bodyDescription(box)->mass.mass, 0);

  ASSERT_TRUE(world.setBodyType(box, BodyType::Dynamic).ok());
  EXPECT_TRUE(stateOf(world, box).awake);
  EXPECT_NEAR(world.bodyDescription(box)->mass.mass, materialProperties(kDull).density, 1e-3)
      << "a unit box's mass is its density";
  simulate(world, 3);
  EXPECT_NEAR(stateOf(world, box).position.y(), 0.5, 0.02) << "it fell onto the ground and rests there";
}

TEST(BodyType, DynamicBoxTurnedStaticHoldsAStack) {
  World world;
  const BodyId base = addBox(world, {.center = Vec2(0, 3)});
  const std::vector<BodyId> stack = stackOn(world, Vec2(0, 3));
  ASSERT_TRUE(world.setBodyType(base, BodyType::Static).ok());
  EXPECT_FALSE(stateOf(world, base).awake) << "a static body never counts as awake";
  simulate(world, 3);
  EXPECT_EQ(stateOf(world, base).position.y(), 3) << "the static base does not move";
  EXPECT_EQ(world.bodyDescription(base)->mass.mass, 0);
  EXPECT_NEAR(stateOf(world, stack.back()).position.y(), 6, 0.03) << "the stack stands on the base";
  EXPECT_EQ(world.awakeBodyCount(), 0) << "the stack settles and sleeps on its static base";
}

TEST(BodyType, TurnedStaticWakesWhatRestsOnItAndDropsItsSpeed) {
  World world;
  addGround(world);
  const BodyId box = addBox(world, {.center = Vec2(0, 0.5)});
  const BodyId top = addBox(world, {.center = Vec2(0, 1.5)});
  ASSERT_GE(test::simulateUntilAsleep(world, 5), 0);
  ASSERT_TRUE(world.setBodyType(box, BodyType::Static).ok());
  EXPECT_TRUE(stateOf(world, top).awake) << "the box resting on it lost its contact and must look again";
  EXPECT_EQ(stateOf(world, box).linearVelocity, Vec2::Zero());
  simulate(world, 1);
  EXPECT_NEAR(stateOf(world, top).position.y(), 1.5, 0.02);
}

TEST(BodyType, KinematicKeepsItsVelocityAndPushesWithoutBeingPushed) {
  World world;
  const BodyId pusher = addBox(world, {.center = Vec2(0, 0), .ignoreGravity = true, .velocity = Vec2(2, 0)});
  const BodyId crate = addBox(world, {.center = Vec2(3, 0), .ignoreGravity = true});
  ASSERT_TRUE(world.setBodyType(pusher, BodyType::Kinematic).ok());
  world.setGravity(Vec2(0, -9.81));
  simulate(world, 2);
  const BodyState state = stateOf(world, pusher);
  EXPECT_NEAR(state.position.x(), 4, 1e-3) << "it moved at its own velocity, through the crate's push";
  EXPECT_NEAR(state.position.y(), 0, 1e-6) << "gravity does not act on a kinematic body";
  EXPECT_EQ(state.linearVelocity, Vec2(2, 0));
  EXPECT_GT(stateOf(world, crate).position.x(), 4.9) << "the crate is pushed ahead of it";
  EXPECT_EQ(world.bodyDescription(pusher)->properties.isKinematic, true);
}

TEST(BodyType, KinematicTurnedDynamicFallsAgain) {
  World world;
  addDullGround(world);
  BodyOptions options;
  options.properties.isKinematic = true;
  options.material = kDull;
  const CreateResult platform = world.createCircle(Vec2(0, 4), Real(0.5), options);
  ASSERT_TRUE(platform.ok());
  simulate(world, 0.5);
  EXPECT_EQ(stateOf(world, platform.id).position.y(), 4);
  ASSERT_TRUE(world.setBodyType(platform.id, BodyType::Dynamic).ok());
  simulate(world, 2);
  EXPECT_NEAR(stateOf(world, platform.id).position.y(), 0.5, 0.02);
}

TEST(BodyType, RefusalsNameTheReasonAndChangeNothing) {
  World world;
  const BodyId ground = addGround(world);
  const CreateResult wall = world.createSegment(Vec2(-1, 2), Vec2(1, 2));
  ASSERT_TRUE(wall.ok());
  const InputResult noArea = world.setBodyType(wall.id, BodyType::Dynamic);
  EXPECT_FALSE(noArea.ok());
  EXPECT_TRUE(mentions(noArea.error, "area")) << noArea.error;
  EXPECT_EQ(typeOf(world, wall.id), BodyType::Static);
  EXPECT_TRUE(world.setBodyType(wall.id, BodyType::Kinematic).ok()) << "a kinematic segment needs no mass";

  const BodyId hanging = addBox(world, {.center = Vec2(0, 3)});
  JointDef pin;
  pin.bodyA = hanging;
  pin.bodyB = ground;
  pin.anchorA = pin.anchorB = Vec2(0, 3.5);
  pin.settings = RevoluteJointSettings{};
  ASSERT_TRUE(world.createJoint(pin).ok());
  const InputResult jointed = world.setBodyType(hanging, BodyType::Static);
  EXPECT_FALSE(jointed.ok());
  EXPECT_TRUE(mentions(jointed.error, "joint")) << jointed.error;
  EXPECT_EQ(typeOf(world, hanging), BodyType::Dynamic);
  EXPECT_TRUE(stateOf(world, hanging).awake);

  EXPECT_TRUE(mentions(world.setBodyType(BodyId{9999}, BodyType::Static).error, "unknown body"));
  EXPECT_TRUE(mentions(world.setBodyType(hanging, static_cast<BodyType>(7)).error, "unknown body type"));
  EXPECT_TRUE(world.setBodyType(hanging, BodyType::Dynamic).ok()) << "the type it has already";
}

// A scene with every kind of change, stepped on from a saved copy and from
// itself: the copy must stay bit-identical.
void buildChangedScene(World& world) {
  addGround(world);
  const BodyId base = addBox(world, {.center = Vec2(0, 3)});
  stackOn(world, Vec2(0, 3));
  const BodyId hung = addBox(world, {.center = Vec2(3, 4), .isStatic = true});
  const BodyId slider = addCircle(world, {.center = Vec2(-4, 1), .velocity = Vec2(1, 0)});
  simulate(world, 0.3);
  EXPECT_TRUE(world.setBodyType(base, BodyType::Static).ok());
  EXPECT_TRUE(world.setBodyType(hung, BodyType::Dynamic).ok());
  EXPECT_TRUE(world.setBodyType(slider, BodyType::Kinematic).ok());
  simulate(world, 0.3);
}

TEST(BodyType, SaveLoadAndDeterminismAfterAChange) {
  World first;
  World second;
  buildChangedScene(first);
  buildChangedScene(second);
  EXPECT_EQ(first.stateHash(), second.stateHash()) << "the same changes give the same bits";

  World loaded;
  const InputResult imported = loaded.importState(first.exportState());
  ASSERT_TRUE(imported.ok()) << imported.error;
  for (int i = 0; i < 120; ++i) {
    first.step(kDt);
    loaded.step(kDt);
  }
  EXPECT_EQ(first.stateHash(), loaded.stateHash()) << "the loaded world steps on bit for bit";
}

TEST(BodyAsleep, KeepsStillUntilTouched) {
  World world;
  BodyOptions asleep;
  asleep.isAwake = false;
  const CreateResult box = world.createCircle(Vec2(0, 3), Real(0.5), asleep);
  ASSERT_TRUE(box.ok());
  EXPECT_FALSE(stateOf(world, box.id).awake);
  simulate(world, 1);
  EXPECT_EQ(stateOf(world, box.id).position.y(), 3) << "asleep in mid-air, it does not fall";
  EXPECT_EQ(world.awakeBodyCount(), 0);

  const BodyId ball = addCircle(world, {.center = Vec2(0, 5)});
  simulate(world, 1.5);
  EXPECT_TRUE(stateOf(world, box.id).awake) << "the ball landing on it woke it";
  EXPECT_LT(stateOf(world, box.id).position.y(), 2.5) << "awake, it falls";
  EXPECT_LT(stateOf(world, ball).position.y(), 4);
}

TEST(BodyAsleep, WokenByAPushAndKeptAsleepBySaveLoad) {
  World world;
  BodyDef def;
  def.shape = Shape::makeCircle(Real(0.5));
  def.position = Vec2(1, 2);
  def.isAwake = false;
  const CreateResult sleeper = world.createBody(def);
  ASSERT_TRUE(sleeper.ok());

  World loaded;
  ASSERT_TRUE(loaded.importState(world.exportState()).ok());
  simulate(loaded, 0.5);
  EXPECT_FALSE(stateOf(loaded, sleeper.id).awake) << "saved asleep, loaded asleep";
  EXPECT_EQ(stateOf(loaded, sleeper.id).position.y(), 2);

  ASSERT_TRUE(loaded.applyImpulse(sleeper.id, Vec2(0, 0.1)).ok());
  EXPECT_TRUE(stateOf(loaded, sleeper.id).awake);
  simulate(loaded, 0.5);
  EXPECT_LT(stateOf(loaded, sleeper.id).position.y(), 2);
}

TEST(SetTransform, TeleportsAndWakes) {
  World world;
  addDullGround(world);
  const BodyId box = addBox(world, {.center = Vec2(0, 0.5), .material = kDull});
  ASSERT_GE(test::simulateUntilAsleep(world, 5), 0);
  // A quarter turn: the box lands flat again.
  const Real quarterTurn = Real(test::kPi / 2);
  ASSERT_TRUE(world.setTransform(box, Vec2(2, 4), quarterTurn).ok());
  BodyState state = stateOf(world, box);
  EXPECT_EQ(state.position, Vec2(2, 4));
  EXPECT_NEAR(state.angle, quarterTurn, 1e-6);
  EXPECT_TRUE(state.awake);
  simulate(world, 3);
  state = stateOf(world, box);
  EXPECT_NEAR(state.position.x(), 2, 0.05) << "it fell straight down from where it was put";
  EXPECT_NEAR(state.position.y(), 0.5, 0.02) << "and lies on the ground";
}

TEST(SetTransform, MovingTheGroundAwayDropsWhatSleptOnIt) {
  World world;
  const BodyId ground = addGround(world, 0, 2);
  const BodyId box = addBox(world, {.center = Vec2(0, 0.5)});
  ASSERT_GE(test::simulateUntilAsleep(world, 5), 0);
  ASSERT_TRUE(world.setTransform(ground, Vec2(10, -1), 0).ok());
  EXPECT_TRUE(stateOf(world, box).awake);
  simulate(world, 0.5);
  EXPECT_LT(stateOf(world, box).position.y(), -0.5) << "nothing holds it now";
}

TEST(SetTransform, RefusesBadPositionsAndLeavesTheBody) {
  World world;
  const BodyId box = addBox(world, {.center = Vec2(0, 1), .ignoreGravity = true});
  const InputResult outside = world.setTransform(box, Vec2(1000, 0), 0);
  EXPECT_FALSE(outside.ok());
  EXPECT_TRUE(mentions(outside.error, "bounds")) << outside.error;
  EXPECT_FALSE(world.setTransform(box, Vec2(0, 0), std::nan("")).ok());
  EXPECT_TRUE(mentions(world.setTransform(BodyId{4242}, Vec2(0, 0), 0).error, "unknown body"));
  EXPECT_EQ(stateOf(world, box).position, Vec2(0, 1));
}

TEST(SetMaterial, EveryShapeTakesItAndTheMassFollows) {
  World world;
  BodyDef def;
  def.shape = Shape::makePolygon(makeBox(Real(0.5), Real(0.5)));
  def.extraShapes.push_back({translated(Shape::makeCircle(Real(0.5)), Vec2(2, 0)), Material::Foam, {}, {}});
  def.materialOverride.density = 50;
  def.position = Vec2(0, 2);
  const CreateResult body = world.createBody(def);
  ASSERT_TRUE(body.ok());

  ASSERT_TRUE(world.setMaterial(body.id, Material::Metal).ok());
  const BodyDescription description = world.bodyDescription(body.id).value();
  const MaterialProperties metal = materialProperties(Material::Metal);
  for (const ShapeDescription& shape : description.shapes) {
    EXPECT_EQ(shape.material, Material::Metal);
    EXPECT_EQ(shape.coefficients.density, metal.density) << "the override gave way to the material";
    EXPECT_EQ(shape.coefficients.dynamicFriction, metal.dynamicFriction);
  }
  const double area = 1 + 0.25 * test::kPi;
  EXPECT_NEAR(description.mass.mass, metal.density * area, 1e-3 * metal.density * area);
  // Of equal density, the centre of mass lies between the two shapes' centres by area.
  const BodyState state = stateOf(world, body.id);
  EXPECT_NEAR(state.position.x(), 2 * 0.25 * test::kPi / area, 1e-4);

  EXPECT_FALSE(world.setMaterial(body.id, static_cast<Material>(42)).ok());
  EXPECT_FALSE(world.setMaterial(BodyId{777}, Material::Ice).ok());
}

TEST(SetMaterial, NewContactsMixTheNewFriction) {
  // A box sliding on a level floor stops sooner on rubber than on ice.
  auto slide = [](Material floor) {
    World world;
    const BodyId ground = addGround(world);
    const BodyId box = addBox(world, {.center = Vec2(0, 0.5), .velocity = Vec2(3, 0)});
    EXPECT_TRUE(world.setMaterial(ground, floor).ok());
    EXPECT_TRUE(world.setMaterial(box, floor).ok());
    simulate(world, 1);
    return stateOf(world, box).position.x();
  };
  EXPECT_GT(slide(Material::Ice), slide(Material::Rubber) + 1);
}

}  // namespace
}  // namespace impulse
