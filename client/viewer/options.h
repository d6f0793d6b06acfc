#pragma once
/// Command line of impulse-viewer.

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "impulse/client/client.h"

namespace impulse::viewer {

/// The viewer's area of interest reaches this far past its view by default
/// (metres): a body at 20 m/s enters it 7 snapshots before it reaches the
/// view's edge.
inline constexpr float kDefaultAreaMargin = 5;

struct ViewerOptions {
  client::ConnectOptions connect;
  int width = 1280;
  int height = 720;
  /// panel font; IMPULSE_FONT in the environment overrides the built-in path.
  std::string fontPath;
  /// Load this preset once connected (scripts and screenshots).
  std::optional<int> preset;
  /// Save the window as a BMP after `frames` frames, then quit.
  std::optional<std::string> screenshot;
  /// Quit after this many frames (0: run until Esc or the window closes).
  int frames = 0;
  bool vsync = true;
  /// Ctrl+S saves the scene here, Ctrl+O loads it (docs/scenes.md).
  std::string sceneFile = "impulse.scene";
  /// The shape library (Ctrl+D, Ctrl+1..9).
  std::string shapeFile = "impulse-shapes.txt";
  /// Predict the viewer's own drags and pushes (docs/networked-play.md);
  /// the panel's "Predict my actions" box changes it while running.
  bool predict = true;
  /// Receive only the bodies in the view grown by this many metres (an area
  /// of interest, sent again as the view pans or zooms); none: the whole
  /// room (--whole-room, and --quantized without --area-margin).
  std::optional<float> areaMargin = kDefaultAreaMargin;
  /// Snapshot bytes a second the server may send this viewer, the most
  /// important changes first (a bandwidth budget); none: no budget.
  std::optional<double> budget;
};

struct ParsedViewerOptions {
  std::optional<ViewerOptions> options;
  bool help = false;
  std::string error;
};

ParsedViewerOptions parseViewerOptions(std::span<const std::string_view> args);
std::string viewerUsage();
/// The font used when none is given: IMPULSE_FONT, else the built-in path.
std::string defaultFontPath();

}  // namespace impulse::viewer
