#include "options.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include "impulse/scenes/presets.h"

namespace impulse::viewer {

namespace {

// The command line's text values, converted once CLI11 has them.
struct TextValues {
  std::string connect = "127.0.0.1:7777";
  std::string size = "1280x720";
  int preset = -1;
  std::string screenshot;
};

// Flags, descriptions and ranges in one place, for parsing and for --help.
void describe(CLI::App& app, ViewerOptions& options, TextValues& text) {
  app.description("The SDL2 viewer of an impulse-server world.");
  app.add_option("--connect", text.connect, "server to view (default " + text.connect + ")")
      ->option_text("HOST:PORT");
  app.add_option("--size", text.size, "window size in pixels (default " + text.size + ")")
      ->option_text("WxH");
  app.add_option("--preset", text.preset,
                 "load preset N (0-" + std::to_string(kPresetCount - 1) + ") once connected")
      ->check(CLI::Range(0, kPresetCount - 1))
      ->option_text("N");
  app.add_option("--screenshot", text.screenshot,
                 "save the window as BMP after --frames frames (default 60), then quit")
      ->option_text("FILE.bmp");
  app.add_option("--frames", options.frames, "quit after N frames")
      ->check(CLI::Range(1, 100000000))
      ->option_text("N");
  app.add_flag("--no-vsync", [&options](std::int64_t) { options.vsync = false; },
               "do not wait for the display's refresh");
  app.add_option("--scene-file", options.sceneFile,
                 "Ctrl+S saves the scene to FILE, Ctrl+O loads it (default " + options.sceneFile +
                     ")")
      ->option_text("FILE");
  app.add_option("--shape-file", options.shapeFile,
                 "the shape library Ctrl+D adds to and Ctrl+1..9 stamp from (default " +
                     options.shapeFile + ")")
      ->option_text("FILE");
  app.add_option("--token", options.connect.token,
                 "access token sent in Hello; the admin token gives the admin role (see "
                 "docs/server.md)")
      ->option_text("T");
  app.add_option("--room", options.connect.room,
                 "room to join, made on first join (default: the room \"default\")")
      ->option_text("NAME");
  app.add_flag("--no-predict", [&options](std::int64_t) { options.predict = false; },
               "show the viewer's own drags and pushes only when the server's snapshots bring them "
               "(default: predicted at once; the panel's \"Predict my actions\" box toggles it)");
  app.add_option_function<int>(
         "--added-rtt",
         [&options](int ms) { options.connect.addedRoundTrip = std::chrono::milliseconds(ms); },
         "add MS milliseconds to the round trip to the server (try a slow link on loopback)")
      ->check(CLI::Range(0, 10000))
      ->option_text("MS");
  auto* margin = app.add_option_function<float>(
                        "--area-margin", [&options](float metres) { options.areaMargin = metres; },
                        "receive only the bodies in the view and M metres around it (an area of "
                        "interest, sent again as the view pans or zooms; default: 5)")
                     ->check(CLI::Range(0.0f, 1000.0f))
                     ->option_text("M");
  app.add_flag_callback("--whole-room", [&options] { options.areaMargin.reset(); },
                        "receive every body of the room, not only the view's (no area of interest; "
                        "also with --quantized, which areas cannot use)")
      ->excludes(margin);
  app.add_option_function<double>(
         "--budget", [&options](double bytes) { options.budget = bytes; },
         "the server sends at most BYTES snapshot bytes a second, the most important changes "
         "first (a bandwidth budget, 1000-125000000; default: none)")
      ->check(CLI::Range(1000.0, 125e6))
      ->option_text("BYTES");
  app.add_flag_callback(
      "--quantized",
      [&options] { options.connect.snapshotEncoding = v1::SNAPSHOT_ENCODING_QUANTIZED; },
      "ask for compact snapshots (quantized, delta-coded: docs/snapshots.md)");
  app.footer(
      "Environment: IMPULSE_TOKEN is the default --token; IMPULSE_FONT overrides the panel "
      "font; SDL_VIDEODRIVER=offscreen runs without a display.");
}

std::optional<std::string> applyText(const TextValues& text, ViewerOptions& options) {
  const auto hostPort = client::parseHostPort(text.connect);
  if (!hostPort) return "--connect wants HOST:PORT, not '" + text.connect + "'";
  options.connect.host = hostPort->first;
  options.connect.port = hostPort->second;
  int width = 0;
  int height = 0;
  char x = 0;
  char rest = 0;
  if (std::sscanf(text.size.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 || x != 'x' ||
      width < 100 || width > 10000 || height < 100 || height > 10000) {
    return "--size wants WxH (100-10000 each), not '" + text.size + "'";
  }
  options.width = width;
  options.height = height;
  if (text.preset >= 0) options.preset = text.preset;
  if (!text.screenshot.empty()) options.screenshot = text.screenshot;
  return std::nullopt;
}

}  // namespace

std::string defaultFontPath() {
  if (const char* font = std::getenv("IMPULSE_FONT"); font != nullptr && *font != 0) return font;
  return IMPULSE_VIEWER_FONT;
}

std::string viewerUsage() {
  CLI::App app("", "impulse-viewer");
  ViewerOptions options;
  TextValues text;
  describe(app, options, text);
  return app.help();
}

ParsedViewerOptions parseViewerOptions(std::span<const std::string_view> args) {
  ParsedViewerOptions parsed;
  ViewerOptions options;
  options.connect.name = "impulse-viewer";
  options.fontPath = defaultFontPath();
  // As impulse-cli: the environment's token unless --token overrides it.
  if (const char* token = std::getenv("IMPULSE_TOKEN")) options.connect.token = token;
  TextValues text;
  CLI::App app("", "impulse-viewer");
  describe(app, options, text);
  // CLI11 takes the arguments last first.
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    parsed.help = true;
    return parsed;
  } catch (const CLI::ParseError& error) {
    parsed.error = error.what();
    return parsed;
  }
  if (auto problem = applyText(text, options)) {
    parsed.error = std::move(*problem);
    return parsed;
  }
  if (options.screenshot && options.frames == 0) options.frames = 60;
  // Areas of interest need plain snapshots: quantized ones go to the whole
  // room unless a margin was asked for (the server then says why not).
  if (options.connect.snapshotEncoding == v1::SNAPSHOT_ENCODING_QUANTIZED &&
      app.count("--area-margin") == 0) {
    options.areaMargin.reset();
  }
  parsed.options = std::move(options);
  return parsed;
}

}  // namespace impulse::viewer
