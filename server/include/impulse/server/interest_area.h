#pragma once
/// Areas of interest and bandwidth budgets (docs/networked-play.md): what a
/// subscriber asks for, checked, and where the room's bodies are, so that
/// each subscriber's snapshots can hold only the bodies inside its area.

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "impulse.pb.h"
#include "impulse/math.h"
#include "impulse/server/world_changes.h"
#include "impulse/world.h"

namespace impulse::server {

/// Widest and tallest area of interest, metres.
inline constexpr double kMaxInterestAreaSide = 20000;
/// Range of SetBandwidthBudget.bytes_per_second: 8 kbit/s to 1 Gbit/s.
inline constexpr double kMinBudgetBytesPerSecond = 1000;
inline constexpr double kMaxBudgetBytesPerSecond = 125e6;

/// A SetInterestArea checked: the box, none for the whole room, or the error
/// naming the field that is missing, not finite, empty, inverted or too large.
struct InterestAreaRequest {
  std::optional<AABB> area;
  std::string error;
};
InterestAreaRequest interestAreaFromWire(const v1::SetInterestArea& command);

/// A SetBandwidthBudget checked: bytes a second, none for no budget, or the
/// error naming the field and its range.
struct BudgetRequest {
  std::optional<double> bytesPerSecond;
  std::string error;
};
BudgetRequest budgetFromWire(const v1::SetBandwidthBudget& command);

/// Where one body is: its centre, the radius of a circle about it that
/// holds all its shapes, and its velocity.
struct BodyPlace {
  std::uint32_t id = 0;
  Vec2 centre = Vec2::Zero();
  Real reach = 0;
  Vec2 velocity = Vec2::Zero();
};

/// A joint's two bodies (bodyB 0: the world): it goes to an area holding
/// either of them.
struct JointPlace {
  std::uint32_t id = 0;
  std::uint32_t bodyA = 0;
  std::uint32_t bodyB = 0;
};

/// The box a field acts in (none: everywhere, as gravitation): it goes to
/// an area the box overlaps.
struct FieldPlace {
  std::uint32_t id = 0;
  std::optional<AABB> reach;
};

/// Every body's place, joint's bodies and field's reach, taken once per
/// broadcast for all the subscribers with an area. Reaches are kept between
/// broadcasts (shapes rarely change).
class BodyPlaces {
 public:
  /// Takes every body's place now; `changes` (normalised) says whose shapes
  /// may have changed since the last call.
  void update(const World& world, const WorldChanges& changes);
  /// Takes every body's place now, computing every reach again.
  void rebuild(const World& world);
  /// By id, ascending.
  const std::vector<BodyPlace>& places() const { return places_; }
  const std::vector<JointPlace>& joints() const { return joints_; }
  const std::vector<FieldPlace>& fields() const { return fields_; }
  /// The ids of the bodies whose circle overlaps `area`, ascending.
  void inside(const AABB& area, std::vector<std::uint32_t>& ids) const;
  /// The ids of the joints with a body among `bodies` (ascending), and of
  /// the fields reaching into `area` (none: the whole room), ascending.
  void jointsOf(const std::vector<std::uint32_t>& bodies, std::vector<std::uint32_t>& ids) const;
  void fieldsIn(const std::optional<AABB>& area, std::vector<std::uint32_t>& ids) const;
  /// The body's place; null for a body the world no longer has.
  const BodyPlace* find(std::uint32_t id) const;

 private:
  Real reachOf(const World& world, std::uint32_t id);
  void takeJointsAndFields(const World& world);

  std::vector<BodyPlace> places_;
  std::vector<JointPlace> joints_;
  std::vector<FieldPlace> fields_;
  std::unordered_map<std::uint32_t, Real> reaches_;
};

}  // namespace impulse::server
