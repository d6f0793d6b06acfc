#include "joint_constraints.h"

#include <algorithm>
#include <array>

#include "contact_solver_wide.h"
#include "counting_sort.h"
#include "world_data.h"

namespace impulse {

namespace {

// Blocks of PinGeometry::kLanes lanes that hold `rows` rows.
std::int32_t blocksFor(std::int32_t rows) { return (rows + PinGeometry::kLanes - 1) / PinGeometry::kLanes; }

// Marks, per block of a list laid out colour by colour from `starts`, the
// blocks of the colour's first leadingRows(color) rows (which take another
// pass or softness).
template <class LeadingRows>
void markLeadingBlocks(const ColorStarts& starts, int colours, std::vector<std::uint8_t>& marks,
                       LeadingRows&& leadingRows) {
  marks.assign(std::size_t(starts[std::size_t(colours)]), 0);
  for (int color = 0; color < colours; ++color) {
    const auto first = marks.begin() + starts[std::size_t(color)];
    std::fill(first, first + blocksFor(leadingRows(color)), 1);
  }
}

// How many of `part` (a run of one colour's blocks of `all`) lead it marked:
// a colour's marked blocks come first.
template <class Block>
std::size_t leadingMarked(const std::vector<std::uint8_t>& marks, const std::vector<Block>& all,
                          std::span<Block> part) {
  const auto first = std::size_t(part.data() - all.data());
  std::size_t marked = 0;
  while (marked < part.size() && marks[first + marked] != 0) ++marked;
  return marked;
}

// Rigid rows are as stiff as the soft step allows (a quarter of the sub-step
// rate, beyond which it rings): 60 Hz at the default 4 sub-steps of 60 Hz,
// Box2D v3's figure, and stiffer with more sub-steps, which is what lets a
// heavy load on light links stretch them less (joint_accuracy_test).
constexpr Real kJointDampingRatio = 2;
// The plain pins of a group with a loop (a grid, a linkage) are stiffer:
// the tree pass never solves them, and a soft pin gives way by its load over
// its own effective mass times its stiffness squared, so in Solver2D's
// 30 x 30 grid the pin beside a fixed circle that holds a flap of 360 circles
// opened 11.8 cm at the quarter rate. At a third of the sub-step rate,
// damped at a ratio of 1, it opens 8.8 cm, v3's 100 x 100 grid 0.42 m
// (0.60) and a four-bar linkage 6.5 mm (9.6); a higher ratio damps the
// swing of a linkage's error more slowly (at 5: 17 mm). From 0.4 of the rate
// v3's grid stirs itself apart (2.6 m).
constexpr Real kLoopPinRate = Real(0.33);
constexpr Real kLoopPinDampingRatio = 1;

// Joint rows per range of a colour run side by side: a row costs tens of
// nanoseconds, a hand-off to a thread about a microsecond; a block of eight
// (a ragdoll's joints) a few hundred nanoseconds.
constexpr std::int32_t kJointRowsPerRange = 32;
constexpr std::int32_t kJointBlocksPerRange = 4;
// Joints per range when making their rows side by side (a row reads its
// joint, its bodies and their contact lists: a few hundred nanoseconds).
constexpr std::int32_t kJointsPerMakeRange = 64;

struct Side {
  std::int32_t state = 0;
  Real invMass = 0;
  Real invInertia = 0;
  Vec2 center = Vec2::Zero();
  Rot q;
};

// A missing or static body, or one asleep, is the static dummy state 0:
// the world frame for a missing one.
Side sideOf(const WorldData& world, std::int32_t slot) {
  if (slot == kNullIndex) return {};
  const Body& body = world.bodies[slot];
  Side side{0, 0, 0, body.transform.p, body.transform.q};
  if (body.awake)
    side = {body.solverIndex, body.invMass, body.invInertia, body.transform.p, body.transform.q};
  return side;
}

// A mouse joint pulls towards a world point, whatever B is.
bool pullsToWorldPoint(const Joint& joint) { return std::holds_alternative<MouseJointSettings>(joint.settings); }

// B's side of the joint's row.
Side sideBOf(const WorldData& world, const Joint& joint) {
  return pullsToWorldPoint(joint) ? Side{} : sideOf(world, joint.edges.bodyB);
}

bool hasAwakeBody(const WorldData& world, const Joint& joint) {
  auto awake = [&](std::int32_t slot) { return slot != kNullIndex && world.bodies[slot].awake; };
  return joint.alive && (awake(joint.edges.bodyA) || awake(joint.edges.bodyB));
}

// A revolute joint with no limit, motor or spring (JointRow::plainPin).
bool isPlainPin(const Joint& joint) {
  return std::holds_alternative<RevoluteJointSettings>(joint.settings) && !hasSoftRows(joint.settings);
}

JointRow makeRow(const WorldData& world, const Joint& joint, std::int32_t index) {
  const Side a = sideOf(world, joint.edges.bodyA);
  const bool mouse = pullsToWorldPoint(joint);
  const Side b = sideBOf(world, joint);
  JointRow row;
  row.joint = &joint;
  row.index = index;
  row.stateA = a.state;
  row.stateB = b.state;
  row.invMassA = a.invMass;
  row.invInertiaA = a.invInertia;
  row.invMassB = b.invMass;
  row.invInertiaB = b.invInertia;
  row.anchorA = a.q.apply(joint.localAnchorA);
  row.anchorB = mouse ? joint.target : b.q.apply(joint.localAnchorB);
  row.deltaCenter = b.center - a.center;
  row.softRows = hasSoftRows(joint.settings);
  row.plainPin = isPlainPin(joint);
  // An awake body on a touching contact (the contacts' marks: a static or
  // sleeping one, state 0, counts for nothing).
  row.touches = world.contactConstraints.touches(a.state) || world.contactConstraints.touches(b.state);
  // The angle's atan2 is a frame's costliest part, and a pin never reads it.
  row.deltaAngle = row.plainPin ? Real(0) : jointAngle(joint, a.q, b.q);
  row.axis = a.q.apply(joint.localAxisA);
  row.lastAxis = row.axis;
  if (world.settings.enableWarmStarting) row.impulses = joint.impulses;
  // The count is the rows themselves at the step's start: one definition.
  RigidRows scratch;
  row.rigidRowCount = rigidRows(row, SolverState{}, SolverState{}, scratch);
  return row;
}

// A mouse joint whose anchor is further than this from its target is still
// pulling, though a wall may hold the body still: the body must not sleep.
// (isAwayFromTarget takes a mouse joint's row.)
constexpr Real kMouseAtTarget = Real(0.01);

bool isAwayFromTarget(const JointRow& row) {
  // At the step's start, as the rows measure it (B, the world, centred at the origin).
  const Vec2 gap = row.deltaCenter + row.anchorB - row.anchorA;
  return gap.squaredNorm() > kMouseAtTarget * kMouseAtTarget;
}

}  // namespace

JointPass jointPassAt(Real h) {
  const Real hertz = Real(0.25) / h;
  return {h, 1 / h, makeSoftness(hertz, kJointDampingRatio, h), makeSoftness(kLoopPinRate / h, kLoopPinDampingRatio, h),
          true};
}

bool JointConstraints::prepare(const WorldData& world, const SolveStep& step,
                               GraphColoring& coloring) {
  if (world.liveJoints == 0) {
    // No rows: the solver skips every pass (empty()), which leaves the rest
    // unread.
    rows_.clear();
    tree_.clear();
    return false;
  }
  colorStarts_ = {};
  pullingRows_.clear();
  pinBlocks_.clear();
  revoluteBlocks_.clear();
  treePinBlocks_.clear();
  rowsBesidePins_.clear();
  pinBlockStarts_ = {};
  revoluteBlockStarts_ = {};
  treePinBlockStarts_ = {};
  besideStarts_ = {};
  // What the colouring needs of each joint, side by side; then the colours
  // one by one (a colour depends on the joints before it), from those
  // alone; then the rows, side by side.
  findJointSides(world);
  jointOf_.clear();
  colorOf_.clear();
  for (std::size_t index = 0; index < jointSides_.size(); ++index) {
    const JointSides& sides = jointSides_[index];
    if (!sides.solved) continue;
    if (sides.pulls) pullingRows_.push_back(static_cast<std::int32_t>(jointOf_.size()));
    jointOf_.push_back(static_cast<std::int32_t>(index));
    colorOf_.push_back(coloring.take(sides.stateA, sides.stateB));
  }
  // Solved in colour order, so a colour's joints could run side by side.
  // Each row is made in the joints' order and written to its place there:
  // joints read in colour order instead jump across the list, a miss a row.
  colorStarts_ = sortByColor(colorOf_, order_);
  placesInOrder(order_, rankOf_);
  for (std::int32_t& row : pullingRows_) row = rankOf_[std::size_t(row)];
  rows_.resize(jointOf_.size());
  world.tasks.forRanges(std::int32_t(jointOf_.size()), kJointsPerMakeRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t i = begin; i < end; ++i) {
      const std::int32_t index = jointOf_[std::size_t(i)];
      rows_[std::size_t(rankOf_[std::size_t(i)])] = makeRow(world, world.joints[std::size_t(index)], index);
    }
  });
  pass_ = jointPassAt(step.h);
  tree_.order(rows_, world.solverStates.size(), pass_.rigid, world.tasks);
  placeBlocks(world.tasks);
  fillBlocks(world.tasks);
  kernels_ = &wideContactKernels(world.settings.simdWidth);
  return false;
}

void JointConstraints::findJointSides(const WorldData& world) {
  jointSides_.resize(world.joints.size());
  world.tasks.forRanges(std::int32_t(world.joints.size()), kJointsPerMakeRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t index = begin; index < end; ++index) {
      const Joint& joint = world.joints[std::size_t(index)];
      JointSides& sides = jointSides_[std::size_t(index)];
      sides.solved = hasAwakeBody(world, joint);
      if (!sides.solved) continue;
      sides.stateA = sideOf(world, joint.edges.bodyA).state;
      sides.stateB = sideBOf(world, joint).state;
      sides.pulls = pullsToWorldPoint(joint);
    }
  });
}

// Each colour's plain pins, its revolute joints with turning rows, and its
// plain pins that the tree pass solves get a place in blocks of their own
// kind (block times eight plus lane, by rank); the colour's other rows are
// listed beside them. A colour's rows share no awake body, so solving its
// blocks first changes nothing. The tree pass reads and writes its pins'
// impulses in the rows during the step, which a pin block would hold: its
// pins take blocks that leave them there (as a revolute block does).
void JointConstraints::placeBlocks(const TaskRunner& tasks) {
  // Overflow rows stay out of blocks; the coloured rows are all written
  // below, side by side, a colour to a range: first each row's kind and
  // each colour's counts, then (from where each colour starts, summed in
  // order) each row's lane or place beside the blocks.
  placeOf_.resize(order_.size());
  std::fill(placeOf_.begin() + colorStarts_[GraphColoring::kOverflow], placeOf_.end(), BlockPlace{});
  const int colours = coloursTaken(colorStarts_);
  // Colours per range: enough for kJointsPerMakeRange rows, so that a few
  // dozen joints are placed without a hand-off.
  const std::int32_t coloured = colorStarts_[std::size_t(colours)];
  const std::int32_t coloursPerRange =
      std::max<std::int32_t>(1, colours * kJointsPerMakeRange / std::max<std::int32_t>(coloured, 1));
  std::array<ColourRows, GraphColoring::kOverflow> counts{};
  tasks.forRanges(colours, coloursPerRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t color = begin; color < end; ++color) counts[std::size_t(color)] = markRowKinds(color);
  });
  for (int color = 0; color < colours; ++color) {
    const ColourRows& rows = counts[std::size_t(color)];
    const auto next = std::size_t(color) + 1;
    pinBlockStarts_[next] =
        pinBlockStarts_[next - 1] + blocksFor(rows.loopPins) + blocksFor(rows.pins);
    revoluteBlockStarts_[next] = revoluteBlockStarts_[next - 1] + blocksFor(rows.revolutes);
    treePinBlockStarts_[next] =
        treePinBlockStarts_[next - 1] + blocksFor(rows.relaxedTreePins) + blocksFor(rows.exactTreePins);
    besideStarts_[next] = besideStarts_[next - 1] + rows.beside;
  }
  rowsBesidePins_.resize(std::size_t(besideStarts_[std::size_t(colours)]));
  tasks.forRanges(colours, coloursPerRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t color = begin; color < end; ++color)
      placeRowsOfColour(color, counts[std::size_t(color)]);
  });
  pinBlocks_.resize(std::size_t(pinBlockStarts_[std::size_t(colours)]));
  markLeadingBlocks(pinBlockStarts_, colours, pinBlockInLoop_,
                    [&](int color) { return counts[std::size_t(color)].loopPins; });
  revoluteBlocks_.resize(std::size_t(revoluteBlockStarts_[std::size_t(colours)]));
  treePinBlocks_.resize(std::size_t(treePinBlockStarts_[std::size_t(colours)]));
  markLeadingBlocks(treePinBlockStarts_, colours, treePinBlockRelaxed_,
                    [&](int color) { return counts[std::size_t(color)].relaxedTreePins; });
}

// Each row of the colour marked with the kind of block it goes in (None:
// beside the blocks), and the colour's counts of each.
JointConstraints::ColourRows JointConstraints::markRowKinds(std::int32_t color) {
  ColourRows counts;
  for (std::int32_t r = colorStarts_[std::size_t(color)]; r < colorStarts_[std::size_t(color) + 1]; ++r) {
    const JointRow& row = rows_[std::size_t(r)];
    BlockKind kind = BlockKind::None;
    if (row.plainPin && !row.inTree) {
      kind = BlockKind::Pin;
      ++(row.pinInLoop ? counts.loopPins : counts.pins);
    } else if (row.plainPin) {
      kind = BlockKind::TreePin;
      ++(row.relaxedExactly ? counts.exactTreePins : counts.relaxedTreePins);
    } else if (isTurningRevolute(row)) {
      kind = BlockKind::Revolute;
      ++counts.revolutes;
    } else {
      ++counts.beside;
    }
    placeOf_[std::size_t(r)] = {kind, 0};
  }
  return counts;
}

// Each blocked row of the colour its lane (block times eight plus lane, by
// rank within its kind, pins in loops and tree pins relaxed first), each
// other row its place beside the blocks.
void JointConstraints::placeRowsOfColour(std::int32_t color, const ColourRows& rows) {
  std::int32_t loopPin = pinBlockStarts_[std::size_t(color)] * PinGeometry::kLanes;
  std::int32_t pin =
      (pinBlockStarts_[std::size_t(color)] + blocksFor(rows.loopPins)) * PinGeometry::kLanes;
  std::int32_t revolute = revoluteBlockStarts_[std::size_t(color)] * PinGeometry::kLanes;
  std::int32_t relaxedTreePin = treePinBlockStarts_[std::size_t(color)] * PinGeometry::kLanes;
  std::int32_t exactTreePin =
      (treePinBlockStarts_[std::size_t(color)] + blocksFor(rows.relaxedTreePins)) * PinGeometry::kLanes;
  std::int32_t beside = besideStarts_[std::size_t(color)];
  for (std::int32_t r = colorStarts_[std::size_t(color)]; r < colorStarts_[std::size_t(color) + 1]; ++r) {
    BlockPlace& place = placeOf_[std::size_t(r)];
    if (place.kind == BlockKind::Pin)
      place.lane = rows_[std::size_t(r)].pinInLoop ? loopPin++ : pin++;
    if (place.kind == BlockKind::Revolute) place.lane = revolute++;
    if (place.kind == BlockKind::TreePin)
      place.lane = rows_[std::size_t(r)].relaxedExactly ? exactTreePin++ : relaxedTreePin++;
    if (place.kind == BlockKind::None) rowsBesidePins_[std::size_t(beside++)] = r;
  }
}

// Copies each blocked joint into its lane, side by side. The lanes no joint
// takes keep their empty defaults: the blocks are made afresh each step
// (prepare clears them, placeBlocks sizes them).
void JointConstraints::fillBlocks(const TaskRunner& tasks) {
  tasks.forRanges(
      std::int32_t(rows_.size()), kJointsPerMakeRange, [&](std::int32_t begin, std::int32_t end) {
        for (std::int32_t r = begin; r < end; ++r) {
          const BlockPlace place = placeOf_[std::size_t(r)];
          const auto block = std::size_t(place.lane / PinGeometry::kLanes);
          const int lane = place.lane % PinGeometry::kLanes;
          if (place.kind == BlockKind::Pin)
            placePin(pinBlocks_[block], lane, rows_[std::size_t(r)], r);
          if (place.kind == BlockKind::Revolute)
            placeRevolute(revoluteBlocks_[block], lane, rows_[std::size_t(r)], r, pass_.h);
          if (place.kind == BlockKind::TreePin)
            placeGeometry(treePinBlocks_[block].pin, lane, rows_[std::size_t(r)], r);
        }
      });
}

// Colour by colour: visitPins(blocks) on the colour's pin blocks,
// visitRevolutes(blocks) on its revolute blocks, visitTreePins(blocks) on
// its tree pin blocks and visit(row, stateA, stateB) on its other rows, all
// side by side; then the rows that found no
// colour one by one. Rows on a static or sleeping body write a copy of the
// dummy state 0, never the state itself, which two threads would otherwise
// write together (it stays zero: such a body has no inverse mass); the
// block kernels' scatter does the same.
template <class Visit, class VisitPins, class VisitRevolutes, class VisitTreePins>
void JointConstraints::forEachRowByColor(const SubStep& sub, Visit&& visit, VisitPins&& visitPins,
                                         VisitRevolutes&& visitRevolutes, VisitTreePins&& visitTreePins) {
  auto visitRow = [&](std::int32_t r, SolverState& sink) {
    JointRow& row = rows_[std::size_t(r)];
    visit(row, row.stateA != 0 ? sub.states[row.stateA] : sink, row.stateB != 0 ? sub.states[row.stateB] : sink);
  };
  const int colours = coloursTaken(colorStarts_);
  for (int color = 0; color < colours; ++color) {
    const std::int32_t firstPins = pinBlockStarts_[std::size_t(color)];
    const std::int32_t pins = pinBlockStarts_[std::size_t(color) + 1] - firstPins;
    const std::int32_t firstRevolutes = revoluteBlockStarts_[std::size_t(color)];
    const std::int32_t revolutes = pins + revoluteBlockStarts_[std::size_t(color) + 1] - firstRevolutes;
    const std::int32_t firstTreePins = treePinBlockStarts_[std::size_t(color)];
    const std::int32_t blocks = revolutes + treePinBlockStarts_[std::size_t(color) + 1] - firstTreePins;
    const std::int32_t firstBeside = besideStarts_[std::size_t(color)];
    const std::int32_t beside = besideStarts_[std::size_t(color) + 1] - firstBeside;
    // Items [0, pins) are pin blocks, [pins, revolutes) revolute blocks,
    // [revolutes, blocks) tree pin blocks, the rest the rows beside them.
    const std::int32_t perRange = blocks > 0 ? kJointBlocksPerRange : kJointRowsPerRange;
    sub.tasks->forRanges(
        blocks + beside, perRange, [&](std::int32_t begin, std::int32_t end) {
          // The range's share of items [from, to), the colour's blocks of
          // `list` from `first` on, visited as one span.
          const auto visitShare = [&](auto& list, std::int32_t first, std::int32_t from, std::int32_t to,
                                      auto&& visitBlocks) {
            const std::int32_t shareBegin = std::max(begin, from);
            const std::int32_t shareEnd = std::min(end, to);
            if (shareBegin < shareEnd) {
              visitBlocks(std::span(list).subspan(std::size_t(first + shareBegin - from),
                                                  std::size_t(shareEnd - shareBegin)));
            }
          };
          visitShare(pinBlocks_, firstPins, 0, pins, visitPins);
          visitShare(revoluteBlocks_, firstRevolutes, pins, revolutes, visitRevolutes);
          visitShare(treePinBlocks_, firstTreePins, revolutes, blocks, visitTreePins);
          SolverState sink = sub.states[0];
          for (std::int32_t item = std::max(begin, blocks); item < end; ++item) {
            visitRow(rowsBesidePins_[std::size_t(firstBeside + item - blocks)], sink);
          }
        });
  }
  SolverState sink = sub.states[0];
  for (std::int32_t r = colorStarts_[GraphColoring::kOverflow]; r < colorStarts_[GraphColoring::kOverflow + 1]; ++r) {
    visitRow(r, sink);
  }
}

void JointConstraints::warmStart(const SubStep& sub) {
  forEachRowByColor(
      sub, [](JointRow& row, SolverState& a, SolverState& b) { warmStartJoint(row, a, b); },
      [&](std::span<PinBlock> blocks) { kernels_->warmStartPins(sub.states, blocks); },
      [&](std::span<RevoluteBlock> blocks) {
        kernels_->warmStartRevolutes(sub.states, blocks, rows_);
      },
      [&](std::span<TreePinBlock> blocks) { kernels_->warmStartTreePins(sub.states, blocks, rows_); });
}

void JointConstraints::run(const SubStep& sub, bool useBias) {
  JointPass pass = pass_;
  pass.useBias = useBias;
  forEachRowByColor(
      sub, [&](JointRow& row, SolverState& a, SolverState& b) { solveJoint(row, a, b, pass); },
      [&](std::span<PinBlock> blocks) { solvePinBlocks(sub, blocks, pass); },
      [&](std::span<RevoluteBlock> blocks) {
        kernels_->solveRevolutes(sub.states, blocks, rows_, pass);
      },
      [&](std::span<TreePinBlock> blocks) {
        if (!useBias) relaxTreePinBlocks(sub, blocks, pass);
      });
}

// Pin blocks of one colour at each block's softness: those of pins in loops
// come first.
void JointConstraints::solvePinBlocks(const SubStep& sub, std::span<PinBlock> blocks,
                                      const JointPass& pass) {
  const std::size_t loopBlocks = leadingMarked(pinBlockInLoop_, pinBlocks_, blocks);
  if (loopBlocks > 0)
    kernels_->solvePins(sub.states, blocks.first(loopBlocks), loopPinSoftness(pass));
  if (loopBlocks < blocks.size())
    kernels_->solvePins(sub.states, blocks.subspan(loopBlocks), rowSoftness(pass));
}

// Tree pin blocks of one colour in the relax: only those the tree pass does
// not relax exactly, which come first. The biased pass leaves them all to
// the tree pass.
void JointConstraints::relaxTreePinBlocks(const SubStep& sub, std::span<TreePinBlock> blocks,
                                          const JointPass& pass) {
  const std::size_t relaxed = leadingMarked(treePinBlockRelaxed_, treePinBlocks_, blocks);
  if (relaxed > 0) kernels_->solveTreePins(sub.states, blocks.first(relaxed), rows_, rowSoftness(pass));
}

void JointConstraints::solve(const SubStep& sub) { run(sub, true); }
void JointConstraints::solveExact(const SubStep& sub) {
  tree_.solve(rows_, sub.states, pass_.h, *sub.tasks);
}
void JointConstraints::relaxExact(const SubStep& sub) { tree_.relax(rows_, sub.states, *sub.tasks); }
void JointConstraints::pushExact(const SubStep& sub) {
  tree_.push(sub.states, *sub.tasks);
}
void JointConstraints::relax(const SubStep& sub) { run(sub, false); }

void JointConstraints::countPasses(SolverPasses& passes) const {
  passes.joints += static_cast<int>(rows_.size());
  passes.treeJoints += tree_.jointCount();
}

void JointConstraints::store(WorldData& world) {
  // Each block's lanes write their own rows: side by side.
  world.tasks.forRanges(std::int32_t(pinBlocks_.size()), kJointRowsPerRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t k = begin; k < end; ++k) storePinImpulses(pinBlocks_[std::size_t(k)], rows_);
  });
  world.tasks.forRanges(std::int32_t(revoluteBlocks_.size()), kJointRowsPerRange, [&](std::int32_t begin, std::int32_t end) {
    for (std::int32_t k = begin; k < end; ++k) storeRevoluteImpulses(revoluteBlocks_[std::size_t(k)], rows_);
  });
  // Each row writes its own joint: side by side.
  world.tasks.forRanges(
      std::int32_t(rows_.size()), kJointRowsPerRange, [&](std::int32_t begin, std::int32_t end) {
        for (std::int32_t r = begin; r < end; ++r) {
          const JointRow& row = rows_[std::size_t(r)];
          Joint& joint = world.joints[row.index];
          joint.impulses = row.impulses;
          jointReaction(row, pass_.invH, joint.reactionForce, joint.reactionTorque);
        }
      });
  // Two mouse joints may hold one body: its wake is written one by one.
  for (std::int32_t r : pullingRows_) {
    const JointRow& row = rows_[std::size_t(r)];
    if (isAwayFromTarget(row)) world.bodies[row.joint->edges.bodyA].sleepTime = 0;
  }
}

}  // namespace impulse
