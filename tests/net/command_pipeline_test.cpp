// The server's command pipeline: a message resolved to its table row once,
// its reply completed in one place, its changes read from the simulation.

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "impulse/client/commands.h"
#include "impulse/server/access.h"
#include "impulse/server/commands.h"
#include "impulse/server/wire_box.h"
#include "impulse/wire/scene_convert.h"

namespace impulse::server {
namespace {

v1::ClientMessage withRequest(v1::ClientMessage message, std::uint64_t id) {
  message.set_request_id(id);
  return message;
}

// The request id of whichever message answers.
std::uint64_t requestIdOf(const v1::ServerMessage& reply) {
  switch (reply.message_case()) {
    case v1::ServerMessage::kCommandResult:
      return reply.command_result().request_id();
    case v1::ServerMessage::kPong:
      return reply.pong().request_id();
    case v1::ServerMessage::kBodyInfo:
      return reply.body_info().request_id();
    case v1::ServerMessage::kJointInfo:
      return reply.joint_info().request_id();
    case v1::ServerMessage::kRoomList:
      return reply.room_list().request_id();
    case v1::ServerMessage::kSceneData:
      return reply.scene_data().request_id();
    case v1::ServerMessage::kQueryResult:
      return reply.query_result().request_id();
    default:
      return 0;
  }
}

TEST(CommandPipeline, EveryKindOfReplyNamesItsRequest) {
  Simulation simulation(SimulationSettings{.preset = 0});
  const CommandOutcome spawned = applyCommand(simulation, client::spawnCircle({0, 5}, 0.5), {});
  const std::uint32_t body = spawned.reply.command_result().body_id();
  const CommandOutcome joined =
      applyCommand(simulation, client::distanceJoint({body, 0, {0, 5}, {0, 6}}, {}), {});
  const std::uint32_t joint = joined.reply.command_result().joint_id();
  ASSERT_NE(joint, 0u) << joined.reply.command_result().error();
  const std::vector<v1::ClientMessage> commands = {client::setGravity({0, -5}),
                                                   client::queryBody(body),
                                                   client::queryJoint(joint),
                                                   client::ping(7),
                                                   client::listRooms(),
                                                   client::saveScene(),
                                                   client::rayCast({-5, 5}, {10, 0}),
                                                   client::queryBody(9999),
                                                   v1::ClientMessage{}};
  std::set<v1::ServerMessage::MessageCase> kinds;
  std::uint64_t id = 100;
  for (const v1::ClientMessage& command : commands) {
    const CommandOutcome outcome = applyCommand(simulation, withRequest(command, ++id), {});
    kinds.insert(outcome.reply.message_case());
    EXPECT_EQ(requestIdOf(outcome.reply), id) << commandName(command);
  }
  EXPECT_EQ(kinds.size(), 7u)
      << "a result, body and joint info, pong, room list, scene and query result";
}

TEST(CommandPipeline, AResultCarriesTheTickItsLatenessAndTheSendersWords) {
  Simulation simulation(SimulationSettings{.preset = 0, .paused = true});
  for (int i = 0; i < 5; ++i) simulation.step();
  v1::ClientMessage late = client::setGravity({0, -3});
  late.set_for_tick(2);
  const v1::CommandResult applied = applyCommand(simulation, late, {}).reply.command_result();
  EXPECT_TRUE(applied.ok());
  EXPECT_EQ(applied.tick(), 5u);
  EXPECT_TRUE(applied.late());

  const v1::CommandResult refused =
      applyCommand(simulation, client::spawnCircle({0, 5}, std::nan("")), {})
          .reply.command_result();
  EXPECT_FALSE(refused.ok());
  EXPECT_EQ(refused.tick(), 5u);
  EXPECT_FALSE(refused.late()) << "not stamped";
  EXPECT_EQ(refused.error(), "circle R is not a finite number") << "in the words of the script";
}

// A command's "changed" is the simulation's version moving: no handler says it.
TEST(CommandPipeline, ChangedIsWhatTheSimulationRecorded) {
  Simulation simulation(SimulationSettings{.preset = 0, .paused = true});
  EXPECT_TRUE(applyCommand(simulation, client::setPaused(true), {}).changed)
      << "the pause flag is meta";
  EXPECT_TRUE(applyCommand(simulation, client::spawnCircle({0, 5}, 0.5), {}).changed);
  EXPECT_FALSE(applyCommand(simulation, client::spawnCircle({0, 5}, -1), {}).changed) << "refused";
  EXPECT_FALSE(applyCommand(simulation, client::queryBody(1), {}).changed) << "a read";
  EXPECT_FALSE(applyCommand(simulation, client::ping(1), {}).changed);
  EXPECT_FALSE(applyCommand(simulation, client::removeBody(9999), {}).changed) << "unknown body";
}

TEST(CommandPipeline, AMessageWithoutARowIsRefusedByName) {
  Simulation simulation(SimulationSettings{.preset = 0});
  EXPECT_EQ(findCommand(v1::ClientMessage{}), nullptr);
  v1::ClientMessage hello;
  hello.mutable_hello()->set_client_name("again");
  EXPECT_EQ(findCommand(hello), nullptr);
  EXPECT_NE(applyCommand(simulation, hello, {})
                .reply.command_result()
                .error()
                .find("hello was already received"),
            std::string::npos);
  const CommandRow* row = findCommand(client::loadScene("x"));
  ASSERT_NE(row, nullptr);
  EXPECT_EQ(row->name, "load_scene");
  EXPECT_EQ(row->role, CommandRole::Admin);
}

// Applies `message` for `client` as the room does, through its row once.
v1::CommandResult applyAs(Simulation& simulation, Ownership& ownership,
                          const v1::ClientMessage& message, std::uint32_t client) {
  const CommandRow& row = *findCommand(message);
  CommandOutcome outcome = applyCommand(simulation, row, message, {});
  ownership.recordOutcome(row, message, outcome.reply, client, simulation);
  return outcome.reply.command_result();
}

// A scene load replaces the world, so owners are forgotten; a refused one
// replaced nothing, so the player keeps its body.
TEST(CommandPipeline, OnlyASceneLoadedForgetsWhatPlayersOwn) {
  constexpr std::uint32_t kPlayer = 7, kAdmin = 1;
  Simulation simulation(SimulationSettings{.preset = 0});
  Ownership ownership;
  const std::uint32_t body =
      applyAs(simulation, ownership, client::spawnCircle({5, 5}, 0.5), kPlayer).body_id();
  const v1::ClientMessage push = client::applyImpulse(body, {1, 0});
  const CommandRow& pushRow = *findCommand(push);
  ASSERT_TRUE(ownership.playerRefusal(pushRow, push, kPlayer).empty());

  EXPECT_FALSE(applyAs(simulation, ownership, client::loadScene("not a scene"), kAdmin).ok());
  EXPECT_TRUE(ownership.playerRefusal(pushRow, push, kPlayer).empty())
      << "the world was not replaced";

  const std::string scene = wire::saveScene(simulation.world());
  ASSERT_TRUE(applyAs(simulation, ownership, client::loadScene(scene), kAdmin).ok());
  ASSERT_TRUE(simulation.world().isValid(BodyId{body})) << "the scene has a body of that id";
  EXPECT_NE(ownership.playerRefusal(pushRow, push, kPlayer).find("was not created by this client"),
            std::string::npos);
}

v1::Vec2 corner(double x, double y) {
  v1::Vec2 point;
  point.set_x(x);
  point.set_y(y);
  return point;
}

// Interest areas and room bounds are read by the same checker: one rule
// set, refusals that name the message's own fields.
TEST(WireBox, CornersAreCheckedByTheRulesGiven) {
  const WireBoxRules rules{.message = "m",
                           .minField = "lo",
                           .maxField = "hi",
                           .what = "box",
                           .bothOrNeither = "or neither",
                           .maxCoordinate = 100,
                           .minSide = 2,
                           .maxSide = 50};
  const auto error = [&](const v1::Vec2* lo, const v1::Vec2* hi) {
    return boxFromWire(lo, hi, rules).error;
  };
  const v1::Vec2 origin = corner(0, 0), ten = corner(10, 10), far = corner(150, 0),
                 thin = corner(1, 10), wide = corner(60, 10), nan = corner(std::nan(""), 0);
  EXPECT_FALSE(boxFromWire(nullptr, nullptr, rules).box);
  EXPECT_TRUE(error(nullptr, nullptr).empty());
  EXPECT_EQ(error(&origin, nullptr), "m.hi is missing (or neither)");
  EXPECT_EQ(error(&nan, &ten), "m.lo is not a finite point");
  EXPECT_EQ(error(&origin, &far),
            "m.hi (150, 0) lies outside the largest box: each coordinate must be within +-100 m");
  EXPECT_EQ(error(&origin, &thin),
            "m is 1 m wide and 10 m high: m.hi must exceed m.lo by at least 2 m in x and y");
  EXPECT_EQ(error(&ten, &origin),
            "m is -10 m wide and -10 m high: m.hi must exceed m.lo by at least 2 m in x and y");
  EXPECT_EQ(error(&origin, &wide), "m is 60 m wide and 10 m high: each side may be at most 50 m");
  const WireBox box = boxFromWire(&origin, &ten, rules);
  ASSERT_TRUE(box.box);
  EXPECT_EQ(box.box->upper, Vec2(10, 10));
}

}  // namespace
}  // namespace impulse::server
