#pragma once
// Soft contact constraints (Box2D v3's "soft step"): normal, friction and
// rolling resistance rows solved with sub-stepping and relaxation.

#include <span>

#include "world_data.h"

namespace impulse {

/// Spring-damper softness for a constraint of stiffness `hertz` and
/// `dampingRatio`, solved with sub-step h.
Softness makeSoftness(Real hertz, Real dampingRatio, Real h);

struct ContactSolverContext {
  std::span<SolverState> states;  // [0] is the static dummy
  std::span<ContactConstraint> constraints;
  Real inverseSubStep = 0;
  Real maxPushSpeed = 0;
  Real restitutionThreshold = 0;
  /// Solve each manifold's second normal point first. Solving two points one
  /// after the other favours one side, and a tall stack leans that way; the
  /// solver alternates the order every sub-step so the favour cancels.
  bool reversePointOrder = false;
};

/// The step's contact softness: between dynamic bodies, and against static
/// ones (stiffer, so stacks are not pushed into the ground).
struct ContactSoftness {
  Softness dynamic;
  Softness statics;
};

/// Fills a constraint from a touching contact (velocities read from the
/// world's solver states).
void prepareContact(const WorldData& world, const ConstraintRef& ref, const ContactSoftness& softness,
                    ContactConstraint& constraint);

/// Applies the accumulated impulses to the velocities.
void warmStartContacts(const ContactSolverContext& context);

/// One Gauss-Seidel pass. With useBias the rows also push overlap out
/// (softly, no faster than the load needs); without it they only remove
/// approach velocity (relaxation).
void solveContacts(const ContactSolverContext& context, bool useBias);

/// Overlap deeper than a contact's load explains (bodies created or
/// pushed into each other) beyond this is pushed out by the push pass.
inline constexpr Real kIntrusionSlop = Real(0.005);

/// True when a point of the prepared constraint overlaps deeper than its
/// load explains by more than kIntrusionSlop.
bool hasIntrusion(const ContactConstraint& constraint, const Manifold& manifold);

/// Split-impulse push: moves overlapping bodies apart through the velocities
/// in the states, which the caller has swapped for zeroed pseudo velocities;
/// only positions keep the result, so pushing adds no energy.
void pushOverlap(const ContactSolverContext& context);

/// Bounces: adds restitution to contacts that were approaching fast enough.
void applyRestitution(const ContactSolverContext& context);

/// Writes the impulses back into the manifolds for next step's warm start.
void storeImpulses(std::span<const ContactConstraint> constraints, WorldData& world);

}  // namespace impulse
