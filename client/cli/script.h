#pragma once
// The impulse-cli script grammar: one command per line, '#' starts a comment.
// The protocol's words, their grammar and help are the rows of the command
// table (impulse/wire/command_table.h); the CLI adds words of its own
// (bodies, wait-snapshot). scriptGrammar() writes them all for --help;
// tests/net/command_table_test.cpp holds README.md and docs/server.md to it.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impulse.pb.h"

namespace impulse::cli {

/// A script word: how it is written and what it does.
struct ScriptWord {
  std::string_view word;
  std::string_view usage;
  std::string_view help;
};

struct ScriptCommand {
  enum class Kind { Server, Bodies, WaitSnapshot };
  std::string name;  // first word, as typed
  Kind kind = Kind::Server;
  v1::ClientMessage message;  // for Kind::Server
  /// `save`: where the reply's scene goes; `load`: the scene file, read
  /// when the line runs (after the lines before it, which may write it).
  std::string file{};
  /// `at +N COMMAND`: sent stamped N ticks after the room's tick as the
  /// client last saw it (`at TICK` stamps the message itself).
  std::optional<std::uint64_t> ticksAhead{};
};

struct ParsedLine {
  std::optional<ScriptCommand> command{};  // nothing for blank and comment lines
  std::string error{};                     // set when the line is invalid
  std::string name{};                      // the line's first word, also when invalid
};

/// Parses one line. Errors say what was expected and what was wrong.
ParsedLine parseScriptLine(std::string_view line);

/// How a line stands in the block structure: `repeat N [$I] {` opens a
/// block, a line of `}` alone closes one.
enum class LineShape { Plain, OpensBlock, ClosesBlock };
LineShape lineShape(std::string_view line);

/// The words of a line that opens a block: the count as written (a number
/// or a variable) and the counter's name without '$' (empty when none).
struct RepeatWords {
  std::string count;
  std::string counter;
  std::string error;  // set when the words do not fit `repeat N [$I] {`
};
RepeatWords parseRepeat(std::string_view line);
/// The count of a `repeat` after its variables were replaced, or nothing
/// with `error` saying why.
std::optional<long long> repeatCount(std::string_view count, std::string& error);

/// Every script word: the command table's, in its order, then the CLI's own.
std::vector<ScriptWord> scriptWords();
/// One "usage  help" entry per word, as --help and README.md show them.
std::string scriptGrammar();
/// One "| `usage` | help |" row per word, as docs/server.md shows them.
std::string scriptGrammarTable();

}  // namespace impulse::cli
