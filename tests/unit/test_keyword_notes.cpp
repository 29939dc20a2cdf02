// `clinch keywords` joins the registry with the prose of src/cli/keyword_notes.cpp: every keyword
// clinch supports must have its sentence, and a note must not describe a keyword the registry
// does not have (a renamed or removed keyword would otherwise leave a stale page).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "base/fold_name.hpp"
#include "parser/deck_reader.hpp"
#include "src/model/connection_types.hpp"
#include "tests/unit/checked_deck.hpp"
#include "parser/keyword_registry.hpp"
#include "src/cli/keyword_notes.hpp"

namespace clinch {
namespace {

TEST(KeywordNotes, EverySupportedKeywordHasASummary) {
  for (const KeywordSpec* spec : KeywordRegistry::instance().specs()) {
    if (spec->keyword_class != KeywordClass::Supported) continue;
    const KeywordNotes* notes = find_keyword_notes(spec->name);
    ASSERT_NE(notes, nullptr) << "*" << spec->name << " has no notes";
    EXPECT_FALSE(notes->summary.empty()) << "*" << spec->name;
  }
}

TEST(KeywordNotes, EveryNoteNamesASupportedKeyword) {
  for (const KeywordNotes& notes : all_keyword_notes()) {
    const KeywordSpec* spec = KeywordRegistry::instance().find(fold_name(notes.name));
    ASSERT_NE(spec, nullptr) << "notes for unknown keyword *" << notes.name;
    EXPECT_EQ(spec->keyword_class, KeywordClass::Supported) << "*" << notes.name;
  }
}

TEST(KeywordNotes, RefusedAndIgnoredOptionsSayWhy) {
  for (const KeywordNotes& notes : all_keyword_notes()) {
    for (const auto* list : {&notes.refused, &notes.ignored}) {
      for (const KeywordRefusal& option : *list) {
        EXPECT_FALSE(option.what.empty()) << "*" << notes.name;
        EXPECT_FALSE(option.why.empty()) << "*" << notes.name << ": " << option.what;
      }
    }
  }
}

// The amplitude definitions the notes call refused are those the reader refuses, and no others: a
// definition that becomes supported (or refused) must change the notes, hence docs/keywords.md.
TEST(KeywordNotes, RefusedAmplitudeDefinitionsAreTheOnesTheReaderRefuses) {
  const KeywordNotes* notes = find_keyword_notes("AMPLITUDE");
  ASSERT_NE(notes, nullptr);
  std::vector<std::string> listed;
  for (const KeywordRefusal& refusal : notes->refused) {
    constexpr std::string_view kPrefix = "DEFINITION=";
    if (refusal.what.substr(0, kPrefix.size()) != kPrefix) continue;
    std::string_view rest = refusal.what.substr(kPrefix.size());
    while (!rest.empty()) {
      const std::size_t comma = rest.find(", ");
      listed.emplace_back(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 2);
    }
  }
  const KeywordSpec* spec = KeywordRegistry::instance().find("AMPLITUDE");
  ASSERT_NE(spec, nullptr);
  const auto definition = std::find_if(spec->params.begin(), spec->params.end(),
                                       [](const ParamSpec& p) { return p.name == "DEFINITION"; });
  ASSERT_NE(definition, spec->params.end());
  for (std::string_view value : definition->values) {
    CheckedDeck deck;
    read_deck_text("deck.inp",
                   "*AMPLITUDE, NAME=A, DEFINITION=" + std::string(value) +
                       "\n0., 0., 1., 1.\n*NODE\n1, 0., 0., 0.\n*STEP\n*STATIC\n*END STEP\n",
                   deck.sources, deck.model, deck.sink);
    bool refused = false;
    for (const Diagnostic* d : deck.with(DiagCode::unsupported_option)) {
      if (d->loc.line == 1) refused = true;
    }
    const bool in_notes = std::find(listed.begin(), listed.end(), value) != listed.end();
    EXPECT_EQ(refused, in_notes) << "DEFINITION=" << value << (refused ? " is" : " is not")
                                 << " refused by the reader:\n"
                                 << deck.dump();
  }
}

// The connection types the notes say take PREDEFINED friction are those the check accepts it on.
TEST(KeywordNotes, PredefinedFrictionTypesAreTheOnesTheCheckAccepts) {
  const KeywordNotes* notes = find_keyword_notes("CONNECTOR FRICTION");
  ASSERT_NE(notes, nullptr);
  std::vector<std::string> listed;
  for (const KeywordRefusal& refusal : notes->refused) {
    constexpr std::string_view kMarker = "PREDEFINED on a connection type other than ";
    if (refusal.what.substr(0, kMarker.size()) != kMarker) continue;
    std::string_view rest = refusal.what.substr(kMarker.size());
    while (!rest.empty()) {
      const std::size_t comma = rest.find(", ");
      listed.emplace_back(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 2);
    }
  }
  ASSERT_FALSE(listed.empty());
  for (const ConnectionTypeInfo& type : connection_types()) {
    if (type.support != V1Support::Supported) continue;
    CheckedDeck deck;
    read_deck_text("deck.inp",
                   "*NODE\n1, 0., 0., 0.\n2, 0., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n"
                   "1, 1, 2\n*ORIENTATION, NAME=O\n1., 0., 0., 0., 1., 0.\n"
                   "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\n" +
                       std::string(type.name) +
                       ",\nO, O\n*CONNECTOR BEHAVIOR, NAME=B\n"
                       "*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1000.\n*FRICTION\n0.3\n"
                       "*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n*END STEP\n",
                   deck.sources, deck.model, deck.sink);
    const bool accepted = deck.with(DiagCode::unsupported_option).empty() &&
                          deck.with(DiagCode::friction_predefined_unavailable).empty();
    const bool in_notes = std::find(listed.begin(), listed.end(), type.name) != listed.end();
    EXPECT_EQ(accepted, in_notes) << type.name << (accepted ? " takes" : " does not take")
                                  << " predefined friction:\n"
                                  << deck.dump();
  }
}

}  // namespace
}  // namespace clinch
