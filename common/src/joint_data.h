#pragma once
// A joint as the engine keeps it (the public face is impulse/joint.h and
// World). Threaded through its bodies' joint edge lists (edge_list.h); a
// side fixed to the world has no body (kNullIndex) and is not linked.

#include <cstdint>

#include "edge_list.h"
#include "impulse/joint.h"

namespace impulse {

struct Joint {
  EdgeLinks edges;
  JointSettings settings;
  Vec2 localAnchorA = Vec2::Zero();  ///< from A's centre, in A's frame
  Vec2 localAnchorB = Vec2::Zero();  ///< from B's centre in B's frame; world point without B
  Vec2 localAxisA = Vec2(1, 0);      ///< unit, in A's frame (prismatic, wheel)
  Real referenceAngle = 0;           ///< B's angle minus A's at creation
  Real referenceTranslation = 0;     ///< along the axis at creation
  Real referencePerpendicular = 0;   ///< across the axis at creation
  Real length = 0;                   ///< rest or maximum length (distance, rope)
  Vec2 target = Vec2::Zero();        ///< world point (mouse)
  JointImpulses impulses;
  Vec2 reactionForce = Vec2::Zero();  ///< on B, last step
  Real reactionTorque = 0;
  std::uint32_t generation = 0;
  bool alive = false;
  bool collideConnected = false;
};

}  // namespace impulse
