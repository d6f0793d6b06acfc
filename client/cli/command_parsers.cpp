#include "command_parsers.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

#include "impulse/client/commands.h"
#include "impulse/wire/command_table.h"
#include "impulse/wire/convert.h"
#include "impulse/wire/parse_number.h"
#include "field_parsers.h"
#include "joint_parsers.h"

namespace impulse::cli {

namespace {

// Each parser turns a line's words into its builder's arguments, or nothing
// with the problem noted.

std::optional<std::tuple<int, Material>> parsePreset(Arguments& line) {
  const auto id = line.integerAt(1);
  if (!id) return std::nullopt;
  Material material = Material::Solid;
  if (line.size() > 2) {
    const auto named = wire::materialFromName(line.word(2));
    if (!named) {
      line.refuse(quoted(line.word(2), " is not a material"));
      return std::nullopt;
    }
    material = *named;
  }
  if (!line.maxWords(3)) return std::nullopt;
  return std::tuple{int(*id), material};
}

std::optional<std::tuple<>> parseNoArguments(Arguments& line) {
  if (!line.maxWords(1)) return std::nullopt;
  return std::tuple{};
}

std::optional<std::tuple<bool>> parsePause(Arguments& line) {
  if (!parseNoArguments(line)) return std::nullopt;
  return std::tuple{true};
}

std::optional<std::tuple<bool>> parseResume(Arguments& line) {
  if (!parseNoArguments(line)) return std::nullopt;
  return std::tuple{false};
}

std::optional<std::tuple<std::uint32_t>> parseStep(Arguments& line) {
  const auto ticks = line.integerAt(1);
  if (!ticks || !line.maxWords(2)) return std::nullopt;
  if (*ticks < 1 || *ticks > 0xffffffffLL) {
    line.refuse("tick count out of range");
    return std::nullopt;
  }
  return std::tuple{std::uint32_t(*ticks)};
}

std::optional<std::tuple<client::Point, double, client::SpawnOptions>> parseCircle(
    Arguments& line) {
  const auto x = line.numberAt(1), y = line.numberAt(2), r = line.numberAt(3);
  if (!x || !y || !r) return std::nullopt;
  client::SpawnOptions options;
  if (!line.bodyFlags(4, options)) return std::nullopt;
  return std::tuple{client::Point{*x, *y}, *r, options};
}

// What a parser calls the points it reads, in errors.
struct Noun {
  const char* one;
  const char* many;
};

// The X Y pairs from word `i` on, up to the first word that is not a
// number; `i` ends past them. Nothing (noted, calling each a `noun`) when a
// pair lacks its y or there is none.
std::optional<std::vector<client::Point>> readPoints(Arguments& line, std::size_t& i, const Noun& noun) {
  std::vector<client::Point> points;
  while (i < line.size() && wire::parseNumber<double>(line.word(i))) {
    const auto x = line.numberAt(i), y = line.numberAt(i + 1);
    if (!y) {
      line.refuse(std::string(noun.one) + " " + std::to_string(points.size() + 1) + " has no y");
      return std::nullopt;
    }
    points.push_back({*x, *y});
    i += 2;
  }
  if (points.empty()) {
    line.refuse(std::string("no ") + noun.many);
    return std::nullopt;
  }
  return points;
}

std::optional<std::tuple<std::vector<client::Point>, client::SpawnOptions>> parsePolygon(
    Arguments& line) {
  std::size_t i = 1;
  auto points = readPoints(line, i, {"vertex", "vertices"});
  if (!points) return std::nullopt;
  client::SpawnOptions options;
  if (!line.bodyFlags(i, options)) return std::nullopt;
  // Too few or too many vertices are for the server to judge, with the
  // same message every client gets.
  return std::tuple{std::move(*points), options};
}

std::optional<std::tuple<client::Point, client::Point, double, client::SpawnOptions>> parseCapsule(
    Arguments& line) {
  const auto x1 = line.numberAt(1), y1 = line.numberAt(2), x2 = line.numberAt(3), y2 = line.numberAt(4);
  const auto r = line.numberAt(5);
  if (!x1 || !y1 || !x2 || !y2 || !r) return std::nullopt;
  client::SpawnOptions options;
  if (!line.bodyFlags(6, options)) return std::nullopt;
  return std::tuple{client::Point{*x1, *y1}, client::Point{*x2, *y2}, *r, options};
}

std::optional<std::tuple<client::Point, client::Point, client::SpawnOptions>> parseSegment(Arguments& line) {
  const auto x1 = line.numberAt(1), y1 = line.numberAt(2), x2 = line.numberAt(3), y2 = line.numberAt(4);
  if (!x1 || !y1 || !x2 || !y2) return std::nullopt;
  client::SpawnOptions options;
  if (!line.bodyFlags(5, options)) return std::nullopt;
  return std::tuple{client::Point{*x1, *y1}, client::Point{*x2, *y2}, options};
}

std::optional<std::tuple<std::vector<client::Point>, bool, client::SpawnOptions>> parseChain(Arguments& line) {
  std::size_t i = 1;
  auto points = readPoints(line, i, {"point", "points"});
  if (!points) return std::nullopt;
  const bool loop = i < line.size() && line.word(i) == "loop";
  client::SpawnOptions options;
  if (!line.bodyFlags(loop ? i + 1 : i, options)) return std::nullopt;
  return std::tuple{std::move(*points), loop, options};
}

// One PART of `body`: circle CX CY R | box CX CY HW HH | capsule X1 Y1 X2 Y2 R,
// from word `i` (which ends past it).
std::optional<client::BodyPart> readBodyPart(Arguments& line, std::size_t& i) {
  using Kind = client::BodyPart::Kind;
  static const std::array<std::tuple<std::string_view, Kind, int>, 3> kinds{
      {{"circle", Kind::Circle, 3}, {"box", Kind::Box, 4}, {"capsule", Kind::Capsule, 5}}};
  for (const auto& [word, kind, count] : kinds) {
    if (line.word(i) != word) continue;
    std::array<double, 5> n{};
    for (int k = 0; k < count; ++k) {
      const auto value = line.numberAt(i + 1 + std::size_t(k));
      if (!value) return std::nullopt;
      n[std::size_t(k)] = *value;
    }
    i += std::size_t(count) + 1;
    if (kind == Kind::Circle) return client::BodyPart{kind, {n[0], n[1]}, {}, n[2]};
    if (kind == Kind::Box) return client::BodyPart{kind, {n[0], n[1]}, {n[2], n[3]}, 0};
    return client::BodyPart{kind, {n[0], n[1]}, {n[2], n[3]}, n[4]};
  }
  return std::nullopt;
}

std::optional<std::tuple<client::Point, double, std::vector<client::BodyPart>, client::SpawnOptions>> parseBody(
    Arguments& line) {
  const auto x = line.numberAt(1), y = line.numberAt(2), angle = line.numberAt(3);
  if (!x || !y || !angle) return std::nullopt;
  std::vector<client::BodyPart> parts;
  std::size_t i = 4;
  while (i < line.size()) {
    auto part = readBodyPart(line, i);
    if (!part) break;
    parts.push_back(*part);
  }
  if (parts.empty()) {
    line.refuse("no parts (circle CX CY R, box CX CY HW HH or capsule X1 Y1 X2 Y2 R)");
    return std::nullopt;
  }
  client::SpawnOptions options;
  if (!line.bodyFlags(i, options)) return std::nullopt;
  for (client::BodyPart& part : parts) part.material = options.material;
  return std::tuple{client::Point{*x, *y}, *angle, std::move(parts), options};
}

std::optional<std::tuple<std::uint32_t, client::Point, double>> parseTarget(Arguments& line) {
  const auto id = line.integerAt(1);
  const auto x = line.numberAt(2), y = line.numberAt(3);
  if (!id || !x || !y) return std::nullopt;
  double angle = 0;
  if (line.size() > 4) {
    const auto given = line.numberAt(4);
    if (!given) return std::nullopt;
    angle = *given;
  }
  if (!line.maxWords(5)) return std::nullopt;
  if (*id < 0 || *id > 0xffffffffLL) {
    line.refuse("body id out of range");
    return std::nullopt;
  }
  return std::tuple{std::uint32_t(*id), client::Point{*x, *y}, angle};
}

// material ID MATERIAL
std::optional<std::tuple<std::uint32_t, Material>> parseBodyMaterial(Arguments& line) {
  const auto id = line.idAt(1);
  if (!id) return std::nullopt;
  if (line.size() < 3) {
    line.refuse("MATERIAL is missing");
    return std::nullopt;
  }
  const auto material = wire::materialFromName(line.word(2));
  if (!material) {
    line.refuse(quoted(line.word(2), " is not a material"));
    return std::nullopt;
  }
  if (!line.maxWords(3)) return std::nullopt;
  return std::tuple{*id, *material};
}

// body-type ID static|kinematic|dynamic
std::optional<std::tuple<std::uint32_t, BodyType>> parseBodyType(Arguments& line) {
  static constexpr std::array<std::pair<std::string_view, BodyType>, 3> kTypes{
      {{"static", BodyType::Static}, {"kinematic", BodyType::Kinematic}, {"dynamic", BodyType::Dynamic}}};
  const auto id = line.idAt(1);
  if (!id) return std::nullopt;
  if (line.size() < 3) {
    line.refuse("TYPE is missing (static, kinematic or dynamic)");
    return std::nullopt;
  }
  const auto type = std::find_if(kTypes.begin(), kTypes.end(), [&](const auto& row) { return row.first == line.word(2); });
  if (type == kTypes.end()) {
    line.refuse(quoted(line.word(2), " is not a body type (static, kinematic or dynamic)"));
    return std::nullopt;
  }
  if (!line.maxWords(3)) return std::nullopt;
  return std::tuple{*id, type->second};
}

std::optional<std::tuple<client::Point>> parsePoint(Arguments& line) {
  const auto x = line.numberAt(1), y = line.numberAt(2);
  if (!x || !y || !line.maxWords(3)) return std::nullopt;
  return std::tuple{client::Point{*x, *y}};
}

std::optional<std::tuple<std::uint32_t>> parseBodyId(Arguments& line) {
  const auto id = line.idAt(1);
  if (!id || !line.maxWords(2)) return std::nullopt;
  return std::tuple{*id};
}

std::optional<std::tuple<std::uint32_t, client::Point, std::optional<client::Point>>> parseImpulse(
    Arguments& line) {
  const auto id = line.idAt(1);
  const auto jx = line.numberAt(2), jy = line.numberAt(3);
  if (!id || !jx || !jy) return std::nullopt;
  std::optional<client::Point> point;
  if (line.size() > 4) {
    const auto px = line.numberAt(4), py = line.numberAt(5);
    if (!px || !py) return std::nullopt;
    point = client::Point{*px, *py};
  }
  if (!line.maxWords(6)) return std::nullopt;
  return std::tuple{*id, client::Point{*jx, *jy}, point};
}

std::optional<std::tuple<std::uint32_t, client::Point, double>> parseVelocity(Arguments& line) {
  const auto id = line.idAt(1);
  const auto vx = line.numberAt(2), vy = line.numberAt(3);
  if (!id || !vx || !vy) return std::nullopt;
  const auto angular = line.size() > 4 ? line.numberAt(4) : std::optional<double>(0);
  if (!angular || !line.maxWords(5)) return std::nullopt;
  return std::tuple{*id, client::Point{*vx, *vy}, *angular};
}

// flags ID WORD...: every word a shape flag or filter word.
std::optional<std::tuple<std::uint32_t, ShapeInteraction>> parseShapeFlags(Arguments& line) {
  const auto id = line.idAt(1);
  if (!id) return std::nullopt;
  ShapeInteraction flags;
  for (std::size_t i = 2; i < line.size(); ++i) {
    if (line.shapeFlag(line.word(i), flags)) continue;
    line.note("unexpected " + quoted(line.word(i), " (sensor, contact-events, hit-events, no-sensor-events, "
                                                   "category=N, mask=N or group=N)"));
    return std::nullopt;
  }
  return std::tuple{*id, flags};
}

// category=N and mask=N words from `from` on.
bool readQueryFilter(Arguments& line, std::size_t from, QueryFilter& filter) {
  for (std::size_t i = from; i < line.size(); ++i) {
    const std::string_view word = line.word(i);
    ShapeInteraction read;
    read.filter.categoryBits = filter.categoryBits;
    read.filter.maskBits = filter.maskBits;
    if ((word.starts_with("category=") || word.starts_with("mask=")) && line.shapeFlag(word, read)) {
      filter = {read.filter.categoryBits, read.filter.maskBits};
      continue;
    }
    line.note("unexpected " + quoted(word, " (category=N or mask=N)"));
    return false;
  }
  return true;
}

std::optional<std::tuple<client::Point, client::Point, bool, QueryFilter, std::uint32_t>> parseRayCast(
    Arguments& line) {
  const auto x = line.numberAt(1), y = line.numberAt(2), dx = line.numberAt(3), dy = line.numberAt(4);
  if (!x || !y || !dx || !dy) return std::nullopt;
  const bool all = line.size() > 5 && line.word(5) == "all";
  QueryFilter filter;
  if (!readQueryFilter(line, all ? 6 : 5, filter)) return std::nullopt;
  return std::tuple{client::Point{*x, *y}, client::Point{*dx, *dy}, all, filter, std::uint32_t(0)};
}

std::optional<std::tuple<client::Point, double, client::BodyPart, client::Point, QueryFilter>> parseShapeCast(
    Arguments& line) {
  const auto x = line.numberAt(1), y = line.numberAt(2), angle = line.numberAt(3);
  if (!x || !y || !angle) return std::nullopt;
  std::size_t i = 4;
  const auto part = line.size() > i ? readBodyPart(line, i) : std::nullopt;
  if (!part) {
    line.note("no PART (circle CX CY R, box CX CY HW HH or capsule X1 Y1 X2 Y2 R)");
    return std::nullopt;
  }
  const auto dx = line.numberAt(i), dy = line.numberAt(i + 1);
  if (!dx || !dy) return std::nullopt;
  QueryFilter filter;
  if (!readQueryFilter(line, i + 2, filter)) return std::nullopt;
  return std::tuple{client::Point{*x, *y}, *angle, *part, client::Point{*dx, *dy}, filter};
}

std::optional<std::tuple<client::Point, client::Point, QueryFilter, std::uint32_t>> parseOverlap(Arguments& line) {
  const auto x1 = line.numberAt(1), y1 = line.numberAt(2), x2 = line.numberAt(3), y2 = line.numberAt(4);
  if (!x1 || !y1 || !x2 || !y2) return std::nullopt;
  QueryFilter filter;
  if (!readQueryFilter(line, 5, filter)) return std::nullopt;
  return std::tuple{client::Point{*x1, *y1}, client::Point{*x2, *y2}, filter, std::uint32_t(0)};
}

std::optional<std::tuple<bool>> parseEvents(Arguments& line) {
  const auto setting = line.size() > 1 ? line.word(1) : std::string_view();
  if ((setting != "on" && setting != "off") || !line.maxWords(2)) {
    line.note("events takes on or off");
    return std::nullopt;
  }
  return std::tuple{setting == "on"};
}

std::optional<std::tuple<std::uint64_t, bool>> parsePing(Arguments& line) {
  if (!parseNoArguments(line)) return std::nullopt;
  const bool wantStateHash = false;
  return std::tuple{std::uint64_t(0), wantStateHash};
}

std::optional<std::tuple<double>> parseTimeScale(Arguments& line) {
  const auto scale = line.numberAt(1);
  if (!scale || !line.maxWords(2)) return std::nullopt;
  return std::tuple{*scale};
}

std::optional<std::tuple<std::optional<client::Box>>> parseInterestArea(Arguments& line) {
  if (line.size() > 1 && line.word(1) == "all") {
    if (!line.maxWords(2)) return std::nullopt;
    return std::tuple{std::optional<client::Box>()};
  }
  const auto x1 = line.numberAt(1), y1 = line.numberAt(2), x2 = line.numberAt(3), y2 = line.numberAt(4);
  if (!x1 || !y1 || !x2 || !y2 || !line.maxWords(5)) return std::nullopt;
  return std::tuple{std::optional<client::Box>(client::Box{{*x1, *y1}, {*x2, *y2}})};
}

std::optional<std::tuple<std::optional<double>>> parseBandwidthBudget(Arguments& line) {
  if (line.size() > 1 && line.word(1) == "off") {
    if (!line.maxWords(2)) return std::nullopt;
    return std::tuple{std::optional<double>()};
  }
  const auto rate = line.numberAt(1);
  if (!rate || !line.maxWords(2)) return std::nullopt;
  return std::tuple{std::optional<double>(*rate)};
}

// save FILE and load FILE: the file is the CLI's (ScriptCommand::file). A
// load's bytes are read when its line runs, after the lines before it.
std::optional<std::tuple<>> parseSceneFileName(Arguments& line) {
  if (line.size() < 2) line.note("FILE is missing");
  if (line.size() < 2 || !line.maxWords(2)) return std::nullopt;
  return std::tuple{};
}

std::optional<std::tuple<std::string>> parseSceneFile(Arguments& line) {
  if (!parseSceneFileName(line)) return std::nullopt;
  return std::tuple{std::string()};
}

// A row's parser composed with its builder.
template <class Parsed, class Builder>
std::optional<v1::ClientMessage> build(const std::optional<Parsed>& arguments, Builder builder) {
  if (!arguments) return std::nullopt;
  return std::apply(builder, *arguments);
}

#define IMPULSE_SCRIPT_WORD(Case, field, role, handler, word, usage, help, parser, builder) \
  ProtocolWord{{word, usage, help},                                                         \
               [](Arguments& arguments) { return build(parser(arguments), builder); }},
constexpr std::array kProtocolWords{IMPULSE_COMMAND_TABLE(IMPULSE_SCRIPT_WORD)};
#undef IMPULSE_SCRIPT_WORD

}  // namespace

std::span<const ProtocolWord> protocolWords() { return kProtocolWords; }

}  // namespace impulse::cli
