#pragma once
/// The side panel beside the scene (never over it), docked to the window's
/// right edge: a fixed header (title, room, connection, notices, time) that
/// never scrolls away, then sections that scroll under it and wrap to its
/// width: the scene picker with the explanation, inspector, server and
/// viewer figures with live plots, debug overlays, next shape with the
/// material legend, gravity, the controls.

#include <imgui.h>

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "controls.h"
#include "history.h"
#include "impulse.pb.h"
#include "impulse/scenes/presets.h"
#include "link_state.h"
#include "view_transform.h"

namespace impulse::viewer {

/// Everything the panel shows that is not in Controls.
/// The predictor's figures (docs/networked-play.md, "Prediction").
struct PredictionFigures {
  std::uint64_t leadTicks = 0;    ///< how far the copy runs ahead of the last snapshot
  double shownCorrection = 0;     ///< m, the largest correction still being blended in
  double largestCorrection = 0;   ///< m, the largest a snapshot brought so far
};

struct PanelInput {
  const PresetInfo* preset = nullptr;
  std::string room;  ///< the room joined
  /// What the scene picker offers: every preset, and the scene files.
  const std::vector<PresetInfo>* presets = nullptr;
  std::vector<std::string> sceneFiles;
  Vec2 gravity = Vec2::Zero();
  bool serverPaused = false;
  std::uint64_t tick = 0;
  double simTime = 0;
  double timeScale = 1;  ///< simulated seconds per wall second
  /// The selected body's details (QueryBody), when they arrived; their
  /// positions are in the mirror's frame, from `origin`.
  const v1::BodyInfo* inspected = nullptr;
  /// The room's origin (Welcome.world_origin): the inspector shows and takes
  /// positions from (0, 0), in double.
  Vec2d origin = Vec2d::Zero();
  LinkState link = LinkState::Connecting;
  std::string linkText;  ///< what the connection line says
  std::size_t bodies = 0;
  double roundTripMs = -1;  ///< < 0 while unknown
  double snapshotsPerSecond = 0;
  double playoutDelayMs = 0;
  double frameMs = 0;
  double framesPerSecond = 0;
  float zoom = 1;
  /// The server's health from its last Pong.
  const v1::ServerStats* stats = nullptr;
  const History* stepMs = nullptr;
  const History* kineticEnergy = nullptr;
  /// Events messages received while the flashes are on.
  std::uint64_t eventMessages = 0;
  std::optional<std::string> notice;
  /// Prediction wanted, and its figures once the predictor runs.
  bool predicting = false;
  std::optional<PredictionFigures> prediction;
};

/// Fonts of the panel (the title's is larger).
struct PanelFonts {
  ImFont* text = nullptr;
  ImFont* title = nullptr;
};

/// What the panel's widgets do: `key` acts as the key would, `loadScene`
/// loads a scene file, `send` sends a command (`what` names it in errors).
struct PanelActions {
  std::function<void(ControlKey)> key;
  std::function<void(const std::string&)> loadScene;
  std::function<void(v1::ClientMessage message, std::string what)> send;
  /// The "Predict my actions" box: prediction on or off.
  std::function<void(bool)> setPredicting;
};

/// A row of three of the inspector's fields while a person edits them: the
/// server's figures (five a second) would overwrite the typing otherwise.
struct FieldsEdit {
  std::uint32_t body = 0;
  double values[3] = {};
  bool editing = false;
};

/// What the panel keeps from frame to frame, and where it drew what a test
/// may want to point at.
struct PanelState {
  /// Each preset entry of the scene picker that is on screen: id, window pixels.
  std::vector<std::pair<int, PixelRect>> presetEntries;
  /// The inspector's Stop button, when it is on screen.
  std::optional<PixelRect> stopButton;
  /// The "Predict my actions" check box, when on screen.
  std::optional<PixelRect> predictBox;
  /// The inspector's position-and-angle fields, and its static, kinematic
  /// and dynamic buttons, when on screen.
  std::optional<PixelRect> poseFields;
  std::array<std::optional<PixelRect>, 3> typeButtons;
  /// The inspector's flag check boxes: sensor, sensor events, contact
  /// events, hit events, when on screen.
  std::array<std::optional<PixelRect>, 4> flagBoxes;
  FieldsEdit poseEdit;      ///< x, y (m), angle (degrees)
  FieldsEdit velocityEdit;  ///< vx, vy (m/s), angular (rad/s)
};

/// Draws the panel into `rect`; `state`'s positions are refilled.
void drawSidePanel(const PixelRect& rect, const PanelFonts& fonts, Controls& controls,
                   const PanelInput& input, const PanelActions& actions, PanelState& state);

/// The last item's place in the window, for a test to point at.
PixelRect lastItemRect();

/// SameLine() when an item `width` pixels wide still fits on this line;
/// otherwise the item goes on the next line (rows that fit any width).
void sameLineIfFits(float width);

// The sections, one file each.
void drawScenePicker(const PanelInput& input, const PanelActions& actions, PanelState& state);
void drawInspectorSection(const Controls& controls, const PanelInput& input,
                          const PanelActions& actions, PanelState& state);
void drawStatsSection(const PanelInput& input);
void drawControlsTable();

}  // namespace impulse::viewer
