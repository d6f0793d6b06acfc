// Snapshots: deltas leave out what did not change, and a mirror that applies
// them in order (from the start, or from a full snapshot taken at any time)
// always equals the world exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "impulse/client/world_mirror.h"
#include "impulse/server/simulation.h"
#include "impulse/server/snapshot_builder.h"
#include "impulse/wire/framing.h"

namespace impulse::server {
namespace {

v1::Snapshot decode(const SharedFrame& frame) {
  wire::FrameReader reader(std::size_t(64) << 20);
  const auto result = reader.feed(std::span<const char>(frame->data(), frame->size()));
  EXPECT_EQ(result.status, wire::FrameReader::Status::Frame);
  EXPECT_EQ(result.consumed, frame->size());
  v1::ServerMessage message;
  EXPECT_TRUE(wire::parseFrame(reader.frame(), message));
  EXPECT_TRUE(message.has_snapshot());
  return message.snapshot();
}

void expectMirrorEqualsWorld(const client::WorldMirror& mirror, const World& world) {
  const auto ids = world.bodyIds();
  ASSERT_EQ(mirror.bodies().size(), ids.size());
  for (const BodyId id : ids) {
    const auto* body = mirror.find(id);
    ASSERT_NE(body, nullptr) << id.value;
    const auto state = *world.bodyState(id);
    EXPECT_EQ(body->state.position, state.position) << id.value;
    EXPECT_EQ(body->state.angle, state.angle) << id.value;
    EXPECT_EQ(body->state.linearVelocity, state.linearVelocity) << id.value;
    EXPECT_EQ(body->state.angularVelocity, state.angularVelocity) << id.value;
    EXPECT_EQ(body->state.awake, state.awake) << id.value;
    EXPECT_EQ(body->shape.type(), world.bodyDescription(id)->shape.type());
  }
}

SimulationSettings pausedSandbox() {
  SimulationSettings settings;
  settings.paused = true;
  return settings;
}

TEST(SnapshotBuilder, FullSnapshotListsEveryBodyWithThePreset) {
  Simulation sim(pausedSandbox());
  SnapshotBuilder snapshots(sim);
  const auto snapshot = decode(snapshots.full());
  EXPECT_TRUE(snapshot.full());
  EXPECT_EQ(snapshot.preset().id(), 0);
  EXPECT_FALSE(snapshot.preset().title().empty());
  EXPECT_EQ(snapshot.added_size(), sim.world().bodyCount());
  EXPECT_EQ(snapshot.bodies_size(), sim.world().bodyCount());
}

TEST(SnapshotBuilder, DeltaLeavesOutSleepingAndUnchangedBodies) {
  Simulation sim(pausedSandbox());
  SnapshotBuilder snapshots(sim);
  snapshots.delta(sim.takeChanges());  // the preset's full snapshot
  const auto ball = sim.createCircle(Vec2(5, 5), 0.5f, {});
  ASSERT_TRUE(ball.ok()) << ball.error;
  sim.step();
  auto delta = decode(snapshots.delta(sim.takeChanges()));
  EXPECT_FALSE(delta.full());
  ASSERT_EQ(delta.added_size(), 1);
  EXPECT_EQ(delta.added(0).id(), ball.id.value);
  // The static walls never appear; the falling ball does.
  ASSERT_EQ(delta.bodies_size(), 1);
  EXPECT_EQ(delta.bodies(0).id(), ball.id.value);

  // Once everything sleeps, a step sends no body at all.
  for (int i = 0; i < 600 && sim.world().awakeBodyCount() > 0; ++i) sim.step();
  ASSERT_EQ(sim.world().awakeBodyCount(), 0);
  snapshots.delta(sim.takeChanges());
  sim.step();
  delta = decode(snapshots.delta(sim.takeChanges()));
  EXPECT_EQ(delta.bodies_size(), 0);
  EXPECT_EQ(delta.added_size(), 0);
}

TEST(SnapshotBuilder, ReplacedWorldGivesAFullSnapshotWithTheNewPreset) {
  Simulation sim(pausedSandbox());
  SnapshotBuilder snapshots(sim);
  snapshots.delta(sim.takeChanges());
  ASSERT_TRUE(sim.loadPreset(3, Material::Solid));
  const auto snapshot = decode(snapshots.delta(sim.takeChanges()));
  EXPECT_TRUE(snapshot.full());
  EXPECT_EQ(snapshot.preset().id(), 3);
  EXPECT_GT(snapshot.preset().markers_size(), 0);
}

// One random change: a spawn, a removal, a push while paused, now and then
// a clear, else a step.
void changeAtRandom(Simulation& sim, std::mt19937& random, std::vector<BodyId>& live, int round) {
  const int action = int(random() % 10);
  if (action < 4) {
    const auto created = sim.createCircle(Vec2(2 + float(random() % 20), 3 + float(random() % 12)),
                                          0.3f + 0.1f * (random() % 4), {});
    if (created.ok()) live.push_back(created.id);
  } else if (action == 4 && !live.empty()) {
    const std::size_t index = random() % live.size();
    ASSERT_TRUE(sim.removeBody(live[index]));
    live.erase(live.begin() + std::ptrdiff_t(index));
  } else if (action == 5 && !live.empty()) {
    const BodyId id = live[random() % live.size()];
    ASSERT_TRUE(sim.applyImpulse(id, Vec2(50, 80), std::nullopt));
  } else if (action == 6 && round % 40 == 6) {
    sim.clear();
    live.clear();
  } else {
    sim.step();
  }
}

TEST(SnapshotBuilder, MirrorsFollowTheWorldExactlyThroughRandomChanges) {
  Simulation sim(pausedSandbox());
  SnapshotBuilder snapshots(sim);
  client::WorldMirror fromStart;
  ASSERT_TRUE(fromStart.apply(decode(snapshots.delta(sim.takeChanges()))));
  client::WorldMirror lateJoiner;
  bool joined = false;
  std::mt19937 random(11);
  std::vector<BodyId> live;
  for (int round = 0; round < 120; ++round) {
    changeAtRandom(sim, random, live, round);
    // Between broadcasts, a client joins with a full snapshot of "now".
    if (!joined && round == 37) {
      ASSERT_TRUE(lateJoiner.apply(decode(snapshots.full())));
      joined = true;
    }
    if (round % 3 == 2) {
      const auto delta = decode(snapshots.delta(sim.takeChanges()));
      std::string error;
      ASSERT_TRUE(fromStart.apply(delta, &error)) << error;
      expectMirrorEqualsWorld(fromStart, sim.world());
      if (joined) {
        ASSERT_TRUE(lateJoiner.apply(delta, &error)) << error;
        expectMirrorEqualsWorld(lateJoiner, sim.world());
      }
    }
  }
}

void expectMirrorWithinAQuantum(const client::WorldMirror& mirror, const World& world) {
  namespace q = wire::quantized;
  const Real position = Real(double(q::kPositionQuantum) * q::kPositionUnit);
  const Real velocity = Real(double(q::kVelocityQuantum) * q::kVelocityUnit);
  ASSERT_EQ(mirror.bodies().size(), std::size_t(world.bodyCount()));
  for (const auto& [id, body] : mirror.bodies()) {
    const auto truth = world.bodyState(BodyId{id});
    ASSERT_TRUE(truth) << id;
    EXPECT_LT((body.state.position - truth->position).cwiseAbs().maxCoeff(), position) << id;
    EXPECT_LT(std::abs(body.state.angle - truth->angle), position) << id;
    EXPECT_LT((body.state.linearVelocity - truth->linearVelocity).cwiseAbs().maxCoeff(), velocity)
        << id;
    EXPECT_EQ(body.state.awake, truth->awake) << id;
  }
}

// Quantized mirrors see every broadcast's states within a quantum; a client
// that joins between broadcasts starts from a key frame (the baseline's
// states, not "now") and is within a quantum from the next delta on.
TEST(SnapshotBuilder, QuantizedMirrorsFollowTheWorldWithinAQuantumThroughRandomChanges) {
  Simulation sim(pausedSandbox());
  SnapshotBuilder snapshots(sim);
  client::WorldMirror fromStart;
  ASSERT_TRUE(fromStart.apply(decode(snapshots.quantizedFull())));
  client::WorldMirror lateJoiner;
  bool joined = false;
  std::mt19937 random(12);
  std::vector<BodyId> live;
  for (int round = 0; round < 150; ++round) {
    changeAtRandom(sim, random, live, round);
    if (!joined && round == 40) {
      ASSERT_TRUE(lateJoiner.apply(decode(snapshots.quantizedFull())));
      joined = true;
    }
    if (round % 3 == 2) {
      WorldChanges& changes = sim.takeChanges();
      snapshots.delta(changes);
      const auto delta = decode(snapshots.quantizedDelta(changes));
      EXPECT_EQ(delta.bodies_size(), 0);
      std::string error;
      ASSERT_TRUE(fromStart.apply(delta, &error)) << error;
      expectMirrorWithinAQuantum(fromStart, sim.world());
      if (joined) {
        ASSERT_TRUE(lateJoiner.apply(delta, &error)) << error;
        expectMirrorWithinAQuantum(lateJoiner, sim.world());
      }
    }
  }
}

}  // namespace
}  // namespace impulse::server
