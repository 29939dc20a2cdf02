// Unit tests of *CONNECTOR DERIVED COMPONENT and *CONNECTOR POTENTIAL
// (derived-components-and-potentials.md §1–§2, §4): parsing of each form, the stored data, the
// classification g_S/g_M/g_N/mixed and P_N/P_S, placement, and every rule with its diagnostic
// position. Deck tests go through the reader; availability tests build the model by hand, so that
// they do not depend on the section keywords.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "tests/unit/checked_deck.hpp"
#include "base/diagnostic.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"
#include "src/model/potential_queries.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

struct Deck : CheckedDeck {
  // W0501 about a derived component (the behaviour itself may be unused in these decks).
  const Diagnostic* unused_derived() const {
    for (const Diagnostic* d : with(DiagCode::defined_but_unused)) {
      if (d->message.find("derived component") != std::string::npos) return d;
    }
    return nullptr;
  }
  const ConnectorBehavior& behavior(std::size_t i = 0) const {
    return model.behaviors.behaviors.at(i);
  }
};

std::unique_ptr<Deck> read(const std::string& text) {
  auto deck = std::make_unique<Deck>();
  read_deck_text("t.inp", text, deck->sources, deck->model, deck->sink);
  return deck;
}

// A behaviour block that starts on line 1; the keywords of a test follow from line 2 on.
std::string block(const std::string& body) {
  return "*CONNECTOR BEHAVIOR, NAME=weld\n" + body;
}

void expect_at(const Diagnostic* d, std::uint32_t line, std::uint32_t column,
               const std::string& dump) {
  ASSERT_NE(d, nullptr) << dump;
  EXPECT_EQ(d->loc.line, line) << d->message << "\n" << dump;
  EXPECT_EQ(d->loc.column, column) << d->message << "\n" << dump;
}

const std::string kSpotWeld = block(
    "*CONNECTOR PLASTICITY\n"                                                  // 2
    "*CONNECTOR HARDENING, DEFINITION=TABULAR\n"                               // 3
    "40000.0, 0.0\n"                                                           // 4
    "*CONNECTOR POTENTIAL, EXPONENT=1.5\n"                                     // 5
    "normal, 0.02, , MACAULEY\n"                                               // 6
    "shear,  0.05, , ABS\n"                                                    // 7
    "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n"       // 8
    "3\n"                                                                      // 9
    "1.0\n"                                                                    // 10
    "*CONNECTOR DERIVED COMPONENT, NAME=normal\n"                              // 11
    "4, 5\n"                                                                   // 12
    "0.799894, 0.799894\n"                                                     // 13
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n"                               // 14
    "6\n"                                                                      // 15
    "0.399947\n"                                                               // 16
    "*CONNECTOR DERIVED COMPONENT, NAME=shear\n"                               // 17
    "1, 2\n"                                                                   // 18
    "1.0, 1.0\n");                                                             // 19

// --- *CONNECTOR DERIVED COMPONENT ----------------------------------------------------------------

TEST(DerivedComponent, SpotWeldTermsAreStoredWithNormDefault) {
  auto deck = read(kSpotWeld);
  const ConnectorBehavior& b = deck->behavior();
  ASSERT_EQ(b.derived_terms.size(), 4u) << deck->dump();
  const DerivedComponentTerm& t0 = b.derived_terms[0];
  EXPECT_EQ(t0.name.key, "NORMAL");
  EXPECT_EQ(t0.name.display, "normal");
  EXPECT_EQ(t0.op, DerivedOperator::MacauleySum);
  EXPECT_EQ(t0.components, std::vector<int>({3}));
  EXPECT_EQ(t0.coefficients, std::vector<double>({1.0}));
  EXPECT_TRUE(t0.complete);
  const DerivedComponentTerm& t1 = b.derived_terms[1];
  EXPECT_EQ(t1.op, DerivedOperator::Norm);  // the default operator is NORM (§1.1)
  EXPECT_EQ(t1.components, std::vector<int>({4, 5}));
  EXPECT_DOUBLE_EQ(t1.coefficients[1], 0.799894);
  EXPECT_EQ(t1.sign, 1);
  EXPECT_EQ(t1.component_locs[1].line, 12u);
  EXPECT_EQ(t1.component_locs[1].column, 4u);
  // Classification (§1.5): normal = T_M + T_N → g_N; shear = two T_N → g_N.
  for (const DerivedComponentTerm& t : b.derived_terms) {
    EXPECT_EQ(t.component_type, DerivedType::Norm) << t.name.display;
    EXPECT_TRUE(t.referenced);
  }
  EXPECT_EQ(deck->unused_derived(), nullptr) << deck->dump();
}

TEST(DerivedComponent, ClassificationOfEachTermMix) {
  auto deck = read(block(
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n"
      "-10., 10.\n"
      "*CONNECTOR POTENTIAL, EXPONENT=1.0\n"
      "s, , , NONE\n"
      "m\n"
      "x, , , NONE\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=s, OPERATOR=SUM\n1, 2\n1.0, -1.0\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=m, OPERATOR=MACAULEY SUM\n1\n-1.0\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=x, OPERATOR=SUM\n1\n1.0\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=x\n2\n1.0\n"));
  const ConnectorBehavior& b = deck->behavior();
  ASSERT_EQ(b.derived_terms.size(), 4u) << deck->dump();
  EXPECT_EQ(b.derived_terms[0].component_type, DerivedType::Sum);
  EXPECT_EQ(b.derived_terms[1].component_type, DerivedType::Macauley);
  EXPECT_EQ(b.derived_terms[2].component_type, DerivedType::Mixed);
  EXPECT_EQ(b.derived_terms[3].component_type, DerivedType::Mixed);
  ASSERT_EQ(b.potentials.size(), 1u);
  const Potential& p = b.potentials[0];
  // s (g_S) with H=NONE → P_S; m (g_M) → P_N; x (mixed) with H=NONE → unknown.
  EXPECT_TRUE(p.contributions[0].type_known);
  EXPECT_EQ(p.contributions[0].type, ContributionType::Sum);
  EXPECT_EQ(p.contributions[1].type, ContributionType::Norm);
  EXPECT_FALSE(p.contributions[2].type_known);
  // Damage potentials are not held to the plasticity/friction rules (§2.6).
  EXPECT_EQ(deck->first(DiagCode::potential_mixed_type), nullptr) << deck->dump();
  EXPECT_EQ(deck->first(DiagCode::dc_mixed_type), nullptr) << deck->dump();
}

TEST(DerivedComponent, OperatorAliasWarnsAtTheValue) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=a, OPERATOR=RSS\n1\n1.0\n"));
  expect_at(deck->first(DiagCode::operator_alias), 2, 48, deck->dump());
  EXPECT_NE(deck->first(DiagCode::operator_alias)->message.find("OPERATOR=RSS read as NORM"),
            std::string::npos);
  EXPECT_EQ(deck->behavior().derived_terms.at(0).op, DerivedOperator::Norm);
}

TEST(DerivedComponent, UnknownOperatorSuggests) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=a, OPERATOR=NROM\n1\n1.0\n"));
  const Diagnostic* d = deck->first(DiagCode::invalid_value);
  expect_at(d, 2, 48, deck->dump());
  ASSERT_FALSE(d->notes.empty());
  EXPECT_NE(d->notes[0].message.find("NORM"), std::string::npos);
}

TEST(DerivedComponent, NumericNameIsAnError) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=12\n1\n1.0\n"));
  expect_at(deck->first(DiagCode::dc_numeric_name), 2, 36, deck->dump());
  EXPECT_TRUE(deck->behavior().derived_terms.empty());
}

TEST(DerivedComponent, DuplicateAndBadComponentsPointAtTheField) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=a\n1, 7, 1\n1.0, 1.0, 1.0\n"));
  expect_at(deck->first(DiagCode::dc_bad_component), 3, 4, deck->dump());
  const Diagnostic* dup = deck->first(DiagCode::dc_duplicate_component);
  expect_at(dup, 3, 7, deck->dump());
  ASSERT_EQ(dup->notes.size(), 1u);
  EXPECT_EQ(dup->notes[0].loc.column, 1u);
  EXPECT_FALSE(deck->behavior().derived_terms.at(0).complete);
}

TEST(DerivedComponent, MissingCoefficientLine) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=a\n1, 2\n"));
  expect_at(deck->first(DiagCode::dc_missing_coefficients), 2, 1, deck->dump());
}

TEST(DerivedComponent, BlankCoefficientReadsAsZeroWithWarning) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=a\n1, 2, 3\n1.0, , 2.0\n"));
  expect_at(deck->first(DiagCode::dc_zero_coefficient), 4, 6, deck->dump());
  const DerivedComponentTerm& t = deck->behavior().derived_terms.at(0);
  EXPECT_EQ(t.coefficients, std::vector<double>({1.0, 0.0, 2.0}));
  EXPECT_TRUE(t.complete);
}

TEST(DerivedComponent, TemperatureTableIsRejected) {
  auto deck = read(block("*CONNECTOR DERIVED COMPONENT, NAME=a\n1\n1.0, 20.\n2.0, 40.\n"));
  expect_at(deck->first(DiagCode::temperature_ignored), 4, 6, deck->dump());
  expect_at(deck->first(DiagCode::unsupported_dependencies), 5, 1, deck->dump());
}

TEST(DerivedComponent, IndependentComponentsIsUnsupported) {
  auto deck = read(block(
      "*CONNECTOR DERIVED COMPONENT, NAME=a, INDEPENDENT COMPONENTS=POSITION\n1\n1\n1.0, 0.\n"));
  expect_at(deck->first(DiagCode::unsupported_option), 2, 39, deck->dump());
  EXPECT_EQ(deck->first(DiagCode::too_many_fields), nullptr) << deck->dump();
}

// --- *CONNECTOR POTENTIAL: data lines ------------------------------------------------------------

TEST(Potential, SixFieldLayoutAndDefaults) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL, EXPONENT=2.0\n"
      "1, 100.0, 2.0, ABS, 10.0, 1.0\n"
      "2\n"));
  const ConnectorBehavior& b = deck->behavior();
  ASSERT_EQ(b.potentials.size(), 1u) << deck->dump();
  const Potential& p = b.potentials[0];
  EXPECT_EQ(p.op, PotentialOperator::Sum);
  EXPECT_DOUBLE_EQ(p.exponent, 2.0);
  ASSERT_EQ(p.contributions.size(), 2u);
  const PotentialContribution& c0 = p.contributions[0];
  EXPECT_FALSE(c0.derived);
  EXPECT_EQ(c0.component, 1);
  EXPECT_DOUBLE_EQ(c0.scale, 100.0);
  EXPECT_DOUBLE_EQ(c0.alpha, 2.0);
  EXPECT_EQ(c0.function, PotentialFunction::Abs);
  EXPECT_DOUBLE_EQ(c0.shift, 10.0);
  EXPECT_DOUBLE_EQ(c0.sign, 1.0);
  const PotentialContribution& c1 = p.contributions[1];
  EXPECT_DOUBLE_EQ(c1.scale, 1.0);
  EXPECT_DOUBLE_EQ(c1.alpha, 2.0);  // α defaults to β
  EXPECT_FALSE(c1.alpha_given);
  EXPECT_EQ(c1.function, PotentialFunction::Abs);
  EXPECT_EQ(c1.type, ContributionType::Norm);
  EXPECT_EQ(p.owner, 0);
  EXPECT_EQ(b.potential_owners.at(0).potential, 0);
  EXPECT_EQ(deck->first(DiagCode::potential_missing), nullptr) << deck->dump();
}

TEST(Potential, ShortLayoutIsReadWithAWarning) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL, EXPONENT=1.5\n"
      "normal, 0.02, MACAULEY\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n3\n1.0\n"));
  const Diagnostic* d = deck->first(DiagCode::potential_short_layout);
  expect_at(d, 4, 15, deck->dump());
  EXPECT_NE(d->message.find("write 'normal, 0.02, , MACAULEY' to silence"), std::string::npos)
      << d->message;
  const PotentialContribution& c = deck->behavior().potentials.at(0).contributions.at(0);
  EXPECT_EQ(c.function, PotentialFunction::Macauley);
  EXPECT_DOUBLE_EQ(c.alpha, 1.5);
  EXPECT_TRUE(c.derived);
}

TEST(Potential, FieldErrorsPointAtTheirFields) {
  auto deck = read(block(
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n-1., 1.\n"
      "*CONNECTOR POTENTIAL, EXPONENT=1.0\n"
      "1, 0.0\n"                  // 5: zero scale at col 4
      "2, 1.0, , IDENTITY\n"      // 6: invalid H at col 11
      "3, 1.0, , ABS, 0., 0.5\n"  // 7: bad sign at col 20
      "7\n"));                    // 8: out of range at col 1
  expect_at(deck->first(DiagCode::potential_zero_scale), 5, 4, deck->dump());
  const Diagnostic* h = deck->first(DiagCode::invalid_value);
  expect_at(h, 6, 11, deck->dump());
  ASSERT_FALSE(h->notes.empty());
  EXPECT_EQ(h->notes[0].message, "did you mean NONE?");
  expect_at(deck->first(DiagCode::potential_bad_sign), 7, 20, deck->dump());
  expect_at(deck->first(DiagCode::value_out_of_range), 8, 1, deck->dump());
}

TEST(Potential, IdentityRuleAtField4) {
  auto deck = read(block(
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n-1., 1.\n"
      "*CONNECTOR POTENTIAL, EXPONENT=2.0\n"
      "1, 1.0, , NONE\n"));
  const Diagnostic* d = deck->first(DiagCode::potential_identity_exponent);
  expect_at(d, 5, 11, deck->dump());
  EXPECT_NE(d->message.find("H=NONE requires alpha = beta = 1"), std::string::npos);
}

TEST(Potential, MaximumSuggestsMaxAndExponentIsIgnoredWithMax) {
  auto a = read(block("*CONNECTOR PLASTICITY\n*CONNECTOR POTENTIAL, OPERATOR=MAXIMUM\n1\n"));
  const Diagnostic* d = a->first(DiagCode::invalid_value);
  expect_at(d, 3, 32, a->dump());
  ASSERT_FALSE(d->notes.empty());
  EXPECT_EQ(d->notes[0].message, "did you mean MAX?");

  auto b = read(block(
      "*CONNECTOR PLASTICITY\n*CONNECTOR POTENTIAL, OPERATOR=MAX, EXPONENT=3.0\n1, 1., 2.\n"));
  auto ignored = b->with(DiagCode::potential_exponent_ignored);
  ASSERT_EQ(ignored.size(), 2u) << b->dump();
  expect_at(ignored[0], 3, 37, b->dump());
  expect_at(ignored[1], 4, 8, b->dump());
  EXPECT_EQ(b->behavior().potentials.at(0).op, PotentialOperator::Max);
}

TEST(Potential, NonPositiveExponentAndEmptyPotential) {
  auto deck = read(block("*CONNECTOR PLASTICITY\n*CONNECTOR POTENTIAL, EXPONENT=-1.0\n"));
  expect_at(deck->first(DiagCode::value_out_of_range), 3, 32, deck->dump());
  expect_at(deck->first(DiagCode::potential_empty), 3, 1, deck->dump());
}

// --- placement (§2.7) ----------------------------------------------------------------------------

TEST(PotentialPlacement, NoOwnerAtTheStarOfTheKeyword) {
  auto deck = read(block("  *CONNECTOR POTENTIAL\n1\n"));
  expect_at(deck->first(DiagCode::potential_no_owner), 2, 3, deck->dump());
}

TEST(PotentialPlacement, DuplicateNotesTheFirst) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR HARDENING\n100., 0.\n"
      "*CONNECTOR POTENTIAL\n1\n"
      "*CONNECTOR POTENTIAL\n2\n"));
  const Diagnostic* d = deck->first(DiagCode::potential_duplicate);
  expect_at(d, 7, 1, deck->dump());
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].loc.line, 5u);
  EXPECT_EQ(deck->behavior().potentials.size(), 2u);
  EXPECT_EQ(deck->behavior().potentials[1].owner, -1);
}

TEST(PotentialPlacement, NotAllowedAfterComponentOwner) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING\n100., 0.\n"
      "*CONNECTOR POTENTIAL\n1\n"));
  const Diagnostic* d = deck->first(DiagCode::potential_not_allowed);
  expect_at(d, 5, 1, deck->dump());
  EXPECT_NE(d->message.find("COMPONENT=1"), std::string::npos) << d->message;
}

TEST(PotentialPlacement, MissingAtTheOwnerLine) {
  auto deck = read(block(
      "*CONNECTOR ELASTICITY, COMPONENT=1\n1000.\n"
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR HARDENING\n100., 0.\n"));
  expect_at(deck->first(DiagCode::potential_missing), 4, 1, deck->dump());
}

TEST(PotentialPlacement, HardeningAndDerivedComponentsMayStandBetween) {
  auto deck = read(kSpotWeld);
  EXPECT_EQ(deck->first(DiagCode::potential_no_owner), nullptr);
  EXPECT_EQ(deck->first(DiagCode::potential_missing), nullptr) << deck->dump();
  EXPECT_EQ(deck->behavior().potentials.at(0).owner, 0);
}

// --- plasticity/friction rules (§2.6, §1.5) ------------------------------------------------------

TEST(PotentialRules, SpotWeldPassesEveryRule) {
  auto deck = read(kSpotWeld);
  for (DiagCode code :
       {DiagCode::potential_mixed_type, DiagCode::potential_negative_norm_sign,
        DiagCode::potential_exponent_rule, DiagCode::dc_mixed_type,
        DiagCode::dc_negative_norm_term, DiagCode::undefined_derived_component}) {
    EXPECT_EQ(deck->first(code), nullptr) << deck->dump();
  }
  const Potential& p = deck->behavior().potentials.at(0);
  EXPECT_FALSE(p.mixed);
  EXPECT_EQ(p.type, ContributionType::Norm);
}

TEST(PotentialRules, MixedTypeAtTheOffendingLineWithNote) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL, EXPONENT=1.0\n"
      "2, 1.0, , ABS\n"     // 4: P_N
      "1, 1.0, , NONE\n"));  // 5: P_S
  const Diagnostic* d = deck->first(DiagCode::potential_mixed_type);
  expect_at(d, 5, 1, deck->dump());
  EXPECT_NE(d->message.find("contribution 2 of the potential of *CONNECTOR PLASTICITY is "
                            "sum-type (H=NONE on component 1), but contribution 1 is norm-type"),
            std::string::npos)
      << d->message;
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].loc.line, 4u);
  EXPECT_EQ(d->notes[0].message, "contribution 1 (norm-type) is here");
  EXPECT_TRUE(deck->behavior().potentials.at(0).mixed);
}

TEST(PotentialRules, NegativeNormSignAtField6) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL\n"
      "1, 1.0, , ABS, 0.0, -1.0\n"));
  expect_at(deck->first(DiagCode::potential_negative_norm_sign), 4, 21, deck->dump());
  // Plasticity potentials do not get the damage-only complex-base warning.
  EXPECT_EQ(deck->first(DiagCode::potential_may_be_complex), nullptr);
}

TEST(PotentialRules, ExponentRuleAtAlphaFieldAndAtExponentValue) {
  auto alpha = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL, EXPONENT=1.5\n"
      "1, 1.0, 2.0\n"));
  const Diagnostic* d = alpha->first(DiagCode::potential_exponent_rule);
  expect_at(d, 4, 9, alpha->dump());
  EXPECT_NE(d->message.find("exponent alpha=2.0 differs from EXPONENT=1.5; in a plasticity or "
                            "friction potential every alpha must equal beta"),
            std::string::npos)
      << d->message;

  auto beta = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL, EXPONENT=0.5\n"
      "1\n"));
  expect_at(beta->first(DiagCode::potential_exponent_rule), 3, 32, beta->dump());
  EXPECT_EQ(beta->with(DiagCode::potential_exponent_rule).size(), 1u) << beta->dump();
}

TEST(PotentialRules, DerivedMixedTypeAtTheTermWithTwoNotes) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"                                             // 2
      "*CONNECTOR POTENTIAL\n"                                              // 3
      "normal\n"                                                            // 4
      "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=SUM\n3\n1.0\n"    // 5
      "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n4\n1.0\n"));  // 8
  const Diagnostic* d = deck->first(DiagCode::dc_mixed_type);
  expect_at(d, 8, 44, deck->dump());
  EXPECT_NE(d->message.find("derived component 'normal' mixes a MACAULEY SUM term with SUM terms "
                            "and cannot be used by *CONNECTOR PLASTICITY"),
            std::string::npos)
      << d->message;
  ASSERT_EQ(d->notes.size(), 2u);
  EXPECT_EQ(d->notes[0].loc.line, 5u);
  EXPECT_EQ(d->notes[0].message, "first term (SUM) is here");
  EXPECT_EQ(d->notes[1].loc.line, 4u);
  EXPECT_EQ(d->notes[1].message, "used by the potential contribution here");
}

TEST(PotentialRules, NegativeNormTermAtSignParameter) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL\n"
      "shear\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=shear, SIGN=NEGATIVE\n1, 2\n1.0, 1.0\n"));
  const Diagnostic* d = deck->first(DiagCode::dc_negative_norm_term);
  expect_at(d, 5, 43, deck->dump());
  EXPECT_NE(d->message.find("derived component 'shear' has a NORM term with SIGN=NEGATIVE"),
            std::string::npos);
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].loc.line, 4u);
}

TEST(PotentialRules, EachUseGetsItsOwnError) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n*CONNECTOR POTENTIAL\nd\n"
      "*CONNECTOR FRICTION, STICK STIFFNESS=1.0e4\n*CONNECTOR POTENTIAL\nd\n*FRICTION\n0.2\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=d, SIGN=NEGATIVE\n1\n1.0\n"));
  auto errors = deck->with(DiagCode::dc_negative_norm_term);
  ASSERT_EQ(errors.size(), 2u) << deck->dump();
  EXPECT_NE(errors[0]->message.find("*CONNECTOR PLASTICITY"), std::string::npos);
  EXPECT_NE(errors[1]->message.find("*CONNECTOR FRICTION"), std::string::npos);
}

TEST(PotentialRules, UndefinedDerivedComponentSuggestsAndLists) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR POTENTIAL\n"
      "shaer\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=shear\n1\n1.0\n"));
  const Diagnostic* d = deck->first(DiagCode::undefined_derived_component);
  expect_at(d, 4, 1, deck->dump());
  EXPECT_EQ(d->message, "unknown derived component 'shaer'");
  ASSERT_EQ(d->notes.size(), 2u);
  EXPECT_EQ(d->notes[0].message, "did you mean 'shear'?");
  EXPECT_NE(d->notes[1].message.find("shear"), std::string::npos);
  // The only term is now unused.
  expect_at(deck->unused_derived(), 5, 1, deck->dump());
}

TEST(PotentialRules, DamageNegativeSignWarnsAboutComplexBase) {
  auto deck = read(block(
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n-1., 1.\n"
      "*CONNECTOR POTENTIAL, EXPONENT=2.0\n"
      "1\n"
      "2, 1.0, , ABS, 0.0, -1.0\n"));
  expect_at(deck->first(DiagCode::potential_may_be_complex), 6, 21, deck->dump());
  EXPECT_EQ(deck->first(DiagCode::potential_negative_norm_sign), nullptr);
}

// --- contexts (§4) --------------------------------------------------------------------------------

TEST(DerivedContexts, ForceAndMotionContexts) {
  auto deck = read(block(
      "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING\n100., 0.\n"
      "*CONNECTOR POTENTIAL\nf\n"
      "*CONNECTOR DAMAGE INITIATION, CRITERION=MOTION\n-1., 1.\n"
      "*CONNECTOR POTENTIAL\nu\nf\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=f\n1\n1.0\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=u\n2\n1.0\n"
      "*CONNECTOR DERIVED COMPONENT, NAME=unused\n3\n1.0\n"));
  const ConnectorBehavior& b = deck->behavior();
  EXPECT_TRUE(derived_has_force_context(b, "F"));
  EXPECT_TRUE(derived_has_motion_context(b, "F"));
  EXPECT_FALSE(derived_has_force_context(b, "U"));
  EXPECT_TRUE(derived_has_motion_context(b, "U"));
  EXPECT_FALSE(derived_has_force_context(b, "UNUSED"));
  auto first = first_derived_context(b, "F", true);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->kind, DerivedContextKind::PlasticityPotential);
  EXPECT_EQ(first->loc.line, 6u);
  EXPECT_EQ(derived_context_count(b, "F", true), 1u);
  EXPECT_EQ(derived_component_first_terms(b), std::vector<std::int32_t>({0, 1, 2}));
  expect_at(deck->unused_derived(), 18, 1, deck->dump());
}

// --- the example deck ----------------------------------------------------------------------------

// decks/examples/spot_weld.inp (DCP §3) must check clean, with the parameters substituted.
TEST(SpotWeldExample, ChecksCleanWithTheManualConstants) {
  auto deck = std::make_unique<Deck>();
  std::string error;
  ASSERT_EQ(read_deck_file(std::string(CLINCH_SOURCE_DIR) + "/decks/examples/spot_weld.inp",
                           deck->sources, deck->model, deck->sink, &error),
            ReadStatus::Ok)
      << error;
  EXPECT_TRUE(deck->sink.diagnostics().empty()) << deck->dump();
  const ConnectorBehavior& b = deck->behavior();
  ASSERT_EQ(b.derived_terms.size(), 4u);
  EXPECT_NEAR(b.derived_terms[1].coefficients.at(0), 0.799894, 1e-6);  // or_n = 1/r_n
  EXPECT_NEAR(b.derived_terms[2].coefficients.at(0), 0.399947, 1e-6);  // or_s = 1/r_s
  const Potential& p = b.potentials.at(0);
  EXPECT_DOUBLE_EQ(p.exponent, 1.5);
  EXPECT_DOUBLE_EQ(p.contributions.at(0).scale, 0.02);
  EXPECT_DOUBLE_EQ(p.contributions.at(1).scale, 0.05);
  EXPECT_EQ(p.type, ContributionType::Norm);
  EXPECT_TRUE(derived_has_force_context(b, "NORMAL"));
  EXPECT_FALSE(derived_has_motion_context(b, "NORMAL"));
}

// --- availability against the sections (hand-built model) ----------------------------------------

// One behaviour used by one valid section of the given type and masks.
Model model_with_section(std::vector<std::string> types, ComponentMask available,
                         ComponentMask constrained, ElementType element = ElementType::Conn3D2) {
  Model model;
  ConnectorBehavior b;
  b.name = Name{"W", "w", SourceLoc{0, 1, 1}};
  model.behaviors.behaviors.push_back(std::move(b));
  Element e;
  e.type = element;
  model.elements.push_back(e);
  ConnectorSection s;
  s.behavior = Name{"W", "w", SourceLoc{0, 30, 40}};
  s.behavior_index = 0;
  s.valid = true;
  s.type_names = std::move(types);
  s.available = available;
  s.constrained = constrained;
  s.elements = {0};
  model.sections.connector_sections.push_back(std::move(s));
  return model;
}

DerivedComponentTerm make_term(const std::string& name, std::vector<int> components,
                               std::uint32_t line) {
  DerivedComponentTerm t;
  t.name = Name{name, name, SourceLoc{0, line, 36}};
  t.loc = SourceLoc{0, line, 1};
  t.components = components;
  for (std::size_t j = 0; j < components.size(); ++j) {
    t.component_locs.push_back(SourceLoc{0, line + 1, static_cast<std::uint32_t>(1 + 3 * j)});
    t.coefficients.push_back(1.0);
  }
  t.complete = true;
  return t;
}

Potential make_potential(std::int32_t owner, std::uint32_t line) {
  Potential p;
  p.loc = SourceLoc{0, line, 1};
  p.owner = owner;
  return p;
}

PotentialContribution intrinsic(int k, std::uint32_t line) {
  PotentialContribution c;
  c.loc = c.source_loc = SourceLoc{0, line, 1};
  c.component = k;
  c.valid = true;
  return c;
}

PotentialContribution derived(const std::string& key, std::uint32_t line) {
  PotentialContribution c;
  c.loc = c.source_loc = SourceLoc{0, line, 1};
  c.derived = true;
  c.derived_name = Name{key, key, c.source_loc};
  c.valid = true;
  return c;
}

void add_plasticity_owner(ConnectorBehavior& b, std::int32_t potential) {
  PotentialOwner o;
  o.kind = PotentialOwner::Kind::Plasticity;
  o.index = 0;
  o.loc = SourceLoc{0, 2, 1};
  o.requires_potential = true;
  o.potential = potential;
  b.potential_owners.push_back(o);
}

TEST(PotentialAvailability, IntrinsicComponentNotAvailable) {
  Model model = model_with_section({"SLOT"}, component_bit(1),
                                   component_bit(2) | component_bit(3));
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  add_plasticity_owner(b, 0);
  Potential p = make_potential(0, 10);
  p.contributions.push_back(intrinsic(1, 11));
  p.contributions.push_back(intrinsic(2, 12));
  b.potentials.push_back(p);
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  const Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(d.code, DiagCode::potential_unavailable_component);
  EXPECT_EQ(d.loc.line, 12u);
  EXPECT_EQ(d.message, "component 2 is not available for connection type SLOT (available: 1)");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.line, 30u);
  EXPECT_EQ(d.notes[0].loc.column, 40u);
}

TEST(PotentialAvailability, DerivedComponentListsUnavailableComponent) {
  Model model = model_with_section({"SLOT"}, component_bit(1),
                                   component_bit(2) | component_bit(3));
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  add_plasticity_owner(b, 0);
  b.derived_terms.push_back(make_term("N", {1, 2}, 20));
  Potential p = make_potential(0, 10);
  p.contributions.push_back(derived("N", 11));
  b.potentials.push_back(p);
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  const Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(d.code, DiagCode::dc_unavailable_component);
  EXPECT_EQ(d.loc.line, 21u);
  EXPECT_EQ(d.loc.column, 4u);
  ASSERT_EQ(d.notes.size(), 2u);
  EXPECT_EQ(d.notes[0].loc.line, 11u);
  EXPECT_EQ(d.notes[1].loc.line, 30u);
}

TEST(PotentialAvailability, TwoDimensionalComponentsDoNotExist) {
  Model model = model_with_section({"CARTESIAN"}, component_bit(1) | component_bit(2), 0,
                                   ElementType::Conn2D2);
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  add_plasticity_owner(b, 0);
  b.derived_terms.push_back(make_term("N", {1, 4}, 20));
  Potential p = make_potential(0, 10);
  p.contributions.push_back(derived("N", 11));
  b.potentials.push_back(p);
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);  // dc-bad-component only, not also unavailable
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::dc_bad_component);
  EXPECT_EQ(sink.diagnostics()[0].loc.column, 4u);
}

TEST(PotentialAvailability, UnusedBehaviorSkipsAvailability) {
  Model model = model_with_section({"SLOT"}, component_bit(1), 0);
  model.sections.connector_sections[0].behavior_index = -1;
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  add_plasticity_owner(b, 0);
  Potential p = make_potential(0, 10);
  p.contributions.push_back(intrinsic(5, 11));
  b.potentials.push_back(p);
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  EXPECT_TRUE(sink.diagnostics().empty());
}

}  // namespace
}  // namespace clinch
