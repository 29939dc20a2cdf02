// The decks of ../shared/external-decks/ (written by others): the CalculiX spring decks check
// clean, the fragments and the decks that need unsupported elements get precise errors at the
// right lines, and none of them crashes the reader.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "tests/support/external_decks.hpp"
#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

struct Checked {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
};

std::unique_ptr<Checked> check(const std::string& name) {
  auto result = std::make_unique<Checked>();
  std::string path = std::string(CLINCH_SHARED_DIR) + "/external-decks/" + name;
  std::string error;
  EXPECT_EQ(read_deck_file(path, result->sources, result->model, result->sink, &error),
            ReadStatus::Ok)
      << error;
  return result;
}

bool has(const Checked& c, DiagCode code, std::uint32_t line, std::string_view text = {}) {
  return std::any_of(c.sink.diagnostics().begin(), c.sink.diagnostics().end(),
                     [&](const Diagnostic& d) {
                       return d.code == code && d.loc.line == line &&
                              d.message.find(text) != std::string::npos;
                     });
}

std::string listing(const Checked& c) {
  std::string out;
  for (const Diagnostic& d : c.sink.diagnostics()) out += render_text(d, c.sources);
  return out;
}

// The decks live beside the repository, not in it: a clone with nothing beside it skips them.
class ExternalDecks : public ::testing::Test {
 protected:
  void SetUp() override {
    CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  }
};

TEST_F(ExternalDecks, CalculixSpringDecksCheckClean) {
  for (const char* name : {"ccx-spring1.inp", "ccx-spring2.inp", "ccx-spring6.inp",
                           "ccx-spring7.inp"}) {
    auto c = check(name);
    EXPECT_EQ(c->sink.error_count(), 0u) << name << "\n" << listing(*c);
  }
}

TEST_F(ExternalDecks, UnsupportedElementTypesAreNamedAtTheirLine) {
  auto gap = check("ccx-gap2.inp");
  // C3D8 is read; the block is refused once, as deformable (docs/decisions.md, "Elements held as
  // nodes").
  EXPECT_TRUE(has(*gap, DiagCode::deformable_element, 25, "type C3D8")) << listing(*gap);
  EXPECT_TRUE(has(*gap, DiagCode::unsupported_option, 28, "'GAPUNI' is not supported"));
  EXPECT_TRUE(has(*gap, DiagCode::unsupported_keyword, 33, "'*GAP'"));

  auto dashpot = check("ccx-dashpot1.inp");
  EXPECT_TRUE(has(*dashpot, DiagCode::deformable_element, 22, "type C3D8"));
  // DASHPOTA runs (docs/decisions.md, "Dashpots"); the deck is still refused, first at C3D8.
  EXPECT_FALSE(has(*dashpot, DiagCode::unsupported_option, 24, "'DASHPOTA' is not supported"))
      << listing(*dashpot);
  // *MATERIAL, the five-term *EQUATION (a line ending in a comma, as CalculiX writes it) and the
  // *FREQUENCY step (CalculiX's STORAGE=YES ignored) are read.
  EXPECT_FALSE(has(*dashpot, DiagCode::unsupported_keyword, 41, "'*MATERIAL'"));
  EXPECT_FALSE(has(*dashpot, DiagCode::unsupported_keyword, 47, "'*EQUATION'"));
  EXPECT_EQ(dashpot->model.constraints.equations.size(), 1u) << listing(*dashpot);
  EXPECT_FALSE(has(*dashpot, DiagCode::unsupported_keyword, 52, "'*FREQUENCY'"));
  EXPECT_TRUE(has(*dashpot, DiagCode::parameter_ignored, 52, "STORAGE has no effect"));

  auto spring3 = check("ccx-spring3.inp");
  EXPECT_TRUE(has(*spring3, DiagCode::deformable_element, 23, "type C3D8"));
  EXPECT_FALSE(has(*spring3, DiagCode::unsupported_keyword, 41, "'*EQUATION'"))
      << listing(*spring3);
  EXPECT_FALSE(has(*spring3, DiagCode::unsupported_keyword, 56, "'*FREQUENCY'"));
}

TEST_F(ExternalDecks, BushingFragmentNamesTheUndefinedInstances) {
  auto c = check("adapy-conn-bushing-fragment.inp");
  EXPECT_TRUE(has(*c, DiagCode::undefined_instance, 8, "'bolt1-3'")) << listing(*c);
  EXPECT_TRUE(has(*c, DiagCode::undefined_instance, 13, "'bolt1-2'"));
  EXPECT_TRUE(has(*c, DiagCode::undefined_instance, 13, "'bolt1-1'"));
  EXPECT_TRUE(has(*c, DiagCode::undefined_instance, 18, "'bolt1-4'"));
  // The column of the qualified field on "9, 20, bolt1-3.477".
  for (const Diagnostic& d : c->sink.diagnostics()) {
    if (d.code == DiagCode::undefined_instance && d.loc.line == 8) {
      EXPECT_EQ(d.loc.column, 8u);
    }
  }
}

TEST_F(ExternalDecks, BehaviourFragmentRejectsFieldDependence) {
  auto c = check("adapy-conn-behaviors-deps.inp");
  EXPECT_TRUE(has(*c, DiagCode::unsupported_dependencies, 5)) << listing(*c);
  EXPECT_TRUE(has(*c, DiagCode::unsupported_dependencies, 14));
}

TEST_F(ExternalDecks, EveryDeckIsReadWithoutCrashing) {
  fs::path dir = fs::path(CLINCH_SHARED_DIR) / "external-decks";
  int decks = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".inp") continue;
    auto c = check(entry.path().filename().string());
    ++decks;
    // Every deck produces a well-formed set of diagnostics: each has a valid location.
    for (const Diagnostic& d : c->sink.diagnostics()) EXPECT_TRUE(d.loc.valid());
  }
  EXPECT_EQ(decks, 9);
}

}  // namespace
}  // namespace clinch
