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

bool Arguments::bodyFlags(std::size_t from, client::SpawnOptions& options) {
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

}  // namespace impulse::cli
