// The bench's stage lines (EngineAdapter::stages): an engine's own timers,
// summed over its steps and told as means in the order the engine names them.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "scene.h"

namespace bench {
namespace {

TEST(StageTimes, TellsEachStagesMeanOverTheSteps_InItsOrder) {
  StageTimes times({"pairs", "collide", "solve"});
  EXPECT_EQ(times.describe(), "");  // no step yet
  times.add({1, 2, 3});
  times.add({3, 0, 4});
  EXPECT_EQ(times.describe(), "pairs 2.000 collide 1.000 solve 3.500 ms/step");
}

TEST(StageTimes, ImpulseTellsItsFiveStages_NoneNegative) {
  const auto scenes = box2DSuiteScenes(true);
  std::unique_ptr<EngineAdapter> engine = makeAdapter(scenes.front()->describe(), {Engine::Impulse, 4, 0});
  for (int i = 0; i < 10; ++i) engine->step(kDt);
  const std::string line = engine->stages();
  double pairs = -1, collide = -1, solve = -1, continuous = -1, sleep = -1;
  ASSERT_EQ(std::sscanf(line.c_str(), "pairs %lf collide %lf solve %lf continuous %lf sleep %lf ms/step", &pairs,
                        &collide, &solve, &continuous, &sleep),
            5)
      << line;
  for (double ms : {pairs, collide, solve, continuous, sleep}) EXPECT_GE(ms, 0) << line;
  EXPECT_GT(solve, 0) << line;
}

}  // namespace
}  // namespace bench
