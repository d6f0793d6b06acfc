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

#include <string>
#include <vector>

#include "impulse/material.h"

namespace bench {

struct Vec2d {
  double x = 0;
  double y = 0;
};

enum class ShapeKind { Circle, Polygon };

struct ShapeDesc {
  ShapeKind kind = ShapeKind::Circle;
  double radius = 0;            ///< circles
  std::vector<Vec2d> vertices;  ///< polygons: anticlockwise, centroid at the origin

  static ShapeDesc circle(double radius);
  static ShapeDesc box(double halfWidth, double halfHeight);
  double area() const;
  /// Largest distance from the centroid to the shape.
  double extent() const;
};

struct BodyDesc {
  ShapeDesc shape;
  bool isStatic = false;
  Vec2d position;  ///< centroid
  double angle = 0;
  Vec2d velocity;
  double angularVelocity = 0;
  impulse::Material material = impulse::Material::Solid;
  /// Derived from material by makeBody(); a scene may set its own values
  /// (Impulse then applies them as a per-body MaterialOverride).
  double density = 0;
  double friction = 0;  ///< peers' single coefficient (Impulse's static one)
  double restitution = 0;
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
};

struct SceneDescription {
  Vec2d gravity{0, -9.81};
  bool allowSleep = false;
  std::vector<BodyDesc> bodies;
  std::vector<JointDesc> joints;

  /// True when every body has the same friction and restitution, so an
  /// engine's own mixing rule already yields the mean.
  bool uniformCoefficients() const;
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
