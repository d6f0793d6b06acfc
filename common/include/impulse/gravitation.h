#pragma once
/// Newton's gravitation between bodies as a force field: every pair pulls
/// with G m1 m2 / r^2. Static bodies pull but do not move; sleeping bodies
/// pull and wake when something moves them. Small worlds take the exact
/// pairwise sum; larger ones a Barnes-Hut tree whose error is bounded (see
/// PullTree).

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "impulse/field.h"

namespace impulse {

/// A body as gravitation sees it. Two masses closer than the sum of their
/// reaches (their extents) pull as if they were that far apart: overlapping
/// bodies get a bounded pull, bodies apart get Newton's.
struct PointMass {
  Vec2d position = Vec2d::Zero();
  double mass = 0;
  double reach = 0;
  Vec2d velocity = Vec2d::Zero();
};

/// A body's acceleration and how fast it changes (its time derivative).
struct Pull {
  Vec2d acceleration = Vec2d::Zero();
  Vec2d change = Vec2d::Zero();
};

/// Pull at masses[target] from masses[source] per unit G, its change taken
/// as both move on at their velocities.
Pull pullPerUnitG(const PointMass& target, const PointMass& source);

/// Exact pairwise sum: pulls[i] for i < pulls.size() (the moving masses
/// come first in `masses`) from every other mass. O(n^2).
void exactPull(std::span<const PointMass> masses, double constant, std::span<Pull> pulls);

/// Barnes-Hut quadtree over point masses. A cell whose masses lie within b
/// of its centre of mass, seen from distance d, is taken as one mass at its
/// centre of mass when b < theta * d (and it is clear of the target's
/// reach). The dipole term then vanishes and Taylor's remainder with the
/// third derivative of 1/r (norm 6/r^4) bounds the error of that cell's pull
/// by 3 G sum(m |x - com|^2) / (d - b)^4; a body's error is at most the sum
/// over the cells taken whole, which pull() can report.
class PullTree {
 public:
  explicit PullTree(double theta) : theta_(theta) {}
  void build(std::span<const PointMass> masses);
  /// Pull on masses[target] (per unit G; a cell taken whole moves at its
  /// centre of mass's velocity); adds this answer's error bound on the
  /// acceleration (per unit G) to *bound when given.
  Pull pull(std::size_t target, double* bound = nullptr) const;

 private:
  struct Cell {
    Vec2d lower, upper;
    Vec2d centerOfMass = Vec2d::Zero();
    Vec2d velocity = Vec2d::Zero();  ///< of the centre of mass
    double mass = 0;
    double spread = 0;       ///< sum of m |x - com|^2
    double radius = 0;       ///< b: no mass further than this from the com
    double maxReach = 0;
    int children[4] = {-1, -1, -1, -1};  ///< quarters; -1 where empty or in a leaf
    int begin = 0, end = 0;               ///< the cell's masses in order_
    bool isLeaf() const { return children[0] < 0 && children[1] < 0 && children[2] < 0 && children[3] < 0; }
  };
  int buildCell(Vec2d lower, Vec2d upper, int begin, int end, int depth);
  void summarise(Cell& cell) const;

  double theta_;
  std::span<const PointMass> masses_;
  std::vector<int> order_;
  std::vector<Cell> cells_;
  mutable std::vector<int> stack_;
};

/// Gravitation with constant G between every pair of bodies.
class Gravitation : public ForceField {
 public:
  /// Worlds with at most this many bodies take the exact sum.
  static constexpr std::size_t kExactLimit = 512;
  static constexpr double kTheta = 0.3;

  explicit Gravitation(double constant) : constant_(constant) {}
  double constant() const { return constant_; }
  void apply(const FieldStep& step, std::span<FieldLoad> loads) const override;
  bool needsStillBodies() const override { return true; }

 private:
  void pulls(std::size_t movingCount) const;

  double constant_;
  // Scratch reused every step (a field serves one world at a time).
  mutable std::vector<PointMass> masses_;
  mutable std::vector<Pull> pulls_;
  mutable PullTree tree_{kTheta};
};

struct GravitationDef {
  double constant = 1;  ///< G, N m^2 / kg^2, in (0, 1000]
};

/// The field, or the error naming G and its range.
FieldBuild makeGravitation(const GravitationDef& def);

}  // namespace impulse
