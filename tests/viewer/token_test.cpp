// The viewer's --token against a server with tokens: the admin token gives
// the admin role (world-wide commands such as a preset), the plain token a
// player's, and a wrong token is refused with the server's reason shown.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

constexpr const char* kToken = "viewer-test-token";
constexpr const char* kAdminToken = "viewer-test-admin";

// The viewer's role once connected with `token`: "admin", "player", or the
// link's description when it never connects.
std::string roleWith(std::uint16_t port, const std::string& token) {
  ViewerHarness viewer(port, 640, 480, token);
  const auto& link = viewer.app().connection();
  viewer.runUntil([&] { return link.state() != viewer::LinkState::Connecting; });
  if (!link.connected()) return link.describe();
  return link.client()->welcome().admin() ? "admin" : "player";
}

TEST(ViewerToken, TheAdminTokenGivesAdmin_TheTokenAPlayer_AWrongOneIsRefusedWithTheReason) {
  net_test::ServerProcess server({"--token", kToken, "--admin-token", kAdminToken});
  EXPECT_EQ(roleWith(server.port(), kAdminToken), "admin");
  EXPECT_EQ(roleWith(server.port(), kToken), "player");
  const std::string refused = roleWith(server.port(), "guess");
  EXPECT_NE(refused.find("cannot connect"), std::string::npos) << refused;
  EXPECT_NE(refused.find("Hello.token is not valid"), std::string::npos) << refused;
}

// impulse-viewer --token A --preset N: the preset, a world-wide command, is
// loaded only when the admin token was given on the command line.
int presetAfterViewerRun(const std::string& tokenFlag) {
  net_test::ServerProcess server({"--admin-token", kAdminToken, "--preset", "2"});
  const std::string command =
      "SDL_VIDEODRIVER=offscreen SDL_RENDER_DRIVER=software SDL_FRAMEBUFFER_ACCELERATION=0 "
      "IMPULSE_TOKEN= " +
      std::string(IMPULSE_VIEWER_BINARY) + " --connect 127.0.0.1:" +
      std::to_string(server.port()) + " --preset 4 --frames 45" + tokenFlag;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  client::Client observer(observerOptions(server.port()));
  return observer.mirror().preset() ? observer.mirror().preset()->id : -1;
}

TEST(ViewerToken, TheBinarySendsTheTokenFlag_OnlyTheAdminLoadsAPreset) {
  EXPECT_EQ(presetAfterViewerRun(std::string(" --token ") + kAdminToken), 4);
  EXPECT_EQ(presetAfterViewerRun(""), 2);
}

}  // namespace
}  // namespace impulse::viewer_test
