#pragma once
// The impulse-cli script grammar: one command per line, '#' starts a comment.
//
//   preset N [MATERIAL]          load preset 0-10 (MATERIAL: the one preset 9 uses)
//   pause | resume               stop or restart the tick clock
//   step N                       while paused: advance exactly N ticks
//   circle X Y R [MATERIAL] [static] [nograv]
//   polygon X1 Y1 X2 Y2 X3 Y3 ... [MATERIAL] [static] [nograv]
//   gravity GX GY | nudge DX DY | reset-gravity
//   clear | remove ID | impulse ID JX JY [PX PY]
//   query ID                     body description, state and mass properties
//   bodies                       the client's mirror of every body
//   wait-snapshot                the newest snapshot since the last command (or the
//                                next one to arrive), summarised
//   ping                         round trip and server statistics
//
// MATERIAL is solid, ice, wood, metal or rubber (any case).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "impulse.pb.h"

namespace impulse::cli {

struct ScriptCommand {
  enum class Kind { Server, Bodies, WaitSnapshot };
  std::string name;  // first word, as typed
  Kind kind = Kind::Server;
  v1::ClientMessage message;  // for Kind::Server
};

struct ParsedLine {
  std::optional<ScriptCommand> command{};  // nothing for blank and comment lines
  std::string error{};                     // set when the line is invalid
  std::string name{};                      // the line's first word, also when invalid
};

/// Parses one line. Errors say what was expected and what was wrong.
ParsedLine parseScriptLine(std::string_view line);

}  // namespace impulse::cli
