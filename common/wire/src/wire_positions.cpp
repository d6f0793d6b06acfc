#include "impulse/wire/wire_positions.h"

namespace impulse::wire {

namespace {

void shift(v1::Vec2& point, const Vec2d& offset) {
  point.set_x(point.x() + offset.x());
  point.set_y(point.y() + offset.y());
}

// A message field that is unset stays unset (a missing required point is
// still refused as missing).
template <class Message, class Has, class Mutable>
void shiftIfSet(Message& message, Has has, Mutable get, const Vec2d& offset) {
  if ((message.*has)()) shift(*(message.*get)(), offset);
}

template <class Points>
void shiftAll(Points& points, const Vec2d& offset) {
  for (v1::Vec2& point : points) shift(point, offset);
}

void shiftJoint(v1::JointDescriptor& joint, const Vec2d& offset) {
  // Anchor B is a world point when the joint is fixed to the world.
  if (joint.body_b() == 0) shift(*joint.mutable_local_anchor_b(), offset);
}

template <class Field>
void shiftField(Field& field, const Vec2d& offset) {
  if (field.has_fluid()) shiftAll(*field.mutable_fluid()->mutable_polygon(), offset);
  if (field.has_fan()) shiftIfSet(*field.mutable_fan(), &v1::Fan::has_position, &v1::Fan::mutable_position, offset);
}

void shiftSpawns(v1::ClientMessage& m, const Vec2d& offset) {
  using M = v1::ClientMessage;
  switch (m.command_case()) {
    case M::kSpawnCircle: {
      auto& c = *m.mutable_spawn_circle();
      return shiftIfSet(c, &v1::SpawnCircle::has_center, &v1::SpawnCircle::mutable_center, offset);
    }
    case M::kSpawnPolygon: return shiftAll(*m.mutable_spawn_polygon()->mutable_vertices(), offset);
    case M::kSpawnCapsule: {
      auto& c = *m.mutable_spawn_capsule();
      shiftIfSet(c, &v1::SpawnCapsule::has_center1, &v1::SpawnCapsule::mutable_center1, offset);
      return shiftIfSet(c, &v1::SpawnCapsule::has_center2, &v1::SpawnCapsule::mutable_center2, offset);
    }
    case M::kSpawnSegment: {
      auto& c = *m.mutable_spawn_segment();
      shiftIfSet(c, &v1::SpawnSegment::has_point1, &v1::SpawnSegment::mutable_point1, offset);
      return shiftIfSet(c, &v1::SpawnSegment::has_point2, &v1::SpawnSegment::mutable_point2, offset);
    }
    case M::kSpawnChain: return shiftAll(*m.mutable_spawn_chain()->mutable_points(), offset);
    case M::kSpawnBody: {
      auto& c = *m.mutable_spawn_body();
      return shiftIfSet(c, &v1::SpawnBody::has_position, &v1::SpawnBody::mutable_position, offset);
    }
    default: return;
  }
}

void shiftQueries(v1::ClientMessage& m, const Vec2d& offset) {
  using M = v1::ClientMessage;
  switch (m.command_case()) {
    case M::kRayCast: {
      auto& c = *m.mutable_ray_cast();
      return shiftIfSet(c, &v1::RayCast::has_origin, &v1::RayCast::mutable_origin, offset);
    }
    case M::kShapeCast: {
      auto& c = *m.mutable_shape_cast();
      return shiftIfSet(c, &v1::ShapeCast::has_position, &v1::ShapeCast::mutable_position, offset);
    }
    case M::kQueryAabb: {
      auto& c = *m.mutable_query_aabb();
      shiftIfSet(c, &v1::QueryAABB::has_lower, &v1::QueryAABB::mutable_lower, offset);
      return shiftIfSet(c, &v1::QueryAABB::has_upper, &v1::QueryAABB::mutable_upper, offset);
    }
    case M::kSetInterestArea: {
      auto& c = *m.mutable_set_interest_area();
      shiftIfSet(c, &v1::SetInterestArea::has_min, &v1::SetInterestArea::mutable_min, offset);
      return shiftIfSet(c, &v1::SetInterestArea::has_max, &v1::SetInterestArea::mutable_max, offset);
    }
    default: return;
  }
}

void shiftEdits(v1::ClientMessage& m, const Vec2d& offset) {
  using M = v1::ClientMessage;
  switch (m.command_case()) {
    case M::kSetTargetTransform: {
      auto& c = *m.mutable_set_target_transform();
      return shiftIfSet(c, &v1::SetTargetTransform::has_position, &v1::SetTargetTransform::mutable_position,
                        offset);
    }
    case M::kSetTransform: {
      auto& c = *m.mutable_set_transform();
      return shiftIfSet(c, &v1::SetTransform::has_position, &v1::SetTransform::mutable_position, offset);
    }
    case M::kApplyImpulse: {
      auto& c = *m.mutable_apply_impulse();
      return shiftIfSet(c, &v1::ApplyImpulse::has_point, &v1::ApplyImpulse::mutable_point, offset);
    }
    case M::kCreateJoint: {
      auto& c = *m.mutable_create_joint();
      shiftIfSet(c, &v1::CreateJoint::has_anchor_a, &v1::CreateJoint::mutable_anchor_a, offset);
      return shiftIfSet(c, &v1::CreateJoint::has_anchor_b, &v1::CreateJoint::mutable_anchor_b, offset);
    }
    case M::kUpdateJoint: {
      auto& c = *m.mutable_update_joint();
      return shiftIfSet(c, &v1::UpdateJoint::has_target, &v1::UpdateJoint::mutable_target, offset);
    }
    case M::kAddField: return shiftField(*m.mutable_add_field(), offset);
    default: return;
  }
}

void shiftHits(v1::QueryResult& result, const Vec2d& offset) {
  for (v1::QueryHit& hit : *result.mutable_hits()) {
    shiftIfSet(hit, &v1::QueryHit::has_point, &v1::QueryHit::mutable_point, offset);
  }
}

void shiftState(v1::BodyState& state, const Vec2d& offset) {
  shiftIfSet(state, &v1::BodyState::has_position, &v1::BodyState::mutable_position, offset);
}

}  // namespace

void shiftPositions(v1::ClientMessage& message, const Vec2d& offset) {
  if (offset == Vec2d::Zero()) return;
  shiftSpawns(message, offset);
  shiftQueries(message, offset);
  shiftEdits(message, offset);
}

void shiftPositions(v1::Snapshot& snapshot, const Vec2d& offset) {
  if (offset == Vec2d::Zero()) return;
  for (v1::BodyState& state : *snapshot.mutable_bodies()) shiftState(state, offset);
  for (v1::JointDescriptor& joint : *snapshot.mutable_joints_added()) shiftJoint(joint, offset);
  for (v1::FieldDescriptor& field : *snapshot.mutable_fields_added()) shiftField(field, offset);
  if (snapshot.has_preset()) {
    for (v1::Marker& marker : *snapshot.mutable_preset()->mutable_markers()) {
      shiftIfSet(marker, &v1::Marker::has_center, &v1::Marker::mutable_center, offset);
    }
  }
}

void shiftPositions(v1::Events& events, const Vec2d& offset) {
  for (v1::HitEvent& hit : *events.mutable_hits()) {
    shiftIfSet(hit, &v1::HitEvent::has_point, &v1::HitEvent::mutable_point, offset);
  }
}

void shiftPositions(v1::ServerMessage& message, const Vec2d& offset) {
  if (offset == Vec2d::Zero()) return;
  using M = v1::ServerMessage;
  switch (message.message_case()) {
    case M::kSnapshot: return shiftPositions(*message.mutable_snapshot(), offset);
    case M::kEvents: return shiftPositions(*message.mutable_events(), offset);
    case M::kQueryResult: return shiftHits(*message.mutable_query_result(), offset);
    case M::kBodyInfo: return shiftState(*message.mutable_body_info()->mutable_state(), offset);
    case M::kJointInfo: return shiftJoint(*message.mutable_joint_info()->mutable_descriptor(), offset);
    default: return;
  }
}

}  // namespace impulse::wire
