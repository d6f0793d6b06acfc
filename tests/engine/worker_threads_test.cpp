// Worker threads: the step gives the same bits on one thread, on the
// world's own threads and through a game's job system, on scenes large
// enough that every parallel phase really splits.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <numbers>
#include <random>
#include <vector>

#include "impulse/scenes/stress.h"
#include "impulse/tasks.h"
#include "impulse/world.h"
#include "world_test_support.h"

namespace impulse {
namespace {

using namespace impulse::test;

using SceneBuilder = void (*)(World& world);

// 2 485 boxes in a 70-row pyramid struck by a heavy ball at 30 m/s, and a
// seeded pile of boxes and circles falling on its far side: chaotic, so
// any difference in the order of arithmetic shows in the bits.
void buildStruckPyramid(World& world) {
  buildPyramid(world, 70);
  world.createCircle(Vec2(-60, 3), 2.5F, {.material = Material::Metal, .linearVelocity = Vec2(30, 0)});
  std::mt19937 random(11);
  std::uniform_real_distribution<Real> x(20, 70);
  std::uniform_real_distribution<Real> y(5, 60);
  std::uniform_real_distribution<Real> size(Real(0.2), Real(0.6));
  for (int i = 0; i < 1500; ++i) {
    const Vec2 centre(x(random), y(random));
    if (i % 2 == 0) {
      world.createCircle(centre, size(random), {.material = Material::Rubber});
    } else {
      addBox(world, {.center = centre, .halfWidth = size(random), .halfHeight = size(random)});
    }
  }
}

// A 60 x 60 grid of circles joined by revolute joints (`settingsOf` the
// k-th) to their right and lower neighbours, the top row's ends pinned:
// 3 600 bodies, 7 080 joints, swinging and colliding as it falls.
template <class SettingsOf>
void buildGridOfJoints(World& world, SettingsOf&& settingsOf) {
  constexpr int kSide = 60;
  std::vector<BodyId> bodies(kSide * kSide);
  for (int row = 0; row < kSide; ++row) {
    for (int column = 0; column < kSide; ++column) {
      const bool pinned = row == 0 && (column == 0 || column == kSide - 1);
      bodies[std::size_t(row * kSide + column)] =
          world.createCircle(Vec2(Real(column) - 30, 40 - Real(row)), Real(0.4), {.properties = {.isStatic = pinned}}).id;
    }
  }
  int joints = 0;
  auto join = [&](int a, int b) {
    const Vec2 anchor = world.bodyState(bodies[std::size_t(b)])->position;
    ASSERT_TRUE(world.createJoint({.bodyA = bodies[std::size_t(a)], .bodyB = bodies[std::size_t(b)],
                                   .anchorA = anchor, .anchorB = anchor,
                                   .settings = settingsOf(joints++)})
                    .ok());
  };
  for (int row = 0; row < kSide; ++row) {
    for (int column = 0; column < kSide; ++column) {
      const int here = row * kSide + column;
      if (column + 1 < kSide) join(here, here + 1);
      if (row + 1 < kSide) join(here, here + kSide);
    }
  }
}

// Plain pins.
void buildJointGrid(World& world) {
  buildGridOfJoints(world, [](int) { return RevoluteJointSettings{}; });
}

// Ragdoll-like joints: every mix of a limit a few degrees wide, a weak
// motor holding still and a soft spring.
void buildTurningJointGrid(World& world) {
  buildGridOfJoints(world, [](int k) {
    RevoluteJointSettings settings;
    settings.enableLimit = k % 2 == 0 || k % 7 == 0;
    settings.lowerAngle = Real(-0.1);
    settings.upperAngle = Real(0.1);
    settings.enableMotor = k % 3 != 0;
    settings.maxMotorTorque = Real(0.5);
    settings.stiffness = k % 5 < 2 ? Real(20) : Real(0);
    settings.damping = Real(0.2);
    return settings;
  });
}

// 3 000 circles and boxes created overlapping in a walled pit: the push
// pass runs on most contacts while they spread out.
void buildOverlappingPile(World& world) {
  addGround(world, 0, 40);
  for (Real x : {Real(-12), Real(12)}) {
    addBox(world, {.center = Vec2(x, 20), .halfWidth = Real(0.5), .halfHeight = 20, .isStatic = true});
  }
  std::mt19937 random(5);
  std::uniform_real_distribution<Real> x(-11, 11);
  std::uniform_real_distribution<Real> y(Real(0.5), 12);
  for (int i = 0; i < 3000; ++i) {
    const Vec2 centre(x(random), y(random));
    if (i % 2 == 0) {
      world.createCircle(centre, Real(0.3));
    } else {
      addBox(world, {.center = centre, .halfWidth = Real(0.3), .halfHeight = Real(0.3)});
    }
  }
}

constexpr Real kHailWallX = 30;

// 600 small circles and boxes fired at 120 m/s (2 m a step, many times
// their size) into a thin static wall, taller than any of them flies, and
// at each other: continuous
// collision sweeps hundreds of bodies a step and the broad phase queues
// most proxies.
void buildHail(World& world) {
  addGround(world, 0, 200);
  addBox(world, {.center = Vec2(kHailWallX, 50), .halfWidth = Real(0.05), .halfHeight = 50, .isStatic = true});
  std::mt19937 random(3);
  std::uniform_real_distribution<Real> x(-40, 0);
  std::uniform_real_distribution<Real> y(2, 58);
  std::uniform_real_distribution<Real> aim(-20, 20);
  for (int i = 0; i < 600; ++i) {
    const Vec2 centre(x(random), y(random));
    const Vec2 velocity(120, aim(random));
    if (i % 2 == 0) {
      world.createCircle(centre, Real(0.1), {.linearVelocity = velocity});
    } else {
      addBox(world, {.center = centre, .halfWidth = Real(0.1), .halfHeight = Real(0.1), .velocity = velocity});
    }
  }
}

// The struck pyramid (over 4 000 touching contacts: their sort runs beside
// the narrow phase's serial pass) and, on the ground to its left, 16 boxes
// created asleep, each woken by a circle dropped on it from its own height:
// steps on which that pass wakes bodies while the sort runs.
void buildStruckPyramidWakingSleepers(World& world) {
  buildStruckPyramid(world);
  for (int i = 0; i < 16; ++i) {
    const Real x = Real(-79 + i);
    BodyDef box;
    box.shape = Shape::makePolygon(makeBox(Real(0.3), Real(0.3)));
    box.position = Vec2(x, Real(0.3));
    box.isAwake = false;
    ASSERT_TRUE(world.createBody(box).ok());
    world.createCircle(Vec2(x, Real(1.5) + Real(0.25) * Real(i)), Real(0.2));
  }
}

// A kinematic drum of 24 capsule staves turning at 1 rad/s around 2 000
// circles and boxes: its hundreds of contacts all read the drum, which
// takes no colour (contacts cannot move it), so many lanes of a colour share
// it on several threads at once.
void buildTurningKinematicDrum(World& world) {
  constexpr int kStaves = 24;
  constexpr Real kRadius = 14;
  const auto stave = [&](int i) {
    const Real step = 2 * std::numbers::pi_v<Real> / kStaves;
    const auto at = [&](Real angle) { return Vec2(kRadius * std::cos(angle), kRadius * std::sin(angle)); };
    return Shape::makeCapsule(at(step * Real(i)), at(step * Real(i + 1)), Real(0.3));
  };
  BodyDef drum;
  drum.shape = stave(0);
  drum.position = Vec2(0, 20);
  drum.properties.isKinematic = true;
  drum.angularVelocity = 1;
  const CreateResult created = world.createBody(drum);
  ASSERT_TRUE(created.ok()) << created.error;
  for (int i = 1; i < kStaves; ++i) {
    ShapeDef def;
    def.shape = stave(i);
    ASSERT_TRUE(world.createShape(created.id, def).ok());
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> offset(-9, 9);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 centre = Vec2(0, 20) + Vec2(offset(random), offset(random));
    if (i % 2 == 0) {
      world.createCircle(centre, Real(0.2));
    } else {
      addBox(world, {.center = centre, .halfWidth = Real(0.2), .halfHeight = Real(0.2)});
    }
  }
}

WorldSettings wideSettings(const TaskSettings& tasks) {
  WorldSettings settings;
  settings.bounds = {Vec2(-150, -50), Vec2(150, 250)};
  settings.tasks = tasks;
  return settings;
}

std::vector<std::uint64_t> hashesAfterEachStep(SceneBuilder build, const TaskSettings& tasks, int steps) {
  World world(wideSettings(tasks));
  build(world);
  std::vector<std::uint64_t> hashes;
  for (int i = 0; i < steps; ++i) {
    world.step(kDt);
    hashes.push_back(world.stateHash());
  }
  return hashes;
}

void expectSameBits(const std::vector<std::uint64_t>& expected, const std::vector<std::uint64_t>& actual,
                    const char* what) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(expected[i], actual[i]) << what << ": states differ from one thread's after step " << i + 1;
  }
}

// The scene stepped on each of `workerCounts` threads gives `one` thread's
// hashes, step by step.
void expectSameBitsOn(std::initializer_list<int> workerCounts, SceneBuilder build,
                      const std::vector<std::uint64_t>& one) {
  for (int workers : workerCounts) {
    expectSameBits(one, hashesAfterEachStep(build, {.workerCount = workers}, int(one.size())),
                   ("workers " + std::to_string(workers)).c_str());
  }
}

// Two and three threads: the three-way split of every phase is checked too
// (on a 2-core machine the third thread only makes it slower).
TEST(WorkerThreads, StruckPyramidGivesTheSameBitsOnOneToThreeThreads) {
  const std::vector<std::uint64_t> one = hashesAfterEachStep(buildStruckPyramid, {}, 60);
  EXPECT_NE(one.front(), one.back()) << "the scene moves";
  expectSameBitsOn({2, 3}, buildStruckPyramid, one);
}

TEST(WorkerThreads, OverlappingPileGivesTheSameBitsOnOneAndTwoThreads) {
  World world(wideSettings({}));
  buildOverlappingPile(world);
  world.step(kDt);
  EXPECT_GT(world.profile().passes.pushedContacts, 2000) << "the push pass runs on a large part of the pile";
  expectSameBitsOn({2}, buildOverlappingPile, hashesAfterEachStep(buildOverlappingPile, {}, 40));
}

TEST(WorkerThreads, JointGridGivesTheSameBitsOnOneAndTwoThreads) {
  const std::vector<std::uint64_t> one = hashesAfterEachStep(buildJointGrid, {}, 60);
  EXPECT_NE(one.front(), one.back()) << "the grid swings";
  expectSameBitsOn({2}, buildJointGrid, one);
}

TEST(WorkerThreads, WakesDuringTheNarrowPhaseGiveTheSameBitsOnOneAndTwoThreads) {
  World world(wideSettings({}));
  buildStruckPyramidWakingSleepers(world);
  const int asleep = int(world.bodyIds().size()) - 1 - world.awakeBodyCount();  // less the ground
  ASSERT_EQ(asleep, 16);
  int wakingSteps = 0;
  for (int i = 0; i < 60; ++i) {
    const int awake = world.awakeBodyCount();
    world.step(kDt);
    const bool sortedBeside = world.profile().passes.contacts > 4096;
    wakingSteps += world.awakeBodyCount() > awake && sortedBeside ? 1 : 0;
  }
  EXPECT_GE(wakingSteps, 8) << "the circles wake their boxes on several steps, among over 4 096 touching contacts";
  expectSameBitsOn({2}, buildStruckPyramidWakingSleepers, hashesAfterEachStep(buildStruckPyramidWakingSleepers, {}, 60));
}

// The joints' blocks are filled side by side: a lane's settings must not
// share a byte with its neighbours'.
TEST(WorkerThreads, GridOfLimitedMotorisedSprungJointsGivesTheSameBitsOnOneToThreeThreads) {
  const std::vector<std::uint64_t> one = hashesAfterEachStep(buildTurningJointGrid, {}, 60);
  EXPECT_NE(one.front(), one.back()) << "the grid swings";
  expectSameBitsOn({2, 3}, buildTurningJointGrid, one);
}

TEST(WorkerThreads, TurningKinematicDrumGivesTheSameBitsOnOneToThreeThreads) {
  const std::vector<std::uint64_t> one = hashesAfterEachStep(buildTurningKinematicDrum, {}, 90);
  EXPECT_NE(one.front(), one.back()) << "the scene moves";
  expectSameBitsOn({2, 3}, buildTurningKinematicDrum, one);
}

TEST(WorkerThreads, HailThroughAThinWallGivesTheSameBitsOnOneAndTwoThreads) {
  expectSameBitsOn({2}, buildHail, hashesAfterEachStep(buildHail, {}, 40));
  World world(wideSettings({.workerCount = 2}));
  buildHail(world);
  for (int i = 0; i < 40; ++i) world.step(kDt);
  int through = 0;
  for (BodyId id : world.bodyIds()) through += world.bodyState(id)->position.x() > kHailWallX + Real(0.1) ? 1 : 0;
  EXPECT_EQ(through, 0) << "bodies went through the wall: the sweep missed them (without it, 548 of 600 do)";
}

// A game's job system that runs each task's ranges backwards, one range of
// minRange items at a time, and only when asked to finish: the most hostile
// order a job system could choose.
struct BackwardsJobs {
  struct Job {
    TaskFunction* task;
    int itemCount;
    int minRange;
    void* context;
  };
  Job pending{};
  int tasks = 0;
  int ranges = 0;

  static void* enqueue(TaskFunction* task, int itemCount, int minRange, void* context, void* user) {
    auto& jobs = *static_cast<BackwardsJobs*>(user);
    jobs.pending = {task, itemCount, minRange, context};
    ++jobs.tasks;
    return &jobs.pending;
  }
  static void finish(void* handle, void* user) {
    auto& jobs = *static_cast<BackwardsJobs*>(user);
    const Job& job = *static_cast<Job*>(handle);
    const int step = std::max(job.minRange, 1);
    for (int end = job.itemCount; end > 0; end -= step) {
      job.task(std::max(end - step, 0), end, 0, job.context);
      ++jobs.ranges;
    }
  }
};

TEST(WorkerThreads, AGamesJobSystemRunningRangesBackwardsGivesTheSameBits) {
  const std::vector<std::uint64_t> one = hashesAfterEachStep(buildStruckPyramid, {}, 60);
  BackwardsJobs jobs;
  const TaskSettings settings{.workerCount = 4,
                              .enqueueTask = &BackwardsJobs::enqueue,
                              .finishTask = &BackwardsJobs::finish,
                              .userContext = &jobs};
  expectSameBits(one, hashesAfterEachStep(buildStruckPyramid, settings, 60), "backwards jobs");
  EXPECT_GT(jobs.tasks, 60) << "every step handed phases to the job system";
  expectSameBits(hashesAfterEachStep(buildOverlappingPile, {}, 20),
                 hashesAfterEachStep(buildOverlappingPile, settings, 20), "backwards jobs, push pass");
  EXPECT_GT(jobs.ranges, 2 * jobs.tasks) << "phases were cut into several ranges";
}

TEST(WorkerThreads, ChangingTheWorkerCountBetweenStepsKeepsTheBits) {
  const std::vector<std::uint64_t> one = hashesAfterEachStep(buildStruckPyramid, {}, 40);
  World world(wideSettings({}));
  buildStruckPyramid(world);
  for (int i = 0; i < 40; ++i) {
    ASSERT_TRUE(world.setTaskSettings({.workerCount = 1 + i % 2}).ok());
    world.step(kDt);
    ASSERT_EQ(one[std::size_t(i)], world.stateHash()) << "after step " << i + 1;
  }
}

TEST(WorkerThreads, BadTaskSettingsAreRefusedAndChangeNothing) {
  World world(wideSettings({.workerCount = 2}));
  const InputResult none = world.setTaskSettings({.workerCount = 0});
  EXPECT_FALSE(none.ok());
  EXPECT_NE(none.error.find("worker count 0"), std::string::npos) << none.error;
  EXPECT_FALSE(world.setTaskSettings({.workerCount = kMaxWorkers + 1}).ok());
  BackwardsJobs jobs;
  const InputResult half = world.setTaskSettings({.workerCount = 2, .enqueueTask = &BackwardsJobs::enqueue,
                                                  .userContext = &jobs});
  EXPECT_FALSE(half.ok());
  EXPECT_NE(half.error.find("finishTask"), std::string::npos) << half.error;
  EXPECT_EQ(world.taskSettings().workerCount, 2);
  EXPECT_EQ(world.taskSettings().enqueueTask, nullptr);
}

}  // namespace
}  // namespace impulse
