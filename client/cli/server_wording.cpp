#include "server_wording.h"

#include <array>
#include <utility>

#include "impulse/wire/plain_numbers.h"

namespace impulse::cli {

namespace {

// Protocol field paths and the script words for them; longer paths first,
// so a path is replaced before its command's prefix.
constexpr std::array<std::pair<const char*, const char*>, 37> kFieldWords{{
    {"spawn_circle.center.x", "circle X"},
    {"spawn_circle.center.y", "circle Y"},
    {"spawn_circle.center", "circle X Y"},
    {"spawn_circle.radius", "circle R"},
    {"spawn_circle.options.material", "circle MATERIAL"},
    {"spawn_circle", "circle"},
    {"spawn_polygon.options.material", "polygon MATERIAL"},
    {"spawn_polygon", "polygon"},
    {"load_preset.material", "preset MATERIAL"},
    {"load_preset", "preset"},
    {"set_gravity.gravity.x", "gravity GX"},
    {"set_gravity.gravity.y", "gravity GY"},
    {"set_gravity", "gravity"},
    {"nudge_gravity.delta.x", "nudge DX"},
    {"nudge_gravity.delta.y", "nudge DY"},
    {"nudge_gravity", "nudge"},
    {"apply_impulse.impulse.x", "impulse JX"},
    {"apply_impulse.impulse.y", "impulse JY"},
    {"apply_impulse.point.x", "impulse PX"},
    {"apply_impulse.point.y", "impulse PY"},
    {"apply_impulse", "impulse"},
    {"set_velocity.velocity.x", "velocity VX"},
    {"set_velocity.velocity.y", "velocity VY"},
    {"set_velocity", "velocity"},
    {"set_transform.position.x", "teleport X"},
    {"set_transform.position.y", "teleport Y"},
    {"set_transform.angle", "teleport ANGLE"},
    {"set_transform", "teleport"},
    {"set_material.material", "material MATERIAL"},
    {"set_material", "material"},
    {"set_body_type.type", "body-type TYPE"},
    {"set_body_type", "body-type"},
    {"remove_body", "remove"},
    {"query_body", "query"},
    // Joint errors keep their protocol paths (create_joint.distance.stiffness):
    // the seven joint words share one message, so a path has no single word.
    {"remove_joint", "remove-joint"},
    {"query_joint", "query-joint"},
    // Field errors keep theirs too (add_field.fan.speed): three words share AddField.
    {"remove_field", "remove-field"},
}};

std::string replaceAll(std::string text, std::string_view from, std::string_view to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// "spawn_polygon.vertices[2].y" -> "polygon Y3": the script counts from 1.
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

}  // namespace

std::string scriptWording(std::string_view serverError) {
  std::string text = polygonVertices(std::string(serverError));
  for (const auto& [field, words] : kFieldWords) text = replaceAll(std::move(text), field, words);
  return wire::plainNumbers(text);
}

}  // namespace impulse::cli
