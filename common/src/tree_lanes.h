#pragma once
// The joint tree pass's numbers for one group (double) or for four groups of
// the same shape side by side (Quad, a lane each): the pass runs the same
// template on either, so a group's arithmetic is the same operations in the
// same order whichever it runs in, and its results the same bits.
//
// Quad is two SSE2 pairs, not one 32-byte vector: without AVX a 32-byte
// vector type changes how functions pass it (GCC's -Wpsabi), and two pairs
// keep four independent chains of arithmetic in flight on any x86-64.

#include <cstdint>

namespace impulse {

using DoublePair = double __attribute__((vector_size(16)));

struct Quad {
  DoublePair lo;
  DoublePair hi;
};

inline Quad operator+(const Quad& a, const Quad& b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline Quad operator-(const Quad& a, const Quad& b) { return {a.lo - b.lo, a.hi - b.hi}; }
inline Quad operator*(const Quad& a, const Quad& b) { return {a.lo * b.lo, a.hi * b.hi}; }
inline Quad operator/(const Quad& a, const Quad& b) { return {a.lo / b.lo, a.hi / b.hi}; }
inline Quad operator-(const Quad& a) { return {-a.lo, -a.hi}; }
inline Quad& operator+=(Quad& a, const Quad& b) { return a = a + b; }
inline Quad& operator-=(Quad& a, const Quad& b) { return a = a - b; }

/// Groups a T holds.
template <class T>
inline constexpr int kLanesOf = 1;
template <>
inline constexpr int kLanesOf<Quad> = 4;

/// x in every lane.
template <class T>
T splat(double x);
template <>
inline double splat<double>(double x) {
  return x;
}
template <>
inline Quad splat<Quad>(double x) {
  return {DoublePair{x, x}, DoublePair{x, x}};
}

inline double laneOf(double x, int) { return x; }
inline double laneOf(const Quad& x, int lane) { return lane < 2 ? x.lo[lane] : x.hi[lane - 2]; }
inline void setLane(double& x, int, double value) { x = value; }
inline void setLane(Quad& x, int lane, double value) {
  if (lane < 2) {
    x.lo[lane] = value;
  } else {
    x.hi[lane - 2] = value;
  }
}

/// A node's numbers: its block H_ii (then D_i, then D_i^-1), its coupling
/// to its parent H_{i,parent} (then D_i^-1 H_{i,parent}), its right-hand
/// side (then solution), and for a joint its rows on A's and B's
/// (vx, vy, w), cut rows zero.
template <class T>
struct TreeNodeNumbers {
  T diagonal[3][3];
  T toParent[3][3];
  T value[3];
  T side[2][3][3];
};

/// A body's inverse masses, its inertia as a hub's block takes it, and the
/// velocity change its joints' impulses make, summed.
template <class T>
struct TreeBodyNumbers {
  T invMass;
  T invInertia;
  T hubInertia;
  T change[3];
};

}  // namespace impulse
