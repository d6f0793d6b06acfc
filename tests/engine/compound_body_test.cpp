// Bodies of several shapes: the union's exact mass, shapes added and removed
// on a live body, per-shape materials, compound bodies resting and falling,
// concave polygons split into pieces, chains as terrain, and save/load of
// all of it.

#include <gtest/gtest.h>

#include <array>

#include "impulse/body.h"
#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using test::kDt;
using test::simulate;
using test::stateOf;

constexpr Real kDensity = 2;

WorldSettings weightless() {
  WorldSettings settings;
  settings.gravity = Vec2::Zero();
  return settings;
}

BodyOptions withDensity(Real density) {
  BodyOptions options;
  options.materialOverride.density = density;
  return options;
}

ShapeDef boxAt(const Vec2& center, Real halfWidth, Real halfHeight, Real density = kDensity) {
  ShapeDef def;
  def.shape = translated(Shape::makePolygon(makeBox(halfWidth, halfHeight)), center);
  def.materialOverride.density = density;
  return def;
}

BodyId createStaticGround(World& world) {
  BodyOptions ground;
  ground.properties.isStatic = true;
  const std::array<Vec2, 4> points{Vec2(-20, -1), Vec2(20, -1), Vec2(20, 0), Vec2(-20, 0)};
  return world.createPolygon(points, ground).id;
}

// A dumbbell: two unit squares 4 m apart. Mass 2 * 1 * density; centre in
// the middle; inertia 2 * (m/12 * (1 + 1) + m * 2^2) for each square of
// mass m = density.
TEST(CompoundBody, MassIsTheUnionsWithTheParallelAxisTheorem) {
  World world;
  BodyDef def;
  def.shape = boxAt(Vec2(-1, 0), Real(0.5), Real(0.5)).shape;
  def.materialOverride.density = kDensity;
  def.extraShapes.push_back(boxAt(Vec2(3, 0), Real(0.5), Real(0.5)));
  def.position = Vec2(0, 5);
  const CreateResult created = world.createBody(def);
  ASSERT_TRUE(created.ok()) << created.error;
  const BodyDescription body = *world.bodyDescription(created.id);
  const double m = kDensity;
  EXPECT_NEAR(body.mass.mass, 2 * m, 1e-5);
  EXPECT_NEAR(body.mass.inertia, 2 * (m / 12 * 2 + m * 4), 1e-4);
  // The centre of mass moved to the middle of the two squares (x = 1).
  EXPECT_NEAR(stateOf(world, created.id).position.x(), 1, 1e-6);
  EXPECT_NEAR(stateOf(world, created.id).position.y(), 5, 1e-6);
  ASSERT_EQ(body.shapes.size(), 2u);
  EXPECT_NEAR(computeMassProperties(body.shapes[0].shape, 1).center.x(), -2, 1e-5);
  EXPECT_NEAR(computeMassProperties(body.shapes[1].shape, 1).center.x(), 2, 1e-5);
}

TEST(CompoundBody, EachShapeKeepsItsOwnMaterial) {
  World world;
  BodyDef def;
  def.shape = boxAt(Vec2(0, 0), Real(0.5), Real(0.5)).shape;
  def.material = Material::Ice;
  ShapeDef rubber = boxAt(Vec2(1, 0), Real(0.5), Real(0.5));
  rubber.material = Material::Rubber;
  rubber.materialOverride = {};
  def.extraShapes.push_back(rubber);
  def.position = Vec2(0, 5);
  const CreateResult created = world.createBody(def);
  ASSERT_TRUE(created.ok()) << created.error;
  const BodyDescription body = *world.bodyDescription(created.id);
  ASSERT_EQ(body.shapes.size(), 2u);
  EXPECT_EQ(body.shapes[0].material, Material::Ice);
  EXPECT_EQ(body.shapes[1].material, Material::Rubber);
  EXPECT_EQ(body.shapes[1].coefficients.restitution, materialProperties(Material::Rubber).restitution);
  // The body's mass is the sum of each shape's area times its own density.
  const double expected = materialProperties(Material::Ice).density + materialProperties(Material::Rubber).density;
  EXPECT_NEAR(body.mass.mass, expected, 1e-4 * expected);
}

TEST(CompoundBody, AddingAndRemovingAShapeKeepsTheOthersInPlace) {
  World world(weightless());
  const CreateResult body = world.createCircle(Vec2(0, 0), 1, withDensity(kDensity));
  ASSERT_TRUE(body.ok());
  const ShapeResult added = world.createShape(body.id, boxAt(Vec2(4, 0), 1, 1));
  ASSERT_TRUE(added.ok()) << added.error;
  // Circle mass pi * 2, square 4 * 2: the centre moves towards the square.
  const double circle = std::numbers::pi * kDensity, square = 4 * kDensity;
  const double centre = square * 4 / (circle + square);
  EXPECT_NEAR(stateOf(world, body.id).position.x(), centre, 1e-5);
  // The circle is where it was: its centre is now -centre in the body's frame.
  const BodyDescription description = *world.bodyDescription(body.id);
  EXPECT_NEAR(description.shapes[0].shape.circle().center.x(), -centre, 1e-5);
  EXPECT_NEAR(description.mass.mass, circle + square, 1e-4);
  EXPECT_EQ(world.shapeBody(added.id), body.id);

  ASSERT_TRUE(world.destroyShape(added.id).ok());
  EXPECT_NEAR(stateOf(world, body.id).position.x(), 0, 1e-5);
  EXPECT_NEAR(world.bodyDescription(body.id)->mass.mass, circle, 1e-4);
  EXPECT_FALSE(world.shapeBody(added.id).has_value()) << "a removed shape's id names nothing";
}

TEST(CompoundBody, RefusesWhatCannotBeAShapeOfABody) {
  World world;
  const CreateResult body = world.createCircle(Vec2(0, 0), 1);
  ASSERT_TRUE(body.ok());
  const ShapeResult far = world.createShape(body.id, boxAt(Vec2(200, 0), 1, 1));
  EXPECT_FALSE(far.ok());
  EXPECT_NE(far.error.find("must stay within 50 m"), std::string::npos) << far.error;
  EXPECT_EQ(world.bodyDescription(body.id)->shapes.size(), 1u) << "a refused shape leaves nothing behind";
  EXPECT_NEAR(stateOf(world, body.id).position.x(), 0, 1e-6);

  const ShapeId only = world.bodyDescription(body.id)->shapes[0].id;
  const InputResult last = world.destroyShape(only);
  EXPECT_FALSE(last.ok());
  EXPECT_NE(last.error.find("remove the body instead"), std::string::npos) << last.error;
  EXPECT_FALSE(world.destroyShape(ShapeId{12345}).ok());

  BodyOptions dynamic;
  const CreateResult massless = world.createBody(makeBodyDef(Shape::makeSegment(Vec2(0, 0), Vec2(1, 0)), Vec2(0, 0), dynamic));
  EXPECT_FALSE(massless.ok());
  EXPECT_NE(massless.error.find("needs a shape with area"), std::string::npos) << massless.error;
}

// An L of two boxes rests on the ground on its long leg and stays there.
TEST(CompoundBody, AnLShapeFallsAndRestsOnItsLongLeg) {
  World world;
  createStaticGround(world);
  BodyDef def;
  def.shape = boxAt(Vec2(0, 0), 2, Real(0.25)).shape;
  def.materialOverride.density = 1;
  def.extraShapes.push_back(boxAt(Vec2(-Real(1.75), Real(0.75)), Real(0.25), Real(0.5), 1));
  def.position = Vec2(0, 3);
  const CreateResult created = world.createBody(def);
  ASSERT_TRUE(created.ok()) << created.error;
  simulate(world, 4);
  const BodyState state = stateOf(world, created.id);
  EXPECT_NEAR(state.angle, 0, 0.01);
  // The long leg's bottom (0.25 m below its centre) lies on the ground: the
  // centre of mass sits at 0.25 + the offset of the union's centroid.
  const double legArea = 4 * 0.5, postArea = 0.5 * 1;
  const double centroidY = (postArea * 0.75) / (legArea + postArea);
  EXPECT_NEAR(state.position.y(), 0.25 + centroidY, 0.01);
  EXPECT_FALSE(state.awake) << "a resting compound body sleeps";
}

TEST(CompoundBody, ShapesOfOneBodyNeverCollideWithEachOther) {
  World world(weightless());
  BodyDef def;
  def.shape = boxAt(Vec2(0, 0), 1, 1).shape;
  def.extraShapes.push_back(boxAt(Vec2(Real(0.5), 0), 1, 1));  // overlapping the first
  def.position = Vec2(0, 0);
  const CreateResult created = world.createBody(def);
  ASSERT_TRUE(created.ok());
  simulate(world, 1);
  EXPECT_EQ(world.contactCount(), 0);
  EXPECT_NEAR(stateOf(world, created.id).linearVelocity.norm(), 0, 1e-6);
}

TEST(ConcavePolygon, AnLOutlineBecomesOneBodyOfConvexPieces) {
  World world;
  createStaticGround(world);
  const std::array<Vec2, 6> outline{Vec2(0, 1), Vec2(3, 1), Vec2(3, 2), Vec2(1, 2), Vec2(1, 4), Vec2(0, 4)};
  const CreateResult created = world.createPolygon(outline);
  ASSERT_TRUE(created.ok()) << created.error;
  const BodyDescription body = *world.bodyDescription(created.id);
  EXPECT_GE(body.shapes.size(), 2u);
  // Area 3 + 2 = 5 m^2 at the material's density.
  EXPECT_NEAR(body.mass.area, 5, 1e-4);
  EXPECT_NEAR(body.mass.mass, 5 * materialProperties(Material::Solid).density, 1e-3);
  // Centroid: (3 * (1.5, 1.5) + 2 * (0.5, 3)) / 5.
  EXPECT_NEAR(stateOf(world, created.id).position.x(), (3 * 1.5 + 2 * 0.5) / 5, 1e-4);
  EXPECT_NEAR(stateOf(world, created.id).position.y(), (3 * 1.5 + 2 * 3.0) / 5, 1e-4);
  simulate(world, 3);
  EXPECT_GT(stateOf(world, created.id).position.y(), 0.5) << "the pieces rest on the ground together";

  const std::array<Vec2, 4> bowtie{Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 2)};
  const CreateResult crossing = world.createPolygon(bowtie);
  EXPECT_FALSE(crossing.ok()) << "a self-intersecting outline is still refused";
}

// A box slides along a 100-segment flat chain: the joins never catch it.
TEST(Chain, ABoxSlidesOverAHundredJoinsWithoutCatching) {
  WorldSettings wide;
  wide.bounds = AABB{Vec2(-25, -25), Vec2(150, 45)};
  World world(wide);
  std::vector<Vec2> points;
  // Right to left: a chain collides on the right of the way its points run.
  for (int i = 101; i >= -1; --i) points.push_back(Vec2(Real(i), 0));
  BodyOptions terrain;
  terrain.materialOverride.staticFriction = 0;
  terrain.materialOverride.dynamicFriction = 0;
  const CreateResult chain = world.createChain(points, false, terrain);
  ASSERT_TRUE(chain.ok()) << chain.error;
  EXPECT_EQ(world.bodyDescription(chain.id)->shapes.size(), points.size() - 3);

  BodyOptions slider = terrain;
  slider.linearVelocity = Vec2(5, 0);
  const std::array<Vec2, 4> box{Vec2(1, 0), Vec2(2, 0), Vec2(2, 1), Vec2(1, 1)};
  const CreateResult boxBody = world.createPolygon(box, slider);
  ASSERT_TRUE(boxBody.ok());
  double slowest = 5;
  double lowest = 1;
  for (int i = 0; i < test::stepsFor(3); ++i) {
    world.step(kDt);
    const BodyState state = stateOf(world, boxBody.id);
    slowest = std::min(slowest, double(state.linearVelocity.x()));
    lowest = std::min(lowest, double(state.position.y()));
  }
  EXPECT_GT(slowest, 4.9) << "no join slowed the frictionless box";
  EXPECT_GT(lowest, 0.49) << "the box never sank into a join";
  EXPECT_GT(stateOf(world, boxBody.id).position.x(), 15);
}

TEST(Chain, RefusesTooFewPoints) {
  World world;
  const std::array<Vec2, 3> three{Vec2(0, 0), Vec2(1, 0), Vec2(2, 0)};
  const CreateResult refused = world.createChain(three, false);
  EXPECT_FALSE(refused.ok());
  EXPECT_EQ(world.bodyCount(), 0);
}

TEST(CompoundBody, SaveAndLoadStepOnBitIdentically) {
  World world;
  createStaticGround(world);
  BodyDef def;
  def.shape = Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.3));
  def.extraShapes.push_back(boxAt(Vec2(0, Real(0.6)), Real(0.4), Real(0.4)));
  def.extraShapes.push_back({Shape::makeCircle(Real(0.35), Vec2(1, Real(0.5))), Material::Rubber, {}, {}});
  def.position = Vec2(0, 4);
  def.angle = Real(0.3);
  ASSERT_TRUE(world.createBody(def).ok());
  const std::array<Vec2, 6> outline{Vec2(4, 1), Vec2(7, 1), Vec2(7, 2), Vec2(5, 2), Vec2(5, 4), Vec2(4, 4)};
  ASSERT_TRUE(world.createPolygon(outline).ok());
  simulate(world, 0.5);

  World copy;
  ASSERT_TRUE(copy.importState(world.exportState()).ok());
  EXPECT_EQ(copy.stateHash(), world.stateHash());
  simulate(world, 1);
  simulate(copy, 1);
  EXPECT_EQ(copy.stateHash(), world.stateHash());
}

TEST(Kinematic, APlatformCarriesABoxUpAndIsNeverPushed) {
  World world;
  BodyOptions platformOptions;
  platformOptions.properties.isKinematic = true;
  const std::array<Vec2, 4> slab{Vec2(-2, 0), Vec2(2, 0), Vec2(2, Real(0.5)), Vec2(-2, Real(0.5))};
  const CreateResult platform = world.createPolygon(slab, platformOptions);
  ASSERT_TRUE(platform.ok()) << platform.error;
  const std::array<Vec2, 4> box{Vec2(-Real(0.5), Real(0.5)), Vec2(Real(0.5), Real(0.5)), Vec2(Real(0.5), Real(1.5)),
                                Vec2(-Real(0.5), Real(1.5))};
  BodyOptions heavy;
  heavy.materialOverride.density = 1000;
  const CreateResult cargo = world.createPolygon(box, heavy);
  ASSERT_TRUE(cargo.ok());
  simulate(world, 1);
  // Held up against gravity by an infinitely heavy body: the platform has
  // not moved under a tonne.
  EXPECT_NEAR(stateOf(world, platform.id).position.y(), 0.25, 1e-6);
  ASSERT_TRUE(world.setVelocity(platform.id, Vec2(0, 1), 0).ok());
  simulate(world, 2);
  EXPECT_NEAR(stateOf(world, platform.id).position.y(), 2.25, 1e-3) << "no gravity, no push";
  EXPECT_NEAR(stateOf(world, cargo.id).position.y(), 3, 0.02) << "the box rode up with it";
  EXPECT_TRUE(stateOf(world, cargo.id).awake) << "a carried box moves, so it stays awake";

  const InputResult pushed = world.applyImpulse(platform.id, Vec2(1, 0));
  EXPECT_FALSE(pushed.ok());
  EXPECT_NE(pushed.error.find("kinematic"), std::string::npos) << pushed.error;
}

TEST(Kinematic, TargetTransformArrivesInOneStep) {
  World world;
  BodyOptions options;
  options.properties.isKinematic = true;
  const CreateResult door = world.createCircle(Vec2(0, 0), Real(0.5), options);
  ASSERT_TRUE(door.ok());
  ASSERT_TRUE(world.setTargetTransform(door.id, Vec2(1, Real(0.5)), Real(0.4), kDt).ok());
  world.step(kDt);
  const BodyState state = stateOf(world, door.id);
  EXPECT_NEAR(state.position.x(), 1, 1e-4);
  EXPECT_NEAR(state.position.y(), 0.5, 1e-4);
  // Turns are integrated to first order per sub-step: within 1 % of 0.4 rad.
  EXPECT_NEAR(state.angle, 0.4, 0.004);
  EXPECT_FALSE(world.setTargetTransform(door.id, Vec2(1, 1), 0, 0).ok()) << "dt must be positive";
}

}  // namespace
}  // namespace impulse
