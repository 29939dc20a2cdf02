// `clinch keywords` joins the registry with the prose of src/cli/keyword_notes.cpp: every keyword
// clinch supports must have its sentence, and a note must not describe a keyword the registry
// does not have (a renamed or removed keyword would otherwise leave a stale page).
#include <gtest/gtest.h>

#include "base/fold_name.hpp"
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

}  // namespace
}  // namespace clinch
