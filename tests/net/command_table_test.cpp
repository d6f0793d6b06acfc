// The command table (impulse/wire/command_table.h) is the only list of
// commands: every protocol command has a row, every row's word parses to
// its command, and the grammar README.md and docs/server.md show is the
// table's, word for word.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "impulse/server/commands.h"
#include "script.h"

namespace impulse::cli {
namespace {

std::string readSourceFile(const std::string& relative) {
  std::ifstream file(std::string(IMPULSE_SOURCE_DIR) + "/" + relative);
  EXPECT_TRUE(file.good()) << relative;
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// The lines of `text` from the line after the one starting with `first`
// through the line before the one starting with `end`.
std::string section(const std::string& text, const std::string& first, const std::string& end) {
  const auto start = text.find("\n" + first);
  if (start == std::string::npos) return "(no line starting with '" + first + "')";
  const auto from = text.find('\n', start + 1) + 1;
  const auto to = text.find("\n" + end, from);
  if (to == std::string::npos) return "(no end line starting with '" + end + "')";
  return text.substr(from, to + 1 - from);
}

TEST(CommandTable, ReadmeGrammarIsTheTables) {
  const auto readme = readSourceFile("README.md");
  const auto block = section(readme, "## Scripting with impulse-cli", "MATERIAL is");
  const auto grammar = section(block, "```", "```");
  EXPECT_EQ(grammar, scriptGrammar()) << "README.md's grammar block should read:\n"
                                      << scriptGrammar();
}

TEST(CommandTable, DocsGrammarTableIsTheTables) {
  const auto docs = readSourceFile("docs/server.md");
  const auto rows = section(docs, "| command | effect |", "MATERIAL is");
  EXPECT_EQ(rows, "|---|---|\n" + scriptGrammarTable() + "\n")
      << "docs/server.md's command table should read:\n"
      << scriptGrammarTable();
}

TEST(CommandTable, ScriptWordsAreUniqueAndEachParsesAlone) {
  std::set<std::string_view> seen;
  for (const ScriptWord& word : scriptWords()) {
    EXPECT_TRUE(seen.insert(word.word).second) << word.word;
    EXPECT_TRUE(word.usage.starts_with(word.word)) << word.usage;
    EXPECT_FALSE(word.help.empty()) << word.word;
  }
}

// Every command the schema knows (found by field number, so a new message in
// the .proto cannot be missed) has a row the server dispatches.
TEST(CommandTable, EveryProtocolCommandHasARow) {
  int commands = 0;
  for (int field = 2; field < 256; ++field) {
    // An empty sub-message in field `field`: tag (field << 3 | 2), then length 0.
    std::string bytes;
    for (unsigned tag = unsigned(field) << 3 | 2; tag != 0; tag >>= 7) {
      bytes += char((tag & 0x7f) | (tag > 0x7f ? 0x80 : 0));
    }
    bytes += '\0';
    v1::ClientMessage message;
    ASSERT_TRUE(message.ParseFromString(bytes));
    if (message.command_case() == v1::ClientMessage::COMMAND_NOT_SET || message.has_hello()) {
      continue;
    }
    ++commands;
    EXPECT_NE(server::commandName(message), "(no command)") << "field " << field;
  }
  EXPECT_GE(commands, 13);
}

}  // namespace
}  // namespace impulse::cli
