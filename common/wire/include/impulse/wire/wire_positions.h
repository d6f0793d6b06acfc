#pragma once
/// Every position on the wire is absolute: metres from (0, 0), in double.
/// A world computes positions relative to its origin (World::origin(),
/// docs/engine.md) in float, precise near that origin however far it lies
/// from (0, 0). These move every position a message carries by `offset`,
/// in double, before anything becomes a float: a room's edge adds its
/// origin to what it sends and takes it from what it receives, and a
/// client keeping floats takes it from what it receives, so no position
/// loses what double holds on the way.
///
/// Only points move: directions, velocities, impulses, normals, shapes and
/// anchors in a body's frame stay as they are. Fields left unset stay
/// unset. Welcome and RoomList carry their bounds from (0, 0) already, and
/// Snapshot.quantized_bodies codes absolute positions itself
/// (quantized_state.h); neither is moved here.

#include "impulse.pb.h"
#include "impulse/math.h"

namespace impulse::wire {

/// The points of a command: spawn centres, vertices and points, target and
/// teleport positions, an impulse's point, query origins and boxes, joint
/// anchors and mouse targets, field outlines and fans, an interest area.
void shiftPositions(v1::ClientMessage& message, const Vec2d& offset);
/// The points of a snapshot, events, query result, body or joint info.
void shiftPositions(v1::ServerMessage& message, const Vec2d& offset);
/// Body positions, joints fixed to the world, fields, preset markers.
void shiftPositions(v1::Snapshot& snapshot, const Vec2d& offset);
/// The hits' points.
void shiftPositions(v1::Events& events, const Vec2d& offset);

}  // namespace impulse::wire
