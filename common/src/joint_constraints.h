#pragma once
// Joints as a constraint kind: each step takes the joints with an awake
// body, colours them in the shared colouring (before the contacts take
// theirs) and solves them soft-step style: rigid rows with the joint
// softness (stiffer for the plain pins of groups with loops), warm started;
// springs as exact-stiffness implicit rows.

#include <cstdint>
#include <span>
#include <vector>

#include "constraint_kind.h"
#include "joint_pins.h"
#include "joint_row.h"
#include "joint_tree_pass.h"

namespace impulse {

struct WideContactKernels;
class TaskRunner;

/// The joints' pass at sub-step h, with position correction: the rigid
/// rows' softness and the stiffer one of plain pins in loops.
JointPass jointPassAt(Real h);

class JointConstraints final : public ConstraintKind {
 public:
  bool prepare(const WorldData& world, const SolveStep& step, GraphColoring& coloring) override;
  bool empty() const override { return rows_.empty(); }
  void warmStart(const SubStep& sub) override;
  void solve(const SubStep& sub) override;
  void solveExact(const SubStep& sub) override;
  void relaxExact(const SubStep& sub) override;
  void pushExact(const SubStep& sub) override;
  void relax(const SubStep& sub) override;
  void store(WorldData& world) override;
  void countPasses(SolverPasses& passes) const override;

 private:
  void run(const SubStep& sub, bool useBias);
  template <class Visit, class VisitPins, class VisitRevolutes, class VisitTreePins>
  void forEachRowByColor(const SubStep& sub, Visit&& visit, VisitPins&& visitPins, VisitRevolutes&& visitRevolutes,
                         VisitTreePins&& visitTreePins);
  void findJointSides(const WorldData& world);
  /// How many of a colour's rows go in pin blocks (those of pins in loops
  /// apart), in revolute blocks, in tree pin blocks (those the tree pass
  /// relaxes exactly apart) and beside them.
  struct ColourRows {
    std::int32_t loopPins = 0;
    std::int32_t pins = 0;
    std::int32_t revolutes = 0;
    std::int32_t relaxedTreePins = 0;
    std::int32_t exactTreePins = 0;
    std::int32_t beside = 0;
  };
  void placeBlocks(const TaskRunner& tasks);
  ColourRows markRowKinds(std::int32_t color);
  void placeRowsOfColour(std::int32_t color, const ColourRows& rows);
  void solvePinBlocks(const SubStep& sub, std::span<PinBlock> blocks, const JointPass& pass);
  void relaxTreePinBlocks(const SubStep& sub, std::span<TreePinBlock> blocks, const JointPass& pass);
  void fillBlocks(const TaskRunner& tasks);

  std::vector<JointRow> rows_;
  /// Per joint slot, what the colouring reads: whether it is solved this
  /// step (an awake body), its sides' solver states, and whether it pulls.
  struct JointSides {
    std::int32_t stateA = 0;
    std::int32_t stateB = 0;
    bool solved = false;
    bool pulls = false;  ///< a mouse joint (pullingRows_)
  };
  std::vector<JointSides> jointSides_;
  /// The joints of this step's rows, in the joints' order.
  std::vector<std::int32_t> jointOf_;
  /// The rows (in colour order) of mouse joints, which keep their body awake.
  std::vector<std::int32_t> pullingRows_;
  std::vector<std::int32_t> colorOf_;
  std::vector<std::int32_t> order_;
  /// Per entry of jointOf_, its row's place in colour order.
  std::vector<std::int32_t> rankOf_;
  /// Colour c's rows are [colorStarts_[c], colorStarts_[c + 1]), overflow last.
  ColorStarts colorStarts_{};
  /// Colour c's plain pins outside the tree pass, eight to a block, are
  /// pinBlocks_[pinBlockStarts_[c], pinBlockStarts_[c + 1]), its revolute
  /// joints with turning rows likewise in revoluteBlocks_, its plain pins
  /// of the tree pass in treePinBlocks_; its other rows are
  /// rowsBesidePins_[besideStarts_[c], besideStarts_[c + 1]). A colour's
  /// pins in loops (JointRow::pinInLoop) fill its first pin blocks, marked
  /// in pinBlockInLoop_, as they take another softness; its tree pins that
  /// the relax solves (not JointRow::relaxedExactly) fill its first tree pin
  /// blocks, marked in treePinBlockRelaxed_.
  std::vector<PinBlock> pinBlocks_;
  std::vector<std::uint8_t> pinBlockInLoop_;
  std::vector<RevoluteBlock> revoluteBlocks_;
  std::vector<TreePinBlock> treePinBlocks_;
  std::vector<std::uint8_t> treePinBlockRelaxed_;
  /// Per row (by rank), the kind of block it is in and its block * 8 + lane.
  enum class BlockKind : std::uint8_t { None, Pin, Revolute, TreePin };
  struct BlockPlace {
    BlockKind kind = BlockKind::None;
    std::int32_t lane = 0;
  };
  std::vector<BlockPlace> placeOf_;
  ColorStarts pinBlockStarts_{};
  ColorStarts revoluteBlockStarts_{};
  ColorStarts treePinBlockStarts_{};
  std::vector<std::int32_t> rowsBesidePins_;
  ColorStarts besideStarts_{};
  const WideContactKernels* kernels_ = nullptr;
  JointPass pass_;
  JointTreePass tree_;
};

}  // namespace impulse
