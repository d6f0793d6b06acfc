// Rooms far from (0, 0): a room's world computes around its origin (its
// bounds' centre rounded to 10 km) and every position on the wire is from
// (0, 0), converted in double at the room's edge and the client's. So a
// pyramid 80 km out settles as the same pyramid at (0, 0) does, and a
// command at a far position lands where it asked, in both encodings.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "net_test_support.h"

namespace impulse::net_test {
namespace {

using client::Client;

/// The far room's floor centre: off its origin (80 km), so its positions are
/// not the near room's numbers shifted but floats of their own.
constexpr double kFarBaseX = 80037.5;
constexpr int kPyramidRows = 10;
constexpr std::uint32_t kSettleTicks = 300;

/// The admin making a 100 x 100 m room around a floor centred at (baseX, 0).
client::ConnectOptions roomAround(std::uint16_t port, double baseX,
                                  v1::SnapshotEncoding encoding = v1::SNAPSHOT_ENCODING_PLAIN) {
  auto options = localClient(port, "maker");
  options.room = "at" + std::to_string(std::int64_t(baseX));
  options.roomBounds = client::Box{{baseX - 50, -10}, {baseX + 50, 90}};
  options.snapshotEncoding = encoding;
  return options;
}

/// A client joining the room the maker made with those options.
client::ConnectOptions joinerOf(const client::ConnectOptions& maker, v1::SnapshotEncoding encoding) {
  auto options = maker;
  options.roomBounds.reset();
  options.name = "joiner";
  options.snapshotEncoding = encoding;
  return options;
}

/// Runs until the client's mirror holds `body` alone (ids start over after
/// a clear: an older body may have had its id).
void awaitOnly(Client& client, std::uint32_t body) {
  while (client.mirror().bodies().size() != 1 || !client.mirror().find(BodyId{body})) {
    ASSERT_TRUE(client.awaitSnapshot(milliseconds(3000)));
  }
}

Vec2d globalPosition(const Client& client, std::uint32_t body) {
  return client.mirror().toGlobal(client.mirror().find(BodyId{body})->state.position);
}

/// What a settled pyramid looks like from its base, metres.
struct PyramidFigures {
  double topHeight = 0;
  double meanHeight = 0;
  double largestDrift = 0;  ///< a box's sideways move from where it was made
  std::vector<Vec2d> relative;  ///< each box's position from the base
};

/// A floor at (baseX, 0) and a pyramid of 1 m boxes on it, built paused and
/// stepped kSettleTicks ticks; its boxes as the client's mirror holds them.
PyramidFigures settledPyramid(Client& client, double baseX) {
  EXPECT_TRUE(result(client.request(client::clearWorld())).ok());
  EXPECT_TRUE(result(client.request(client::setPaused(true))).ok());
  const std::vector<client::Point> floor{{baseX - 40, -1}, {baseX + 40, -1}, {baseX + 40, 0}, {baseX - 40, 0}};
  EXPECT_TRUE(result(client.request(client::spawnPolygon(floor, {.isStatic = true}))).ok());
  std::vector<std::pair<std::uint32_t, double>> boxes;  // id, x made at (from the base)
  for (int row = 0; row < kPyramidRows; ++row) {
    for (int column = 0; column < kPyramidRows - row; ++column) {
      const double x = (column - (kPyramidRows - row - 1) / 2.0) * 1.05;
      const double y = row * 1.0;
      const std::vector<client::Point> box{
          {baseX + x - 0.5, y}, {baseX + x + 0.5, y}, {baseX + x + 0.5, y + 1}, {baseX + x - 0.5, y + 1}};
      const v1::CommandResult made = result(client.request(client::spawnPolygon(box)));
      EXPECT_TRUE(made.ok()) << made.error();
      boxes.emplace_back(made.body_id(), x);
    }
  }
  const v1::CommandResult stepped = result(client.request(client::step(kSettleTicks)));
  EXPECT_TRUE(stepped.ok()) << stepped.error();
  while (client.mirror().tick() < stepped.tick()) EXPECT_TRUE(client.awaitSnapshot(milliseconds(3000)));

  PyramidFigures figures;
  for (const auto& [id, madeAtX] : boxes) {
    const Vec2d relative = globalPosition(client, id) - Vec2d(baseX, 0);
    figures.relative.push_back(relative);
    figures.topHeight = std::max(figures.topHeight, relative.y());
    figures.meanHeight += relative.y() / double(boxes.size());
    figures.largestDrift = std::max(figures.largestDrift, std::abs(relative.x() - madeAtX));
  }
  return figures;
}

TEST(RoomOrigin, APyramid80KmOutSettlesAsTheSamePyramidAtTheOrigin) {
  ServerProcess server;
  Client near(roomAround(server.port(), 0));
  Client far(roomAround(server.port(), kFarBaseX));
  EXPECT_EQ(far.welcome().world_origin().x(), 80000);
  EXPECT_EQ(far.welcome().world_origin().y(), 0);
  EXPECT_EQ(far.welcome().world_min().x(), kFarBaseX - 50) << "bounds from (0, 0)";

  const PyramidFigures atOrigin = settledPyramid(near, 0);
  const PyramidFigures farOut = settledPyramid(far, kFarBaseX);
  double largestDifference = 0;
  for (std::size_t i = 0; i < atOrigin.relative.size(); ++i) {
    largestDifference = std::max(largestDifference, (farOut.relative[i] - atOrigin.relative[i]).norm());
  }
  std::cout << "pyramid of " << atOrigin.relative.size() << " boxes after " << kSettleTicks
            << " ticks, at (0, 0) / at 80 km: top " << atOrigin.topHeight << " / " << farOut.topHeight << " m, mean "
            << atOrigin.meanHeight << " / " << farOut.meanHeight << " m, largest drift " << atOrigin.largestDrift
            << " / " << farOut.largestDrift << " m; largest difference of a box " << largestDifference << " m\n";
  EXPECT_NEAR(atOrigin.topHeight, kPyramidRows - 0.5, 0.1) << "the pyramid stands";
  EXPECT_NEAR(farOut.topHeight, atOrigin.topHeight, 0.1 * atOrigin.topHeight);
  EXPECT_NEAR(farOut.meanHeight, atOrigin.meanHeight, 0.1 * atOrigin.meanHeight);
  EXPECT_NEAR(farOut.largestDrift, atOrigin.largestDrift, 0.1 * atOrigin.largestDrift + 1e-4);
  EXPECT_LT(largestDifference, 0.01) << "a float 80 km from its origin would step by 7.8 mm";
}

TEST(RoomOrigin, ACommandAtAFarPositionLandsWhereItAsked_InEitherEncoding) {
  ServerProcess server;
  const client::ConnectOptions making = roomAround(server.port(), kFarBaseX);
  Client maker(making);
  Client quantized(joinerOf(making, v1::SNAPSHOT_ENCODING_QUANTIZED));
  ASSERT_TRUE(result(maker.request(client::clearWorld())).ok());
  // What the snapshots sent for each body since the clear, as sent: the
  // last one applied may carry none (a static ball is sent once).
  std::map<std::uint32_t, double> sentX;
  maker.onSnapshot([&](const v1::Snapshot& snapshot, std::size_t) {
    for (const v1::BodyState& body : snapshot.bodies()) sentX[body.id()] = body.position().x();
  });
  const client::Point asked{kFarBaseX + 12.345678, 20.125};
  const std::uint32_t ball =
      result(maker.request(client::spawnCircle(asked, 0.5, {.isStatic = true}))).body_id();

  const v1::ServerMessage info = maker.request(client::queryBody(ball));
  EXPECT_NEAR(info.body_info().state().position().x(), asked.x, 1e-5);
  EXPECT_NEAR(info.body_info().state().position().y(), asked.y, 1e-5);
  awaitOnly(maker, ball);
  EXPECT_NEAR(globalPosition(maker, ball).x(), asked.x, 1e-5);
  ASSERT_TRUE(sentX.contains(ball)) << "a snapshot carried the ball";
  EXPECT_NEAR(sentX.at(ball), asked.x, 1e-5) << "the snapshot from (0, 0)";
  awaitOnly(quantized, ball);
  // A quantized position is within a quantum (2^-9 m) of the truth.
  EXPECT_NEAR(globalPosition(quantized, ball).x(), asked.x, 1.0 / 512);
  EXPECT_NEAR(globalPosition(quantized, ball).y(), asked.y, 1.0 / 512);

  const v1::ServerMessage hit = maker.request(client::rayCast({asked.x - 5, asked.y}, {10, 0}));
  ASSERT_EQ(hit.query_result().hits_size(), 1);
  EXPECT_NEAR(hit.query_result().hits(0).point().x(), asked.x - 0.5, 1e-4) << "a query far out, answered from (0, 0)";

  const client::Point moved{kFarBaseX - 30.5, 2.75};
  ASSERT_TRUE(result(maker.request(client::setTransform(ball, moved))).ok());
  const v1::ServerMessage after = maker.request(client::queryBody(ball));
  EXPECT_NEAR(after.body_info().state().position().x(), moved.x, 1e-5);
  EXPECT_NEAR(after.body_info().state().position().y(), moved.y, 1e-5);
}

TEST(RoomOrigin, AFarRoomsSceneLoadsBackInPlace_AndIsRefusedWhereItsBodiesLieOutside) {
  ServerProcess server;
  Client far(roomAround(server.port(), kFarBaseX));
  ASSERT_TRUE(result(far.request(client::clearWorld())).ok());
  const client::Point asked{kFarBaseX + 3.25, 4.5};
  const std::uint32_t ball = result(far.request(client::spawnCircle(asked, 0.5, {.isStatic = true}))).body_id();
  const std::string scene = far.request(client::saveScene()).scene_data().data();

  ASSERT_TRUE(result(far.request(client::loadScene(scene))).ok());
  EXPECT_NEAR(far.request(client::queryBody(ball)).body_info().state().position().x(), asked.x, 1e-5);

  Client near(localClient(server.port(), "near"));
  const v1::CommandResult refused = result(near.request(client::loadScene(scene)));
  EXPECT_FALSE(refused.ok());
  EXPECT_TRUE(mentions(refused.error(), "outside the bounds")) << refused.error();
}

/// "(x, y)" as a refusal quotes a point: as written, without trailing zeros.
std::string quoted(double x, double y) {
  std::ostringstream text;
  text << std::setprecision(12) << "(" << x << ", " << y << ")";
  return text.str();
}

TEST(RoomOrigin, RefusalsQuotePositionsAndBoundsFromZero_AsTheClientGaveThem) {
  ServerProcess server;
  const client::ConnectOptions making = roomAround(server.port(), kFarBaseX);
  Client far(making);
  ASSERT_TRUE(result(far.request(client::clearWorld())).ok());
  const client::Box bounds = *making.roomBounds;

  const std::string outside =
      errorOf(far.request(client::spawnCircle({bounds.max.x + 100, 5}, 0.5)));
  EXPECT_TRUE(mentions(outside, "position is outside the world bounds " +
                                    quoted(bounds.min.x, bounds.min.y) + " to " +
                                    quoted(bounds.max.x, bounds.max.y)))
      << outside;

  // Points of application may lie within the bounds grown by the escape
  // margin (1000 m); one 2 km past the bounds is quoted as it was given.
  const std::uint32_t ball =
      result(far.request(client::spawnCircle({kFarBaseX + 0.25, 5}, 0.5))).body_id();
  const client::Point wayOut{bounds.max.x + 2000.75, 5.5};
  const std::string grown = quoted(bounds.min.x - 1000, bounds.min.y - 1000) + " to " +
                            quoted(bounds.max.x + 1000, bounds.max.y + 1000);
  const std::string pushed = errorOf(far.request(client::applyImpulse(ball, {1, 0}, wayOut)));
  EXPECT_TRUE(
      mentions(pushed, "impulse point " + quoted(wayOut.x, wayOut.y) + " is outside " + grown))
      << pushed;

  v1::MouseJoint mouse;
  mouse.set_max_force(1000);
  const std::uint32_t hand =
      result(far.request(client::mouseJoint(ball, {kFarBaseX + 0.25, 5}, mouse))).joint_id();
  const std::string dragged = errorOf(far.request(client::setJointTarget(hand, wayOut)));
  EXPECT_TRUE(mentions(dragged, "target " + quoted(wayOut.x, wayOut.y) + " is outside " + grown))
      << dragged;
}

/// A room as large as a level, 3 km from its origin (80 000, 0): its bounds
/// do not hold the preset scene where the presets draw it.
constexpr client::Box kLevelBounds{{83000, 0}, {83100, 100}};
/// Where a preset's scene origin lands in it: the scene's centre (12.5,
/// 9.375) on the bounds' centre (83 050, 50).
const Vec2d kLevelSceneOrigin(83037.5, 40.625);
/// Two floats 3 km out lie 0.24 mm apart: a mirror position there is within it.
constexpr double kMirrorResolution = 1e-3;

client::ConnectOptions roomWithBounds(std::uint16_t port, const std::string& name, const client::Box& bounds) {
  auto options = localClient(port, "maker");
  options.room = name;
  options.roomBounds = bounds;
  return options;
}

/// A preset's bodies (positions from (0, 0) by id) and markers' centres.
struct LoadedPreset {
  std::map<std::uint32_t, Vec2d> bodies;
  std::vector<Vec2d> markers;
};

/// Loads `preset` into the client's paused room, steps it `steps` ticks and
/// returns it as the client's mirror then holds it.
LoadedPreset loadedPreset(Client& client, int preset, std::uint32_t steps) {
  EXPECT_TRUE(result(client.request(client::setPaused(true))).ok());
  const v1::CommandResult loaded = result(client.request(client::loadPreset(preset)));
  EXPECT_TRUE(loaded.ok()) << loaded.error();
  const v1::CommandResult stepped = result(client.request(client::step(steps)));
  EXPECT_TRUE(stepped.ok()) << stepped.error();
  const auto holdsIt = [&] {
    const auto& shown = client.mirror().preset();
    return client.mirror().tick() >= stepped.tick() && shown && shown->id == preset;
  };
  while (!holdsIt()) {
    if (!client.awaitSnapshot(milliseconds(3000))) {
      ADD_FAILURE() << "no snapshot of preset " << preset << " after " << steps << " ticks";
      break;
    }
  }
  LoadedPreset seen;
  const client::WorldMirror& mirror = client.mirror();
  for (const auto& [id, body] : mirror.bodies()) seen.bodies[id] = mirror.toGlobal(body.state.position);
  if (mirror.preset()) {
    for (const Marker& marker : mirror.preset()->markers) seen.markers.push_back(mirror.toGlobal(marker.center));
  }
  return seen;
}

bool inside(const client::Box& bounds, const Vec2d& point) {
  return point.x() >= bounds.min.x && point.x() <= bounds.max.x && point.y() >= bounds.min.y &&
         point.y() <= bounds.max.y;
}

/// Preset `preset` loaded in a room around (0, 0) and in the level room,
/// stepped `steps` ticks: the level's is the same scene, moved whole.
void expectMovedWhole(int preset, std::uint32_t steps) {
  SCOPED_TRACE("preset " + std::to_string(preset));
  ServerProcess server;
  Client near(roomAround(server.port(), 0));
  Client level(roomWithBounds(server.port(), "level", kLevelBounds));
  const LoadedPreset atOrigin = loadedPreset(near, preset, steps);
  const LoadedPreset inLevel = loadedPreset(level, preset, steps);
  ASSERT_FALSE(atOrigin.bodies.empty());
  ASSERT_EQ(inLevel.bodies.size(), atOrigin.bodies.size()) << "every body of the scene is made";
  for (const auto& [id, place] : atOrigin.bodies) {
    const auto found = inLevel.bodies.find(id);
    ASSERT_NE(found, inLevel.bodies.end()) << "body " << id;
    EXPECT_TRUE(inside(kLevelBounds, found->second))
        << "body " << id << " at (" << found->second.x() << ", " << found->second.y() << ")";
    // The level computes around the scene's own origin, the same floats;
    // the mirror holds them 3 km from the room's, a quarter millimetre apart.
    EXPECT_LT((found->second - kLevelSceneOrigin - place).norm(), kMirrorResolution) << "body " << id;
  }
  ASSERT_EQ(inLevel.markers.size(), atOrigin.markers.size());
  for (std::size_t i = 0; i < atOrigin.markers.size(); ++i) {
    EXPECT_LT((inLevel.markers[i] - kLevelSceneOrigin - atOrigin.markers[i]).norm(), kMirrorResolution)
        << "marker " << i;
  }
}

TEST(RoomOrigin, APresetInALevelFarOutIsCentredOnItsBounds_ItsMarkersWithIt) {
  expectMovedWhole(3, 1);  // the polygon tutorial and its three markers
}

TEST(RoomOrigin, TheElevatorsScriptDrivesItsPlatformInALevelFarOut_AsAtTheOrigin) {
  expectMovedWhole(19, 120);  // 2 s: the platform has risen
}

TEST(RoomOrigin, APresetLargerThanTheRoomIsRefused_NamingBothSizes_AndTheWorldIsKept) {
  ServerProcess server;
  const client::Box narrow{{83000, 0}, {83020, 100}};
  Client maker(roomWithBounds(server.port(), "narrow", narrow));
  const v1::CommandResult made = result(maker.request(client::spawnCircle({83010, 50}, 0.5)));
  ASSERT_TRUE(made.ok()) << made.error();
  const std::string refused = errorOf(maker.request(client::loadPreset(1)));
  EXPECT_TRUE(mentions(refused, "preset scene is 25 x 18.75 m: it does not fit in the room's bounds (20 x 100 m)"))
      << refused;
  EXPECT_TRUE(maker.request(client::queryBody(made.body_id())).has_body_info()) << "the world is as it was";
}

}  // namespace
}  // namespace impulse::net_test
