// Runs every bad deck under tests/diagnostics/ through the reader and checks its diagnostics
// against the expectations written in its ** comments (ARCHITECTURE.md, testing habit 5):
//   ** expected-error@+1 {{message substring}}      error on the next line
//   ** expected-warning@-2:14 {{...}}              warning two lines up, at column 14
//   ** expected-note@+1 {{...}}                    a note (of any diagnostic) on the next line
// Offsets are relative to the comment line (none or @+0: that line). Every error and warning
// produced must be expected, and every expectation must be met, in every file the deck reads;
// notes that no expectation names are not checked.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

struct Expectation {
  std::uint32_t file;
  Severity severity;
  std::uint32_t line;
  std::uint32_t column;  // 0: any
  std::string text;
  bool met = false;
};

std::vector<Expectation> parse_expectations(const SourceManager& sources) {
  static const std::regex pattern(
      R"(expected-(error|warning|note)(@([+-]?\d+))?(:(\d+))?\s*\{\{(.*?)\}\})");
  std::vector<Expectation> out;
  for (std::uint32_t f = 0; f < sources.file_count(); ++f) {
    std::istringstream text{std::string(sources.text(f))};
    std::string line;
    std::uint32_t number = 0;
    while (std::getline(text, line)) {
      ++number;
      if (line.rfind("**", 0) != 0) continue;
      for (auto it = std::sregex_iterator(line.begin(), line.end(), pattern);
           it != std::sregex_iterator(); ++it) {
        const std::smatch& m = *it;
        Expectation e;
        e.file = f;
        e.severity = m[1] == "error"     ? Severity::Error
                     : m[1] == "warning" ? Severity::Warning
                                         : Severity::Note;
        const long offset = m[3].matched ? std::stol(m[3]) : 0;
        e.line = static_cast<std::uint32_t>(static_cast<long>(number) + offset);
        e.column = m[5].matched ? static_cast<std::uint32_t>(std::stoul(m[5])) : 0;
        e.text = m[6];
        out.push_back(e);
      }
    }
  }
  return out;
}

std::vector<fs::path> diagnostic_decks() {
  std::vector<fs::path> decks;
  fs::path dir = fs::path(CLINCH_SOURCE_DIR) / "tests" / "diagnostics";
  if (!fs::exists(dir)) return decks;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".inp") decks.push_back(entry.path());
  }
  std::sort(decks.begin(), decks.end());
  return decks;
}

class DiagnosticDeck : public ::testing::TestWithParam<fs::path> {};

TEST_P(DiagnosticDeck, ProducesExactlyTheExpectedDiagnostics) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string io_error;
  ASSERT_EQ(read_deck_file(GetParam().string(), sources, model, sink, &io_error), ReadStatus::Ok)
      << io_error;
  std::vector<Expectation> expectations = parse_expectations(sources);
  ASSERT_FALSE(expectations.empty()) << "a diagnostics deck must expect at least one diagnostic";
  for (const Diagnostic& d : sink.diagnostics()) {
    bool matched = false;
    for (Expectation& e : expectations) {
      if (e.met || e.severity != d.severity || e.file != d.loc.file || e.line != d.loc.line) {
        continue;
      }
      if (e.column && e.column != d.loc.column) continue;
      if (d.message.find(e.text) == std::string::npos &&
          std::string(diag_code_name(d.code)).find(e.text) == std::string::npos) {
        continue;
      }
      e.met = matched = true;
      break;
    }
    EXPECT_TRUE(matched) << "unexpected " << render_text(d, sources);
    for (const DiagNote& note : d.notes) {
      for (Expectation& e : expectations) {
        if (e.met || e.severity != Severity::Note || e.file != note.loc.file ||
            e.line != note.loc.line || (e.column && e.column != note.loc.column) ||
            note.message.find(e.text) == std::string::npos) {
          continue;
        }
        e.met = true;
        break;
      }
    }
  }
  for (const Expectation& e : expectations) {
    EXPECT_TRUE(e.met) << "expected "
                       << (e.severity == Severity::Error     ? "error"
                           : e.severity == Severity::Warning ? "warning"
                                                             : "note")
                       << " not produced: " << sources.file(e.file).display_name << ":"
                       << e.line << (e.column ? fmt::format(":{}", e.column) : std::string())
                       << " {{" << e.text << "}}";
  }
}

std::string deck_name(const ::testing::TestParamInfo<fs::path>& info) {
  std::string name = info.param.stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Decks, DiagnosticDeck, ::testing::ValuesIn(diagnostic_decks()),
                         deck_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(DiagnosticDeck);

TEST(DiagnosticDecks, ThereAreAtLeastForty) { EXPECT_GE(diagnostic_decks().size(), 40u); }

// A field error underlines the whole field, clang-style: the caret at its first column and '~'
// under the rest (ARCHITECTURE.md principle 7); the JSON gives the last column as end_column.
TEST(DiagnosticRender, FieldErrorUnderlinesTheWholeField) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  read_deck_text("deck.inp",
                 "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
                 "*CONNECTOR SECTION, ELSET=C\n  HINGEE,\n*STEP\n*STATIC\n*END STEP\n",
                 sources, model, sink);
  const auto it = std::find_if(sink.diagnostics().begin(), sink.diagnostics().end(),
                               [](const Diagnostic& d) { return d.severity == Severity::Error; });
  ASSERT_NE(it, sink.diagnostics().end());
  EXPECT_EQ(it->loc, (SourceLoc{it->loc.file, 7, 3, 6}));
  const std::string text = render_text(*it, sources);
  EXPECT_NE(text.find("deck.inp:7:3: error: unknown connection type 'HINGEE'"), std::string::npos)
      << text;
  EXPECT_NE(text.find("\n   HINGEE,\n   ^~~~~~\n"), std::string::npos) << text;
  const std::string json = render_json({*it}, sources);
  EXPECT_NE(json.find("\"column\": 3"), std::string::npos) << json;
  EXPECT_NE(json.find("\"end_column\": 8"), std::string::npos) << json;
}

// The abbreviation note names the full keyword only for a prefix of exactly one keyword:
// *ORIENT → *ORIENTATION; *RESTART is a keyword of its own (no note), *CONNECTOR is a prefix of
// many (did-you-mean instead).
TEST(DiagnosticNotes, AbbreviationNoteOnlyForAPrefixOfOneKeyword) {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  read_deck_text("deck.inp",
                 "*NODE\n1, 0., 0., 0.\n*ORIENT, NAME=O\n*CONNECTOR, NAME=X\n*STEP\n*STATIC\n"
                 "*Restart, write, frequency=0\n*END STEP\n",
                 sources, model, sink);
  std::vector<std::string> notes;
  for (const Diagnostic& d : sink.diagnostics()) {
    for (const auto& note : d.notes) notes.push_back(d.message + " | " + note.message);
  }
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0],
            "unknown keyword '*ORIENT' | keywords cannot be abbreviated; the full name is "
            "'*ORIENTATION'");
  EXPECT_EQ(notes[1].rfind("unknown keyword '*CONNECTOR' | did you mean", 0), 0u) << notes[1];
}

// A location without an extent keeps the caret alone.
TEST(DiagnosticRender, PointLocationHasACaretOnly) {
  SourceManager sources;
  const std::uint32_t file = sources.add_buffer("deck.inp", "*NODE\n1, 0., 0., 0.\n");
  Diagnostic d{DiagCode::undefined_node, Severity::Error, SourceLoc{file, 2, 4}, "x", {}};
  EXPECT_NE(render_text(d, sources).find("\n 1, 0., 0., 0.\n    ^\n"), std::string::npos)
      << render_text(d, sources);
  d.loc.length = 3;
  EXPECT_NE(render_text(d, sources).find("\n 1, 0., 0., 0.\n    ^~~\n"), std::string::npos)
      << render_text(d, sources);
}

}  // namespace
}  // namespace clinch
