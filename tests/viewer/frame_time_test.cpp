// The frame time of the viewer with 2000 bodies (SPEC's scale target for the
// closing note), offscreen with the software renderer: the slowest setup the
// viewer meets, so a real display's GPU renderer only does better.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <vector>

#include "impulse/client/commands.h"
#include "server_process.h"
#include "viewer_harness.h"

namespace impulse::viewer_test {
namespace {

// The figure itself is reported (printed and recorded); the assertion only
// catches a gross regression, since timings on these shared two-core machines
// swing with whatever else runs (36 ms measured at load 10 against 27 ms on
// a quieter machine). Sanitizer builds run the viewer several times slower.
#ifdef IMPULSE_TESTS_SANITIZED
constexpr double kFrameBudgetMs = 400;
#else
constexpr double kFrameBudgetMs = 100;
#endif

// CPU time this thread has used, milliseconds.
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

using std::chrono::milliseconds;

TEST(FrameTime, TwoThousandBodies_StaysWellUnderAFrame) {
  net_test::ServerProcess server;
  client::Client driver(observerOptions(server.port()));
  // Circles and boxes in a grid, pipelined (one tick applies them all).
  std::vector<std::uint64_t> ids;
  for (int i = 0; i < 2000; ++i) {
    const double x = 1.0 + (i % 50) * 0.46;
    const double y = 1.0 + (i / 50) * 0.42;
    if (i % 2 == 0) {
      ids.push_back(driver.send(client::spawnCircle({x, y}, 0.18)));
    } else {
      const std::vector<client::Point> box{{x - 0.17, y - 0.17}, {x + 0.17, y - 0.17},
                                           {x + 0.17, y + 0.17}, {x - 0.17, y + 0.17}};
      ids.push_back(driver.send(client::spawnPolygon(box)));
    }
  }
  for (const auto id : ids) {
    const auto reply = driver.awaitReply(id, milliseconds(20000));
    ASSERT_TRUE(reply && reply->command_result().ok());
  }
  // Paused, the server's step does not compete with the viewer for the CPU:
  // the figure is the viewer's own. Interpolation still runs every frame.
  ASSERT_TRUE(driver.request(client::setPaused(true)).command_result().ok());

  ViewerHarness viewer(server.port());
  ASSERT_TRUE(viewer.runUntil([&] { return viewer.app().world().bodies().size() >= 2000; },
                              milliseconds(15000)));
  viewer.tap(SDLK_x);
  viewer.runFrames(20);
  std::vector<double> work;
  viewer::FrameTiming sum;
  double cpuMs = 0;
  for (int i = 0; i < 120; ++i) {
    const double cpuBefore = threadCpuMs();
    viewer.app().frame();
    cpuMs += threadCpuMs() - cpuBefore;
    const auto& t = viewer.app().timing();
    work.push_back(t.update + t.draw + t.present);
    sum.update += t.update;
    sum.draw += t.draw;
    sum.present += t.present;
  }
  std::sort(work.begin(), work.end());
  double mean = 0;
  for (const double w : work) mean += w;
  mean /= double(work.size());
  const double p95 = work[work.size() * 95 / 100];
  std::printf("viewer frame time, %zu bodies, offscreen software renderer: mean %.2f ms, "
              "median %.2f ms, p95 %.2f ms\n",
              viewer.app().world().bodies().size(), mean, work[work.size() / 2], p95);
  std::printf("  of which update %.2f ms, draw %.2f ms, present %.2f ms\n", sum.update / 120,
              sum.draw / 120, sum.present / 120);
  cpuMs /= 120;
  std::printf("  CPU time of the frame thread: mean %.2f ms\n", cpuMs);
  RecordProperty("mean_frame_ms", std::to_string(mean));
  RecordProperty("mean_frame_cpu_ms", std::to_string(cpuMs));
  RecordProperty("p95_frame_ms", std::to_string(p95));
  viewer.capture(screenshotPath("bodies_2000.bmp"));
  // Software rasterising (anti-aliased), the frame thread's own CPU time: at
  // least 10 frames per second even on a loaded machine (a GPU renderer does
  // far better).
  EXPECT_LT(cpuMs, kFrameBudgetMs);
}

}  // namespace
}  // namespace impulse::viewer_test
