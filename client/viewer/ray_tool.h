#pragma once
/// The ray tool (E): a ray dragged across the scene and cast by the server
/// (RayCast, the closest hit). At most one cast is in flight: while the
/// pointer moves, the ray asked next is the newest one, so a fast drag
/// sends one cast per round trip, not one per pointer event. A ray left
/// in place is cast again a few times a second, so its hit follows moving
/// bodies.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "impulse.pb.h"
#include "impulse/math.h"

namespace impulse::viewer {

/// A ray from `origin` to `end`, world metres.
struct Ray {
  Vec2 origin = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  friend bool operator==(const Ray&, const Ray&) = default;
};

/// Where a cast ray first entered a shape (a QueryHit).
struct RayHit {
  std::uint32_t body = 0;
  std::uint32_t shape = 0;
  Vec2 point = Vec2::Zero();   ///< on the shape's surface
  Vec2 normal = Vec2::Zero();  ///< unit, facing the ray
  double fraction = 0;         ///< the hit is at origin + fraction * (end - origin)
};

/// A ray and what the server answered for it: its hit, or none (a miss).
struct RayAnswer {
  Ray ray;
  std::optional<RayHit> hit;
};

class RayTool {
 public:
  /// A ray left in place is cast again this often (seconds).
  static constexpr double kRecastInterval = 0.1;

  /// The ray to show and cast: from the press to the pointer.
  void aim(const Ray& ray);
  /// The ray to cast (RayCast, closest hit) at `now`, if one is due: none
  /// while a cast is in flight, none shorter than a millimetre (the server
  /// refuses a zero ray), none when the aimed ray was answered and asked
  /// less than kRecastInterval ago. The ray returned is then in flight.
  std::optional<Ray> request(double now);
  /// The server's reply to the cast in flight: a QueryResult, or a refusal
  /// (CommandResult), whose reason is returned.
  std::optional<std::string> answered(const v1::ServerMessage& reply);
  /// Forgets the ray and its answer (the tool was left); a reply to a cast
  /// still in flight is then ignored.
  void clear();

  const std::optional<Ray>& aimed() const { return aimed_; }
  /// The newest answer: its ray may lag the aimed one by a round trip.
  const std::optional<RayAnswer>& answer() const { return answer_; }
  bool inFlight() const { return inFlight_.has_value(); }

 private:
  struct Cast {
    Ray ray;
    std::uint64_t generation;
  };
  std::optional<Ray> aimed_;
  std::optional<Cast> inFlight_;
  std::optional<RayAnswer> answer_;
  double askedAt_ = 0;
  /// Counts clear(): a reply to an older generation's cast is not shown.
  std::uint64_t generation_ = 0;
};

/// The ray tool's picture in world coordinates: the ray up to the hit (or
/// all of it on a miss), the rest beyond the hit, and the hit's normal as
/// an arrow `normalLength` long with its two barbs.
struct RayFigure {
  Vec2 origin = Vec2::Zero();
  Vec2 end = Vec2::Zero();
  /// Where the ray stops being drawn solid: the hit point, or `end`.
  Vec2 reach = Vec2::Zero();
  bool hit = false;
  Vec2 normalTip = Vec2::Zero();
  std::array<Vec2, 2> barbs{Vec2::Zero(), Vec2::Zero()};
};
RayFigure rayFigure(const RayAnswer& answer, Real normalLength);

/// "body 4, shape 7 at 0.42 of the ray" or "miss", for the panel.
std::string describeRay(const RayAnswer& answer);

}  // namespace impulse::viewer
