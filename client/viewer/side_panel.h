#pragma once
/// The side panel beside the scene (never over it): title and explanation,
/// notices, time, next shape with the material legend, gravity, inspector,
/// server and viewer figures with live plots, debug overlays, the controls.

#include <imgui.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "controls.h"
#include "history.h"
#include "impulse.pb.h"
#include "impulse/scenes/presets.h"
#include "link_state.h"
#include "view_transform.h"

namespace impulse::viewer {

/// Everything the panel shows that is not in Controls.
struct PanelInput {
  const PresetInfo* preset = nullptr;
  Vec2 gravity = Vec2::Zero();
  bool serverPaused = false;
  std::uint64_t tick = 0;
  double simTime = 0;
  double timeScale = 1;  ///< simulated seconds per wall second
  /// The selected body's details (QueryBody), when they arrived.
  const v1::BodyInfo* inspected = nullptr;
  LinkState link = LinkState::Connecting;
  std::string linkText;  ///< what the connection line says
  std::size_t bodies = 0;
  double roundTripMs = -1;  ///< < 0 while unknown
  double snapshotsPerSecond = 0;
  double playoutDelayMs = 0;
  double frameMs = 0;
  float zoom = 1;
  /// The server's health from its last Pong.
  const v1::ServerStats* stats = nullptr;
  const History* stepMs = nullptr;
  const History* kineticEnergy = nullptr;
  std::optional<std::string> notice;
};

/// Fonts of the panel (the title's is larger).
struct PanelFonts {
  ImFont* text = nullptr;
  ImFont* title = nullptr;
};

/// Draws the panel into `rect`; buttons act through `act` as the keys would.
void drawSidePanel(const PixelRect& rect, const PanelFonts& fonts, Controls& controls,
                   const PanelInput& input, const std::function<void(ControlKey)>& act);

// The sections, one file each.
void drawInspectorSection(const Controls& controls, const PanelInput& input);
void drawStatsSection(const PanelInput& input);
void drawControlsTable();

}  // namespace impulse::viewer
