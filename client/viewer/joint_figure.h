#pragma once
/// How a joint looks on screen, computed without a window: its anchors where
/// the drawn bodies are, and its kind's figure (a rod, a spring's zig-zag, a
/// rope, a pin, a slider, the hand's pull).

#include <optional>
#include <vector>

#include "impulse/joint.h"
#include "impulse/math.h"
#include "interpolation.h"

namespace impulse::viewer {

enum class JointLook { Rod, Spring, Rope, Pin, Slider, Pull };

struct JointFigure {
  JointLook look = JointLook::Rod;
  Vec2 a = Vec2::Zero();  ///< anchor on body A
  Vec2 b = Vec2::Zero();  ///< anchor on body B, the world point, or the pull's target
};

JointLook jointLook(const JointSettings& settings);

/// The figure of `joint` with its bodies drawn at `a` and `b` (`b` null
/// for a joint to the world); nothing when body A is not drawn.
std::optional<JointFigure> jointFigure(const JointDescription& joint, const BodySample* a,
                                       const BodySample* b);

/// A spring's zig-zag from `from` to `to` into `points` (replacing what it
/// held, so a caller's buffer is reused every frame): straight ends, then
/// `teeth` corners `width` to either side of the line.
void zigzag(const Vec2& from, const Vec2& to, int teeth, Real width, std::vector<Vec2>& points);

}  // namespace impulse::viewer
