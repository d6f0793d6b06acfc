#include "script.h"

#include <charconv>
#include <cmath>
#include <vector>

#include "impulse/client/commands.h"
#include "impulse/wire/convert.h"

namespace impulse::cli {

namespace {

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size() || line[i] == '#') break;
    std::size_t end = i;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r' &&
           line[end] != '#') {
      ++end;
    }
    words.push_back(line.substr(i, end - i));
    i = end;
  }
  return words;
}

// "'word' rest". Built by append: GCC 12 warns falsely (-Wrestrict) on
// "'" + std::string(word) + "...".
std::string quoted(std::string_view word, std::string_view rest) {
  std::string text(1, '\'');
  text.append(word);
  text += '\'';
  text.append(rest);
  return text;
}

std::optional<double> number(std::string_view word) {
  double value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

std::optional<long long> integer(std::string_view word) {
  long long value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

class LineParser {
 public:
  explicit LineParser(std::vector<std::string_view> words) : words_(std::move(words)) {}

  ParsedLine parse() {
    ScriptCommand command;
    command.name = std::string(words_[0]);
    const std::string_view name = words_[0];
    if (name == "preset") {
      usage_ = "preset N [MATERIAL]";
      const auto id = integerAt(1);
      if (!id) return fail();
      Material material = Material::Solid;
      if (words_.size() > 2) {
        const auto m = wire::materialFromName(words_[2]);
        if (!m) return fail(quoted(words_[2], " is not a material"));
        material = *m;
      }
      if (!maxWords(3)) return fail();
      command.message = client::loadPreset(int(*id), material);
    } else if (name == "pause" || name == "resume") {
      usage_ = std::string(name);
      if (!maxWords(1)) return fail();
      command.message = client::setPaused(name == "pause");
    } else if (name == "step") {
      usage_ = "step N (1 or more ticks)";
      const auto ticks = integerAt(1);
      if (!ticks || !maxWords(2)) return fail();
      if (*ticks < 1 || *ticks > 0xffffffffLL) return fail("tick count out of range");
      command.message = client::step(std::uint32_t(*ticks));
    } else if (name == "circle") {
      usage_ = "circle X Y R [MATERIAL] [static] [nograv]";
      const auto x = numberAt(1), y = numberAt(2), r = numberAt(3);
      if (!x || !y || !r) return fail();
      client::SpawnOptions options;
      if (!bodyFlags(4, options)) return fail();
      command.message = client::spawnCircle({*x, *y}, *r, options);
    } else if (name == "polygon") {
      usage_ = "polygon X1 Y1 X2 Y2 X3 Y3 ... [MATERIAL] [static] [nograv]";
      std::vector<client::Point> points;
      std::size_t i = 1;
      while (i < words_.size() && number(words_[i])) {
        const auto y = numberAt(i + 1);
        if (!y) return fail("vertex " + std::to_string(points.size() + 1) + " has no y");
        points.push_back({*number(words_[i]), *y});
        i += 2;
      }
      if (points.empty()) return fail("no vertices");
      client::SpawnOptions options;
      if (!bodyFlags(i, options)) return fail();
      // Too few or too many vertices are for the server to judge, with the
      // same message every client gets.
      command.message = client::spawnPolygon(points, options);
    } else if (name == "gravity" || name == "nudge") {
      usage_ = std::string(name) + (name == "gravity" ? " GX GY" : " DX DY");
      const auto x = numberAt(1), y = numberAt(2);
      if (!x || !y || !maxWords(3)) return fail();
      command.message =
          name == "gravity" ? client::setGravity({*x, *y}) : client::nudgeGravity({*x, *y});
    } else if (name == "reset-gravity") {
      usage_ = "reset-gravity";
      if (!maxWords(1)) return fail();
      command.message = client::resetGravity();
    } else if (name == "clear") {
      usage_ = "clear";
      if (!maxWords(1)) return fail();
      command.message = client::clearWorld();
    } else if (name == "remove" || name == "query") {
      usage_ = std::string(name) + " ID";
      const auto id = idAt(1);
      if (!id || !maxWords(2)) return fail();
      command.message = name == "remove" ? client::removeBody(*id) : client::queryBody(*id);
    } else if (name == "impulse") {
      usage_ = "impulse ID JX JY [PX PY]";
      const auto id = idAt(1);
      const auto jx = numberAt(2), jy = numberAt(3);
      if (!id || !jx || !jy) return fail();
      std::optional<client::Point> point;
      if (words_.size() > 4) {
        const auto px = numberAt(4), py = numberAt(5);
        if (!px || !py) return fail();
        point = client::Point{*px, *py};
      }
      if (!maxWords(6)) return fail();
      command.message = client::applyImpulse(*id, {*jx, *jy}, point);
    } else if (name == "bodies" || name == "wait-snapshot") {
      usage_ = std::string(name);
      if (!maxWords(1)) return fail();
      command.kind =
          name == "bodies" ? ScriptCommand::Kind::Bodies : ScriptCommand::Kind::WaitSnapshot;
    } else if (name == "ping") {
      usage_ = "ping";
      if (!maxWords(1)) return fail();
      command.message = client::ping(0);
    } else {
      return {std::nullopt, "unknown command " + quoted(name, "")};
    }
    return {std::move(command), {}};
  }

 private:
  ParsedLine fail(std::string problem = {}) {
    if (problem.empty()) problem = problem_;
    return {std::nullopt, usage_ + ": " + problem};
  }

  // Keeps the first problem found on the line.
  void note(std::string problem) {
    if (problem_.empty()) problem_ = std::move(problem);
  }

  bool present(std::size_t i) {
    if (i < words_.size()) return true;
    note("missing argument " + std::to_string(i));
    return false;
  }

  std::optional<double> numberAt(std::size_t i) {
    if (!present(i)) return std::nullopt;
    const auto value = number(words_[i]);
    // Non-finite values are sent as typed: the server's answer is the test.
    if (!value) note(quoted(words_[i], " is not a number"));
    return value;
  }

  std::optional<long long> integerAt(std::size_t i) {
    if (!present(i)) return std::nullopt;
    const auto value = integer(words_[i]);
    if (!value) note(quoted(words_[i], " is not an integer"));
    return value;
  }

  std::optional<std::uint32_t> idAt(std::size_t i) {
    const auto value = integerAt(i);
    if (!value) return std::nullopt;
    if (*value < 0 || *value > 0xffffffffLL) {
      note("body id " + std::to_string(*value) + " out of range");
      return std::nullopt;
    }
    return std::uint32_t(*value);
  }

  bool maxWords(std::size_t count) {
    if (words_.size() <= count) return true;
    note("unexpected " + quoted(words_[count], ""));
    return false;
  }

  bool bodyFlags(std::size_t from, client::SpawnOptions& options) {
    for (std::size_t i = from; i < words_.size(); ++i) {
      const std::string_view word = words_[i];
      if (word == "static") {
        options.isStatic = true;
      } else if (word == "nograv") {
        options.ignoreGravity = true;
      } else if (const auto material = wire::materialFromName(word)) {
        options.material = *material;
      } else {
        note("unexpected " + quoted(word, " (material, static or nograv)"));
        return false;
      }
    }
    return true;
  }

  std::vector<std::string_view> words_;
  std::string usage_;
  std::string problem_;
};

}  // namespace

ParsedLine parseScriptLine(std::string_view line) {
  auto words = splitWords(line);
  if (words.empty()) return {};
  const std::string name(words.front());
  ParsedLine parsed = LineParser(std::move(words)).parse();
  parsed.name = name;
  return parsed;
}

}  // namespace impulse::cli
