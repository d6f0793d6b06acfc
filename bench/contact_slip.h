#pragma once
// How far pieces slide along each other where they touch, measured from
// poses alone, the same way for every engine: a card sliding down its
// partner is a slip, a house settling as a whole is not.

#include <map>
#include <utility>
#include <vector>

#include "engine_adapter.h"

namespace bench {

/// Watches the contacts between a scene's polygon bodies (other shapes and
/// compound bodies are left out) at every observation: two bodies touch
/// where one polygon's face and the other's nearest edge come within
/// kTouching of each other (Box2D 2.4.1's polygons rest that far apart, on
/// their skin). At each touch the two bodies' material points at the
/// contact are followed to the next observation, and their relative
/// displacement along the contact's tangent is added to the pair's slip;
/// turning about the contact (rolling, a card leaning further) adds none.
class ContactSlipProbe {
 public:
  static constexpr double kTouching = 0.01;  ///< m

  explicit ContactSlipProbe(const SceneDescription& scene);
  /// Adds the slip since the last observation (the first: since the
  /// scene's described poses), then finds the touches at the engine's
  /// current poses.
  void observe(const EngineAdapter& engine);
  /// The largest slip any pair has accumulated at any observation (m): its
  /// signed sum, so a piece rocking back and forth slips only as far as it
  /// gets.
  double largestSlip() const { return largest_; }

 private:
  struct Touch {
    std::pair<std::size_t, std::size_t> polygons;  ///< indices into polygons_, lower first
    Vec2d localA;                                  ///< the contact in each body's frame
    Vec2d localB;
    Vec2d tangent;  ///< the normal (from the first body to the second) turned left
  };

  /// The touches at `poses` (one per entry of polygons_).
  void findTouches(const std::vector<Pose>& poses);

  const SceneDescription& scene_;
  std::vector<int> polygons_;  ///< the bodies watched
  std::vector<Touch> touches_;
  std::map<std::pair<std::size_t, std::size_t>, double> slip_;
  double largest_ = 0;
};

}  // namespace bench
