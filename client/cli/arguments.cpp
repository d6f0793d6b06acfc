#include "arguments.h"

#include <charconv>

#include "impulse/wire/convert.h"
#include "impulse/wire/parse_number.h"

namespace impulse::cli {

// Built by append: GCC 12 warns falsely (-Wrestrict) on
// "'" + std::string(word) + "...".
std::string quoted(std::string_view word, std::string_view rest) {
  std::string text(1, '\'');
  text.append(word);
  text += '\'';
  text.append(rest);
  return text;
}

Arguments::Arguments(std::vector<std::string_view> words) : words_(std::move(words)) {}

void Arguments::note(std::string problem) {
  if (problem_.empty()) problem_ = std::move(problem);
}

bool Arguments::present(std::size_t i) {
  if (i < words_.size()) return true;
  note("missing argument " + std::to_string(i));
  return false;
}

std::optional<double> Arguments::numberAt(std::size_t i) {
  if (!present(i)) return std::nullopt;
  const auto value = wire::parseNumber<double>(words_[i]);
  // Non-finite values are sent as typed: the server's answer is the test.
  if (!value) note(quoted(words_[i], " is not a number"));
  return value;
}

std::optional<long long> Arguments::integerAt(std::size_t i) {
  if (!present(i)) return std::nullopt;
  const auto value = wire::parseNumber<long long>(words_[i]);
  if (!value) note(quoted(words_[i], " is not an integer"));
  return value;
}

std::optional<std::uint32_t> Arguments::idAt(std::size_t i) {
  const auto value = integerAt(i);
  if (!value) return std::nullopt;
  if (*value < 0 || *value > 0xffffffffLL) {
    note("body id " + std::to_string(*value) + " out of range");
    return std::nullopt;
  }
  return std::uint32_t(*value);
}

bool Arguments::maxWords(std::size_t count) {
  if (words_.size() <= count) return true;
  note("unexpected " + quoted(words_[count], ""));
  return false;
}

namespace {

// NAME=VALUE words of the per-body properties (docs/protocol.md), each setting
// one SpawnOptions field; ranges are the server's to judge.
struct PropertyWord {
  std::string_view name;
  void (*set)(client::SpawnOptions& options, double value);
};

constexpr PropertyWord kPropertyWords[] = {
    {"density", [](client::SpawnOptions& o, double v) { o.density = v; }},
    {"friction", [](client::SpawnOptions& o, double v) { o.friction = v; }},
    {"restitution", [](client::SpawnOptions& o, double v) { o.restitution = v; }},
    {"damping", [](client::SpawnOptions& o, double v) { o.linearDamping = v; }},
    {"angular-damping", [](client::SpawnOptions& o, double v) { o.angularDamping = v; }},
    {"gravity-scale", [](client::SpawnOptions& o, double v) { o.gravityScale = v; }},
};

}  // namespace

bool Arguments::bodyProperty(std::string_view word, client::SpawnOptions& options) {
  const auto equals = word.find('=');
  if (equals == std::string_view::npos) return false;
  for (const PropertyWord& property : kPropertyWords) {
    if (word.substr(0, equals) != property.name) continue;
    const auto value = wire::parseNumber<double>(word.substr(equals + 1));
    if (!value) {
      note(quoted(word, " has no number after '='"));
      return false;
    }
    property.set(options, *value);
    return true;
  }
  return false;
}

namespace {

// N in decimal, or hex after 0x.
template <class T>
std::optional<T> parseBits(std::string_view text) {
  if (text.starts_with("0x")) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data() + 2, end, value, 16);
    if (text.size() == 2 || error != std::errc() || stop != end) return std::nullopt;
    return value;
  }
  return wire::parseNumber<T>(text);
}

constexpr std::string_view kFlagWords = "sensor, contact-events, hit-events or no-sensor-events";

}  // namespace

bool Arguments::shapeFlag(std::string_view word, ShapeInteraction& flags) {
  if (word == "sensor") return flags.isSensor = true;
  if (word == "contact-events") return flags.enableContactEvents = true;
  if (word == "hit-events") return flags.enableHitEvents = true;
  if (word == "no-sensor-events") {
    flags.enableSensorEvents = false;
    return true;
  }
  const auto equals = word.find('=');
  const std::string_view name = word.substr(0, equals);
  if (equals == std::string_view::npos || (name != "category" && name != "mask" && name != "group")) return false;
  const std::string_view number = word.substr(equals + 1);
  if (name == "group") {
    const auto group = parseBits<std::int32_t>(number);
    if (group) flags.filter.groupIndex = *group;
    if (!group) note(quoted(word, " needs a whole number"));
    return bool(group);
  }
  const auto bits = parseBits<std::uint64_t>(number);
  if (!bits) {
    note(quoted(word, " needs a 64-bit number (decimal or 0x hex)"));
    return false;
  }
  (name == "category" ? flags.filter.categoryBits : flags.filter.maskBits) = *bits;
  return true;
}

bool Arguments::bodyFlags(std::size_t from, client::SpawnOptions& options) {
  for (std::size_t i = from; i < words_.size(); ++i) {
    const std::string_view word = words_[i];
    if (shapeFlag(word, options.flags)) continue;
    if (!problem_.empty()) return false;
    if (word.find('=') != std::string_view::npos) {
      if (!bodyProperty(word, options)) {
        note("unexpected " + quoted(word, " (density=, friction=, restitution=, damping=, "
                                          "angular-damping=, gravity-scale=, category=, mask= or group=)"));
        return false;
      }
    } else if (word == "static") {
      options.isStatic = true;
    } else if (word == "kinematic") {
      options.isKinematic = true;
    } else if (word == "asleep") {
      options.isAwake = false;
    } else if (word == "nograv") {
      options.ignoreGravity = true;
    } else if (const auto material = wire::materialFromName(word)) {
      options.material = *material;
    } else {
      note("unexpected " + quoted(word, " (material, static, kinematic, asleep, nograv, " + std::string(kFlagWords) + ")"));
      return false;
    }
  }
  return true;
}

}  // namespace impulse::cli
