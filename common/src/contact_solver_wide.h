#pragma once
// The contact solver four constraints at a time. Constraints are coloured so
// that no two of one colour share a dynamic body; each colour is cut into
// bundles of four, whose lanes can then be solved together without one lane
// overwriting another's body. Constraints that find no free colour stay in
// an overflow list solved one by one (contact_solver.h).

#include "contact_solver.h"

namespace impulse {

/// Colours `constraints` and packs them into bundles plus overflow.
void buildWideContacts(std::span<const ContactConstraint> constraints, std::size_t stateCount,
                       WideContactSet& set);

void warmStartWide(const ContactSolverContext& context, WideContactSet& set);
void solveWide(const ContactSolverContext& context, WideContactSet& set, bool useBias);
/// The push pass (pushOverlap) four constraints at a time.
void pushWide(const ContactSolverContext& context, WideContactSet& set);
void restitutionWide(const ContactSolverContext& context, WideContactSet& set);

/// Copies the lanes' impulses back into the scalar constraints.
void unpackWideContacts(const WideContactSet& set, std::span<ContactConstraint> constraints);

}  // namespace impulse
