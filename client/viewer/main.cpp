// impulse-viewer: the SDL2 viewer of an impulse-server world.
#include <cstdio>
#include <exception>
#include <string_view>
#include <vector>

#include "app.h"
#include "options.h"

int main(int argc, char** argv) {
  using namespace impulse::viewer;
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  const auto parsed = parseViewerOptions(args);
  if (parsed.help) {
    std::fputs(viewerUsage().c_str(), stdout);
    return 0;
  }
  if (!parsed.options) {
    std::fprintf(stderr, "impulse-viewer: %s\n%s", parsed.error.c_str(), viewerUsage().c_str());
    return 2;
  }
  try {
    App app(*parsed.options);
    return app.run();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "impulse-viewer: %s\n", error.what());
    return 1;
  }
}
