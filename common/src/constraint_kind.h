#pragma once
// The seam between the solver and what it solves. Each kind of constraint
// (contacts today, joints tomorrow) implements these stages; the solver runs
// every stage for every kind in turn (solver.cpp), so a new kind adds one
// class and one entry in the solver's list, not a new loop.

#include <span>

#include "graph_coloring.h"
#include "solver_data.h"
#include "task_runner.h"

namespace impulse {

struct WorldData;
struct SolverPasses;

/// What one step's solve gives every kind.
struct SolveStep {
  Real h = 0;  ///< sub-step length (s)
  int subSteps = 1;
};

/// One sub-step: the awake bodies' states ([0] is the static dummy, which
/// stands for every static or sleeping body) and the sub-step's number.
struct SubStep {
  std::span<SolverState> states;
  int index = 0;
  /// Runs a colour's constraints side by side (they share no awake body).
  const TaskRunner* tasks = nullptr;
};

class ConstraintKind {
 public:
  virtual ~ConstraintKind() = default;

  /// Once per step, after the solver states are loaded: gathers this kind's
  /// constraints on awake bodies, takes their colours from `coloring` (which
  /// every kind shares) and prepares them. Returns whether any of them needs
  /// the push pass this step.
  virtual bool prepare(const WorldData& world, const SolveStep& step, GraphColoring& coloring) = 0;
  /// After prepare: whether this step has none of this kind's constraints.
  /// The solver then skips the kind's passes, which would only walk its
  /// empty colours.
  virtual bool empty() const = 0;
  /// Applies last step's impulses to the velocities.
  virtual void warmStart(const SubStep& sub) = 0;
  /// One pass that removes velocity error and softly corrects position error.
  virtual void solve(const SubStep& sub) = 0;
  /// After every kind's solve pass: a direct pass that leaves this kind's
  /// rows exactly satisfied where Gauss-Seidel cannot (joint trees).
  virtual void solveExact(const SubStep&) {}
  /// One pass without position correction: takes out the velocity the
  /// correction added, once the positions have moved.
  virtual void relax(const SubStep& sub) = 0;
  /// After every kind's relax: the direct pass again, without position
  /// correction, so the contacts' relax does not have the last word over
  /// rows that must hold exactly (a ragdoll landing: the contacts stopped
  /// its shins and its thighs went on, the knees opened 0.29 m).
  virtual void relaxExact(const SubStep&) {}
  /// Split impulse: moves bodies out of position error through the states'
  /// velocities, which the solver has swapped for zeroed pseudo velocities.
  /// Runs only in steps where some kind's prepare asked for it.
  virtual void push(const SubStep&) {}
  /// After every kind's push: the exact pass on the pseudo velocities, so a
  /// rigid joint carries one body's push out of an overlap to the other.
  /// The bodies have not moved since this sub-step's solveExact.
  virtual void pushExact(const SubStep&) {}
  /// Once per step, after the sub-steps: bounces.
  virtual void restitution(const SubStep&) {}
  /// Keeps the impulses for next step's warm start.
  virtual void store(WorldData& world) = 0;
  /// Adds this step's constraints, and how many of them each optional pass
  /// runs on, to the step's report.
  virtual void countPasses(SolverPasses& passes) const = 0;
};

}  // namespace impulse
