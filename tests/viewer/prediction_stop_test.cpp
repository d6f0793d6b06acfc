// The viewer's link (Connection) when prediction cannot go on: a bandwidth
// budget too small for its area withholds states, the predictor throws
// client::PredictionError, and the viewer turns prediction off with a
// message naming the cause, stays connected, and draws on from its
// interpolated picture.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "connection.h"
#include "impulse/client/commands.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// One frame of the viewer's loop as App runs it: receive, send, predict,
/// sample the picture. Returns what advancePrediction said.
std::optional<std::string> frame(viewer::Connection& link, viewer::InterpolatedWorld& world, double now) {
  link.update();
  std::optional<std::string> stopped = link.advancePrediction();
  world.update(now);
  std::this_thread::sleep_for(std::chrono::milliseconds(16));
  return stopped;
}

TEST(ViewerPrediction, AStreamThatWithholdsStatesTurnsPredictionOffByName_AndThePictureGoesOn) {
  net_test::ServerProcess server(std::vector<std::string>{});
  const auto start = Clock::now();
  viewer::InterpolatedWorld world;
  viewer::Connection link(observerOptions(server.port()), world, [&] { return secondsSince(start); }, true);
  for (int i = 0; i < 600 && !link.predictor(); ++i) ASSERT_FALSE(frame(link, world, secondsSince(start)));
  ASSERT_NE(link.predictor(), nullptr) << "prediction starts once a round trip is measured";

  ASSERT_TRUE(link.send(client::setInterestArea(client::Box{{-5, -2}, {5, 5}}), "area"));
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(link.send(client::spawnCircle({-4.5 + 0.3 * (i % 30), 1.5 + 0.15 * (i / 30)}, 0.1,
                                              {.ignoreGravity = true, .velocityY = 0.5}),
                          "circle"));
  }
  ASSERT_TRUE(link.send(client::setBandwidthBudget(1000), "budget"));
  std::optional<std::string> stopped;
  for (int i = 0; i < 600 && !stopped; ++i) stopped = frame(link, world, secondsSince(start));
  ASSERT_TRUE(stopped) << "the budget withheld states and prediction went on";
  EXPECT_NE(stopped->find("Prediction off"), std::string::npos) << *stopped;
  EXPECT_NE(stopped->find("states_withheld"), std::string::npos) << *stopped;
  EXPECT_FALSE(link.predicting()) << "the panel's box clears";
  EXPECT_EQ(link.predictor(), nullptr);

  const double drawnAt = world.renderTime();
  for (int i = 0; i < 30; ++i) EXPECT_FALSE(frame(link, world, secondsSince(start))) << "said once";
  EXPECT_TRUE(link.connected());
  EXPECT_GT(world.renderTime(), drawnAt) << "the interpolated picture plays on";
  EXPECT_FALSE(world.bodies().empty());
}

}  // namespace
}  // namespace impulse::viewer_test
