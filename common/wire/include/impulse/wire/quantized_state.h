#pragma once
/// The model both ends of a compact snapshot stream share
/// (docs/snapshots.md): body states as integers, and the prediction each
/// snapshot is coded against. Everything here is integer arithmetic with
/// stated rounding, so encoder and decoder (in any language) agree exactly.

#include <array>
#include <cstdint>

#include "impulse/body.h"

namespace impulse::wire::quantized {

/// Position (m) and angle (rad) are kept in units of 2^-12, velocity (m/s)
/// and angular velocity (rad/s) in units of 2^-10: fine enough that the
/// prediction's rounding stays far below a quantum.
inline constexpr double kPositionUnit = 1.0 / 4096;
inline constexpr double kVelocityUnit = 1.0 / 1024;
/// Corrections are sent in quanta, in units: 2^-9 m (and rad), 2^-5 m/s
/// (and rad/s). A decoded value is always within one quantum of the truth.
inline constexpr std::int64_t kPositionQuantum = 16;
inline constexpr std::int64_t kVelocityQuantum = 32;
/// Accelerations are kept in velocity units / 16 per tick.
inline constexpr std::int64_t kAccelerationScale = 16;
/// Magnitude limits (units) that keep every product below 2^63.
inline constexpr std::int64_t kValueLimit = std::int64_t(1) << 41;
inline constexpr std::int64_t kAccelerationLimit = std::int64_t(1) << 36;
/// Predictions extrapolate over at most this many ticks, of at most this
/// many substeps.
inline constexpr std::int64_t kMaxPredictionTicks = 256;
inline constexpr std::int64_t kMaxSubSteps = 64;
/// Tick rates a stream may state (Hz).
inline constexpr std::int64_t kMaxTickHz = 100000;

/// How the server integrates: ticks per second, substeps per tick, and
/// gravity (acceleration units, per axis).
struct Integration {
  std::int64_t tickHz = 60;
  std::int64_t subSteps = 4;
  std::array<std::int64_t, 2> gravity{};
};

/// The integration of a world stepped at `tickHz` (rounded; substeps
/// clamped to 1..kMaxSubSteps) under `gravity`.
Integration integrationOf(double tickHz, int subSteps, const Vec2& gravity);

/// Index 0, 1, 2: x, y, angle (and their rates).
struct State {
  std::array<std::int64_t, 3> position{};
  std::array<std::int64_t, 3> velocity{};
  /// The last observed change of velocity per tick: what predictions assume.
  std::array<std::int64_t, 3> acceleration{};
  bool awake = false;

  bool operator==(const State&) const = default;
};

/// a / b rounded to nearest, halves away from zero (b > 0).
std::int64_t divideRounded(std::int64_t a, std::int64_t b);

/// The state in units (rounded to nearest, clamped to half of kValueLimit
/// to leave room for corrections), no acceleration. Its position is the
/// world's `origin` plus the state's (relative to it): units count from
/// (0, 0), as every position on the wire does.
State quantize(const BodyState& state, const Vec2d& origin);
/// Back to metres, radians and seconds, the position relative to `origin`
/// (taken away in double, before it becomes a float).
BodyState dequantize(BodyId id, const State& state, const Vec2d& origin);

/// Where an awake body is `ticks` ticks later if it keeps its acceleration
/// (the engine's semi-implicit Euler over every substep); a sleeping body
/// stays.
State predict(const State& state, std::int64_t ticks, const Integration& integration);

/// Corrections in quanta, per component: x, y, angle, vx, vy, angular velocity.
using Residuals = std::array<std::int64_t, 6>;
inline constexpr Residuals kQuanta = {kPositionQuantum, kPositionQuantum, kPositionQuantum,
                                      kVelocityQuantum, kVelocityQuantum, kVelocityQuantum};

/// The residuals that bring `predicted` within a quantum of `truth`: zero
/// where it already is (the dead zone that makes good predictions free),
/// else the nearest whole number of quanta.
Residuals residualsBetween(const State& predicted, const State& truth);
/// The state a record makes of a prediction: the residuals applied, the
/// awake flag set, and the acceleration learnt from `before` over `ticks`
/// (kept when no tick passed, zero for a sleeping body). A learnt
/// acceleration within a velocity quantum (over the interval) of gravity
/// becomes gravity, one within a quantum of zero becomes zero: falling and
/// resting are then predicted exactly, not from noisy quantized velocities.
State corrected(const State& predicted, const Residuals& residuals, bool awake,
                const State& before, std::int64_t ticks, const Integration& integration);

}  // namespace impulse::wire::quantized
