#pragma once
/// Builders of the ClientMessage for each command (request ids are assigned
/// by Client::send).

#include <cstdint>
#include <optional>
#include <span>

#include "impulse.pb.h"
#include "impulse/material.h"
#include "impulse/math.h"

namespace impulse::client {

/// Options of a spawned body, in wire units.
struct SpawnOptions {
  Material material = Material::Solid;
  bool isStatic = false;
  bool ignoreGravity = false;
  double velocityX = 0;
  double velocityY = 0;
  float angularVelocity = 0;
};

struct Point {
  double x = 0;
  double y = 0;
};

v1::ClientMessage spawnCircle(Point center, double radius, const SpawnOptions& options = {});
v1::ClientMessage spawnPolygon(std::span<const Point> vertices, const SpawnOptions& options = {});
v1::ClientMessage loadPreset(int preset, Material material = Material::Solid);
v1::ClientMessage setGravity(Point gravity);
v1::ClientMessage nudgeGravity(Point delta);
v1::ClientMessage resetGravity();
v1::ClientMessage clearWorld();
v1::ClientMessage removeBody(std::uint32_t id);
v1::ClientMessage applyImpulse(std::uint32_t id, Point impulse,
                               std::optional<Point> point = std::nullopt);
v1::ClientMessage setPaused(bool paused);
v1::ClientMessage step(std::uint32_t ticks);
v1::ClientMessage queryBody(std::uint32_t id);
/// With `wantStateHash` the Pong's stats carry the world's state hash.
v1::ClientMessage ping(std::uint64_t clientTimeUs, bool wantStateHash = false);

}  // namespace impulse::client
