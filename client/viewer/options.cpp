#include "options.h"

#include <charconv>
#include <cstdlib>

namespace impulse::viewer {

namespace {

bool parseInt(std::string_view text, int low, int high, int& out) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < low || value > high) {
    return false;
  }
  out = value;
  return true;
}

}  // namespace

std::string defaultFontPath() {
  if (const char* font = std::getenv("IMPULSE_FONT"); font != nullptr && *font != 0) return font;
  return IMPULSE_VIEWER_FONT;
}

std::string viewerUsage() {
  return "usage: impulse-viewer [--connect HOST:PORT] [--size WxH] [--preset N]\n"
         "                      [--screenshot FILE.bmp] [--frames N] [--no-vsync]\n"
         "  --connect HOST:PORT  server to view (default 127.0.0.1:7777)\n"
         "  --size WxH           window size in pixels (default 800x600)\n"
         "  --preset N           load preset N (0-10) once connected\n"
         "  --screenshot FILE    save the window as BMP after --frames frames (default 60),\n"
         "                       then quit\n"
         "  --frames N           quit after N frames\n"
         "  --no-vsync           do not wait for the display's refresh\n"
         "Environment: IMPULSE_FONT overrides the HUD font; SDL_VIDEODRIVER=offscreen\n"
         "runs without a display.\n";
}

ParsedViewerOptions parseViewerOptions(std::span<const std::string_view> args) {
  ParsedViewerOptions parsed;
  ViewerOptions options;
  options.connect.name = "impulse-viewer";
  options.fontPath = defaultFontPath();
  auto fail = [&](std::string message) {
    parsed.error = std::move(message);
    return parsed;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string_view flag = args[i];
    std::string_view value;
    bool inlineValue = false;
    if (const auto eq = flag.find('='); flag.starts_with("--") && eq != std::string_view::npos) {
      value = flag.substr(eq + 1);
      flag = flag.substr(0, eq);
      inlineValue = true;
    }
    auto next = [&]() -> bool {
      if (inlineValue) return true;
      if (i + 1 >= args.size()) return false;
      value = args[++i];
      return true;
    };
    if (flag == "--help" || flag == "-h") {
      parsed.help = true;
      return parsed;
    }
    if (flag == "--no-vsync") {
      options.vsync = false;
      continue;
    }
    if (!next()) return fail(std::string(flag) + " needs a value");
    if (flag == "--connect") {
      const auto hostPort = client::parseHostPort(value);
      if (!hostPort) return fail("--connect wants HOST:PORT, not '" + std::string(value) + "'");
      options.connect.host = hostPort->first;
      options.connect.port = hostPort->second;
    } else if (flag == "--size") {
      const auto x = value.find('x');
      if (x == std::string_view::npos || !parseInt(value.substr(0, x), 100, 10000, options.width) ||
          !parseInt(value.substr(x + 1), 100, 10000, options.height)) {
        return fail("--size wants WxH (100-10000 each), not '" + std::string(value) + "'");
      }
    } else if (flag == "--preset") {
      int preset = 0;
      if (!parseInt(value, 0, 10, preset)) return fail("--preset wants 0-10");
      options.preset = preset;
    } else if (flag == "--screenshot") {
      options.screenshot = std::string(value);
    } else if (flag == "--frames") {
      if (!parseInt(value, 1, 100000000, options.frames)) return fail("--frames wants a count");
    } else {
      return fail("unknown option " + std::string(flag));
    }
  }
  if (options.screenshot && options.frames == 0) options.frames = 60;
  parsed.options = std::move(options);
  return parsed;
}

}  // namespace impulse::viewer
