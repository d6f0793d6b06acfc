#include "impulse/server/user_words.h"

#include <algorithm>
#include <array>
#include <utility>

#include "impulse/wire/command_table.h"
#include "impulse/wire/plain_numbers.h"

namespace impulse::server {

namespace {

using Case = v1::ClientMessage::CommandCase;

struct WordRow {
  Case wireCase;
  std::string_view wireName;
  std::string_view word;
};

#define IMPULSE_WORD_ROW(Case, field, role, handler, word, ...) \
  WordRow{v1::ClientMessage::k##Case, #field, word},
constexpr std::array kWordRows{IMPULSE_COMMAND_TABLE(IMPULSE_WORD_ROW)};
#undef IMPULSE_WORD_ROW

// Argument paths and the usage's names for them (the command table's usage
// column); paths not listed read as their field names ("distance stiffness").
// Longer paths first, so a path is replaced before its prefix.
constexpr std::array<std::pair<std::string_view, std::string_view>, 54> kArgumentWords{{
    {"spawn_circle.center.x", "circle X"},
    {"spawn_circle.center.y", "circle Y"},
    {"spawn_circle.center", "circle X Y"},
    {"spawn_circle.radius", "circle R"},
    {"spawn_circle.options.material", "circle MATERIAL"},
    {"spawn_polygon.options.material", "polygon MATERIAL"},
    {"spawn_capsule.center1.x", "capsule X1"},
    {"spawn_capsule.center1.y", "capsule Y1"},
    {"spawn_capsule.center2.x", "capsule X2"},
    {"spawn_capsule.center2.y", "capsule Y2"},
    {"spawn_capsule.radius", "capsule R"},
    {"spawn_segment.point1.x", "segment X1"},
    {"spawn_segment.point1.y", "segment Y1"},
    {"spawn_segment.point2.x", "segment X2"},
    {"spawn_segment.point2.y", "segment Y2"},
    {"spawn_body.position.x", "body X"},
    {"spawn_body.position.y", "body Y"},
    {"spawn_body.angle", "body ANGLE"},
    {"set_target_transform.position.x", "move-to X"},
    {"set_target_transform.position.y", "move-to Y"},
    {"set_target_transform.angle", "move-to ANGLE"},
    {"load_preset.material", "preset MATERIAL"},
    {"set_gravity.gravity.x", "gravity GX"},
    {"set_gravity.gravity.y", "gravity GY"},
    {"nudge_gravity.delta.x", "nudge DX"},
    {"nudge_gravity.delta.y", "nudge DY"},
    {"apply_impulse.impulse.x", "impulse JX"},
    {"apply_impulse.impulse.y", "impulse JY"},
    {"apply_impulse.point.x", "impulse PX"},
    {"apply_impulse.point.y", "impulse PY"},
    {"set_velocity.velocity.x", "velocity VX"},
    {"set_velocity.velocity.y", "velocity VY"},
    {"set_transform.position.x", "teleport X"},
    {"set_transform.position.y", "teleport Y"},
    {"set_transform.angle", "teleport ANGLE"},
    {"set_material.material", "material MATERIAL"},
    {"set_body_type.type", "body-type TYPE"},
    {"ray_cast.origin.x", "raycast X"},
    {"ray_cast.origin.y", "raycast Y"},
    {"ray_cast.translation.x", "raycast DX"},
    {"ray_cast.translation.y", "raycast DY"},
    {"shape_cast.position.x", "shapecast X"},
    {"shape_cast.position.y", "shapecast Y"},
    {"shape_cast.angle", "shapecast ANGLE"},
    {"shape_cast.translation.x", "shapecast DX"},
    {"shape_cast.translation.y", "shapecast DY"},
    {"query_aabb.lower.x", "overlap X1"},
    {"query_aabb.lower.y", "overlap Y1"},
    {"query_aabb.upper.x", "overlap X2"},
    {"query_aabb.upper.y", "overlap Y2"},
    {"update_joint.motor_speed", "motor SPEED"},
    {"set_interest_area.min", "area X1 Y1"},
    {"set_interest_area.max", "area X2 Y2"},
    {"set_bandwidth_budget.bytes_per_second", "budget BYTES_PER_SECOND"},
}};

// The engine's errors for a new joint name its JointDef; a joint's usage
// says A B, and 0 for the world.
constexpr std::array<std::pair<std::string_view, std::string_view>, 3> kJointWords{{
    {"bodyA", "A"},
    {"bodyB", "B"},
    {"the world (null)", "the world (0)"},
}};

// The word of a command that several rows share: chosen by what it carries.
std::string_view sharedWord(const v1::ClientMessage& message) {
  using Joint = v1::CreateJoint;
  using Field = v1::AddField;
  switch (message.command_case()) {
    case Case::kSetPaused: return message.set_paused().paused() ? "pause" : "resume";
    case Case::kUpdateJoint: return message.update_joint().has_target() ? "target" : "motor";
    case Case::kCreateJoint:
      switch (message.create_joint().kind_case()) {
        case Joint::kDistance: return "distance";
        case Joint::kRope: return "rope";
        case Joint::kRevolute: return "revolute";
        case Joint::kPrismatic: return "prismatic";
        case Joint::kWeld: return "weld";
        case Joint::kWheel: return "wheel";
        case Joint::kMouse: return "mouse";
        case Joint::KIND_NOT_SET: return {};
      }
      return {};
    case Case::kAddField:
      switch (message.add_field().kind_case()) {
        case Field::kGravitation: return "gravitation";
        case Field::kFluid: return "fluid";
        case Field::kFan: return "fan";
        case Field::KIND_NOT_SET: return {};
      }
      return {};
    default: return {};
  }
}

std::string_view wireNameOf(Case wireCase) {
  const auto row = std::ranges::find(kWordRows, wireCase, &WordRow::wireCase);
  return row == kWordRows.end() ? std::string_view() : row->wireName;
}

std::string replaceAll(std::string text, std::string_view from, std::string_view to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isPathChar(char c) {
  return (c >= 'a' && c <= 'z') || isDigit(c) || c == '_' || c == '.' || c == '[' || c == ']';
}

// "spawn_polygon.vertices[2].y" -> "polygon Y3": the usage counts from 1.
std::string polygonVertices(std::string text) {
  constexpr std::string_view kPrefix = "spawn_polygon.vertices[";
  for (auto at = text.find(kPrefix); at != std::string::npos; at = text.find(kPrefix, at + 1)) {
    std::size_t digits = at + kPrefix.size();
    std::size_t end = digits;
    while (end < text.size() && isDigit(text[end])) ++end;
    // "]." and the axis must follow the index.
    if (end == digits || end + 2 >= text.size() || text[end] != ']' || text[end + 1] != '.' ||
        (text[end + 2] != 'x' && text[end + 2] != 'y')) {
      continue;
    }
    const std::string words = std::string("polygon ") + (text[end + 2] == 'x' ? 'X' : 'Y') +
                              std::to_string(std::stoul(text.substr(digits, end - digits)) + 1);
    text.replace(at, end + 3 - at, words);
  }
  return text;
}

// "create_joint.distance.stiffness" -> "distance stiffness": the command's
// word, then the rest of the path as words (the kind the word already
// names, and "options", which the usage writes as flags, left out).
std::string pathInWords(std::string_view path, std::string_view word) {
  std::string words(word);
  std::size_t begin = path.find('.');
  bool first = true;
  while (begin != std::string_view::npos) {
    const std::size_t end = path.find('.', begin + 1);
    std::string part(path.substr(begin + 1, end == std::string_view::npos ? end : end - begin - 1));
    begin = end;
    const bool named = (first && part == word) || part == "options";
    first = false;
    if (named) continue;
    std::ranges::replace(part, '_', ' ');
    words += " " + part;
  }
  return words;
}

// Every remaining path of the command (or its bare wire name) in words.
std::string commandPaths(std::string text, std::string_view wireName, std::string_view word) {
  for (auto at = text.find(wireName); at != std::string::npos; at = text.find(wireName, at)) {
    if (at > 0 && isPathChar(text[at - 1])) {
      at += wireName.size();
      continue;
    }
    std::size_t end = at + wireName.size();
    while (end < text.size() && isPathChar(text[end])) ++end;
    // A sentence's full stop is not a path.
    while (end > at + wireName.size() && text[end - 1] == '.') --end;
    const std::string words = pathInWords(std::string_view(text).substr(at, end - at), word);
    text.replace(at, end - at, words);
    at += words.size();
  }
  return text;
}

}  // namespace

std::string_view commandWord(const v1::ClientMessage& message) {
  const auto wireCase = message.command_case();
  const auto rows = std::ranges::count(kWordRows, wireCase, &WordRow::wireCase);
  if (rows == 1) return std::ranges::find(kWordRows, wireCase, &WordRow::wireCase)->word;
  const std::string_view shared = sharedWord(message);
  return shared.empty() ? wireNameOf(wireCase) : shared;
}

std::string inUserWords(const v1::ClientMessage& message, std::string_view error) {
  std::string text = polygonVertices(std::string(error));
  for (const auto& [path, words] : kArgumentWords) text = replaceAll(std::move(text), path, words);
  if (message.has_create_joint()) {
    for (const auto& [name, words] : kJointWords) text = replaceAll(std::move(text), name, words);
  }
  const std::string_view wireName = wireNameOf(message.command_case());
  if (!wireName.empty()) text = commandPaths(std::move(text), wireName, commandWord(message));
  return wire::plainNumbers(text);
}

}  // namespace impulse::server
