#pragma once
/// The viewer's controls (docs/product.md's table plus time, hands, view and debug
/// keys) as a state machine without a window: abstract key and pointer
/// events in, protocol commands and view state out. key_map.h turns SDL keys
/// into Control values.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "grab.h"
#include "ray_tool.h"
#include "impulse.pb.h"
#include "impulse/client/commands.h"
#include "impulse/material.h"
#include "impulse/math.h"
#include "impulse/shape.h"
#include "view_transform.h"

namespace impulse::viewer {

/// What a key does; `index` carries the preset (0-14), the material
/// (0-7) or a standard shape's number of sides (3-6).
enum class Control {
  PolygonMode,
  CircleMode,
  CapsuleMode,
  SegmentMode,
  /// Chain mode; again: the open chain drawn so far.
  ChainMode,
  /// The chain drawn so far, closed into a loop.
  CloseChain,
  /// The ray tool: drag a ray, the server casts it; again: leave it.
  RayMode,
  ClearUserBodies,
  ClearAll,
  TogglePanel,
  ToggleInspector,
  ToggleStatic,
  ToggleGravity,
  GravityUp,
  GravityLeft,
  GravityDown,
  GravityRight,
  ResetGravity,
  PushUp,
  PushLeft,
  PushDown,
  PushRight,
  LoadPreset,
  SelectMaterial,
  TogglePause,
  StepOnce,
  RemoveBody,
  FitView,
  ToggleContacts,
  ToggleBounds,
  ToggleVelocities,
  /// Flashes of contacts, hits and sensors (the server's event stream).
  ToggleEventFlashes,
  PinSelected,
  CancelOrQuit,
  // Time scale: halve, double, back to 1x.
  SlowerTime,
  FasterTime,
  NormalTime,
  /// A regular polygon of `index` sides at the cursor, and its size.
  StandardShape,
  ShapeSmaller,
  ShapeLarger,
};

struct ControlKey {
  Control control;
  int index = 0;
  friend bool operator==(const ControlKey&, const ControlKey&) = default;
};

enum class DrawMode { None, Polygon, Circle, Capsule, Segment, Chain, Ray };

/// The grabbed body as the newest snapshot has it.
struct GrabbedBody {
  Vec2 position = Vec2::Zero();  ///< centre of mass
  double mass = 0;
  Real angle = 0;
};

/// What the controls need to know about the world when an event happens.
struct ControlContext {
  /// Mass of the selected body (0 for a static one), once the server told.
  std::optional<double> selectedMass{};
  bool serverPaused = false;
  Vec2 gravity = Vec2(0, Real(-9.81));
  /// The body under the cursor (Delete removes it).
  std::optional<std::uint32_t> bodyUnderPointer{};
  /// What C removes: every moving body and every body this viewer made;
  /// the scene's static scenery stays.
  std::vector<std::uint32_t> userBodies{};
  /// The newest centre of mass and mass of the grabbed body, while one is
  /// grabbed.
  std::optional<GrabbedBody> grabbed{};
  /// The selected body's centre of mass (J pins it there unless the
  /// pointer is on it).
  std::optional<Vec2> selectedPosition{};
  /// The server's time scale (simulated seconds per wall second).
  double timeScale = 1;
};

/// A body under the cursor when the left button went down.
struct BodyHit {
  std::uint32_t id = 0;
  bool isStatic = false;
  Vec2 position = Vec2::Zero();  ///< its centre of mass
  Real angle = 0;
};

/// A command for the server and what to call it in an error message.
struct Outgoing {
  v1::ClientMessage message;
  std::string what;
};

struct ControlSettings {
  /// Held gravity and push keys repeat at this rate (Hz), first at the press.
  double repeatHz = 20;
  /// Gravity change per repeat, m/s^2.
  double gravityStep = 0.25;
  /// Velocity given to the selected body per push repeat, m/s.
  double pushSpeed = 0.25;
  /// How long a notice stays on screen, seconds.
  double noticeSeconds = 4;
  /// A grabbed body's target follows the cursor this often (Hz): about the
  /// snapshot rate.
  double grabHz = 30;
  /// The cursor must move this far (m) before a press becomes a drag, so a
  /// click that selects a body does not disturb it.
  double dragThreshold = 0.1;
  GrabSettings grab;
};

/// Debug overlays drawn over the scene.
struct Overlays {
  bool contacts = false;
  bool bounds = false;
  bool velocities = false;
  /// Subscribed to the server's events, flashing hits, contacts that begin
  /// and sensors that fire. Off at start: the stream costs the server and
  /// the link, and only shapes that ask for events make any.
  bool eventFlashes = false;
};

class Controls {
 public:
  explicit Controls(ControlSettings settings = {});

  void keyPressed(ControlKey key, const ControlContext& context, double now);
  void keyReleased(ControlKey key);
  /// Left button down at world point `at` over `hit` (if any).
  void pointerPressed(const Vec2& at, std::optional<BodyHit> hit, double now);
  void pointerMoved(const Vec2& at);
  void pointerReleased(const Vec2& at);
  /// A right click (not a drag) on `body`, or on empty space: removes it.
  void removeClicked(std::optional<std::uint32_t> body, double now);
  /// Once per frame: repeats held keys, steers a grabbed body.
  void update(const ControlContext& context, double now);

  /// The server's reply to the ray tool's cast (`what` "ray"); a refusal
  /// becomes a notice.
  void rayAnswered(const v1::ServerMessage& reply, double now);
  /// Commands produced since the last call, in order.
  std::vector<Outgoing> takeCommands();
  /// Shows `text` for a few seconds (also used for server errors).
  void notify(std::string text, double now);
  /// The notice to show at `now`, if any.
  std::optional<std::string> notice(double now) const;

  // View state.
  bool quitRequested() const { return quit_; }
  bool panelVisible() const { return panelVisible_; }
  bool inspectorVisible() const { return inspectorVisible_; }
  std::optional<std::uint32_t> selectedBody() const { return selected_; }
  /// The selected body went away.
  void deselect() { selected_.reset(); }
  Overlays& overlays() { return overlays_; }
  const Overlays& overlays() const { return overlays_; }
  const Camera& camera() const { return camera_; }
  /// The world rectangle the view fits before zoom and pan (F fits it
  /// again): the preset scene until a room's frame is set.
  const AABB& frame() const { return frame_; }
  /// Where the room opens (scene_frame.h); zoom and pan start afresh.
  void setFrame(const AABB& frame);
  /// Mouse wheel: zoom by `factor` about the window pixel (px, py).
  void zoomAt(float factor, float px, float py, const PixelRect& viewport);
  /// Right or middle drag: moves the view by pixels.
  void pan(float dx, float dy);
  /// The body being dragged by hand, if any.
  std::optional<std::uint32_t> grabbedBody() const;
  /// Where the grabbed body is held, in world coordinates, when its centre
  /// of mass is at `position` and it is turned by `angle`: the held point
  /// turns with the body.
  std::optional<Vec2> heldPoint(const Vec2& position, Real angle) const;

  // Next shape.
  DrawMode mode() const { return mode_; }
  bool nextStatic() const { return nextStatic_; }
  bool nextFeelsGravity() const { return nextFeelsGravity_; }
  Material material() const { return material_; }
  /// Circumradius of the next standard shape, m.
  Real shapeSize() const { return shapeSize_; }
  /// Radius of the next capsule, m.
  Real capsuleRadius() const { return capsuleRadius_; }

  // Drawing previews.
  /// The points a polygon or chain has so far.
  const std::vector<Vec2>& placedPoints() const { return points_; }
  const Vec2& pointer() const { return pointer_; }
  /// Polygon and chain modes: a click at the pointer would place a point.
  bool pointerValid() const;
  /// Circle, capsule and segment modes: where the drag began (a circle's
  /// centre, a capsule's or segment's first end) and where it is now.
  std::optional<Vec2> dragStart() const { return dragStart_; }
  const Vec2& dragEnd() const { return dragEnd_; }
  /// Circle mode: the radius dragged so far.
  Real circleRadius() const;
  /// Ray mode: the ray dragged and the server's answer.
  const RayTool& rayTool() const { return ray_; }

 private:
  struct Held {
    ControlKey key;
    double nextRepeat;
  };
  struct Grab {
    std::uint32_t body = 0;
    Vec2 offset = Vec2::Zero();     ///< the grabbed point in the body's frame
    Vec2 pressedAt = Vec2::Zero();  ///< where the press was, world
    bool dragging = false;
    /// The mouse joint's tag (CreateJoint.tag), once it was asked for.
    std::uint32_t jointTag = 0;
    Vec2 sentTarget = Vec2::Zero();
    double nextTarget = 0;
  };

  /// A drawing key: enters `mode`, or, pressed again, creates what was drawn.
  void toggleMode(DrawMode mode, double now);
  /// Sends what was drawn; false when the drawing stays open for more.
  bool finishDrawing(double now);
  bool finishPolygon(double now);
  bool finishCircle(double now);
  bool finishCapsule(double now);
  bool finishSegment(double now);
  bool finishChain(bool loop, double now);
  void closeChain(double now);
  /// The press of a drawing tool at `at`.
  void pressWhileDrawing(const Vec2& at);
  void cancelDrawing();
  void cancelOrQuit(double now);
  void clearUserBodies(const ControlContext& context, double now);
  void togglePause(const ControlContext& context);
  void stepOnce(const ControlContext& context, double now);
  void removeBody(std::optional<std::uint32_t> body, double now);
  void steerGrabbed(const ControlContext& context, double now);
  /// Lets go: removes the drag's joint unless `bodyGone` (then it went with
  /// the body).
  void endGrab(bool bodyGone = false);
  void pinSelected(const ControlContext& context, double now);
  /// Asks for the time scale times `factor`, kept in the server's range.
  void scaleTime(const ControlContext& context, double factor, double now);
  /// The time scale a time key starts from: the server's, or the one asked
  /// for last while the server has not shown it yet (for a second at most).
  double timeScale(const ControlContext& context, double now) const;
  void spawnStandardShape(int sides);
  void resizeShapes(Real factor, double now);
  /// Acts once for a repeating key; false when the key does not repeat.
  bool repeatAction(ControlKey key, const ControlContext& context, double now);
  void repeatHeldKeys(const ControlContext& context, double now);
  void send(v1::ClientMessage message, std::string what);
  client::SpawnOptions spawnOptions() const;

  ControlSettings settings_;
  std::vector<Outgoing> outbox_;
  std::vector<Held> held_;
  std::string notice_;
  double noticeUntil_ = -1;

  bool quit_ = false;
  bool panelVisible_ = true;
  bool inspectorVisible_ = false;
  std::optional<std::uint32_t> selected_;
  std::optional<Grab> grab_;
  /// The last time scale asked for, and when.
  struct AskedScale {
    double wanted;
    double at;
  };
  std::optional<AskedScale> askedScale_;
  /// The tag of the last drag's mouse joint: each drag's is new.
  std::uint32_t lastJointTag_ = 0;
  Overlays overlays_;
  Camera camera_;
  AABB frame_ = kPresetScene;

  DrawMode mode_ = DrawMode::None;
  bool nextStatic_ = false;
  bool nextFeelsGravity_ = true;
  Material material_ = Material::Solid;
  Real shapeSize_;

  std::vector<Vec2> points_;
  Vec2 pointer_ = Vec2::Zero();
  std::optional<Vec2> dragStart_;
  Vec2 dragEnd_ = Vec2::Zero();
  bool dragging_ = false;
  Real capsuleRadius_;
  RayTool ray_;
};

/// A world point as the client library's commands take it.
client::Point toPoint(const Vec2& v);

/// The material's name as docs/product.md writes it (SOLID, ICE, ...).
std::string materialLabel(Material material);

}  // namespace impulse::viewer
