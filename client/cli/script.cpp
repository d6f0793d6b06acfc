#include "script.h"

#include <algorithm>
#include <array>

#include "arguments.h"
#include "command_parsers.h"
#include "impulse/wire/parse_number.h"
#include "variables.h"

namespace impulse::cli {

namespace {

// The CLI's own words: answered from the client's mirror, not sent.
struct LocalWord {
  ScriptWord text;
  ScriptCommand::Kind kind;
};
constexpr std::array kLocalWords{
    LocalWord{{"bodies", "bodies", "every body as the client's mirror has it, after a round trip"},
              ScriptCommand::Kind::Bodies},
    LocalWord{{"wait-snapshot", "wait-snapshot",
               "the newest snapshot received since the last command was sent, or else the next "
               "one to arrive, summarised (tick, full, counts, bytes)"},
              ScriptCommand::Kind::WaitSnapshot},
};

// The language around the commands: variables and loops (script_runner.h
// runs them).
constexpr std::array kLanguageWords{
    ScriptWord{"$NAME", "$NAME = COMMAND",
               "keep the id in COMMAND's reply (body, joint or field); $NAME = NUMBER, or A OP B "
               "with OP one of + - * /, keeps a number; $NAME then stands for it wherever a "
               "number goes (density=$NAME too)"},
    ScriptWord{"at", "at TICK COMMAND | at +N COMMAND",
               "send COMMAND stamped for the room's tick TICK (for_tick), or N ticks after the "
               "room's tick as the client last saw it; the server applies it at that tick "
               "(docs/networked-play.md)"},
    ScriptWord{"repeat", "repeat N [$I] { ... }",
               "run the lines up to the matching } (a line of its own) N times; $I counts the "
               "passes, 1 to N"},
};

// Where the help column starts in scriptGrammar(); longer usages put their
// help on the next line.
constexpr std::size_t kHelpColumn = 30;

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

ParsedLine refused(std::string_view usage, const std::string& problem) {
  return {std::nullopt, std::string(usage) + ": " + problem};
}

ParsedLine parseProtocolWord(const ProtocolWord& row, Arguments& arguments) {
  auto message = row.parse(arguments);
  if (!message) return refused(row.text.usage, arguments.problem());
  ScriptCommand command{std::string(row.text.word), ScriptCommand::Kind::Server,
                        std::move(*message)};
  if (command.message.has_save_scene() || command.message.has_load_scene()) {
    command.file = std::string(arguments.word(1));
  }
  return {std::move(command)};
}

ParsedLine parseLocalWord(const LocalWord& row, Arguments& arguments) {
  if (!arguments.maxWords(1)) return refused(row.text.usage, arguments.problem());
  return {ScriptCommand{std::string(row.text.word), row.kind, {}}};
}

ParsedLine parseWords(std::vector<std::string_view> words);

// `at TICK COMMAND ...` and `at +N COMMAND ...`: the command, stamped.
ParsedLine parseStamped(std::vector<std::string_view> words) {
  constexpr std::string_view kUsage = "at TICK COMMAND | at +N COMMAND";
  if (words.size() < 3) return refused(kUsage, "expected a tick and a command after at");
  const std::string_view tick = words[1];
  const bool relative = tick.starts_with('+');
  const auto value = wire::parseNumber<std::uint64_t>(relative ? tick.substr(1) : tick);
  if (!value) {
    return refused(kUsage, quoted(tick, " is not a tick (a whole number, 0 or more) nor +N (ticks ahead)"));
  }
  ParsedLine parsed = parseWords({words.begin() + 2, words.end()});
  if (!parsed.command) return parsed;
  if (parsed.command->kind != ScriptCommand::Kind::Server) {
    return refused(kUsage, quoted(words[2], " is answered by the client itself: only commands sent to the "
                                            "server can be stamped"));
  }
  if (relative) {
    parsed.command->ticksAhead = *value;
  } else {
    parsed.command->message.set_for_tick(*value);
  }
  return parsed;
}

ParsedLine parseWords(std::vector<std::string_view> words) {
  const std::string_view name = words.front();
  if (name == "at") return parseStamped(std::move(words));
  Arguments arguments(std::move(words));
  for (const ProtocolWord& row : protocolWords()) {
    if (row.text.word == name) return parseProtocolWord(row, arguments);
  }
  for (const LocalWord& row : kLocalWords) {
    if (row.text.word == name) return parseLocalWord(row, arguments);
  }
  return {std::nullopt, "unknown command " + quoted(name, "")};
}

}  // namespace

ParsedLine parseScriptLine(std::string_view line) {
  auto words = splitWords(line);
  if (words.empty()) return {};
  const std::string name(words.front());
  ParsedLine parsed = parseWords(std::move(words));
  parsed.name = name;
  return parsed;
}

LineShape lineShape(std::string_view line) {
  const auto words = splitWords(line);
  if (words.size() == 1 && words.front() == "}") return LineShape::ClosesBlock;
  if (words.size() >= 2 && words.front() == "repeat" && words.back() == "{") {
    return LineShape::OpensBlock;
  }
  return LineShape::Plain;
}

RepeatWords parseRepeat(std::string_view line) {
  const auto words = splitWords(line);
  const std::string usage = "repeat N [$I] {: ";
  if (words.size() < 3 || words.size() > 4) return {{}, {}, usage + "expected 2 or 3 words before {"};
  RepeatWords repeat{std::string(words[1]), {}, {}};
  if (words.size() == 4) {
    if (!words[2].starts_with('$') || !isVariableName(words[2].substr(1))) {
      repeat.error = usage + quoted(words[2], " is not a $name to count the passes in");
    }
    repeat.counter = std::string(words[2].substr(1));
  }
  return repeat;
}

std::optional<long long> repeatCount(std::string_view count, std::string& error) {
  const auto value = wire::parseNumber<long long>(count);
  if (!value || *value < 0) {
    error = "repeat N [$I] {: N must be a whole number, 0 or more, not " + quoted(count, "");
    return std::nullopt;
  }
  return value;
}

std::vector<ScriptWord> scriptWords() {
  std::vector<ScriptWord> words;
  for (const ProtocolWord& row : protocolWords()) words.push_back(row.text);
  for (const LocalWord& row : kLocalWords) words.push_back(row.text);
  for (const ScriptWord& word : kLanguageWords) words.push_back(word);
  return words;
}

std::string scriptGrammar() {
  std::string text;
  for (const ScriptWord& word : scriptWords()) {
    text.append(word.usage);
    if (word.usage.size() >= kHelpColumn) {
      text += '\n';
      text.append(kHelpColumn, ' ');
    } else {
      text.append(kHelpColumn - word.usage.size(), ' ');
    }
    text.append(word.help);
    text += '\n';
  }
  return text;
}

std::string scriptGrammarTable() {
  std::string text;
  for (const ScriptWord& word : scriptWords()) {
    text.append("| `").append(word.usage).append("` | ").append(word.help).append(" |\n");
  }
  return text;
}

}  // namespace impulse::cli
