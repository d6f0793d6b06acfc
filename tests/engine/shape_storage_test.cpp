// Shape geometry is stored per type (shape_data.h): a slot holds no
// geometry of its own, shapes of the same geometry share a place, a freed
// place is handed out again, and an address handed out stays valid however
// much the pools grow.

#include <gtest/gtest.h>

#include <vector>

#include "shape_data.h"

namespace impulse {
namespace {

TEST(ShapeStorage, ASlotIsSmallerThanThePolygonItPointsAt) {
  EXPECT_LT(sizeof(ShapeSlot), sizeof(Polygon));
}

TEST(ShapeStorage, StoredGeometryReadsBackAsGiven) {
  ShapeGeometries geometries;
  ShapeSlot circle;
  ShapeSlot box;
  geometries.store(circle, Shape::makeCircle(Real(0.3), Vec2(1, 2)));
  geometries.store(box, Shape::makePolygon(makeBox(2, 1)));
  ASSERT_EQ(circle.type(), ShapeType::Circle);
  ASSERT_EQ(box.type(), ShapeType::Polygon);
  EXPECT_EQ(geometryAs<Circle>(circle.ref()).radius, Real(0.3));
  EXPECT_EQ(geometryAs<Circle>(circle.ref()).center, Vec2(1, 2));
  const Polygon expected = makeBox(2, 1);
  const Polygon& stored = geometryAs<Polygon>(box.ref());
  ASSERT_EQ(stored.count, expected.count);
  for (int i = 0; i < expected.count; ++i) EXPECT_EQ(stored.vertices[i], expected.vertices[i]);
  EXPECT_EQ(geometries.liveCount<Circle>(), 1);
  EXPECT_EQ(geometries.liveCount<Polygon>(), 1);
}

TEST(ShapeStorage, AReleasedPlaceIsHandedOutAgainAndAddressesSurviveGrowth) {
  ShapeGeometries geometries;
  std::vector<ShapeSlot> slots(5000);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    geometries.store(slots[i], Shape::makeCircle(Real(0.1) + Real(i) * Real(1e-4)));
  }
  // Thousands of circles span several chunks: the first is where it was.
  EXPECT_EQ(geometryAs<Circle>(slots[0].ref()).radius, Real(0.1));
  EXPECT_EQ(geometryAs<Circle>(slots[4999].ref()).radius, Real(0.1) + Real(4999) * Real(1e-4));

  const void* freed = slots[7].ref().geometry;
  geometries.release(slots[7]);
  EXPECT_EQ(slots[7].geometryIndex, kNullIndex);
  EXPECT_EQ(geometries.liveCount<Circle>(), 4999);
  ShapeSlot reused;
  geometries.store(reused, Shape::makeCircle(Real(0.7)));
  EXPECT_EQ(reused.ref().geometry, freed);
  EXPECT_EQ(geometryAs<Circle>(reused.ref()).radius, Real(0.7));
}

TEST(ShapeStorage, StoringAnotherTypeGivesTheOldGeometryBack) {
  ShapeGeometries geometries;
  ShapeSlot slot;
  geometries.store(slot, Shape::makeCircle(Real(0.5)));
  geometries.store(slot, Shape::makeCapsule(Vec2(-1, 0), Vec2(1, 0), Real(0.25)));
  EXPECT_EQ(slot.type(), ShapeType::Capsule);
  EXPECT_EQ(geometries.liveCount<Circle>(), 0);
  EXPECT_EQ(geometries.liveCount<Capsule>(), 1);
  EXPECT_EQ(geometryAs<Capsule>(slot.ref()).center2, Vec2(1, 0));
}

TEST(ShapeStorage, EqualGeometryIsSharedUntilItsLastShapeLetsGo) {
  ShapeGeometries geometries;
  ShapeSlot first;
  ShapeSlot second;
  ShapeSlot other;
  geometries.store(first, Shape::makePolygon(makeBox(1, 1)));
  geometries.store(second, Shape::makePolygon(makeBox(1, 1)));
  geometries.store(other, Shape::makePolygon(makeBox(1, 2)));
  EXPECT_EQ(first.ref().geometry, second.ref().geometry);
  EXPECT_NE(first.ref().geometry, other.ref().geometry);
  EXPECT_EQ(geometries.liveCount<Polygon>(), 2);

  geometries.release(first);
  EXPECT_EQ(geometries.liveCount<Polygon>(), 2);
  EXPECT_EQ(geometryAs<Polygon>(second.ref()).vertices[0], makeBox(1, 1).vertices[0]);
  geometries.release(second);
  EXPECT_EQ(geometries.liveCount<Polygon>(), 1);

  // The freed place is no longer found as the box's: storing the box again
  // fills it afresh.
  ShapeSlot again;
  geometries.store(again, Shape::makePolygon(makeBox(1, 1)));
  EXPECT_EQ(geometries.liveCount<Polygon>(), 2);
  EXPECT_EQ(geometryAs<Polygon>(again.ref()).vertices[0], makeBox(1, 1).vertices[0]);
}

}  // namespace
}  // namespace impulse
