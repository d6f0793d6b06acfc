// Every subscriber's picture of the world is the world (issue 30): random
// bursts of commands from several clients (presets, pause, spawns, removals,
// clears, steps, scene loads, joints, fields) while plain and quantized
// subscribers, fast and slow, and the viewer's own picture (the client
// library feeding an InterpolatedWorld, as the viewer's Connection does)
// follow. After every burst the world is paused and each picture must come
// to equal what a newcomer's full snapshot shows.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <sstream>

#include "impulse/wire/convert.h"
#include "impulse/wire/quantized_state.h"
#include "interpolated_world.h"
#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;
using client::MirrorBody;
using client::WorldMirror;
using SteadyClock = std::chrono::steady_clock;
namespace q = wire::quantized;

double localSeconds() {
  return std::chrono::duration<double>(SteadyClock::now().time_since_epoch()).count();
}

// ------------------------------------------------------------- comparison

// How far a picture's body states may be from the world's.
struct Tolerance {
  double position = 0;
  double velocity = 0;
};

constexpr Tolerance kExact{};
const Tolerance kQuantum{double(q::kPositionQuantum) * q::kPositionUnit,
                         double(q::kVelocityQuantum) * q::kVelocityUnit};

// Two shapes are the same when they say the same on the wire (every kind,
// every number).
bool sameShape(const Shape& a, const Shape& b) {
  v1::Shape wireA, wireB;
  wire::toWire(a, &wireA);
  wire::toWire(b, &wireB);
  return wireA.SerializeAsString() == wireB.SerializeAsString();
}

bool near(const Vec2& a, const Vec2& b, double tolerance) {
  return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

std::string describeState(const BodyState& s) {
  std::ostringstream text;
  text << "(" << s.position.x() << ", " << s.position.y() << ") angle " << s.angle << " v ("
       << s.linearVelocity.x() << ", " << s.linearVelocity.y() << ") w " << s.angularVelocity
       << (s.awake ? " awake" : " asleep");
  return text.str();
}

std::string compareState(std::uint32_t id, const BodyState& truth, const BodyState& seen,
                         Tolerance tolerance) {
  const bool same = near(truth.position, seen.position, tolerance.position) &&
                    std::abs(truth.angle - seen.angle) <= tolerance.position &&
                    near(truth.linearVelocity, seen.linearVelocity, tolerance.velocity) &&
                    std::abs(truth.angularVelocity - seen.angularVelocity) <= tolerance.velocity &&
                    truth.awake == seen.awake;
  if (same) return {};
  return "body " + std::to_string(id) + " is " + describeState(seen) + ", the world's " +
         describeState(truth);
}

template <class Map>
std::string compareIds(const char* what, const Map& truth, const Map& seen) {
  if (truth.size() == seen.size() &&
      std::equal(truth.begin(), truth.end(), seen.begin(),
                 [](const auto& a, const auto& b) { return a.first == b.first; })) {
    return {};
  }
  auto list = [](const Map& map) {
    std::string text;
    for (const auto& entry : map) text.append(" ").append(std::to_string(entry.first));
    return text;
  };
  return std::string(what) + ":" + list(seen) + " instead of" + list(truth);
}

// The first difference between a client's mirror and the world's, or "".
std::string compareMirror(const WorldMirror& truth, const WorldMirror& seen, Tolerance tolerance) {
  if (seen.tick() != truth.tick()) {
    return "tick " + std::to_string(seen.tick()) + " instead of " + std::to_string(truth.tick());
  }
  if (seen.paused() != truth.paused()) return "not paused";
  if (seen.gravity() != truth.gravity()) return "gravity differs";
  if (seen.timeScale() != truth.timeScale()) return "time scale differs";
  if (auto problem = compareIds("bodies", truth.bodies(), seen.bodies()); !problem.empty()) {
    return problem;
  }
  if (auto problem = compareIds("joints", truth.joints(), seen.joints()); !problem.empty()) {
    return problem;
  }
  if (auto problem = compareIds("fields", truth.fields(), seen.fields()); !problem.empty()) {
    return problem;
  }
  for (const auto& [id, body] : truth.bodies()) {
    const MirrorBody& other = seen.bodies().at(id);
    if (!sameShape(body.shape, other.shape) || body.material != other.material ||
        body.isStatic != other.isStatic || body.ignoreGravity != other.ignoreGravity) {
      return "body " + std::to_string(id) + " has another body's shape or material";
    }
    if (auto problem = compareState(id, body.state, other.state, tolerance); !problem.empty()) {
      return problem;
    }
  }
  return {};
}

// The first difference between what the viewer draws now and the world.
std::string compareView(const WorldMirror& truth, const viewer::InterpolatedWorld& view,
                        Tolerance tolerance) {
  const auto& drawn = view.bodies();
  std::string ids;
  for (const auto& body : drawn) ids.append(" ").append(std::to_string(body.state.id));
  if (drawn.size() != truth.bodies().size()) {
    return "draws " + std::to_string(drawn.size()) + " bodies (" + ids + " ) instead of " +
           std::to_string(truth.bodies().size());
  }
  auto body = drawn.begin();
  for (const auto& [id, world] : truth.bodies()) {
    if (body->state.id != id) return "draws bodies" + ids + ", not body " + std::to_string(id);
    if (!sameShape(body->look->shape, world.shape) || body->look->material != world.material) {
      return "draws body " + std::to_string(id) + " with another body's shape or material";
    }
    const auto& s = body->state;
    const BodyState seen{BodyId{id}, s.position, s.angle, s.velocity, s.angularVelocity, s.awake};
    if (auto problem = compareState(id, world.state, seen, tolerance); !problem.empty()) {
      return "draws " + problem;
    }
    ++body;
  }
  return {};
}

// ------------------------------------------------------------- subscribers

// A picture under test: a subscribed client, and for a viewer the
// InterpolatedWorld it feeds exactly as the viewer's Connection does.
struct Subscriber {
  std::string label;
  Tolerance tolerance;
  /// Read only when checked: its small socket buffer fills and the server
  /// makes it skip snapshots.
  bool slow = false;
  std::unique_ptr<Client> client;
  std::unique_ptr<viewer::InterpolatedWorld> view;
  int mismatches = 0;

  std::string difference(const WorldMirror& truth) {
    if (!view) return compareMirror(truth, client->mirror(), tolerance);
    view->update(localSeconds());
    return compareView(truth, *view, tolerance);
  }
};

Subscriber subscribe(std::uint16_t port, std::string label, bool quantized, bool slow,
                     bool viewer) {
  auto options = localClient(port, label);
  if (quantized) options.snapshotEncoding = v1::SNAPSHOT_ENCODING_QUANTIZED;
  // A few KiB: the server's send buffer fills after a few large snapshots.
  if (slow) options.receiveBufferBytes = 4096;
  Subscriber subscriber{std::move(label), quantized ? kQuantum : kExact, slow,
                        std::make_unique<Client>(options), nullptr};
  if (viewer) {
    // Connection::adopt: reset, seed with the first snapshot, then every
    // snapshot applied as it arrives.
    auto& client = *subscriber.client;
    subscriber.view =
        std::make_unique<viewer::InterpolatedWorld>(1.0 / client.welcome().snapshot_hz());
    subscriber.view->seed(client.mirror(), localSeconds());
    client.onSnapshot(
        [view = subscriber.view.get(), &client](const v1::Snapshot& snapshot, std::size_t) {
          view->onSnapshot(client.mirror(), snapshot, localSeconds());
        });
  }
  return subscriber;
}

// ------------------------------------------------------------- the viewer's bug

// A snapshot at tick `tick` (30 Hz) describing `circles` (id, radius), each
// at (id, 1).
v1::Snapshot snapshotAt(int tick, bool full,
                        const std::vector<std::pair<std::uint32_t, double>>& circles = {}) {
  v1::Snapshot snapshot;
  snapshot.set_tick(std::uint64_t(tick));
  snapshot.set_sim_time(tick / 30.0);
  snapshot.set_full(full);
  snapshot.set_time_scale(1);
  for (const auto& [id, radius] : circles) {
    auto* descriptor = snapshot.add_added();
    descriptor->set_id(id);
    descriptor->mutable_shape()->mutable_circle()->set_radius(radius);
    auto* state = snapshot.add_bodies();
    state->set_id(id);
    state->mutable_position()->set_x(id);
    state->mutable_position()->set_y(1);
  }
  return snapshot;
}

// A viewer's picture fed snapshots by hand, as its Connection feeds them.
struct ViewerPicture {
  WorldMirror mirror;
  viewer::InterpolatedWorld view{1.0 / 30.0};
  void feed(const v1::Snapshot& snapshot) {
    ASSERT_TRUE(mirror.apply(snapshot));
    view.onSnapshot(mirror, snapshot, snapshot.sim_time());
  }
};

double drawnRadius(const viewer::InterpolatedWorld& view, std::uint32_t id) {
  for (const auto& body : view.bodies()) {
    if (body.state.id == id) return body.look->shape.circle().radius;
  }
  return 0;
}

// `preset 0`, `pause`, `circle ...` in one tick: a full snapshot without the
// old world's body 5, then a delta adding the new ball as body 5 (ids start
// over with each world). The viewer kept "body 5 departed at T" and, once
// its frames were past T, dropped the look the ball had just been given:
// the ball was never drawn again.
TEST(WorldPicture, ViewerDrawsABodyAddedUnderAnIdOfTheWorldItReplaced) {
  ViewerPicture picture;
  viewer::InterpolatedWorld& view = picture.view;
  auto feed = [&](const v1::Snapshot& snapshot) { picture.feed(snapshot); };
  feed(snapshotAt(0, true, {{1, 0.5}, {2, 0.5}, {3, 0.5}, {4, 0.5}, {5, 0.25}}));
  for (int tick = 1; tick <= 10; ++tick) feed(snapshotAt(tick, false));
  feed(snapshotAt(11, true, {{1, 0.5}, {2, 0.5}, {3, 0.5}, {4, 0.5}}));
  feed(snapshotAt(11, false, {{5, 1.0}}));
  // Frames before the load still show the old world's body 5, as it was.
  view.update(11 / 30.0);
  ASSERT_LT(view.renderTime(), 11 / 30.0);
  EXPECT_EQ(drawnRadius(view, 5), 0.25);
  for (int tick = 12; tick <= 60; ++tick) {
    feed(snapshotAt(tick, false));
    view.update(tick / 30.0);
  }
  ASSERT_GT(view.renderTime(), 12 / 30.0);
  EXPECT_EQ(view.bodies().size(), 5u);
  EXPECT_EQ(drawnRadius(view, 5), 1.0);
}

// A frame's bodies are read again before the next frame is sampled (the
// energy plot, picking under the cursor), after the snapshots that arrived
// in between. A removal retired the look its drawn body pointed at, freeing
// it: the viewer read freed memory (a crash in CI, a re-added body's look
// under the same address here).
TEST(WorldPicture, AFramesBodiesKeepTheirLooksThroughTheSnapshotsThatFollowIt) {
  ViewerPicture picture;
  viewer::InterpolatedWorld& view = picture.view;
  auto feed = [&](const v1::Snapshot& snapshot) { picture.feed(snapshot); };
  feed(snapshotAt(0, true, {{1, 0.5}, {2, 0.25}}));
  for (int tick = 1; tick <= 10; ++tick) feed(snapshotAt(tick, false));
  view.update(10 / 30.0);
  ASSERT_EQ(drawnRadius(view, 2), 0.25);
  v1::Snapshot removal = snapshotAt(11, false, {{3, 1.0}});
  removal.add_removed(2);
  feed(removal);
  feed(snapshotAt(12, true, {{1, 0.75}}));
  // Still the frame sampled before both snapshots, each body as it was.
  ASSERT_EQ(view.bodies().size(), 2u);
  EXPECT_EQ(drawnRadius(view, 1), 0.5);
  EXPECT_EQ(drawnRadius(view, 2), 0.25);
}

// ------------------------------------------------------------- bursts

// Random commands that mostly make sense for the world as last seen.
class BurstMaker {
 public:
  BurstMaker(std::uint32_t seed, const v1::Welcome& welcome) : random_(seed) {
    lower_ = {welcome.world_min().x(), welcome.world_min().y()};
    upper_ = {welcome.world_max().x(), welcome.world_max().y()};
  }

  std::vector<v1::ClientMessage> burst(const WorldMirror& world,
                                       const std::vector<std::string>& scenes) {
    std::vector<v1::ClientMessage> commands;
    const int count = uniform(2, 9);
    for (int i = 0; i < count; ++i) commands.push_back(command(world, scenes));
    return commands;
  }

 private:
  int uniform(int low, int high) { return std::uniform_int_distribution(low, high)(random_); }
  double real(double low, double high) {
    return std::uniform_real_distribution(low, high)(random_);
  }
  client::Point somewhere() {
    // Inside the sandbox's walls, above its floor.
    return {real(2, std::min(upper_.x - 2, 22.0)), real(2, std::min(upper_.y - 2, 14.0))};
  }
  std::uint32_t anyBody(const WorldMirror& world) {
    if (world.bodies().empty() || uniform(0, 9) == 0) return std::uint32_t(uniform(1, 40));
    auto it = world.bodies().begin();
    std::advance(it, uniform(0, int(world.bodies().size()) - 1));
    return it->first;
  }
  template <class Map>
  std::uint32_t anyOf(const Map& map) {
    if (map.empty()) return std::uint32_t(uniform(1, 5));
    auto it = map.begin();
    std::advance(it, uniform(0, int(map.size()) - 1));
    return it->first;
  }

  v1::ClientMessage joint(const WorldMirror& world) {
    const std::uint32_t a = anyBody(world);
    const std::uint32_t b = uniform(0, 2) == 0 ? 0 : anyBody(world);
    auto position = [&](std::uint32_t id) {
      const MirrorBody* body = world.find(BodyId{id});
      return body ? client::Point{body->state.position.x(), body->state.position.y()} : somewhere();
    };
    client::JointEnds ends{a, b, position(a), position(b)};
    if (b == 0) ends.anchorB = {ends.anchorA.x, ends.anchorA.y + 1};
    return client::distanceJoint(ends, v1::DistanceJoint{});
  }

  v1::ClientMessage field() {
    if (uniform(0, 1) == 0) return client::gravitationField(0.05);
    v1::Fan fan;
    const auto at = somewhere();
    fan.mutable_position()->set_x(at.x);
    fan.mutable_position()->set_y(1);
    fan.mutable_direction()->set_y(1);
    fan.set_speed(8);
    fan.set_range(10);
    fan.set_spread(0.4);
    return client::fanField(fan);
  }

  v1::ClientMessage polygon() {
    const auto c = somewhere();
    const double h = real(0.2, 0.8);
    const std::vector<client::Point> box{
        {c.x - h, c.y - h}, {c.x + h, c.y - h}, {c.x + h, c.y + h}, {c.x - h, c.y + h}};
    return client::spawnPolygon(box);
  }

  v1::ClientMessage command(const WorldMirror& world, const std::vector<std::string>& scenes) {
    switch (uniform(0, 16)) {
      case 0:
        return client::loadPreset(uniform(0, kPresetCount - 1));
      case 1:
        return client::setPaused(true);
      case 2:
        return client::setPaused(false);
      case 3:
      case 4: {
        client::SpawnOptions options;
        options.material = Material::Rubber;
        return client::spawnCircle(somewhere(), real(0.2, 1.0), options);
      }
      case 5:
        return polygon();
      case 6:
        return client::removeBody(anyBody(world));
      case 7:
        return client::applyImpulse(anyBody(world), {real(-5, 5), real(0, 10)});
      case 8:
        return client::clearWorld();
      case 9:
        return client::step(std::uint32_t(uniform(1, 4)));
      case 10:
        return client::saveScene();
      case 11:
        if (scenes.empty()) return client::saveScene();
        return client::loadScene(scenes[std::size_t(uniform(0, int(scenes.size()) - 1))]);
      case 12:
        return joint(world);
      case 13:
        return client::removeJoint(anyOf(world.joints()));
      case 14:
        return field();
      case 15:
        return client::removeField(anyOf(world.fields()));
      default:
        return client::setGravity({real(-2, 2), real(-12, -2)});
    }
  }

  std::mt19937 random_;
  client::Point lower_;
  client::Point upper_;
};

std::uint32_t propertySeed() {
  if (const char* text = std::getenv("IMPULSE_PROPERTY_SEED"))
    return std::uint32_t(std::atol(text));
  return 30;
}

// Polls `subscribers` that are not slow while waiting for `done`.
template <class Done>
void serveWhile(std::vector<Subscriber>& subscribers, Done done) {
  const auto deadline = SteadyClock::now() + std::chrono::seconds(20);
  while (!done()) {
    ASSERT_LT(SteadyClock::now(), deadline) << "a burst was not answered within 20 s";
    for (auto& subscriber : subscribers) {
      if (!subscriber.slow) subscriber.client->poll(milliseconds(0));
    }
    std::this_thread::sleep_for(milliseconds(1));
  }
}

TEST(WorldPicture, EverySubscribersPictureIsTheWorldAfterEveryBurst) {
  constexpr int kBursts = 60;
  constexpr int kDrivers = 3;
  const std::uint32_t seed = propertySeed();
  ServerProcess server;

  std::vector<std::unique_ptr<Client>> drivers;
  for (int i = 0; i < kDrivers; ++i) {
    drivers.push_back(
        std::make_unique<Client>(localClient(server.port(), "driver" + std::to_string(i), false)));
  }
  std::vector<Subscriber> subscribers;
  subscribers.push_back(subscribe(server.port(), "plain fast", false, false, false));
  subscribers.push_back(subscribe(server.port(), "plain slow", false, true, false));
  subscribers.push_back(subscribe(server.port(), "quantized fast", true, false, false));
  subscribers.push_back(subscribe(server.port(), "quantized slow", true, true, false));
  subscribers.push_back(subscribe(server.port(), "viewer", false, false, true));
  subscribers.push_back(subscribe(server.port(), "quantized viewer", true, false, true));

  BurstMaker maker(seed, drivers[0]->welcome());
  std::vector<std::string> scenes;
  std::optional<Client> truth;
  truth.emplace(localClient(server.port(), "truth"));
  int commandsSent = 0;
  int checks = 0;
  std::string firstMismatch;
  const auto start = SteadyClock::now();

  for (int burst = 0; burst < kBursts; ++burst) {
    // Every driver's burst goes out at once, then every reply is awaited.
    std::vector<std::vector<std::uint64_t>> sent(kDrivers);
    for (int d = 0; d < kDrivers; ++d) {
      for (auto& command : maker.burst(truth->mirror(), scenes)) {
        sent[std::size_t(d)].push_back(drivers[std::size_t(d)]->send(std::move(command)));
        ++commandsSent;
      }
    }
    for (int d = 0; d < kDrivers; ++d) {
      for (const std::uint64_t id : sent[std::size_t(d)]) {
        std::optional<v1::ServerMessage> reply;
        serveWhile(subscribers, [&] {
          reply = drivers[std::size_t(d)]->awaitReply(id, milliseconds(0));
          return reply.has_value();
        });
        if (reply && reply->has_scene_data() && scenes.size() < 8) {
          scenes.push_back(reply->scene_data().data());
        }
      }
    }
    // The world runs a little (if the burst left it running), then stops.
    const auto until = SteadyClock::now() + milliseconds(20 * (burst % 5));
    serveWhile(subscribers, [&] { return SteadyClock::now() >= until; });
    ASSERT_TRUE(result(drivers[0]->request(client::setPaused(true))).ok());

    truth.reset();
    truth.emplace(localClient(server.port(), "truth"));
    for (auto& subscriber : subscribers) {
      ++checks;
      std::string difference;
      const auto deadline = SteadyClock::now() + milliseconds(3000);
      do {
        subscriber.client->poll(milliseconds(5));
        difference = subscriber.difference(truth->mirror());
      } while (!difference.empty() && SteadyClock::now() < deadline);
      if (difference.empty()) continue;
      ++subscriber.mismatches;
      if (firstMismatch.empty()) {
        firstMismatch =
            "burst " + std::to_string(burst) + ", " + subscriber.label + ": " + difference;
      }
    }
  }

  const auto stats = drivers[0]->ping().stats();
  const double seconds = std::chrono::duration<double>(SteadyClock::now() - start).count();
  std::printf(
      "world picture (seed %u): %d bursts, %d commands from %d clients, %zu subscribers, "
      "%d checks, %llu snapshots skipped, %zu scenes saved, %.1f s\n",
      seed, kBursts, commandsSent, kDrivers, subscribers.size(), checks,
      static_cast<unsigned long long>(stats.snapshots_skipped()), scenes.size(), seconds);
  for (const auto& subscriber : subscribers) {
    EXPECT_EQ(subscriber.mismatches, 0) << subscriber.label;
  }
  EXPECT_TRUE(firstMismatch.empty()) << "first mismatch: " << firstMismatch;
  // The bursts did reach the slow subscribers' limits and used scenes.
  EXPECT_FALSE(scenes.empty());
}

}  // namespace
}  // namespace impulse::net_test
