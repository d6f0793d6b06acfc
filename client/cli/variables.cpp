#include "variables.h"

#include <algorithm>

namespace impulse::cli {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool isNameStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isNameChar(char c) { return isNameStart(c) || (c >= '0' && c <= '9'); }

std::size_t skipBlanks(std::string_view text, std::size_t at) {
  while (at < text.size() && isBlank(text[at])) ++at;
  return at;
}

// End of the name that starts at `at` (just after a '$').
std::size_t nameEnd(std::string_view text, std::size_t at) {
  std::size_t end = at;
  if (end < text.size() && isNameStart(text[end])) {
    while (end < text.size() && isNameChar(text[end])) ++end;
  }
  return end;
}

// "$name", built by append: GCC 12 warns falsely (-Wrestrict) on
// "$" + std::string(name).
std::string withDollar(std::string_view name) {
  std::string text(1, '$');
  text.append(name);
  return text;
}

}  // namespace

bool isVariableName(std::string_view name) {
  return !name.empty() && nameEnd(name, 0) == name.size();
}

std::optional<Assignment> splitAssignment(std::string_view line) {
  const std::size_t dollar = skipBlanks(line, 0);
  if (dollar >= line.size() || line[dollar] != '$') return std::nullopt;
  const std::size_t end = nameEnd(line, dollar + 1);
  const std::size_t equals = skipBlanks(line, end);
  if (end == dollar + 1 || equals >= line.size() || line[equals] != '=') return std::nullopt;
  return Assignment{std::string(line.substr(dollar + 1, end - dollar - 1)),
                    line.substr(skipBlanks(line, equals + 1))};
}

void Variables::set(const std::string& name, std::string value) {
  values_[name] = {Value::State::Set, std::move(value), 0};
}

void Variables::await(const std::string& name, std::size_t line) {
  values_[name] = {Value::State::Waiting, {}, line};
}

void Variables::fail(const std::string& name, std::size_t line) {
  values_[name] = {Value::State::Failed, {}, line};
}

Variables::Substitution Variables::substitute(std::string_view line) const {
  Substitution result;
  const std::string_view code = line.substr(0, std::min(line.find('#'), line.size()));
  std::size_t copied = 0;
  for (std::size_t dollar = code.find('$'); dollar != std::string_view::npos;
       dollar = code.find('$', dollar + 1)) {
    const std::size_t end = nameEnd(code, dollar + 1);
    const std::string_view name = code.substr(dollar + 1, end - dollar - 1);
    if (name.empty()) {
      result.error = "'$' without a variable name after it";
      return result;
    }
    const auto found = values_.find(name);
    if (found == values_.end()) {
      const std::string variable = withDollar(name);
      result.error = variable + " has no value (set it with " + variable + " = COMMAND or " +
                     variable + " = NUMBER)";
      return result;
    }
    const Value& value = found->second;
    if (value.state == Value::State::Waiting) {
      result.waiting = true;
      return result;
    }
    if (value.state == Value::State::Failed) {
      result.error = withDollar(name) + " has no value: line " +
                     std::to_string(value.line) + ", which sets it, failed";
      return result;
    }
    result.text.append(code, copied, dollar - copied).append(value.text);
    copied = end;
  }
  result.text.append(line, copied);
  return result;
}

}  // namespace impulse::cli
