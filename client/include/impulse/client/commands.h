#pragma once
/// Builders of the ClientMessage for each command (request ids are assigned
/// by Client::send).

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "impulse.pb.h"
#include "impulse/body.h"
#include "impulse/query.h"
#include "impulse/material.h"
#include "impulse/math.h"

namespace impulse::client {

/// Options of a spawned body, in wire units.
struct SpawnOptions {
  Material material = Material::Solid;
  bool isStatic = false;
  bool isKinematic = false;
  /// False: created asleep, still until touched or woken.
  bool isAwake = true;
  bool ignoreGravity = false;
  double velocityX = 0;
  double velocityY = 0;
  float angularVelocity = 0;
  /// Per-body properties (docs/protocol.md); unset: the material's values.
  std::optional<double> density{};
  std::optional<double> friction{};
  std::optional<double> restitution{};
  double linearDamping = 0;
  double angularDamping = 0;
  std::optional<double> gravityScale{};
  /// Every shape's filter, sensor flag and events (docs/protocol.md, Events).
  ShapeInteraction flags{};
};

struct Point {
  double x = 0;
  double y = 0;
};

v1::ClientMessage spawnCircle(Point center, double radius, const SpawnOptions& options = {});
v1::ClientMessage spawnPolygon(std::span<const Point> vertices, const SpawnOptions& options = {});
v1::ClientMessage spawnCapsule(Point center1, Point center2, double radius, const SpawnOptions& options = {});
v1::ClientMessage spawnSegment(Point point1, Point point2, const SpawnOptions& options = {});
v1::ClientMessage spawnChain(std::span<const Point> points, bool loop, const SpawnOptions& options = {});

/// One shape of a compound body: a circle, box or capsule in the body's
/// frame, with its material.
struct BodyPart {
  enum class Kind { Circle, Box, Capsule } kind = Kind::Circle;
  Point point1;        ///< circle or box centre, capsule's first centre
  Point point2;        ///< box half extents, capsule's second centre
  double radius = 0;   ///< circle and capsule
  Material material = Material::Solid;
};
v1::ClientMessage spawnBody(Point position, double angle, std::span<const BodyPart> parts,
                            const SpawnOptions& options = {});
v1::ClientMessage setTargetTransform(std::uint32_t body, Point position, double angle);
/// Puts the body's centre of mass at `position`, turned to `angle`, at once.
v1::ClientMessage setTransform(std::uint32_t body, Point position, double angle = 0);
v1::ClientMessage setMaterial(std::uint32_t body, Material material);
v1::ClientMessage setBodyType(std::uint32_t body, BodyType type);
v1::ClientMessage loadPreset(int preset, Material material = Material::Solid);
v1::ClientMessage setGravity(Point gravity);
v1::ClientMessage nudgeGravity(Point delta);
v1::ClientMessage resetGravity();
v1::ClientMessage clearWorld();
v1::ClientMessage removeBody(std::uint32_t id);
v1::ClientMessage applyImpulse(std::uint32_t id, Point impulse,
                               std::optional<Point> point = std::nullopt);
/// `angular` in rad/s.
v1::ClientMessage setVelocity(std::uint32_t id, Point velocity, double angular = 0);
/// Every shape of the body takes the flags.
v1::ClientMessage setShapeFlags(std::uint32_t id, const ShapeInteraction& flags);
/// Starts (true) or stops this client's Events stream.
v1::ClientMessage subscribeEvents(bool enabled);
/// The first shape the ray enters, or with allHits every one (maxHits 0:
/// the most the server gives); answered by QueryResult.
v1::ClientMessage rayCast(Point origin, Point translation, bool allHits = false, const QueryFilter& filter = {},
                          std::uint32_t maxHits = 0);
/// The part's shape (its material unused) placed at position, angle and
/// swept along translation: the first shape it touches.
v1::ClientMessage shapeCast(Point position, double angle, const BodyPart& shape, Point translation,
                            const QueryFilter& filter = {});
/// The shapes whose bounding box overlaps lower-upper (maxResults 0: the
/// most the server gives).
v1::ClientMessage queryAabb(Point lower, Point upper, const QueryFilter& filter = {}, std::uint32_t maxResults = 0);
v1::ClientMessage setPaused(bool paused);
v1::ClientMessage step(std::uint32_t ticks);
v1::ClientMessage queryBody(std::uint32_t id);
/// The two ends of a new joint (docs/protocol.md, "Joints"): anchors are world
/// points now; bodyB 0 fixes the joint to the world at anchorB.
struct JointEnds {
  std::uint32_t bodyA = 0;
  std::uint32_t bodyB = 0;
  Point anchorA;
  Point anchorB;
  bool collideConnected = false;
};

/// CreateJoint, one builder per kind; the reply's joint_id names the joint.
v1::ClientMessage distanceJoint(const JointEnds& ends, const v1::DistanceJoint& kind);
v1::ClientMessage ropeJoint(const JointEnds& ends, const v1::RopeJoint& kind);
v1::ClientMessage revoluteJoint(const JointEnds& ends, const v1::RevoluteJoint& kind);
v1::ClientMessage prismaticJoint(const JointEnds& ends, const v1::PrismaticJoint& kind);
v1::ClientMessage weldJoint(const JointEnds& ends, const v1::WeldJoint& kind);
v1::ClientMessage wheelJoint(const JointEnds& ends, const v1::WheelJoint& kind);
/// Pulls `point` of `body` towards `point` (then setJointTarget) with at
/// most kind.max_force.
v1::ClientMessage mouseJoint(std::uint32_t body, Point point, const v1::MouseJoint& kind);
/// UpdateJoint: a mouse joint's target.
v1::ClientMessage setJointTarget(std::uint32_t joint, Point target);
/// UpdateJoint: a motor's speed, and its max torque or force when given.
v1::ClientMessage setJointMotor(std::uint32_t joint, double speed,
                                std::optional<double> maxForce = std::nullopt);
v1::ClientMessage removeJoint(std::uint32_t joint);
/// A CreateJoint given the client's own name for its joint
/// (CreateJoint.tag, not 0), so later commands may name it by tag before
/// the reply names its id.
v1::ClientMessage tagJoint(v1::ClientMessage createJoint, std::uint32_t tag);
/// An UpdateJoint or RemoveJoint naming the joint by the tag this client
/// gave it (joint_tag) instead of its id: byJointTag(setJointTarget(0, p), 7).
v1::ClientMessage byJointTag(v1::ClientMessage jointCommand, std::uint32_t tag);
/// The same command naming the joint by its id instead.
v1::ClientMessage byJointId(v1::ClientMessage jointCommand, std::uint32_t joint);
/// Answered by a JointInfo.
v1::ClientMessage queryJoint(std::uint32_t joint);
/// Answered by a SceneData holding the serialised Scene.
v1::ClientMessage saveScene();
/// `data`: a serialised Scene, as SceneData.data or a scene file holds it.
v1::ClientMessage loadScene(std::string data);

/// AddField, one builder per kind; the reply's field_id names the field.
v1::ClientMessage gravitationField(double constant);
v1::ClientMessage fluidField(const v1::FluidRegion& fluid);
v1::ClientMessage fanField(const v1::Fan& fan);
v1::ClientMessage removeField(std::uint32_t field);
/// With `wantStateHash` the Pong's stats carry the world's state hash.
v1::ClientMessage ping(std::uint64_t clientTimeUs, bool wantStateHash = false);
/// Simulated seconds per wall second, 0.01..16 (docs/protocol.md, "Time").
v1::ClientMessage setTimeScale(double scale);

/// Answered by a RoomList: every room of the server.
v1::ClientMessage listRooms();

/// Networked play (docs/networked-play.md): receive only the bodies inside
/// the box min-max (the view plus a margin), or the whole room again.
struct Box {
  Point min;
  Point max;
};
v1::ClientMessage setInterestArea(std::optional<Box> area);
/// At most `bytesPerSecond` snapshot bytes a second, the most important
/// changes first; nothing: no budget.
v1::ClientMessage setBandwidthBudget(std::optional<double> bytesPerSecond);
/// Networked play (docs/networked-play.md): the command, stamped to be
/// applied at `tick` of the room (ClientMessage.for_tick).
v1::ClientMessage forTick(v1::ClientMessage message, std::uint64_t tick);

}  // namespace impulse::client
