#pragma once
// The script side of the command table (impulse/wire/command_table.h): each
// protocol command's word, grammar and help, and its parser composed with
// its client-library builder.

#include <optional>
#include <span>

#include "arguments.h"
#include "impulse.pb.h"
#include "script.h"

namespace impulse::cli {

struct ProtocolWord {
  ScriptWord text;
  /// The message for the line; nothing (the problem noted in `arguments`)
  /// when the words do not fit the usage.
  std::optional<v1::ClientMessage> (*parse)(Arguments& arguments);
};

/// Every row of the command table, in its order.
std::span<const ProtocolWord> protocolWords();

}  // namespace impulse::cli
