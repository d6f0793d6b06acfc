// wire::shiftPositions: every point a message carries moves by the offset,
// in double; directions, velocities, body-local anchors and unset fields do
// not. The room's edge and the client library rest on it.
#include <gtest/gtest.h>

#include "impulse/client/commands.h"
#include "impulse/wire/wire_positions.h"

namespace impulse::net_test {
namespace {

const Vec2d kOffset(80000, -20000);

void expectAt(const v1::Vec2& point, double x, double y) {
  EXPECT_EQ(point.x(), x);
  EXPECT_EQ(point.y(), y);
}

TEST(WirePositions, CommandsPointsMove_TheirDirectionsAndVelocitiesDoNot) {
  v1::ClientMessage spawn = client::spawnCircle({1.5, 2}, 0.5, {.velocityX = 3});
  wire::shiftPositions(spawn, kOffset);
  expectAt(spawn.spawn_circle().center(), 80001.5, -19998);
  expectAt(spawn.spawn_circle().options().velocity(), 3, 0);

  v1::ClientMessage ray = client::rayCast({1, 1}, {10, 0});
  wire::shiftPositions(ray, kOffset);
  expectAt(ray.ray_cast().origin(), 80001, -19999);
  expectAt(ray.ray_cast().translation(), 10, 0);

  v1::ClientMessage push = client::applyImpulse(7, {0, 5});
  wire::shiftPositions(push, kOffset);
  EXPECT_FALSE(push.apply_impulse().has_point()) << "no point given: the centre of mass, still";
  expectAt(push.apply_impulse().impulse(), 0, 5);

  v1::ClientMessage area = client::setInterestArea(client::Box{{-1, -1}, {1, 1}});
  wire::shiftPositions(area, -kOffset);
  expectAt(area.set_interest_area().min(), -80001, 19999);

  v1::ClientMessage everywhere = client::setInterestArea(std::nullopt);
  wire::shiftPositions(everywhere, kOffset);
  EXPECT_FALSE(everywhere.set_interest_area().has_min()) << "the whole room stays the whole room";
}

TEST(WirePositions, SnapshotsMoveStatesWorldAnchorsFieldsAndMarkers_AndComeBackExactly) {
  v1::ServerMessage message;
  v1::Snapshot& snapshot = *message.mutable_snapshot();
  v1::BodyState& state = *snapshot.add_bodies();
  state.mutable_position()->set_x(1.25);
  state.mutable_velocity()->set_x(4);
  v1::JointDescriptor& toWorld = *snapshot.add_joints_added();
  toWorld.set_body_a(1);
  toWorld.mutable_local_anchor_a()->set_x(0.5);
  toWorld.mutable_local_anchor_b()->set_x(2);
  v1::JointDescriptor& between = *snapshot.add_joints_added();
  between.set_body_a(1);
  between.set_body_b(2);
  between.mutable_local_anchor_b()->set_x(2);
  v1::Fan& fan = *snapshot.add_fields_added()->mutable_fan();
  fan.mutable_position()->set_y(3);
  fan.mutable_direction()->set_x(1);
  snapshot.mutable_preset()->add_markers()->mutable_center()->set_x(-1);
  const v1::ServerMessage original = message;

  wire::shiftPositions(message, kOffset);
  expectAt(state.position(), 80001.25, -20000);
  expectAt(state.velocity(), 4, 0);
  expectAt(toWorld.local_anchor_a(), 0.5, 0);  // in body A's frame
  // A world point: the joint is fixed to the world.
  expectAt(toWorld.local_anchor_b(), 80002, -20000);
  expectAt(between.local_anchor_b(), 2, 0);  // in body B's frame
  expectAt(fan.position(), 80000, -19997);
  expectAt(fan.direction(), 1, 0);
  expectAt(snapshot.preset().markers(0).center(), 79999, -20000);

  wire::shiftPositions(message, -kOffset);
  EXPECT_EQ(message.SerializeAsString(), original.SerializeAsString());
}

TEST(WirePositions, QueryHitsEventsAndBodyInfoMove) {
  v1::ServerMessage query;
  v1::QueryHit& hit = *query.mutable_query_result()->add_hits();
  hit.mutable_point()->set_x(1);
  hit.mutable_normal()->set_x(-1);
  wire::shiftPositions(query, kOffset);
  expectAt(hit.point(), 80001, -20000);
  expectAt(hit.normal(), -1, 0);

  v1::ServerMessage events;
  events.mutable_events()->add_hits()->mutable_point()->set_y(2);
  wire::shiftPositions(events, kOffset);
  expectAt(events.events().hits(0).point(), 80000, -19998);

  v1::ServerMessage info;
  info.mutable_body_info()->mutable_state()->mutable_position()->set_x(5);
  wire::shiftPositions(info, kOffset);
  expectAt(info.body_info().state().position(), 80005, -20000);
}

}  // namespace
}  // namespace impulse::net_test
