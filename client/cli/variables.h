#pragma once
// Script variables. `$name = COMMAND` keeps the id in the command's reply
// (body, joint or field), `$name = NUMBER` a number, `repeat N $i {` the
// pass it is on; `$name` then stands for its value wherever a number is
// written, also after NAME= (density=$d).
//
// Replies come back after later lines were sent (pipelining), so a variable
// can be waiting for its reply: the runner then waits for the replies before
// it reads the line again.

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace impulse::cli {

/// A line's `$name = ...` split off: the variable and the rest of the line.
struct Assignment {
  std::string variable;  // without the '$'
  std::string_view command;
};

/// `line` when it starts with "$name =", else nothing.
std::optional<Assignment> splitAssignment(std::string_view line);

/// The names a `$` may start: a letter or '_', then letters, digits, '_'.
bool isVariableName(std::string_view name);

class Variables {
 public:
  void set(const std::string& name, std::string value);
  /// The variable waits for the reply to line `line`.
  void await(const std::string& name, std::size_t line);
  /// The command that was to give the variable a value failed.
  void fail(const std::string& name, std::size_t line);

  /// The outcome of replacing every `$name` of a line by its value.
  struct Substitution {
    std::string text;
    std::string error;  // an unknown variable, or one whose command failed
    bool waiting = false;  // a variable waits for a reply: wait, then try again
  };
  /// `line` with every `$name` before its comment replaced.
  Substitution substitute(std::string_view line) const;

 private:
  struct Value {
    enum class State { Set, Waiting, Failed } state = State::Set;
    std::string text;
    std::size_t line = 0;  // Waiting, Failed: the line that assigns it
  };
  std::map<std::string, Value, std::less<>> values_;
};

}  // namespace impulse::cli
