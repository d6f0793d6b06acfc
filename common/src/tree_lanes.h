#pragma once
// The joint tree pass's numbers for one group (double) or for four groups of
// the same shape side by side (Quad, a lane each): the pass runs the same
// template on either, so a group's arithmetic is the same operations in the
// same order whichever it runs in, and its results the same bits.
//
// Quad is two SSE2 pairs, not one 32-byte vector: without AVX a 32-byte
// vector type changes how functions pass it (GCC's -Wpsabi), and two pairs
// keep four independent chains of arithmetic in flight on any x86-64.

#include <algorithm>
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

/// value where `used` is not zero, and +0 where it is (as though never set).
inline double keepWhere(double used, double value) { return used != 0 ? value : 0.0; }
inline Quad keepWhere(const Quad& used, const Quad& value) {
  const DoublePair zero{0, 0};
  return {used.lo != zero ? value.lo : zero, used.hi != zero ? value.hi : zero};
}

/// Whether any lane is not zero.
inline bool anyNonZero(double x) { return x != 0; }
inline bool anyNonZero(const Quad& x) {
  const DoublePair zero{0, 0};
  const auto nonZero = (x.lo != zero) | (x.hi != zero);
  return (nonZero[0] | nonZero[1]) != 0;
}

/// x clamped into [low, high] lane by lane, as std::clamp does.
inline double clampLanes(double x, double low, double high) { return std::clamp(x, low, high); }
inline Quad clampLanes(const Quad& x, double low, double high) {
  const DoublePair lows{low, low};
  const DoublePair highs{high, high};
  auto clampPair = [&](const DoublePair& pair) {
    const DoublePair raised = pair < lows ? lows : pair;
    return highs < raised ? highs : raised;
  };
  return {clampPair(x.lo), clampPair(x.hi)};
}

/// The lanes of a T in float, as the soft rows work (a float for a double,
/// four for a Quad), and the conversions each way, lane by lane as a cast.
using FloatLanes = float __attribute__((vector_size(16)));
template <class T>
struct FloatLanesFor {
  using type = float;
};
template <>
struct FloatLanesFor<Quad> {
  using type = FloatLanes;
};
template <class T>
using FloatsOf = typename FloatLanesFor<T>::type;

inline float toFloats(double x) { return float(x); }
inline FloatLanes toFloats(const Quad& x) {
  using FloatPair = float __attribute__((vector_size(8)));
  return __builtin_shufflevector(__builtin_convertvector(x.lo, FloatPair), __builtin_convertvector(x.hi, FloatPair), 0,
                                 1, 2, 3);
}
inline double toDoubles(float x) { return x; }
inline Quad toDoubles(const FloatLanes& x) {
  return {__builtin_convertvector(__builtin_shufflevector(x, x, 0, 1), DoublePair),
          __builtin_convertvector(__builtin_shufflevector(x, x, 2, 3), DoublePair)};
}

/// The T, and the float lanes, whose lane l is lane(l): built in registers
/// (a vector stored lane by lane and loaded whole waits for the stores).
template <class T, class Lane>
[[gnu::always_inline]] inline T lanesOf(Lane&& lane) {
  if constexpr (kLanesOf<T> == 1) {
    return lane(0);
  } else {
    return {DoublePair{lane(0), lane(1)}, DoublePair{lane(2), lane(3)}};
  }
}
template <class T, class Lane>
[[gnu::always_inline]] inline FloatsOf<T> floatLanesOf(Lane&& lane) {
  if constexpr (kLanesOf<T> == 1) {
    return lane(0);
  } else {
    return FloatLanes{lane(0), lane(1), lane(2), lane(3)};
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
