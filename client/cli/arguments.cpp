#include "arguments.h"

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

bool Arguments::bodyFlags(std::size_t from, client::SpawnOptions& options) {
  for (std::size_t i = from; i < words_.size(); ++i) {
    const std::string_view word = words_[i];
    if (word.find('=') != std::string_view::npos) {
      if (!bodyProperty(word, options)) {
        note("unexpected " + quoted(word, " (density=, friction=, restitution=, damping=, "
                                          "angular-damping= or gravity-scale=)"));
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
      note("unexpected " + quoted(word, " (material, static, kinematic, asleep or nograv)"));
      return false;
    }
  }
  return true;
}

}  // namespace impulse::cli
