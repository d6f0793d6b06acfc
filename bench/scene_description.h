#pragma once
// A scene described once, engine-neutrally, and translated by each adapter.
//
// Coefficients: Impulse takes density, friction and restitution from a
// Material only (material.h) and mixes a pair as the mean. So each body names
// the Material Impulse uses, and the peers' numbers are derived from it: the
// same density, restitution, and friction = Impulse's *static* coefficient
// (the peers have one coefficient; static is the one that decides whether a
// contact holds). A contact's coefficient is the mean of its two bodies'
// values in every engine; the peer adapters make their engines mix that way.

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "impulse/material.h"

namespace bench {

struct Vec2d {
  double x = 0;
  double y = 0;
};

/// Box2D v3's collision filter: shapes A and B collide when they share a
/// positive group, or, unless they share a negative one, when each one's
/// category is in the other's mask. The default collides with everything.
struct CollisionFilter {
  std::uint32_t category = 1;
  std::uint32_t mask = ~0u;
  int group = 0;
};

/// Solid shapes (circle, polygon, capsule) have area; segments and chains are
/// boundaries (static or kinematic bodies only).
enum class ShapeKind { Circle, Polygon, Capsule, Segment, Chain };

/// A shape in its body's frame (origin at BodyDesc::position).
struct ShapeDesc {
  ShapeKind kind = ShapeKind::Circle;
  /// Circles and capsules: their radius; polygons: the rounding radius.
  double radius = 0;
  Vec2d center;  ///< circles
  /// Polygons: anticlockwise and convex. Capsules and segments: their two
  /// points. Chains: their points, one-sided, solid on the right of the way
  /// they run (Box2D's and Impulse's convention alike).
  std::vector<Vec2d> vertices;
  bool loop = false;  ///< chains
  CollisionFilter filter;
  /// The shape's own friction where it departs from its body's.
  std::optional<double> friction;

  static ShapeDesc circle(double radius, Vec2d center = {});
  static ShapeDesc box(double halfWidth, double halfHeight, Vec2d center = {});
  static ShapeDesc polygon(std::vector<Vec2d> vertices, double rounding = 0);
  static ShapeDesc capsule(Vec2d center1, Vec2d center2, double radius);
  static ShapeDesc segment(Vec2d point1, Vec2d point2);
  static ShapeDesc chain(std::vector<Vec2d> points, bool loop);
  /// Of the polygon's core for polygons (the rounding is left out).
  double area() const;
  /// Largest distance from the body's origin to the shape.
  double extent() const;
};

struct BodyDesc {
  ShapeDesc shape;
  /// Further shapes of the same body, made of its material (compound bodies).
  std::vector<ShapeDesc> extraShapes;
  bool isStatic = false;
  /// Moved only by its velocity, or by SceneDescription::targets.
  bool isKinematic = false;
  /// The body's origin: the centroid of a single centred shape. Poses are
  /// read back at this point in every engine.
  Vec2d position;
  double angle = 0;
  Vec2d velocity;
  double angularVelocity = 0;
  impulse::Material material = impulse::Material::Solid;
  /// Derived from material by makeBody(); a scene may set its own values
  /// (Impulse then applies them as a per-body MaterialOverride).
  double density = 0;
  double friction = 0;  ///< peers' single coefficient (Impulse's static one)
  double restitution = 0;
  /// The step before which the body is created (Box2D's rain drops its
  /// ragdolls in waves); until then its pose is the described one.
  int spawnStep = 0;
  /// Created asleep (Box2D's smash): woken by the first contact.
  bool startsAsleep = false;
  /// Box2D v3's linear damping (1/s): dv/dt = -c v.
  double linearDamping = 0;

  bool isDynamic() const { return !isStatic && !isKinematic; }
};

/// Joints every engine here has: a pin (revolute), a rigid rod and an
/// undamped or damped spring (distance joints).
enum class JointKind { Pin, Rod, Spring };

/// JointDesc::bodyB for a joint to the world.
inline constexpr int kWorldBody = -1;

/// A joint between bodies (indices into SceneDescription::bodies), or a body
/// and the world (bodyB = kWorldBody). Anchors are world points at creation;
/// a pin's two anchors are the same point. Joined bodies do not collide with
/// each other.
struct JointDesc {
  JointKind kind = JointKind::Pin;
  int bodyA = 0;
  int bodyB = kWorldBody;
  Vec2d anchorA;
  Vec2d anchorB;
  double restLength = 0;  ///< springs; rods keep their length at creation
  double stiffness = 0;   ///< springs, N/m
  double damping = 0;     ///< springs, N*s/m
  /// Pins only: Box2D v3's revolute options. Angles are B's turn relative to
  /// A since creation; a motor of speed 0 is joint friction; the spring
  /// (hertz > 0) pulls towards the creation angle.
  bool enableLimit = false;
  double lowerAngle = 0;
  double upperAngle = 0;
  bool enableMotor = false;
  double motorSpeed = 0;      ///< rad/s
  double maxMotorTorque = 0;  ///< N*m
  double springHertz = 0;
  double springDampingRatio = 0;
};

/// Where a kinematic body must be after the step that starts at `time` (s):
/// each engine gives it the velocity that gets it there
/// (b2Body_SetTargetTransform).
struct KinematicTarget {
  int body = 0;
  std::function<Vec2d(double time)> position;
};

struct SceneDescription {
  Vec2d gravity{0, -9.81};
  /// Where an engine with a movable origin centres its world (Impulse:
  /// World::shiftOrigin), as a user would for a level far from (0, 0);
  /// positions here stay measured from (0, 0). Engines whose positions are
  /// plain floats from (0, 0) ignore it.
  Vec2d origin;
  bool allowSleep = false;
  std::vector<BodyDesc> bodies;
  std::vector<JointDesc> joints;
  std::vector<KinematicTarget> targets;

  /// True when every body has the same friction and restitution, so an
  /// engine's own mixing rule already yields the mean.
  bool uniformCoefficients() const;
};

/// Thrown by an adapter for a scene its engine cannot express: the run is
/// reported as skipped, with the reason, not as failed.
class Unsupported : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

BodyDesc makeBody(ShapeDesc shape, Vec2d position, impulse::Material material, bool isStatic = false);
/// A static axis-aligned box from lower to upper corner.
BodyDesc makeStaticBox(Vec2d lower, Vec2d upper, impulse::Material material = impulse::Material::Solid);

/// Appends bodies and returns the index of the first.
int addBody(SceneDescription& scene, const BodyDesc& body);

JointDesc makePin(int bodyA, int bodyB, Vec2d pin);
JointDesc makeRod(int bodyA, int bodyB, Vec2d anchorA, Vec2d anchorB);
JointDesc makeSpring(int bodyA, int bodyB, Vec2d anchorA, Vec2d anchorB, double restLength,
                     double stiffness, double damping);
void addJoint(SceneDescription& scene, const JointDesc& joint);

}  // namespace bench
