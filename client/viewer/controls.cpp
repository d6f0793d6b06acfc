#include "controls.h"

#include <algorithm>
#include <cctype>

#include "impulse/scenes/presets.h"

#include "impulse/client/commands.h"
#include "impulse/client/number_format.h"
#include "standard_shapes.h"

namespace impulse::viewer {

namespace {

bool repeats(Control control) {
  switch (control) {
    case Control::GravityUp:
    case Control::GravityLeft:
    case Control::GravityDown:
    case Control::GravityRight:
    case Control::PushUp:
    case Control::PushLeft:
    case Control::PushDown:
    case Control::PushRight: return true;
    default: return false;
  }
}

// Unit direction of a gravity or push key.
Vec2 direction(Control control) {
  switch (control) {
    case Control::GravityUp:
    case Control::PushUp: return Vec2(0, 1);
    case Control::GravityDown:
    case Control::PushDown: return Vec2(0, -1);
    case Control::GravityLeft:
    case Control::PushLeft: return Vec2(-1, 0);
    default: return Vec2(1, 0);
  }
}

bool isPush(Control control) {
  return control == Control::PushUp || control == Control::PushLeft ||
         control == Control::PushDown || control == Control::PushRight;
}

}  // namespace

client::Point toPoint(const Vec2& v) { return {double(v.x()), double(v.y())}; }

std::string materialLabel(Material material) {
  std::string name(materialProperties(material).name);
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return char(std::toupper(c)); });
  return name;
}

Controls::Controls(ControlSettings settings)
    : settings_(settings), shapeSize_(kDefaultShapeSize), capsuleRadius_(kDefaultCapsuleRadius) {}

void Controls::send(v1::ClientMessage message, std::string what) {
  outbox_.push_back({std::move(message), std::move(what)});
}

std::vector<Outgoing> Controls::takeCommands() { return std::exchange(outbox_, {}); }

void Controls::notify(std::string text, double now) {
  notice_ = std::move(text);
  noticeUntil_ = now + settings_.noticeSeconds;
}

std::optional<std::string> Controls::notice(double now) const {
  if (now >= noticeUntil_) return std::nullopt;
  return notice_;
}

bool Controls::repeatAction(ControlKey key, const ControlContext& context, double now) {
  if (!repeats(key.control)) return false;
  const Vec2 dir = direction(key.control);
  if (!isPush(key.control)) {
    send(client::nudgeGravity(toPoint(dir * Real(settings_.gravityStep))), "gravity");
    return true;
  }
  if (!selected_) {
    notify("Select a body first: M, then click it", now);
  } else if (!context.selectedMass) {
    notify("Waiting for the selected body's details", now);
  } else if (*context.selectedMass <= 0) {
    notify("Static bodies do not move", now);
  } else {
    const Vec2 impulse = dir * Real(*context.selectedMass * settings_.pushSpeed);
    send(client::applyImpulse(*selected_, toPoint(impulse)), "push");
  }
  return true;
}

void Controls::keyPressed(ControlKey key, const ControlContext& context, double now) {
  if (repeatAction(key, context, now)) {
    const auto it = std::find_if(held_.begin(), held_.end(),
                                 [&](const Held& h) { return h.key == key; });
    const double next = now + 1 / settings_.repeatHz;
    if (it == held_.end()) {
      held_.push_back({key, next});
    } else {
      it->nextRepeat = next;
    }
    return;
  }
  switch (key.control) {
    case Control::PolygonMode: toggleMode(DrawMode::Polygon, now); break;
    case Control::CircleMode: toggleMode(DrawMode::Circle, now); break;
    case Control::CapsuleMode: toggleMode(DrawMode::Capsule, now); break;
    case Control::SegmentMode: toggleMode(DrawMode::Segment, now); break;
    case Control::ChainMode: toggleMode(DrawMode::Chain, now); break;
    case Control::CloseChain: closeChain(now); break;
    case Control::RayMode: toggleMode(DrawMode::Ray, now); break;
    case Control::ClearUserBodies: clearUserBodies(context, now); break;
    case Control::ClearAll:
      send(client::clearWorld(), "clear");
      selected_.reset();
      endGrab(true);
      break;
    case Control::TogglePanel: panelVisible_ = !panelVisible_; break;
    case Control::ToggleInspector:
      inspectorVisible_ = !inspectorVisible_;
      if (!inspectorVisible_) selected_.reset();
      break;
    case Control::ToggleStatic: nextStatic_ = !nextStatic_; break;
    case Control::ToggleGravity: nextFeelsGravity_ = !nextFeelsGravity_; break;
    case Control::ResetGravity: send(client::resetGravity(), "gravity reset"); break;
    case Control::LoadPreset:
      send(client::loadPreset(key.index, material_), "preset " + std::to_string(key.index));
      cancelDrawing();
      selected_.reset();
      endGrab(true);
      panelVisible_ = false;
      camera_ = {};
      break;
    case Control::SelectMaterial:
      if (const auto material = materialFromIndex(key.index)) material_ = *material;
      break;
    case Control::TogglePause: togglePause(context); break;
    case Control::StepOnce: stepOnce(context, now); break;
    case Control::RemoveBody: removeBody(selected_ ? selected_ : context.bodyUnderPointer, now); break;
    case Control::FitView: camera_ = {}; break;
    case Control::ToggleContacts: overlays_.contacts = !overlays_.contacts; break;
    case Control::ToggleBounds: overlays_.bounds = !overlays_.bounds; break;
    case Control::ToggleVelocities: overlays_.velocities = !overlays_.velocities; break;
    case Control::ToggleEventFlashes: overlays_.eventFlashes = !overlays_.eventFlashes; break;
    case Control::PinSelected: pinSelected(context, now); break;
    case Control::CancelOrQuit: cancelOrQuit(now); break;
    case Control::SlowerTime: scaleTime(context, 0.5, now); break;
    case Control::FasterTime: scaleTime(context, 2, now); break;
    case Control::NormalTime: scaleTime(context, 1 / timeScale(context, now), now); break;
    case Control::StandardShape: spawnStandardShape(key.index); break;
    case Control::ShapeSmaller: resizeShapes(1 / kShapeSizeFactor, now); break;
    case Control::ShapeLarger: resizeShapes(kShapeSizeFactor, now); break;
    default: break;
  }
}

void Controls::cancelOrQuit(double now) {
  // Esc undoes the innermost thing in progress; it quits only when idle.
  if (mode_ != DrawMode::None) {
    cancelDrawing();
    notify("Drawing cancelled (Esc again quits)", now);
  } else if (grab_) {
    endGrab();
  } else if (selected_) {
    selected_.reset();
  } else {
    quit_ = true;
  }
}

void Controls::clearUserBodies(const ControlContext& context, double now) {
  if (context.userBodies.empty()) {
    notify("Nothing to clear: the scenery stays (Shift+C clears everything)", now);
    return;
  }
  for (const std::uint32_t id : context.userBodies) send(client::removeBody(id), "clear");
  selected_.reset();
  endGrab(true);
}

void Controls::togglePause(const ControlContext& context) {
  send(client::setPaused(!context.serverPaused), context.serverPaused ? "resume" : "pause");
}

void Controls::stepOnce(const ControlContext& context, double now) {
  if (!context.serverPaused) {
    notify("'.' steps one tick while paused: Space pauses", now);
    return;
  }
  send(client::step(1), "step");
}

void Controls::removeBody(std::optional<std::uint32_t> body, double now) {
  if (!body) {
    notify("No body there: point at a body to remove it", now);
    return;
  }
  send(client::removeBody(*body), "remove");
  if (selected_ == body) selected_.reset();
  if (grabbedBody() == body) endGrab(true);
}

void Controls::removeClicked(std::optional<std::uint32_t> body, double now) {
  if (mode_ != DrawMode::None) return;
  removeBody(body, now);
}

void Controls::keyReleased(ControlKey key) {
  std::erase_if(held_, [&](const Held& h) { return h.key == key; });
}

void Controls::update(const ControlContext& context, double now) {
  repeatHeldKeys(context, now);
  steerGrabbed(context, now);
  if (mode_ != DrawMode::Ray) return;
  if (const auto ray = ray_.request(now)) {
    send(client::rayCast(toPoint(ray->origin), toPoint(ray->end - ray->origin)), "ray");
  }
}

void Controls::rayAnswered(const v1::ServerMessage& reply, double now) {
  if (const auto refusal = ray_.answered(reply)) notify("Server refused the ray: " + *refusal, now);
}

void Controls::repeatHeldKeys(const ControlContext& context, double now) {
  for (Held& held : held_) {
    // A steady rate whatever the frame rate; after a long frame, catch up a
    // little but never flood the server.
    int burst = 0;
    while (now >= held.nextRepeat && burst < 3) {
      repeatAction(held.key, context, now);
      held.nextRepeat += 1 / settings_.repeatHz;
      ++burst;
    }
    if (now >= held.nextRepeat) held.nextRepeat = now + 1 / settings_.repeatHz;
  }
}

void Controls::steerGrabbed(const ControlContext& context, double now) {
  if (!grab_ || !grab_->dragging || !context.grabbed) return;
  if (grab_->jointTag == 0) {
    // The held point where the body is now (it may have moved since the press).
    const Vec2 held = *heldPoint(context.grabbed->position, context.grabbed->angle);
    // Tagged, so its targets go out at once, not after the reply naming
    // its id: a predicted drag moves the body in the next frame.
    grab_->jointTag = ++lastJointTag_;
    send(client::tagJoint(client::mouseJoint(grab_->body, toPoint(held),
                                             mouseSpring(context.grabbed->mass, settings_.grab)),
                          grab_->jointTag),
         "drag");
    grab_->sentTarget = held;
  }
  // A still cursor sends nothing: the joint keeps its target.
  if (now < grab_->nextTarget || pointer_ == grab_->sentTarget) return;
  send(client::byJointTag(client::setJointTarget(0, toPoint(pointer_)), grab_->jointTag), "drag target");
  grab_->sentTarget = pointer_;
  grab_->nextTarget = now + 1 / settings_.grabHz;
}

void Controls::endGrab(bool bodyGone) {
  if (!grab_) return;
  if (grab_->jointTag != 0 && !bodyGone) {
    send(client::byJointTag(client::removeJoint(0), grab_->jointTag), "drag end");
  }
  grab_.reset();
}

void Controls::pinSelected(const ControlContext& context, double now) {
  if (!selected_ || !context.selectedPosition) {
    notify("J pins the selected body: M, then click a body", now);
    return;
  }
  // At the cursor when it is on the body (a pendulum), else at the centre.
  const Vec2 pivot =
      context.bodyUnderPointer == selected_ ? pointer_ : *context.selectedPosition;
  send(client::revoluteJoint({*selected_, 0, toPoint(pivot), toPoint(pivot), false}, {}), "pin");
}

double Controls::timeScale(const ControlContext& context, double now) const {
  // Until the server shows the scale asked for last, a press builds on it:
  // quick (or held, repeating) presses each count, though the server's
  // answers to the earlier ones arrive in between. A scale the server never
  // shows (refused, or another client's change won) is let go after a while.
  constexpr double kAnswerSeconds = 1;
  if (askedScale_ && context.timeScale != askedScale_->wanted &&
      now - askedScale_->at < kAnswerSeconds) {
    return askedScale_->wanted;
  }
  return context.timeScale;
}

void Controls::scaleTime(const ControlContext& context, double factor, double now) {
  // The server's range (docs/protocol.md, "Time"): 0.01x to 16x.
  constexpr double kSlowest = 0.01;
  constexpr double kFastest = 16;
  const double current = timeScale(context, now);
  const double wanted = std::clamp(current * factor, kSlowest, kFastest);
  if (wanted == current) {
    notify("Time scale stays " + client::formatNumber(wanted, 2) + "x (0.01x to 16x)", now);
    return;
  }
  send(client::setTimeScale(wanted), "time scale");
  askedScale_ = AskedScale{wanted, now};
}

std::optional<std::uint32_t> Controls::grabbedBody() const {
  if (!grab_) return std::nullopt;
  return grab_->body;
}

std::optional<Vec2> Controls::heldPoint(const Vec2& position, Real angle) const {
  if (!grab_) return std::nullopt;
  return position + Rot::fromAngle(angle).apply(grab_->offset);
}

void Controls::zoomAt(float factor, float px, float py, const PixelRect& viewport) {
  camera_ = viewer::zoomAt(camera_, viewport, frame_, factor, px, py);
}

void Controls::setFrame(const AABB& frame) {
  frame_ = frame;
  camera_ = {};
}

void Controls::pan(float dx, float dy) {
  camera_.panX += dx;
  camera_.panY += dy;
}

void Controls::pointerPressed(const Vec2& at, std::optional<BodyHit> hit, double now) {
  pointer_ = at;
  if (mode_ != DrawMode::None) {
    pressWhileDrawing(at);
    return;
  }
  if (inspectorVisible_) {
    selected_ = hit ? std::optional(hit->id) : std::nullopt;
    if (!selected_) notify("No body there: click inside a body to inspect it", now);
  }
  if (hit && !hit->isStatic) {
    grab_ = Grab{};
    grab_->body = hit->id;
    grab_->offset = Rot::fromAngle(hit->angle).applyInverse(at - hit->position);
    grab_->pressedAt = at;
  }
}

void Controls::pointerMoved(const Vec2& at) {
  pointer_ = at;
  if (dragging_) dragEnd_ = at;
  if (dragging_ && mode_ == DrawMode::Ray) ray_.aim({*dragStart_, at});
  if (grab_ && (at - grab_->pressedAt).norm() > Real(settings_.dragThreshold)) {
    grab_->dragging = true;
  }
}

void Controls::pointerReleased(const Vec2& at) {
  pointerMoved(at);
  dragging_ = false;
  // Letting go is the throw: the body keeps the velocity it was given.
  endGrab();
}

}  // namespace impulse::viewer
