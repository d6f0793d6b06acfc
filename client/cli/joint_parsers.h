#pragma once
// The script words that create and change joints (docs/protocol.md, "Joints"),
// one per joint kind; rows of the command table (impulse/wire/command_table.h).

#include <cstdint>
#include <optional>
#include <tuple>

#include "arguments.h"
#include "impulse.pb.h"
#include "impulse/client/commands.h"

namespace impulse::cli {

template <class Kind>
using JointWords = std::optional<std::tuple<client::JointEnds, Kind>>;

// distance A B AX AY BX BY [LENGTH [K [DAMPING]]] [collide]
JointWords<v1::DistanceJoint> parseDistance(Arguments& line);
// rope A B AX AY BX BY [MAX_LENGTH] [collide]
JointWords<v1::RopeJoint> parseRope(Arguments& line);
// revolute A B X Y [limit LO HI] [motor SPEED TORQUE] [spring K D] [collide]
JointWords<v1::RevoluteJoint> parseRevolute(Arguments& line);
// prismatic A B X Y DX DY [limit LO HI] [motor SPEED FORCE] [spring K D] [collide]
JointWords<v1::PrismaticJoint> parsePrismatic(Arguments& line);
// weld A B X Y [KL KA] [collide]
JointWords<v1::WeldJoint> parseWeld(Arguments& line);
// wheel A B X Y DX DY [spring K D] [motor SPEED TORQUE] [collide]
JointWords<v1::WheelJoint> parseWheel(Arguments& line);
// mouse A X Y MAX_FORCE [K D]
std::optional<std::tuple<std::uint32_t, client::Point, v1::MouseJoint>> parseMouse(
    Arguments& line);
// target J X Y
std::optional<std::tuple<std::uint32_t, client::Point>> parseJointTarget(Arguments& line);
// motor J SPEED [MAX]
std::optional<std::tuple<std::uint32_t, double, std::optional<double>>> parseJointMotor(
    Arguments& line);

}  // namespace impulse::cli
