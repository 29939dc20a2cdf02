// Unit tests of *CONNECTOR FRICTION and *FRICTION in a connector behaviour (friction.md §2, §3,
// §8): the three forms, the stored data, the law forms, and every check with its position.
// Checks that need the connection type use a hand-built model.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "base/diagnostic.hpp"
#include "parser/deck_reader.hpp"
#include "parser/source_manager.hpp"
#include "src/resolve/resolve.hpp"
#include "src/model/default_stick_stiffness.hpp"
#include "src/model/model.hpp"
#include "src/model/potential_queries.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

struct Deck : CheckedDeck {
  const ConnectorBehavior& behavior() const { return model.behaviors.behaviors.at(0); }
};

std::unique_ptr<Deck> read(const std::string& body) {
  auto deck = std::make_unique<Deck>();
  read_deck_text("t.inp", "*CONNECTOR BEHAVIOR, NAME=FRIC\n" + body, deck->sources, deck->model,
                 deck->sink);
  return deck;
}

void expect_at(const Diagnostic* d, std::uint32_t line, std::uint32_t column,
               const std::string& dump) {
  ASSERT_NE(d, nullptr) << dump;
  EXPECT_EQ(d->loc.line, line) << d->message << "\n" << dump;
  EXPECT_EQ(d->loc.column, column) << d->message << "\n" << dump;
}

// --- the three forms
// ------------------------------------------------------------------------------

TEST(ConnectorFriction, PredefinedForm) {
  auto deck = read("*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1.0e4\n*FRICTION\n0.3\n");
  const ConnectorBehavior& b = deck->behavior();
  ASSERT_EQ(b.frictions.size(), 1u) << deck->dump();
  const FrictionDefinition& f = b.frictions[0];
  EXPECT_TRUE(f.predefined);
  ASSERT_TRUE(f.stick_stiffness.has_value());
  EXPECT_DOUBLE_EQ(*f.stick_stiffness, 1.0e4);
  EXPECT_TRUE(f.has_law);
  EXPECT_EQ(f.law.mu, std::vector<double>({0.3}));
  ASSERT_EQ(b.potential_owners.size(), 1u);
  EXPECT_EQ(b.potential_owners[0].kind, PotentialOwner::Kind::Friction);
  EXPECT_FALSE(b.potential_owners[0].allows_potential);
  EXPECT_FALSE(b.potential_owners[0].requires_potential);
  EXPECT_EQ(f.owner, 0);
  EXPECT_EQ(deck->first(DiagCode::friction_zero_contact), nullptr);
  EXPECT_EQ(deck->first(DiagCode::friction_default_stick_stiffness), nullptr);
}

TEST(ConnectorFriction, UncoupledFormWithContactComponentAndInternalForce) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, CONTACT FORCE=2, STICK STIFFNESS=1.0e5\n"
      "1000.0\n"
      "*FRICTION, EXPONENTIAL DECAY\n"
      "0.4, 0.2, 2.0\n");
  const FrictionDefinition& f = deck->behavior().frictions.at(0);
  EXPECT_EQ(f.component, 1);
  EXPECT_EQ(f.contact, FrictionDefinition::Contact::Component);
  EXPECT_EQ(f.contact_component, 2);
  EXPECT_EQ(f.internal_force, std::vector<double>({1000.0}));
  EXPECT_TRUE(f.law.exponential_decay);
  EXPECT_DOUBLE_EQ(f.law.mu_static, 0.4);
  EXPECT_DOUBLE_EQ(f.law.mu_kinetic, 0.2);
  EXPECT_DOUBLE_EQ(f.law.decay, 2.0);
  EXPECT_EQ(f.friction_components, component_bit(1));
  const PotentialOwner& owner = deck->behavior().potential_owners.at(0);
  EXPECT_FALSE(owner.allows_potential);
  EXPECT_EQ(owner.why_not_allowed, "COMPONENT=1");
  EXPECT_EQ(deck->first(DiagCode::friction_exclusive), nullptr) << deck->dump();
}

TEST(ConnectorFriction, CoupledFormWithDerivedContactForce) {
  auto deck = read(
      "*CONNECTOR FRICTION, CONTACT FORCE=PRESS, STICK STIFFNESS=1.0e5\n"  // 2
      "*CONNECTOR POTENTIAL\n2\n3\n"                                       // 3
      "*FRICTION, TAUMAX=50.0\n0.2\n"                                      // 6
      "*CONNECTOR DERIVED COMPONENT, NAME=PRESS\n1\n1.0\n");               // 8
  const ConnectorBehavior& b = deck->behavior();
  const FrictionDefinition& f = b.frictions.at(0);
  EXPECT_EQ(f.contact, FrictionDefinition::Contact::Derived);
  EXPECT_EQ(f.contact_name.key, "PRESS");
  EXPECT_EQ(f.friction_components, component_bit(2) | component_bit(3));
  ASSERT_TRUE(f.law.taumax.has_value());
  EXPECT_DOUBLE_EQ(*f.law.taumax, 50.0);
  EXPECT_EQ(b.potential_owners.at(0).potential, 0);
  EXPECT_EQ(b.potentials.at(0).owner, 0);
  EXPECT_TRUE(b.derived_terms.at(0).referenced);
  EXPECT_TRUE(derived_has_force_context(b, "PRESS"));
  auto use = first_derived_context(b, "PRESS", true);
  ASSERT_TRUE(use.has_value());
  EXPECT_EQ(use->kind, DerivedContextKind::ContactForce);
  for (DiagCode code : {DiagCode::potential_missing, DiagCode::undefined_derived_component,
                        DiagCode::friction_contact_self}) {
    EXPECT_EQ(deck->first(code), nullptr) << deck->dump();
  }
  for (const Diagnostic* d : deck->with(DiagCode::defined_but_unused)) {
    EXPECT_EQ(d->message.find("derived component"), std::string::npos) << d->message;
  }
}

TEST(ConnectorFriction, CoupledFormNeedsAPotential) {
  auto deck = read("*CONNECTOR FRICTION, STICK STIFFNESS=1.0e5\n10.\n*FRICTION\n0.2\n");
  expect_at(deck->first(DiagCode::potential_missing), 2, 1, deck->dump());
}

TEST(ConnectorFriction, PotentialNotAllowedAfterPredefined) {
  auto deck = read(
      "*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1.0e5\n*FRICTION\n0.2\n"
      "*CONNECTOR POTENTIAL\n1\n");
  const Diagnostic* d = deck->first(DiagCode::potential_not_allowed);
  expect_at(d, 5, 1, deck->dump());
  EXPECT_NE(d->message.find("PREDEFINED"), std::string::npos);
}

// --- keyword-line checks
// ----------------------------------------------------------------------------

TEST(ConnectorFriction, ExclusiveAtTheParameter) {
  auto deck = read(
      "*CONNECTOR FRICTION, PREDEFINED, COMPONENT=1, STICK STIFFNESS=1.\n"
      "*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::friction_exclusive), 2, 34, deck->dump());
}

TEST(ConnectorFriction, StickStiffnessAtTheValue) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=-5.0\n10.\n"
      "*FRICTION\n0.1\n");
  const Diagnostic* d = deck->first(DiagCode::friction_stick_stiffness);
  expect_at(d, 2, 51, deck->dump());
  EXPECT_EQ(deck->first(DiagCode::friction_default_stick_stiffness), nullptr);
}

TEST(ConnectorFriction, PredefinedDuplicateNotesTheFirst) {
  auto deck = read(
      "*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1.\n*FRICTION\n0.1\n"
      "*CONNECTOR FRICTION, PREDEFINED, STICK STIFFNESS=1.\n*FRICTION\n0.2\n");
  const Diagnostic* d = deck->first(DiagCode::friction_predefined_duplicate);
  expect_at(d, 5, 1, deck->dump());
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].loc.line, 2u);
}

TEST(ConnectorFriction, ComponentOutOfRangeAtTheValue) {
  auto deck = read("*CONNECTOR FRICTION, COMPONENT=7, STICK STIFFNESS=1.\n10.\n*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::value_out_of_range), 2, 32, deck->dump());
  // COMPONENT= was given: no potential is required even though its value was bad.
  EXPECT_EQ(deck->first(DiagCode::potential_missing), nullptr) << deck->dump();
}

TEST(ConnectorFriction, IndependentComponentsUnsupported) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, INDEPENDENT COMPONENTS=POSITION, "
      "STICK STIFFNESS=1.\n1\n10., 0.\n*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::unsupported_option), 2, 35, deck->dump());
}

// The default is stated once in the run log, not warned per definition; only the 1e6 fallback,
// with no elasticity to scale from, warns (docs/decisions.md, "Friction").
TEST(ConnectorFriction, DefaultStickStiffnessIsStatedOnceInTheLog) {
  auto deck = read(
      "*CONNECTOR ELASTICITY, COMPONENT=1\n2000.\n"
      "*CONNECTOR FRICTION, COMPONENT=1\n10.\n*FRICTION\n0.1\n"
      "*CONNECTOR FRICTION, COMPONENT=1\n5.\n*FRICTION\n0.2\n");
  EXPECT_EQ(deck->first(DiagCode::friction_default_stick_stiffness), nullptr) << deck->dump();
  EXPECT_DOUBLE_EQ(default_stick_stiffness(deck->behavior()).value[0], 2.0e6);  // 1000 × 2000
  EXPECT_EQ(default_stick_stiffness_summary(deck->model.behaviors),
            "friction: STICK STIFFNESS omitted in 2 *CONNECTOR FRICTION definitions, so the "
            "stick stiffness is 1000 times the connector's elastic stiffness (friction.md §5): "
            "behavior 'FRIC': 2e+06 for component 1; behavior 'FRIC': 2e+06 for component 1");

  auto given = read("*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n*FRICTION\n0.1\n");
  EXPECT_EQ(default_stick_stiffness_summary(given->model.behaviors), std::nullopt);

  auto bare = read("*CONNECTOR FRICTION, COMPONENT=2\n10.\n*FRICTION\n0.1\n");
  const Diagnostic* e = bare->first(DiagCode::friction_default_stick_stiffness);
  ASSERT_NE(e, nullptr) << bare->dump();
  expect_at(e, 2, 1, bare->dump());
  EXPECT_EQ(e->message,
            "STICK STIFFNESS omitted; using 1e+06 for component 2 (no connector "
            "elasticity to scale from)");
}

TEST(ConnectorFriction, ExplicitOnlyParametersWarn) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1., RTOL=0.1\n10.\n"
      "*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::explicit_only_parameter), 2, 55, deck->dump());
}

// --- internal contact force ---------------------------------------------------------------------

TEST(ConnectorFriction, InternalForceTable) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n"
      "10., 0.\n20., 0.5\n15., 0.5\n-1.\n*FRICTION\n0.1\n");
  const Diagnostic* d = deck->first(DiagCode::table_not_increasing);
  expect_at(d, 5, 6, deck->dump());
  expect_at(deck->first(DiagCode::friction_negative_internal), 6, 1, deck->dump());
}

TEST(ConnectorFriction, ZeroContactWarning) {
  auto deck = read("*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::friction_zero_contact), 2, 1, deck->dump());
}

TEST(ConnectorFriction, TemperatureColumnOfInternalForce) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n"
      "10., 0., 20.\n12., 1., 30.\n*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::unsupported_dependencies), 4, 10, deck->dump());
}

// --- *FRICTION ----------------------------------------------------------------------------------

TEST(FrictionLaw, TabularInSlipRate) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION\n0.3, 0.0\n0.2, 1.0\n0.1, 2.0\n");
  const FrictionLaw& law = deck->behavior().frictions.at(0).law;
  EXPECT_EQ(law.variable, FrictionLaw::Variable::SlipRate);
  EXPECT_EQ(law.mu, std::vector<double>({0.3, 0.2, 0.1}));
  EXPECT_EQ(law.slip_rate, std::vector<double>({0.0, 1.0, 2.0}));
  EXPECT_TRUE(law.complete);
}

TEST(FrictionLaw, TableChecks) {
  auto both = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION\n0.3, 0.0, 0.0\n0.2, 1.0, 5.0\n");
  expect_at(both->first(DiagCode::unsupported_dependencies), 4, 1, both->dump());
  auto falling = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION\n0.3, , 10.\n0.2, , 5.0\n");
  expect_at(falling->first(DiagCode::table_not_increasing), 6, 8, falling->dump());
  auto negative = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION\n-0.3\n");
  expect_at(negative->first(DiagCode::friction_negative_mu), 5, 1, negative->dump());
}

TEST(FrictionLaw, ExponentialDecayChecks) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION, EXPONENTIAL DECAY\n0.2, 0.4, -1.0\n");
  expect_at(deck->first(DiagCode::friction_negative_mu), 5, 11, deck->dump());
  expect_at(deck->first(DiagCode::friction_decay_increasing), 5, 1, deck->dump());
  auto missing = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION, EXPONENTIAL DECAY\n0.4, 0.2\n");
  expect_at(missing->first(DiagCode::missing_field), 5, 9, missing->dump());
}

TEST(FrictionLaw, MissingAndDuplicateLaw) {
  auto missing = read("*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n");
  expect_at(missing->first(DiagCode::friction_missing_law), 2, 1, missing->dump());
  auto twice = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION\n0.1\n*FRICTION\n0.2\n");
  const Diagnostic* d = twice->first(DiagCode::friction_law_duplicate);
  expect_at(d, 6, 1, twice->dump());
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0].loc.line, 4u);
  EXPECT_EQ(twice->behavior().frictions.at(0).law.mu, std::vector<double>({0.1}));
}

TEST(FrictionLaw, NoDataLine) {
  auto deck = read("*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n*FRICTION\n");
  expect_at(deck->first(DiagCode::missing_data_line), 4, 1, deck->dump());
}

TEST(FrictionLaw, IgnoredAndRejectedParameters) {
  auto deck = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION, SLIP TOLERANCE=0.005\n0.1\n");
  expect_at(deck->first(DiagCode::friction_option_ignored), 4, 12, deck->dump());
  auto aniso = read(
      "*CONNECTOR FRICTION, COMPONENT=1, STICK STIFFNESS=1.\n10.\n"
      "*FRICTION, ANISOTROPIC\n0.1, 0.2\n");
  const Diagnostic* d = aniso->first(DiagCode::unsupported_option);
  expect_at(d, 4, 12, aniso->dump());
  EXPECT_NE(d->message.find("use a *CONNECTOR POTENTIAL for directional friction"),
            std::string::npos);
}

TEST(FrictionLaw, WithoutConnectorFrictionInTheBlock) {
  auto deck = read("*FRICTION\n0.1\n");
  expect_at(deck->first(DiagCode::wrong_level), 2, 1, deck->dump());
}

TEST(FrictionLaw, OutsideABehaviorIsSurfaceContact) {
  auto deck = std::make_unique<Deck>();
  read_deck_text("t.inp", "*FRICTION\n0.1\n", deck->sources, deck->model, deck->sink);
  expect_at(deck->first(DiagCode::unsupported_keyword), 1, 1, deck->dump());
}

// --- checks against the connection type (hand-built model) -------------------------------------

Model model_with_section(std::vector<std::string> types, ComponentMask available,
                         ComponentMask constrained) {
  Model model;
  ConnectorBehavior b;
  b.name = Name{"FRIC", "FRIC", SourceLoc{0, 1, 1}};
  model.behaviors.behaviors.push_back(std::move(b));
  ConnectorSection s;
  s.behavior = Name{"FRIC", "FRIC", SourceLoc{0, 30, 40}};
  s.behavior_index = 0;
  s.valid = true;
  s.type_names = std::move(types);
  s.available = available;
  s.constrained = constrained;
  model.sections.connector_sections.push_back(std::move(s));
  return model;
}

// One friction definition with a law and a stick stiffness (so that only the checks of the test
// speak), registered as an owner.
FrictionDefinition& add_friction(Model& model) {
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  FrictionDefinition f;
  f.loc = SourceLoc{0, 10, 1};
  f.has_law = true;
  f.stick_stiffness = 1.0e4;
  f.stick_stiffness_loc = SourceLoc{0, 10, 60};
  f.internal_force = {10.0};
  f.owner = static_cast<std::int32_t>(b.potential_owners.size());
  PotentialOwner o;
  o.kind = PotentialOwner::Kind::Friction;
  o.index = static_cast<std::int32_t>(b.frictions.size());
  o.loc = f.loc;
  b.potential_owners.push_back(o);
  b.frictions.push_back(f);
  return b.frictions.back();
}

TEST(FrictionTypes, ComponentNotAvailableAtTheSectionBehaviorValue) {
  Model model = model_with_section({"SLOT"}, component_bit(1), component_bit(2) | component_bit(3));
  FrictionDefinition& f = add_friction(model);
  f.component = 2;
  f.component_loc = SourceLoc{0, 10, 22};
  model.behaviors.behaviors[0].potential_owners[0].allows_potential = false;
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  const Diagnostic& d = sink.diagnostics()[0];
  EXPECT_EQ(d.code, DiagCode::component_not_available);
  EXPECT_EQ(d.loc.line, 30u);
  EXPECT_EQ(d.loc.column, 40u);
  EXPECT_EQ(d.message,
            "component 2 of connector behavior 'FRIC' is not available for "
            "connection type SLOT (available: 1)");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.column, 22u);
}

TEST(FrictionTypes, PredefinedPerConnectionType) {
  struct Case {
    std::vector<std::string> types;
    DiagCode code;  // unknown_keyword stands for "no diagnostic"
    ComponentMask j;
  };
  const std::vector<Case> cases = {
      {{"SLOT"}, DiagCode::unknown_keyword, component_bit(1)},
      {{"SLIDE-PLANE"},
       DiagCode::unknown_keyword,
       static_cast<ComponentMask>(component_bit(2) | component_bit(3))},
      {{"SLOT", "CARDAN"}, DiagCode::unknown_keyword, component_bit(1)},
      {{"SLOT", "REVOLUTE"}, DiagCode::unsupported_option, 0},
      {{"CYLINDRICAL"}, DiagCode::unsupported_option, 0},
      {{"HINGE"}, DiagCode::unsupported_option, 0},
      {{"JOIN", "UNIVERSAL"}, DiagCode::unsupported_option, 0},
      {{"REVOLUTE"}, DiagCode::friction_predefined_unavailable, 0},
      {{"RADIAL-THRUST"}, DiagCode::friction_predefined_unavailable, 0},
      {{"BUSHING"}, DiagCode::friction_predefined_unavailable, 0},
  };
  for (const Case& c : cases) {
    Model model = model_with_section(c.types, component_bit(1), 0);
    FrictionDefinition& f = add_friction(model);
    f.predefined = true;
    f.internal_force.clear();
    DiagnosticSink sink;
    resolve_potentials_and_friction(model, sink);
    const std::string type = c.types[0];
    if (c.code == DiagCode::unknown_keyword) {
      EXPECT_TRUE(sink.diagnostics().empty()) << type;
    } else {
      ASSERT_EQ(sink.diagnostics().size(), 1u) << type;
      EXPECT_EQ(sink.diagnostics()[0].code, c.code) << type;
      EXPECT_EQ(sink.diagnostics()[0].loc.line, 10u) << type;
      EXPECT_EQ(sink.diagnostics()[0].notes.at(0).loc.line, 30u) << type;
    }
    EXPECT_EQ(model.behaviors.behaviors[0].frictions[0].friction_components, c.j) << type;
  }
}

TEST(FrictionTypes, PredefinedUnavailableMessage) {
  Model model = model_with_section({"REVOLUTE"}, component_bit(4), 0);
  add_friction(model).predefined = true;
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].message,
            "connection type REVOLUTE has no predefined friction; use COMPONENT= or a "
            "*CONNECTOR POTENTIAL");
}

TEST(FrictionTypes, ContactForceNameUndefinedSuggestsTheDefinition) {
  Model model =
      model_with_section({"SLIDE-PLANE"}, component_bit(2) | component_bit(3), component_bit(1));
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  DerivedComponentTerm t;
  t.name = Name{"PRESS", "PRESS", SourceLoc{0, 47, 36}};
  t.loc = SourceLoc{0, 47, 1};
  t.components = {1};
  t.component_locs = {SourceLoc{0, 48, 1}};
  t.coefficients = {1.0};
  t.complete = true;
  b.derived_terms.push_back(t);
  FrictionDefinition& f = add_friction(model);
  f.component = 2;
  f.contact = FrictionDefinition::Contact::Derived;
  f.contact_name = Name{"PRES", "PRES", SourceLoc{0, 41, 30}};
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  const Diagnostic* undefined = nullptr;
  for (const Diagnostic& d : sink.diagnostics()) {
    if (d.code == DiagCode::undefined_derived_component) undefined = &d;
  }
  ASSERT_NE(undefined, nullptr);
  EXPECT_EQ(undefined->loc.line, 41u);
  EXPECT_EQ(undefined->loc.column, 30u);
  EXPECT_EQ(undefined->message,
            "CONTACT FORCE=PRES: no *CONNECTOR DERIVED COMPONENT of that name in behavior FRIC");
  ASSERT_GE(undefined->notes.size(), 1u);
  EXPECT_EQ(undefined->notes[0].loc.line, 47u);
  EXPECT_EQ(undefined->notes[0].message, "did you mean 'PRESS'?");
}

TEST(FrictionTypes, ContactForceMayListConstrainedComponents) {
  Model model = model_with_section({"SLOT"}, component_bit(1), component_bit(2) | component_bit(3));
  ConnectorBehavior& b = model.behaviors.behaviors[0];
  DerivedComponentTerm t;
  t.name = Name{"N", "N", SourceLoc{0, 47, 36}};
  t.loc = SourceLoc{0, 47, 1};
  t.components = {2, 3, 4};
  t.component_locs = {SourceLoc{0, 48, 1}, SourceLoc{0, 48, 4}, SourceLoc{0, 48, 7}};
  t.coefficients = {1.0, 1.0, 1.0};
  t.complete = true;
  b.derived_terms.push_back(t);
  FrictionDefinition& f = add_friction(model);
  f.component = 1;
  f.contact = FrictionDefinition::Contact::Derived;
  f.contact_name = Name{"N", "N", SourceLoc{0, 10, 40}};
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  // 2 and 3 are constrained (allowed for a contact force); 4 is neither.
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::dc_unavailable_component);
  EXPECT_EQ(sink.diagnostics()[0].loc.column, 7u);
}

TEST(FrictionTypes, ContactSelfWarning) {
  Model model = model_with_section({"CARTESIAN"}, component_bit(1) | component_bit(2), 0);
  FrictionDefinition& f = add_friction(model);
  f.component = 1;
  f.contact = FrictionDefinition::Contact::Component;
  f.contact_component = 1;
  f.contact_loc = SourceLoc{0, 10, 35};
  DiagnosticSink sink;
  resolve_potentials_and_friction(model, sink);
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].code, DiagCode::friction_contact_self);
  EXPECT_EQ(sink.diagnostics()[0].loc.column, 35u);
}

}  // namespace
}  // namespace clinch
