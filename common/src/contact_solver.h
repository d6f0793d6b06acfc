#pragma once
// Soft contact constraints (Box2D v3's "soft step"): normal, friction and
// rolling resistance rows solved with sub-stepping and relaxation.

#include <span>

#include "contact_constraint.h"
#include "world_data.h"

namespace impulse {

/// Fills a constraint from a touching contact (velocities read from the
/// world's solver states), its touching points starting from
/// `startImpulse` more (SupportPass::startImpulses).
void prepareContact(const WorldData& world, const ConstraintRef& ref, const ContactSoftness& softness,
                    Real startImpulse, ContactConstraint& constraint);

/// Applies the accumulated impulses to the velocities.
void warmStartContacts(const ContactSolverContext& context);

/// One Gauss-Seidel pass. With useBias the rows also push overlap out
/// (softly, no faster than the load needs); without it they only remove
/// approach velocity (relaxation).
void solveContacts(const ContactSolverContext& context, bool useBias);

/// The soft push may reach the speed that carries last step's load with a
/// margin, and no more: pushing harder turns overlap into velocity, and
/// along a chain of contacts such pushes add up (a packed crowd flew apart at
/// 22 m/s). Deeper overlap is pushed out by the push pass instead.
inline constexpr Real kLoadPushMargin = Real(1.5);
inline constexpr Real kMinPushSpeed = Real(0.02);

/// Overlap deeper than a contact's load explains (bodies created or
/// pushed into each other) beyond this is pushed out by the push pass.
inline constexpr Real kIntrusionSlop = Real(0.005);

/// How a wedge's contact holds (kHold): none while its load is under
/// `fromWeights` times the lighter body's weight, rising to `share` of it at
/// `fullWeights`.
struct HoldRamp {
  Real fromWeights;
  Real fullWeights;
  Real share;
};

/// A soft contact carries its load at an overlap (its give), and where
/// bodies wedge against each other the give adds up: the stones of an arch
/// sink into their joints, its haunches spread, and the keystone drops many
/// times what one joint gives (Solver2D's arch: 9.5 cm; holding, 4.9 cm).
/// A contact that leans more than 25 degrees off level, between two moving
/// bodies without joints, and not intruding, holds a share of last step's
/// load with no overlap (its push is raised by the speed that carries that
/// share): none under two weights of the lighter body, rising to 0.8 at
/// six, so that a wedge's joint gives a fifth as much. Piles' and stacks'
/// contacts carry less than that sideways and are left as they are; without
/// gravity no contact holds. The share rises with the load rather than
/// switching on at a threshold: a load that hovers there (an arch's lower
/// joints) turned the hold on and off, and the arch shook. That push is no
/// faster than gravity accelerates a body in kHoldSpeedSubSteps sub-steps
/// (an arch's is slower): a heap's contacts, loaded by impacts rather than
/// weights, would otherwise throw its bodies (a thousand random bodies
/// spawned overlapping in a box). A jointed body's loads are not weights it
/// carries (a ragdoll's limbs), and its contacts never hold.
inline constexpr HoldRamp kHold{Real(2), Real(6), Real(0.8)};
inline constexpr Real kHoldSpeedSubSteps = Real(2);

/// A contact of a body that hangs on steep contacts (an arch's stones from
/// its fourth to the keystone, which the support pass reaches over steep
/// joints only, ConstraintRef::hangs) holds from half a weight, fully (0.95)
/// from two. Such a stone is held up by its joints' friction and thrust
/// alone, and the thrust builds only as the joints take load: on the shared
/// ramp a joint held nothing until it carried two weights, the arch's top
/// fell almost freely while its thrust built, the stones beside the
/// keystone slid 13 mm down their joints, and the joints settled 1.5 to 3.6
/// mm into each other (Solver2D's arch: 2.3 cm, 0.62 cm after the first
/// second; so held, 1.3 cm and 0.18 cm, its joints 0.25 to 0.6 mm). The
/// shared ramp lowered as far for every wedge moved other scenes' pieces
/// further: a card house settled 2.5 mm (1.8), the boxes of Solver2D's
/// overlap recovery flew at 4.6 cm/s (2.5), a pyramid under heavy boxes
/// ended 2.4 cm from its place (2.1).
inline constexpr HoldRamp kHangingHold{Real(0.5), Real(2), Real(0.95)};

/// Whether a contact may hold as a wedge's: off level, between two moving
/// bodies without joints (the rest, load and overlap, is per point).
inline bool mayHoldAsWedge(const ConstraintRef& ref) {
  return ref.facing == 0 && !ref.jointed() && ref.stateA != 0 && ref.stateB != 0;
}

/// The soft push's cap of a point: the speed that carries its load, with
/// kLoadPushMargin and at least kMinPushSpeed; held to exactly that speed
/// (heldToLoad) where two moving bodies overlap deeper than their load
/// explains, which the push pass moves out through positions alone. Pushed
/// faster, a packed crowd's intrusions made velocity one relax pass could
/// not take back (each contact's floor push adds up along its chains), and
/// the load that push produced raised the next step's cap by the margin
/// again, until the crowd's whole overlap was a loaded spring whose
/// rearrangements threw circles at 1.2 m/s. A body pressed into a static one
/// keeps the margin: nothing pushes back along a chain there, and overlap
/// recovery needs it.
Real pushCapForLoad(Real biasRate, Real loadOverlap, bool heldToLoad, Real maxPushSpeed);

/// WideContactSet::pushZone, whose intruding bodies the caller has marked
/// kIntrudingBody: marks each ring of bodies the touching contacts `refs`
/// join to the one inside it one less, down to kNearIntrusion, and jointed
/// bodies as their partners. The static dummy is never marked.
void markNearIntrusions(const WorldData& world, std::span<const ConstraintRef> refs, WideContactSet& set);

/// True when a point of the prepared constraint overlaps deeper than its
/// load explains by more than kIntrusionSlop.
bool hasIntrusion(const ContactConstraint& constraint, const Manifold& manifold);

/// Split-impulse push of one constraint: moves overlapping bodies apart
/// through the velocities in the states, which the caller has swapped for
/// zeroed pseudo velocities; only positions keep the result, so pushing adds
/// no energy.
void pushOverlap(const ContactSolverContext& context, ContactConstraint& constraint);

/// Bounces: adds restitution to contacts that were approaching fast enough.
void applyRestitution(const ContactSolverContext& context);

/// Writes the impulses back into the manifolds for next step's warm start.
void storeImpulses(std::span<const ContactConstraint> constraints, WorldData& world);

}  // namespace impulse
