#include "server_wording.h"

#include <array>
#include <functional>
#include <regex>
#include <utility>

#include "impulse/client/number_format.h"

namespace impulse::cli {

namespace {

// Protocol field paths and the script words for them; longer paths first,
// so a path is replaced before its command's prefix.
constexpr std::array<std::pair<const char*, const char*>, 23> kFieldWords{{
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
    {"remove_body", "remove"},
    {"query_body", "query"},
}};

std::string replaceAll(std::string text, std::string_view from, std::string_view to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

// `text` with every match of `pattern` replaced by what `replacement` makes of it.
std::string replaceMatches(const std::string& text, const std::regex& pattern,
                           const std::function<std::string(const std::smatch&)>& replacement) {
  std::string out;
  auto last = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), pattern), end; it != end; ++it) {
    out.append(last, (*it)[0].first);
    out += replacement(*it);
    last = (*it)[0].second;
  }
  out.append(last, text.cend());
  return out;
}

// "spawn_polygon.vertices[2].y" -> "polygon Y3": the script counts from 1.
std::string polygonVertices(const std::string& text) {
  static const std::regex vertex(R"(spawn_polygon\.vertices\[(\d+)\]\.([xy]))");
  return replaceMatches(text, vertex, [](const std::smatch& match) {
    return std::string("polygon ") + (match[2].str() == "x" ? 'X' : 'Y') +
           std::to_string(std::stoul(match[1].str()) + 1);
  });
}

// std::to_string's six fixed decimals ("-25.000000", "0.100000").
std::string tidyNumbers(const std::string& text) {
  static const std::regex fixed(R"(-?\d+\.\d{6}(?!\d))");
  return replaceMatches(text, fixed, [](const std::smatch& match) {
    return client::formatNumber(std::stod(match[0].str()));
  });
}

}  // namespace

std::string scriptWording(std::string_view serverError) {
  std::string text = polygonVertices(std::string(serverError));
  for (const auto& [field, words] : kFieldWords) text = replaceAll(std::move(text), field, words);
  return tidyNumbers(text);
}

}  // namespace impulse::cli
