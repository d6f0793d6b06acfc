#pragma once
// The words of one script line after its command word, read by a command's
// parser (command_parsers.cpp). Each reader notes the first problem it
// finds, so a parser can read everything and then report what went wrong.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impulse/client/commands.h"

namespace impulse::cli {

// "'word' rest".
std::string quoted(std::string_view word, std::string_view rest);

class Arguments {
 public:
  /// `words` includes the command word at index 0.
  explicit Arguments(std::vector<std::string_view> words);

  std::size_t size() const { return words_.size(); }
  std::string_view word(std::size_t i) const { return words_[i]; }

  std::optional<double> numberAt(std::size_t i);
  std::optional<long long> integerAt(std::size_t i);
  std::optional<std::uint32_t> idAt(std::size_t i);
  /// False (noted) when more than `count` words were given.
  bool maxWords(std::size_t count);
  /// Reads MATERIAL, static, kinematic, asleep, nograv and NAME=VALUE properties (density,
  /// friction, restitution, damping, angular-damping, gravity-scale) in any
  /// order from word `from` on.
  bool bodyFlags(std::size_t from, client::SpawnOptions& options);

  /// Keeps the first problem found on the line.
  void note(std::string problem);
  /// A problem that explains the line better than anything noted so far.
  void refuse(std::string problem) { problem_ = std::move(problem); }
  const std::string& problem() const { return problem_; }

 private:
  bool present(std::size_t i);
  /// One NAME=VALUE word into `options`; false when not one of them.
  bool bodyProperty(std::string_view word, client::SpawnOptions& options);

  std::vector<std::string_view> words_;
  std::string problem_;
};

}  // namespace impulse::cli
