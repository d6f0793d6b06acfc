#include "joint_parsers.h"

#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "impulse/wire/parse_number.h"

namespace impulse::cli {

namespace {

// A pair of numbers after a keyword ("limit LO HI", "motor SPEED MAX",
// "spring K D"): what each kind's optional settings look like on a line.
struct Group {
  std::string_view name;
  bool given = false;
  double first = 0;
  double second = 0;
};

// The optional words after a joint's fixed ones: up to `numbers.size()`
// plain numbers first (`count` says how many came), then the named groups
// and "collide" in any order.
struct Tail {
  std::vector<double> numbers;
  std::vector<Group> groups;
  bool collide = false;

  double number(std::size_t i, double fallback = 0) const {
    return i < numbers.size() ? numbers[i] : fallback;
  }
  const Group& group(std::string_view name) const {
    for (const Group& g : groups) {
      if (g.name == name) return g;
    }
    static const Group kNone;
    return kNone;
  }
};

bool readGroup(Arguments& line, std::size_t& i, Group& group) {
  const auto first = line.numberAt(i + 1), second = line.numberAt(i + 2);
  if (!first || !second) return false;
  group = {group.name, true, *first, *second};
  i += 3;
  return true;
}

bool readKeyword(Arguments& line, std::size_t& i, Tail& tail) {
  const std::string_view word = line.word(i);
  if (word == "collide") {
    tail.collide = true;
    ++i;
    return true;
  }
  for (Group& group : tail.groups) {
    if (group.name == word) return readGroup(line, i, group);
  }
  // Built by append: GCC 12 warns falsely (-Wrestrict) on " " + std::string(...).
  std::string expected = " (expected";
  for (const Group& group : tail.groups) {
    expected += ' ';
    expected.append(group.name);
    expected += ',';
  }
  expected.append(" collide)");
  line.note("unexpected " + quoted(word, expected));
  return false;
}

std::optional<Tail> readTail(Arguments& line, std::size_t from, std::size_t maxNumbers,
                             std::initializer_list<std::string_view> groups = {}) {
  Tail tail;
  for (const auto name : groups) tail.groups.push_back({name});
  std::size_t i = from;
  while (i < line.size() && tail.numbers.size() < maxNumbers) {
    const auto value = wire::parseNumber<double>(line.word(i));
    if (!value) break;
    tail.numbers.push_back(*value);
    ++i;
  }
  while (i < line.size()) {
    if (!readKeyword(line, i, tail)) return std::nullopt;
  }
  return tail;
}

// "A B AX AY [BX BY]": the bodies and anchors; with one point both anchors
// are that point (a pin, a weld, a wheel's centre).
std::optional<client::JointEnds> readEnds(Arguments& line, bool twoPoints) {
  const auto a = line.idAt(1), b = line.idAt(2);
  const auto ax = line.numberAt(3), ay = line.numberAt(4);
  if (!a || !b || !ax || !ay) return std::nullopt;
  client::JointEnds ends{*a, *b, {*ax, *ay}, {*ax, *ay}, false};
  if (twoPoints) {
    const auto bx = line.numberAt(5), by = line.numberAt(6);
    if (!bx || !by) return std::nullopt;
    ends.anchorB = {*bx, *by};
  }
  return ends;
}

// The ends (words 1-6 or 1-4), an axis after them when `axis` is set, then
// the tail from the next word.
struct JointLine {
  client::JointEnds ends;
  v1::Vec2 axis;
  Tail tail;
};

std::optional<JointLine> readJoint(Arguments& line, bool twoPoints, bool axis,
                                   std::size_t maxNumbers,
                                   std::initializer_list<std::string_view> groups = {}) {
  auto ends = readEnds(line, twoPoints);
  if (!ends) return std::nullopt;
  std::size_t next = twoPoints ? 7 : 5;
  JointLine result{*ends, {}, {}};
  if (axis) {
    const auto dx = line.numberAt(next), dy = line.numberAt(next + 1);
    if (!dx || !dy) return std::nullopt;
    result.axis.set_x(*dx);
    result.axis.set_y(*dy);
    next += 2;
  }
  auto tail = readTail(line, next, maxNumbers, groups);
  if (!tail) return std::nullopt;
  result.tail = std::move(*tail);
  result.ends.collideConnected = result.tail.collide;
  return result;
}

// "motor SPEED MAX" turns the motor on; `setMax` stores MAX as the kind's
// max torque or force.
template <class Kind, class SetMax>
void applyMotor(const Tail& tail, Kind& kind, SetMax setMax) {
  const Group& motor = tail.group("motor");
  if (!motor.given) return;
  kind.set_enable_motor(true);
  kind.set_motor_speed(motor.first);
  (kind.*setMax)(motor.second);
}

template <class Kind>
void applySpring(const Tail& tail, Kind& kind) {
  const Group& spring = tail.group("spring");
  kind.set_stiffness(spring.first);
  kind.set_damping(spring.second);
}

}  // namespace

JointWords<v1::DistanceJoint> parseDistance(Arguments& line) {
  const auto joint = readJoint(line, true, false, 3);
  if (!joint) return std::nullopt;
  v1::DistanceJoint kind;
  kind.set_length(joint->tail.number(0));
  kind.set_stiffness(joint->tail.number(1));
  kind.set_damping(joint->tail.number(2));
  return std::tuple{joint->ends, kind};
}

JointWords<v1::RopeJoint> parseRope(Arguments& line) {
  const auto joint = readJoint(line, true, false, 1);
  if (!joint) return std::nullopt;
  v1::RopeJoint kind;
  kind.set_max_length(joint->tail.number(0));
  return std::tuple{joint->ends, kind};
}

// Revolute and prismatic joints: "limit LO HI", "motor SPEED MAX" and
// "spring K D"; the two differ in their limit's and motor's field names.
template <class Kind, class SetBound, class SetMax>
void applyLimitMotorSpring(const Tail& tail, Kind& kind, SetBound setLower, SetBound setUpper,
                           SetMax setMax) {
  const Group& limit = tail.group("limit");
  kind.set_enable_limit(limit.given);
  (kind.*setLower)(limit.first);
  (kind.*setUpper)(limit.second);
  applyMotor(tail, kind, setMax);
  applySpring(tail, kind);
}

JointWords<v1::RevoluteJoint> parseRevolute(Arguments& line) {
  const auto joint = readJoint(line, false, false, 0, {"limit", "motor", "spring"});
  if (!joint) return std::nullopt;
  v1::RevoluteJoint kind;
  applyLimitMotorSpring(joint->tail, kind, &v1::RevoluteJoint::set_lower_angle,
                        &v1::RevoluteJoint::set_upper_angle,
                        &v1::RevoluteJoint::set_max_motor_torque);
  return std::tuple{joint->ends, kind};
}

JointWords<v1::PrismaticJoint> parsePrismatic(Arguments& line) {
  const auto joint = readJoint(line, false, true, 0, {"limit", "motor", "spring"});
  if (!joint) return std::nullopt;
  v1::PrismaticJoint kind;
  *kind.mutable_axis() = joint->axis;
  applyLimitMotorSpring(joint->tail, kind, &v1::PrismaticJoint::set_lower,
                        &v1::PrismaticJoint::set_upper, &v1::PrismaticJoint::set_max_motor_force);
  return std::tuple{joint->ends, kind};
}

JointWords<v1::WeldJoint> parseWeld(Arguments& line) {
  const auto joint = readJoint(line, false, false, 2);
  if (!joint) return std::nullopt;
  v1::WeldJoint kind;
  kind.set_linear_stiffness(joint->tail.number(0));
  kind.set_angular_stiffness(joint->tail.number(1));
  return std::tuple{joint->ends, kind};
}

JointWords<v1::WheelJoint> parseWheel(Arguments& line) {
  const auto joint = readJoint(line, false, true, 0, {"spring", "motor"});
  if (!joint) return std::nullopt;
  v1::WheelJoint kind;
  *kind.mutable_axis() = joint->axis;
  applyMotor(joint->tail, kind, &v1::WheelJoint::set_max_motor_torque);
  applySpring(joint->tail, kind);
  return std::tuple{joint->ends, kind};
}

std::optional<std::tuple<std::uint32_t, client::Point, v1::MouseJoint>> parseMouse(
    Arguments& line) {
  const auto body = line.idAt(1);
  const auto x = line.numberAt(2), y = line.numberAt(3), maxForce = line.numberAt(4);
  if (!body || !x || !y || !maxForce) return std::nullopt;
  const auto tail = readTail(line, 5, 2);
  if (!tail || !line.maxWords(7)) return std::nullopt;
  v1::MouseJoint kind;
  kind.set_max_force(*maxForce);
  kind.set_stiffness(tail->number(0));
  kind.set_damping(tail->number(1));
  return std::tuple{*body, client::Point{*x, *y}, kind};
}

std::optional<std::tuple<std::uint32_t, client::Point>> parseJointTarget(Arguments& line) {
  const auto joint = line.idAt(1);
  const auto x = line.numberAt(2), y = line.numberAt(3);
  if (!joint || !x || !y || !line.maxWords(4)) return std::nullopt;
  return std::tuple{*joint, client::Point{*x, *y}};
}

std::optional<std::tuple<std::uint32_t, double, std::optional<double>>> parseJointMotor(
    Arguments& line) {
  const auto joint = line.idAt(1);
  const auto speed = line.numberAt(2);
  if (!joint || !speed) return std::nullopt;
  std::optional<double> maxForce;
  if (line.size() > 3) {
    maxForce = line.numberAt(3);
    if (!maxForce) return std::nullopt;
  }
  if (!line.maxWords(4)) return std::nullopt;
  return std::tuple{*joint, *speed, maxForce};
}

}  // namespace impulse::cli
