#include "impulse/wire/quantized_state.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace impulse::wire::quantized {

namespace {

std::int64_t toUnits(double value, double unit) {
  const double limit = double(kValueLimit / 2);
  const double scaled = std::clamp(value / unit, -limit, limit);
  // Halves away from zero, like llround, but inline: the encoder quantizes
  // every awake body's six components per snapshot. (NaN, which a guarded
  // world never has, becomes 0 instead of undefined behaviour.)
  if (std::isnan(scaled)) return 0;
  return std::int64_t(scaled + (scaled < 0 ? -0.5 : 0.5));
}

std::int64_t clampValue(std::int64_t value) {
  return std::clamp(value, -kValueLimit, kValueLimit);
}

}  // namespace

std::int64_t divideRounded(std::int64_t a, std::int64_t b) {
  return a >= 0 ? (a + b / 2) / b : -((-a + b / 2) / b);
}

State quantize(const BodyState& state, const Vec2d& origin) {
  State q;
  q.position = {toUnits(origin.x() + double(state.position.x()), kPositionUnit),
                toUnits(origin.y() + double(state.position.y()), kPositionUnit),
                toUnits(state.angle, kPositionUnit)};
  q.velocity = {toUnits(state.linearVelocity.x(), kVelocityUnit),
                toUnits(state.linearVelocity.y(), kVelocityUnit),
                toUnits(state.angularVelocity, kVelocityUnit)};
  q.awake = state.awake;
  return q;
}

BodyState dequantize(BodyId id, const State& q, const Vec2d& origin) {
  BodyState state;
  state.id = id;
  state.position = Vec2(Real(double(q.position[0]) * kPositionUnit - origin.x()),
                        Real(double(q.position[1]) * kPositionUnit - origin.y()));
  state.angle = Real(double(q.position[2]) * kPositionUnit);
  state.linearVelocity = Vec2(Real(double(q.velocity[0]) * kVelocityUnit),
                              Real(double(q.velocity[1]) * kVelocityUnit));
  state.angularVelocity = Real(double(q.velocity[2]) * kVelocityUnit);
  state.awake = q.awake;
  return state;
}

State predict(const State& state, std::int64_t ticks, const Integration& integration) {
  if (!state.awake || ticks <= 0) return state;
  const std::int64_t n = std::min(ticks, kMaxPredictionTicks);
  const std::int64_t s = integration.subSteps;
  State next = state;
  for (int i = 0; i < 3; ++i) {
    // Semi-implicit Euler over n*s substeps of dt/s (dt = 1/tickHz), the
    // velocity growing by a/s each (a = acceleration/16 per tick):
    // v' = v + n*a and x' = x + dt * (n*v + a*n*(n*s+1)/(2*s)). Position
    // units are a quarter of velocity units, acceleration units 1/16 of them.
    const std::int64_t v = state.velocity[i];
    const std::int64_t a = state.acceleration[i];
    next.velocity[i] = clampValue(v + divideRounded(a * n, kAccelerationScale));
    const std::int64_t travel =
        divideRounded(n * (32 * s * v + a * (n * s + 1)), 8 * s * integration.tickHz);
    next.position[i] = clampValue(state.position[i] + travel);
  }
  return next;
}

namespace {

std::int64_t& component(State& state, std::size_t i) {
  return i < 3 ? state.position[i] : state.velocity[i - 3];
}

std::int64_t component(const State& state, std::size_t i) {
  return i < 3 ? state.position[i] : state.velocity[i - 3];
}

}  // namespace

Residuals residualsBetween(const State& predicted, const State& truth) {
  Residuals residuals{};
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    const std::int64_t miss = component(truth, i) - component(predicted, i);
    if (std::abs(miss) >= kQuanta[i]) residuals[i] = divideRounded(miss, kQuanta[i]);
  }
  return residuals;
}

Integration integrationOf(double tickHz, int subSteps, const Vec2& gravity) {
  const auto hz = std::clamp<std::int64_t>(std::llround(tickHz), 1, kMaxTickHz);
  auto perTick = [hz](double acceleration) {
    const double units = acceleration / double(hz) / kVelocityUnit * double(kAccelerationScale);
    const double limit = double(kAccelerationLimit);
    return std::llround(std::clamp(units, -limit, limit));
  };
  return {.tickHz = hz,
          .subSteps = std::clamp<std::int64_t>(subSteps, 1, kMaxSubSteps),
          .gravity = {perTick(double(gravity.x())), perTick(double(gravity.y()))}};
}

namespace {

std::int64_t snapped(std::int64_t learnt, std::int64_t gravity, std::int64_t tolerance) {
  if (std::abs(learnt - gravity) <= tolerance) return gravity;
  if (std::abs(learnt) <= tolerance) return 0;
  return learnt;
}

}  // namespace

State corrected(const State& predicted, const Residuals& residuals, bool awake,
                const State& before, std::int64_t ticks, const Integration& integration) {
  State state = predicted;
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    component(state, i) += residuals[i] * kQuanta[i];
  }
  state.awake = awake;
  if (!awake) {
    state.acceleration = {};
  } else if (ticks > 0) {
    const std::int64_t n = std::min(ticks, kMaxPredictionTicks);
    const std::int64_t tolerance = divideRounded(kVelocityQuantum * kAccelerationScale, n);
    for (std::size_t i = 0; i < 3; ++i) {
      const std::int64_t change = state.velocity[i] - before.velocity[i];
      const std::int64_t learnt = std::clamp(divideRounded(change * kAccelerationScale, n),
                                             -kAccelerationLimit, kAccelerationLimit);
      state.acceleration[i] = snapped(learnt, i < 2 ? integration.gravity[i] : 0, tolerance);
    }
  }
  return state;
}

}  // namespace impulse::wire::quantized
