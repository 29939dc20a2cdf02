// Unit tests of *CONNECTOR BEHAVIOR and its sub-options (behaviors.md §2–§8): the numbers each
// keyword form stores, and each diagnostic with its code, line and column. Section-dependent
// checks run check_behaviors on a model whose sections are set up by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "parser/deck_reader.hpp"
#include "tests/unit/checked_deck.hpp"
#include "base/diagnostic.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"
#include "src/check/check.hpp"
#include "src/check/check_behavior_sections.hpp"

namespace clinch {
namespace {

struct Parsed : CheckedDeck {
  const ConnectorBehavior& behavior(std::size_t i = 0) const {
    return model.behaviors.behaviors.at(i);
  }
};

std::unique_ptr<Parsed> parse(const std::string& text) {
  auto p = std::make_unique<Parsed>();
  read_deck_text("deck.inp", text, p->sources, p->model, p->sink);
  return p;
}

void expect_at(const Diagnostic& d, std::uint32_t line, std::uint32_t column) {
  EXPECT_EQ(d.loc.line, line) << d.message;
  EXPECT_EQ(d.loc.column, column) << d.message;
}

// ---------------------------------------------------------------- *CONNECTOR BEHAVIOR (§2)

TEST(ConnectorBehavior, StoresNameAndExtrapolation) {
  auto p = parse("*CONNECTOR BEHAVIOR, NAME=Spring-1, EXTRAPOLATION=LINEAR\n");
  ASSERT_EQ(p->model.behaviors.behaviors.size(), 1u);
  EXPECT_EQ(p->behavior().name.display, "Spring-1");
  EXPECT_EQ(p->behavior().extrapolation, "LINEAR");
  EXPECT_EQ(p->model.behaviors.by_key.at("SPRING-1"), 0);
}

TEST(ConnectorBehavior, DuplicateNameAtTheValueWithNote) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR BEHAVIOR, NAME=b\n");
  const Diagnostic& d = p->one(DiagCode::duplicate_name);
  expect_at(d, 2, 27);
  EXPECT_EQ(d.message, "connector behavior 'b' is already defined");
  ASSERT_EQ(d.notes.size(), 1u);
  EXPECT_EQ(d.notes[0].loc.line, 1u);
  EXPECT_EQ(p->model.behaviors.by_key.at("B"), 0);
  EXPECT_FALSE(p->behavior(1).referable);
}

TEST(ConnectorBehavior, ExplicitOnlyParameters) {
  auto p = parse("*CONNECTOR BEHAVIOR, NAME=B, INTEGRATION=EXPLICIT, RTOL=0.1\n");
  auto found = p->with(DiagCode::explicit_only_parameter);
  ASSERT_EQ(found.size(), 2u) << p->dump();
  expect_at(*found[0], 1, 30);
  EXPECT_EQ(found[0]->message, "INTEGRATION applies only to Abaqus/Explicit; ignored");
  EXPECT_EQ(found[0]->severity, Severity::Warning);
}

TEST(ConnectorBehavior, UnusedBehaviourWarns) {
  auto p = parse("*CONNECTOR BEHAVIOR, NAME=Prop-3\n");
  const Diagnostic& d = p->one(DiagCode::defined_but_unused);
  expect_at(d, 1, 1);
  EXPECT_EQ(d.message, "connector behavior 'Prop-3' is not used by any *CONNECTOR SECTION");
}

TEST(ConnectorBehavior, SubOptionsOfARejectedBehaviourAreSkipped) {
  // The second *CONNECTOR BEHAVIOR has no NAME (E0205): its elasticity must not land in B.
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR BEHAVIOR\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "2000.\n");
  EXPECT_EQ(p->with(DiagCode::missing_parameter).size(), 1u);
  EXPECT_TRUE(p->with(DiagCode::elasticity_duplicate).empty()) << p->dump();
  ASSERT_EQ(p->behavior().elasticities.size(), 1u);
}

// ---------------------------------------------------------------- elasticity (§4)

TEST(Elasticity, LinearStiffness) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n");
  const auto& e = p->behavior().elasticities.at(0);
  EXPECT_EQ(e.kind, ConnectorElasticity::Kind::Linear);
  EXPECT_EQ(e.component, 1);
  EXPECT_DOUBLE_EQ(e.stiffness, 1000.0);
  EXPECT_TRUE(e.valid);
}

TEST(Elasticity, StiffnessNotPositive) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "  -5.\n");
  const Diagnostic& d = p->one(DiagCode::stiffness_not_positive);
  expect_at(d, 3, 3);
  EXPECT_EQ(d.message, "connector stiffness must be positive, got -5.");
}

TEST(Elasticity, ComponentOutOfRangeAtTheValue) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=7\n"
      "1000.\n");
  const Diagnostic& d = p->one(DiagCode::value_out_of_range);
  expect_at(d, 2, 34);
  EXPECT_EQ(d.message, "component 7 is out of range (components are 1-6)");
}

TEST(Elasticity, NonlinearTableE2) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR, EXTRAPOLATION=LINEAR\n"
      "-100.,-0.1\n"
      "0.,0.\n"
      "100.,0.1\n"
      "150.,0.2\n");
  const auto& e = p->behavior().elasticities.at(0);
  EXPECT_EQ(e.kind, ConnectorElasticity::Kind::Nonlinear);
  EXPECT_EQ(e.extrapolation, Extrapolation::Linear);
  ASSERT_EQ(e.table.size(), 4u);
  EXPECT_DOUBLE_EQ(e.table[3].value, 150.0);
  EXPECT_DOUBLE_EQ(e.table[3].at, 0.2);
  EXPECT_TRUE(p->with(DiagCode::zero_tangent_extrapolation).empty());
  EXPECT_TRUE(p->with(DiagCode::nonlinear_elasticity_offset).empty());
}

TEST(Elasticity, NonlinearWarningsOffsetAndConstantExtrapolation) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2, NONLINEAR\n"
      "5.,0.\n"
      "105.,0.1\n");
  const Diagnostic& offset = p->one(DiagCode::nonlinear_elasticity_offset);
  expect_at(offset, 3, 1);
  EXPECT_NE(offset.message.find("gives force 5 at zero motion"), std::string::npos);
  const Diagnostic& zero = p->one(DiagCode::zero_tangent_extrapolation);
  expect_at(zero, 2, 1);
  EXPECT_EQ(zero.severity, Severity::Warning);
}

TEST(Elasticity, NonlinearTableNotIncreasingAndTooShort) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR\n"
      "0.,0.\n"
      "100., 0.2\n"
      "150., 0.1\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2, NONLINEAR\n"
      "0.,0.\n");
  const Diagnostic& d = p->one(DiagCode::table_not_increasing);
  expect_at(d, 5, 7);
  EXPECT_EQ(d.message, "constitutive motions must increase (0.1 after 0.2)");
  expect_at(p->one(DiagCode::table_too_short), 7, 1);
}

TEST(Elasticity, Coupled21TermsColumnByColumn) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "1., 2., 3., 4., 5., 6., 7., 8.\n"
      "9., 10., 11., 12., 13., 14., 15., 16.\n"
      "17., 18., 19., 20., 21.\n");
  const auto& e = p->behavior().elasticities.at(0);
  ASSERT_EQ(e.kind, ConnectorElasticity::Kind::Coupled);
  ASSERT_TRUE(e.valid) << p->dump();
  // behaviors.md §4.3: D11, D12, D22, D13, D23, D33, D14, D24 / D34, D44, D15, D25, D35, D45,
  // D55, D16 / D26, D36, D46, D56, D66.
  const double expected[6][6] = {{1, 2, 4, 7, 11, 16},     {2, 3, 5, 8, 12, 17},
                                 {4, 5, 6, 9, 13, 18},     {7, 8, 9, 10, 14, 19},
                                 {11, 12, 13, 14, 15, 20}, {16, 17, 18, 19, 20, 21}};
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) EXPECT_DOUBLE_EQ(e.coupled[i][j], expected[i][j]) << i << j;
  }
  EXPECT_DOUBLE_EQ(e.coupled_terms[20], 21.0);
}

TEST(Elasticity, CoupledMissingTermIsNamed) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "1., 2., 3., 4., 5., 6., 7., 8.\n"
      "9., 10., 11., 12., 13., 14., 15.\n"
      "17., 18., 19., 20., 21.\n");
  const Diagnostic& d = p->one(DiagCode::missing_field);
  expect_at(d, 4, 33);
  EXPECT_EQ(d.message, "missing value for 'D16' of *CONNECTOR ELASTICITY");
}

TEST(Elasticity, RigidForms) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, RIGID\n"
      "2, 3\n"
      "*CONNECTOR BEHAVIOR, NAME=C\n"
      "*CONNECTOR ELASTICITY, RIGID\n"
      "*CONNECTOR BEHAVIOR, NAME=D\n"
      "*CONNECTOR ELASTICITY, RIGID, COMPONENT=4\n");
  const auto& listed = p->behavior(0).elasticities.at(0);
  EXPECT_EQ(listed.kind, ConnectorElasticity::Kind::Rigid);
  EXPECT_FALSE(listed.rigid_all);
  EXPECT_EQ(listed.rigid_components, 0b110);
  EXPECT_TRUE(p->behavior(1).elasticities.at(0).rigid_all);
  const auto& one = p->behavior(2).elasticities.at(0);
  EXPECT_FALSE(one.rigid_all);
  EXPECT_EQ(one.rigid_components, 0b1000);
}

TEST(Elasticity, UnsupportedOptionsAndDependencies) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1, UNSYMM\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2, DEPENDENCIES=1\n"
      "1000.\n");
  expect_at(p->one(DiagCode::unsupported_option), 2, 37);
  const Diagnostic& d = p->one(DiagCode::unsupported_dependencies);
  expect_at(d, 4, 50);
}

TEST(Elasticity, TemperatureColumn) {
  auto same = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR, EXTRAPOLATION=LINEAR\n"
      "0., 0., 20.\n"
      "100., 0.1, 20.\n");
  expect_at(same->one(DiagCode::temperature_ignored), 3, 9);
  EXPECT_TRUE(same->with(DiagCode::unsupported_dependencies).empty());
  auto varying = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000., , 20.\n"
      "1200., , 80.\n");
  const Diagnostic& d = varying->one(DiagCode::unsupported_dependencies);
  expect_at(d, 4, 10);
  EXPECT_TRUE(varying->with(DiagCode::temperature_ignored).empty());
  auto field = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000., , , 1.\n");
  expect_at(field->one(DiagCode::unsupported_dependencies), 3, 12);
}

TEST(Elasticity, DefinitionsOnAComponentAddButRigidStandsAlone) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "2000.\n"
      "*CONNECTOR ELASTICITY\n"
      "1., 0., 1., 0., 0., 1., 0., 0.\n"
      "0., 1., 0., 0., 0., 0., 1., 0.\n"
      "0., 0., 0., 0., 1.\n"
      "*CONNECTOR BEHAVIOR, NAME=C\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3, RIGID\n");
  auto found = p->with(DiagCode::elasticity_duplicate);
  ASSERT_EQ(found.size(), 1u) << p->dump();
  expect_at(*found[0], 13, 34);
  ASSERT_EQ(found[0]->notes.size(), 1u);
  EXPECT_EQ(found[0]->notes[0].loc.line, 11u);
  EXPECT_NE(found[0]->message.find("component 3"), std::string::npos);
}

// ---------------------------------------------------------------- reference (§3)

TEST(ConstitutiveReference, DegreesToRadiansAndBlanks) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR CONSTITUTIVE REFERENCE\n"
      "9.9, , , 90.\n");
  const auto& ref = *p->behavior().reference;
  EXPECT_DOUBLE_EQ(*ref.value[0], 9.9);
  EXPECT_FALSE(ref.value[1].has_value());
  EXPECT_NEAR(*ref.value[3], std::numbers::pi / 2, 1e-15);
  EXPECT_FALSE(ref.value[5].has_value());
}

TEST(ConstitutiveReference, SecondDefinitionReplacesTheFirst) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR CONSTITUTIVE REFERENCE\n"
      "9.9\n"
      "*CONNECTOR CONSTITUTIVE REFERENCE\n"
      "9.8\n");
  const Diagnostic& d = p->one(DiagCode::keyword_ignored);
  expect_at(d, 2, 1);
  EXPECT_DOUBLE_EQ(*p->behavior().reference->value[0], 9.8);
}

TEST(Extrapolation, OptionWinsOverBehaviour) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B, EXTRAPOLATION=LINEAR\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR\n"
      "0., 0.\n"
      "100., 0.1\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2, NONLINEAR, EXTRAPOLATION=CONSTANT\n"
      "0., 0.\n"
      "100., 0.1\n");
  EXPECT_EQ(p->behavior().elasticities.at(0).extrapolation, Extrapolation::Linear);
  EXPECT_EQ(p->behavior().elasticities.at(1).extrapolation, Extrapolation::Constant);
  expect_at(p->one(DiagCode::zero_tangent_extrapolation), 5, 1);
}

// ---------------------------------------------------------------- stops, locks, failure (§5)

TEST(StopLockFailure, Values) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR STOP, COMPONENT=1\n"
      ", 10.1\n"
      "*CONNECTOR LOCK, COMPONENT=1, LOCK=ALL\n"
      ", 10.04\n"
      "*CONNECTOR LOCK, COMPONENT=2, LOCK=3\n"
      ", , -5.\n"
      "*CONNECTOR FAILURE, COMPONENT=1, RELEASE=2\n"
      ", , , 140.\n");
  const auto& b = p->behavior();
  ASSERT_EQ(b.stops.size(), 1u);
  EXPECT_FALSE(b.stops[0].lower);
  EXPECT_DOUBLE_EQ(*b.stops[0].upper, 10.1);
  ASSERT_EQ(b.locks.size(), 2u);
  EXPECT_EQ(b.locks[0].locked, 0);
  EXPECT_DOUBLE_EQ(*b.locks[0].bounds.position_upper, 10.04);
  EXPECT_EQ(b.locks[1].locked, 3);
  EXPECT_DOUBLE_EQ(*b.locks[1].bounds.force_lower, -5.0);
  ASSERT_EQ(b.failures.size(), 1u);
  EXPECT_EQ(b.failures[0].released, 2);
  EXPECT_DOUBLE_EQ(*b.failures[0].bounds.force_upper, 140.0);
  EXPECT_TRUE(b.failures[0].valid);
}

TEST(StopLockFailure, Errors) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR STOP, COMPONENT=1\n"
      ",\n"
      "*CONNECTOR STOP, COMPONENT=2\n"
      "1., 0.5\n"
      "*CONNECTOR LOCK, COMPONENT=1, EXTRAPOLATION=LINEAR\n"
      ", , ,\n"
      "*CONNECTOR STOP, COMPONENT=2\n"
      "0., 1.\n");
  expect_at(p->one(DiagCode::stop_no_limit), 3, 1);
  const Diagnostic& lu = p->one(DiagCode::value_out_of_range);
  expect_at(lu, 5, 5);
  EXPECT_EQ(lu.message, "stop limits need L < U (L = 1., U = 0.5)");
  expect_at(p->one(DiagCode::lock_no_criterion), 7, 1);
  expect_at(p->one(DiagCode::explicit_only_parameter), 6, 31);
  const Diagnostic& dup = p->one(DiagCode::stop_duplicate);
  expect_at(dup, 8, 28);
  ASSERT_EQ(dup.notes.size(), 1u);
  EXPECT_EQ(dup.notes[0].loc.line, 4u);
}

// ---------------------------------------------------------------- plasticity (§6)

TEST(Plasticity, TabularIsotropicE7AndOwner) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
      "120., 0.\n"
      "170., 0.1\n");
  const auto& b = p->behavior();
  ASSERT_EQ(b.plasticities.size(), 1u);
  const auto& pl = b.plasticities[0];
  EXPECT_EQ(pl.component, 1);
  ASSERT_TRUE(pl.isotropic);
  EXPECT_EQ(pl.isotropic->definition, IsotropicHardening::Definition::Tabular);
  ASSERT_EQ(pl.isotropic->table.size(), 2u);
  EXPECT_DOUBLE_EQ(pl.isotropic->table[1].value, 170.0);
  EXPECT_DOUBLE_EQ(pl.isotropic->table[1].at, 0.1);
  ASSERT_EQ(b.potential_owners.size(), 1u);
  const PotentialOwner& o = b.potential_owners[0];
  EXPECT_EQ(o.kind, PotentialOwner::Kind::Plasticity);
  EXPECT_EQ(o.index, 0);
  EXPECT_FALSE(o.requires_potential);
  EXPECT_FALSE(o.allows_potential);
  EXPECT_EQ(o.why_not_allowed, "COMPONENT=1");
  EXPECT_EQ(o.loc.line, 4u);
  for (DiagCode c : {DiagCode::plasticity_no_hardening, DiagCode::softening_too_steep,
                     DiagCode::plasticity_needs_linear_elasticity}) {
    EXPECT_TRUE(p->with(c).empty()) << p->dump();
  }
}

TEST(Plasticity, CoupledOwnerRequiresPotential) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR HARDENING\n"
      "100., 0.\n");
  const PotentialOwner& o = p->behavior().potential_owners.at(0);
  EXPECT_TRUE(o.requires_potential);
  EXPECT_TRUE(o.allows_potential);
  EXPECT_TRUE(p->behavior().plasticities.at(0).coupled());
}

TEST(Plasticity, ExponentialLawE10AndKinematicParametersE9) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC, DEFINITION=EXPONENTIAL LAW\n"
      "100., 50., 20.\n"
      "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=PARAMETERS\n"
      "100., 2000., 20.\n");
  const auto& pl = p->behavior().plasticities.at(0);
  ASSERT_TRUE(pl.isotropic && pl.kinematic);
  EXPECT_EQ(pl.isotropic->definition, IsotropicHardening::Definition::ExponentialLaw);
  EXPECT_DOUBLE_EQ(pl.isotropic->f0, 100.0);
  EXPECT_DOUBLE_EQ(pl.isotropic->q_inf, 50.0);
  EXPECT_DOUBLE_EQ(pl.isotropic->b, 20.0);
  EXPECT_EQ(pl.kinematic->definition, KinematicHardening::Definition::Parameters);
  EXPECT_DOUBLE_EQ(pl.kinematic->f0, 100.0);
  EXPECT_DOUBLE_EQ(pl.kinematic->c, 2000.0);
  EXPECT_DOUBLE_EQ(pl.kinematic->gamma, 20.0);
  EXPECT_TRUE(p->with(DiagCode::kinematic_f0_ignored).empty());
}

TEST(Plasticity, HalfCycleMapsToLinearKinematic) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=KINEMATIC\n"
      "110., 0.\n"
      "160., 0.1\n");
  const auto& k = *p->behavior().plasticities.at(0).kinematic;
  EXPECT_EQ(k.definition, KinematicHardening::Definition::HalfCycle);
  EXPECT_DOUBLE_EQ(k.f0, 110.0);
  EXPECT_DOUBLE_EQ(k.c, 500.0);  // (F2 − F1)/u2 = 50/0.1
  EXPECT_DOUBLE_EQ(k.gamma, 0.0);
  EXPECT_TRUE(k.valid);
}

TEST(Plasticity, HalfCycleWithThreeRowsIsUnsupported) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=HALF CYCLE\n"
      "110., 0.\n"
      "160., 0.1\n"
      "180., 0.2\n");
  expect_at(p->one(DiagCode::unsupported_option), 8, 1);
}

TEST(Plasticity, AttachmentErrors) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR HARDENING\n"
      "100., 0.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING\n"
      "100., 0.\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
      "100., 0.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n");
  expect_at(p->one(DiagCode::hardening_no_plasticity), 2, 1);
  const Diagnostic& dup = p->one(DiagCode::hardening_duplicate);
  expect_at(dup, 9, 1);
  ASSERT_EQ(dup.notes.size(), 1u);
  EXPECT_EQ(dup.notes[0].loc.line, 7u);
  expect_at(p->one(DiagCode::plasticity_no_hardening), 11, 1);
  expect_at(p->one(DiagCode::plasticity_overlap), 11, 34);
}

TEST(Plasticity, TableChecks) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING\n"
      "100., 0.01\n"
      "*CONNECTOR PLASTICITY, COMPONENT=2\n"
      "*CONNECTOR HARDENING\n"
      "-100., 0.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=3\n"
      "*CONNECTOR HARDENING\n"
      "100., 0.\n"
      "50., 0.01\n");
  const Diagnostic& first = p->one(DiagCode::hardening_first_point);
  expect_at(first, 10, 7);
  const Diagnostic& yield = p->one(DiagCode::yield_not_positive);
  expect_at(yield, 13, 1);
  // Slope −5000 ≤ −1000: the local problem loses uniqueness (§6.1).
  const Diagnostic& steep = p->one(DiagCode::softening_too_steep);
  expect_at(steep, 17, 1);
}

TEST(Plasticity, NeedsLinearElasticity) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR, EXTRAPOLATION=LINEAR\n"
      "0., 0.\n"
      "100., 0.1\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING\n"
      "50., 0.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=2\n"
      "*CONNECTOR HARDENING\n"
      "50., 0.\n");
  auto found = p->with(DiagCode::plasticity_needs_linear_elasticity);
  ASSERT_EQ(found.size(), 2u) << p->dump();
  expect_at(*found[0], 5, 34);
  EXPECT_NE(found[0]->message.find("NONLINEAR"), std::string::npos);
  expect_at(*found[1], 8, 34);
}

TEST(Plasticity, CoupledPotentialComponents) {
  // Component 2 is in the potential of the coupled plasticity and has its own uncoupled one;
  // component 3 is in the potential but its elasticity is NONLINEAR.
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B, EXTRAPOLATION=LINEAR\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=3, NONLINEAR\n"
      "0., 0.\n"
      "100., 0.1\n"
      "*CONNECTOR PLASTICITY, COMPONENT=2\n"
      "*CONNECTOR HARDENING\n"
      "50., 0.\n"
      "*CONNECTOR PLASTICITY\n"
      "*CONNECTOR HARDENING\n"
      "100., 0.\n"
      "*CONNECTOR POTENTIAL\n"
      "1, 1.\n"
      "2, 1.\n"
      "3, 1.\n");
  const Diagnostic& overlap = p->one(DiagCode::plasticity_overlap);
  expect_at(overlap, 9, 34);
  ASSERT_EQ(overlap.notes.size(), 1u);
  EXPECT_EQ(overlap.notes[0].loc.line, 12u);
  const Diagnostic& linear = p->one(DiagCode::plasticity_needs_linear_elasticity);
  expect_at(linear, 12, 1);
  EXPECT_NE(linear.message.find("component 3"), std::string::npos);
}

TEST(Plasticity, KinematicF0Ignored) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=ISOTROPIC\n"
      "120., 0.\n"
      "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=PARAMETERS\n"
      "110., 500., 0.\n");
  const Diagnostic& d = p->one(DiagCode::kinematic_f0_ignored);
  expect_at(d, 8, 1);
  EXPECT_EQ(d.severity, Severity::Warning);
}

// ---------------------------------------------------------------- damage (§7)

TEST(Damage, ForceInitiationAndLinearEvolutionE12) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=FORCE\n"
      ", 90.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=LINEAR\n"
      "0.2\n");
  const auto& b = p->behavior();
  ASSERT_EQ(b.damage_initiations.size(), 1u);
  const auto& init = b.damage_initiations[0];
  EXPECT_EQ(init.criterion, DamageInitiation::Criterion::Force);
  EXPECT_FALSE(init.lower);
  EXPECT_DOUBLE_EQ(*init.upper, 90.0);
  EXPECT_EQ(init.evolution, 0);
  const auto& evo = b.damage_evolutions.at(0);
  EXPECT_EQ(evo.initiation, 0);
  EXPECT_DOUBLE_EQ(evo.failure_motion, 0.2);
  ASSERT_EQ(b.potential_owners.size(), 2u);
  EXPECT_FALSE(b.potential_owners[0].allows_potential);
  EXPECT_EQ(b.potential_owners[0].why_not_allowed, "COMPONENT=1");
  EXPECT_EQ(b.potential_owners[1].kind, PotentialOwner::Kind::DamageEvolution);
  EXPECT_FALSE(b.potential_owners[1].allows_potential);
}

TEST(Damage, EvolutionForms) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=1\n"
      ", 90.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=EXPONENTIAL\n"
      "0.2, 5.\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=1\n"
      ", 90.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=TABULAR, DEGRADATION=MULTIPLICATIVE\n"
      "0., 0.\n"
      "0.5, 0.05\n"
      "1., 0.2\n"
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n"
      ", 1.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=ENERGY, AFFECTED COMPONENTS\n"
      "1, 2\n"
      "10.\n");
  const auto& b = p->behavior();
  ASSERT_EQ(b.damage_evolutions.size(), 3u);
  EXPECT_EQ(b.damage_evolutions[0].softening, DamageEvolution::Softening::Exponential);
  EXPECT_DOUBLE_EQ(b.damage_evolutions[0].exponent, 5.0);
  const auto& tab = b.damage_evolutions[1];
  EXPECT_EQ(tab.degradation, DamageEvolution::Degradation::Multiplicative);
  ASSERT_EQ(tab.table.size(), 3u);
  EXPECT_DOUBLE_EQ(tab.table[1].value, 0.5);
  EXPECT_DOUBLE_EQ(tab.table[1].at, 0.05);
  const auto& energy = b.damage_evolutions[2];
  EXPECT_EQ(energy.type, DamageEvolution::Type::Energy);
  EXPECT_DOUBLE_EQ(energy.fracture_energy, 10.0);
  EXPECT_EQ(energy.affected, 0b11);
  EXPECT_EQ(energy.initiation, 2);
  // The coupled FORCE initiation requires a potential; its evolution may take one.
  EXPECT_TRUE(b.potential_owners[4].requires_potential);
  EXPECT_TRUE(b.potential_owners[5].allows_potential);
  EXPECT_TRUE(p->with(DiagCode::damage_table_first_point).empty());
}

TEST(Damage, Errors) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION\n"
      "0.1\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=1\n"
      ",\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=2, CRITERION=PLASTIC MOTION\n"
      "0.05\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, SOFTENING=TABULAR\n"
      "0.1, 0.01\n"
      "1., 0.1\n");
  expect_at(p->one(DiagCode::evolution_no_initiation), 2, 1);
  expect_at(p->one(DiagCode::damage_no_limit), 5, 1);
  expect_at(p->one(DiagCode::damage_needs_plasticity), 6, 54);
  const Diagnostic& first = p->one(DiagCode::damage_table_first_point);
  expect_at(first, 9, 1);
  EXPECT_EQ(first.severity, Severity::Warning);
  const PotentialOwner& plastic = p->behavior().potential_owners.at(2);
  EXPECT_EQ(plastic.kind, PotentialOwner::Kind::DamageInitiation);
  EXPECT_FALSE(plastic.requires_potential);
}

TEST(Damage, MixedUnitsWithoutEvolutionPotential) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMAGE INITIATION, CRITERION=MOTION\n"
      ", 1.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION, AFFECTED COMPONENTS\n"
      "1, 4\n"
      "0.1\n");
  const Diagnostic& d = p->one(DiagCode::damage_mixed_units);
  expect_at(d, 5, 1);
}

TEST(Damage, MixedUnitsFromTheInitiationPotential) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n"
      ", 1.\n"
      "*CONNECTOR POTENTIAL\n"
      "1, 100.\n"
      "6, 50.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION\n"
      "0.1\n");
  expect_at(p->one(DiagCode::damage_mixed_units), 7, 1);
  auto e15 = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMAGE INITIATION, CRITERION=FORCE\n"
      ", 1.\n"
      "*CONNECTOR POTENTIAL\n"
      "1, 100.\n"
      "2, 50.\n"
      "*CONNECTOR DAMAGE EVOLUTION, TYPE=MOTION\n"
      "0.1\n"
      "*CONNECTOR POTENTIAL\n"
      "1, 1.\n"
      "2, 1.\n");
  EXPECT_TRUE(e15->with(DiagCode::damage_mixed_units).empty()) << e15->dump();
  EXPECT_TRUE(e15->with(DiagCode::potential_missing).empty()) << e15->dump();
}

TEST(Damage, MissingType) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=1\n"
      ", 90.\n"
      "*CONNECTOR DAMAGE EVOLUTION\n"
      "0.1\n");
  expect_at(p->one(DiagCode::missing_parameter), 4, 1);
}

// ---------------------------------------------------------------- damping (§8)

TEST(Damping, IsReadWithoutWarning) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMPING, COMPONENT=1\n"
      "5.\n");
  EXPECT_EQ(p->with(DiagCode::damping_structural_ignored).size(), 0u);
  EXPECT_DOUBLE_EQ(p->behavior().dampings.at(0).coefficient, 5.0);
  EXPECT_FALSE(p->behavior().dampings.at(0).structural);
}

TEST(Damping, StructuralWarnsAtItsTypeAndIndependentComponentsIsRefused) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR DAMPING, COMPONENT=1, TYPE=STRUCTURAL\n"
      "5.\n"
      "*CONNECTOR DAMPING, COMPONENT=2, INDEPENDENT COMPONENTS=POSITION\n"
      "1\n"
      "5., 0.1\n");
  const Diagnostic& d = p->one(DiagCode::damping_structural_ignored);
  expect_at(d, 2, 34);
  EXPECT_TRUE(p->behavior().dampings.at(0).structural);
  expect_at(p->one(DiagCode::unsupported_option), 4, 34);
  // The component line is not read as a table row: no further diagnostic.
  EXPECT_EQ(p->with(DiagCode::missing_field).size() + p->with(DiagCode::table_too_short).size(), 0u);
}

// ---------------------------------------------------------------- features

TEST(BehaviorFeatures, Flags) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR PLASTICITY, COMPONENT=1\n"
      "*CONNECTOR HARDENING, TYPE=KINEMATIC, DEFINITION=PARAMETERS\n"
      "110., 500., 0.\n"
      "*CONNECTOR DAMAGE INITIATION, COMPONENT=1, CRITERION=PLASTIC MOTION\n"
      "0.05\n"
      "*CONNECTOR LOCK, COMPONENT=1\n"
      ", 10.04\n");
  BehaviorFeatures f = behavior_features(p->behavior());
  EXPECT_TRUE(f.elasticity);
  EXPECT_TRUE(f.plasticity);
  EXPECT_TRUE(f.kinematic_hardening);
  EXPECT_TRUE(f.damage);
  EXPECT_TRUE(f.plastic_motion_criterion);
  EXPECT_FALSE(f.force_criterion);
  EXPECT_TRUE(f.stops_or_locks);
  EXPECT_FALSE(f.friction);
}

// ---------------------------------------------------------------- section-dependent checks

// Attaches a hand-made section (connection type `type`, available `mask`) to behaviour 0, with
// one CONN3D2 element between nodes at xa and xb, and runs check_behaviors again.
struct SectionSetup {
  std::string type;
  std::uint8_t mask;
  Vec3 xa{}, xb{};
};

DiagnosticSink revalidate(Parsed& p, const SectionSetup& setup) {
  Model& m = p.model;
  m.nodes.clear();
  m.elements.clear();
  Node a, b;
  a.label = 1;
  a.x = setup.xa;
  b.label = 2;
  b.x = setup.xb;
  m.nodes = {a, b};
  Element e;
  e.label = 7;
  e.nodes = {0, 1};
  m.elements = {e};
  ConnectorSection s;
  s.behavior.key = "B";
  s.behavior.display = "B";
  s.behavior.loc = SourceLoc{0, 99, 47};
  s.behavior_index = 0;
  s.type_names = {setup.type};
  s.available = setup.mask;
  s.valid = true;
  s.elements = {0};
  m.sections.connector_sections = {s};
  m.behaviors.behaviors[0].used = true;
  DiagnosticSink sink;
  check_behaviors(m, sink);
  return sink;
}

std::vector<const Diagnostic*> of(const DiagnosticSink& sink, DiagCode code) {
  std::vector<const Diagnostic*> out;
  for (const Diagnostic& d : sink.diagnostics()) {
    if (d.code == code) out.push_back(&d);
  }
  return out;
}

TEST(BehaviorSections, ComponentNotAvailableAtTheSectionWithNote) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR ELASTICITY, COMPONENT=2\n"
      "1000.\n");
  DiagnosticSink sink = revalidate(*p, {"AXIAL", 0b1, {0, 0, 0}, {10, 0, 0}});
  auto found = of(sink, DiagCode::component_not_available);
  ASSERT_EQ(found.size(), 1u);
  expect_at(*found[0], 99, 47);
  EXPECT_EQ(found[0]->message,
            "component 2 of connector behavior 'B' is not available for connection type AXIAL "
            "(available: 1)");
  ASSERT_EQ(found[0]->notes.size(), 1u);
  EXPECT_EQ(found[0]->notes[0].loc.line, 4u);
  EXPECT_TRUE(of(sink, DiagCode::defined_but_unused).empty());
}

TEST(BehaviorSections, ReferenceIgnored) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR CONSTITUTIVE REFERENCE\n"
      "9.9, 1.\n");
  DiagnosticSink sink = revalidate(*p, {"AXIAL", 0b1, {0, 0, 0}, {10, 0, 0}});
  auto found = of(sink, DiagCode::reference_ignored);
  ASSERT_EQ(found.size(), 1u);
  expect_at(*found[0], 5, 6);
}

TEST(BehaviorSections, CoupledStiffnessIgnoredAndDefiniteness) {
  // E3 stiffness (D11 = 1000, D12 = 200, D22 = 500, D33 = 800) plus a non-zero D44.
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "1000., 200., 500., 0., 0., 800., 0., 0.\n"
      "0., 7., 0., 0., 0., 0., 0., 0.\n"
      "0., 0., 0., 0., 0.\n");
  DiagnosticSink sink = revalidate(*p, {"CARTESIAN", 0b111, {0, 0, 0}, {0, 0, 0}});
  auto ignored = of(sink, DiagCode::coupled_stiffness_ignored);
  ASSERT_EQ(ignored.size(), 1u);
  expect_at(*ignored[0], 3, 1);
  EXPECT_NE(ignored[0]->message.find("component(s) 4"), std::string::npos);
  EXPECT_TRUE(of(sink, DiagCode::stiffness_not_positive_definite).empty());

  auto indefinite = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "100., 200., 100., 0., 0., 800., 0., 0.\n"
      "0., 0., 0., 0., 0., 0., 0., 0.\n"
      "0., 0., 0., 0., 0.\n");
  DiagnosticSink s2 = revalidate(*indefinite, {"CARTESIAN", 0b111, {0, 0, 0}, {0, 0, 0}});
  auto bad = of(s2, DiagCode::stiffness_not_positive_definite);
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_EQ(bad[0]->severity, Severity::Error);

  auto semi = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "100., 100., 100., 0., 0., 800., 0., 0.\n"
      "0., 0., 0., 0., 0., 0., 0., 0.\n"
      "0., 0., 0., 0., 0.\n");
  DiagnosticSink s3 = revalidate(*semi, {"CARTESIAN", 0b111, {0, 0, 0}, {0, 0, 0}});
  auto warn = of(s3, DiagCode::stiffness_not_positive_definite);
  ASSERT_EQ(warn.size(), 1u);
  EXPECT_EQ(warn[0]->severity, Severity::Warning);
}

TEST(BehaviorSections, StopInitiallyViolated) {
  auto p = parse(
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY, COMPONENT=1\n"
      "1000.\n"
      "*CONNECTOR STOP, COMPONENT=1\n"
      "10.5, 12.\n");
  DiagnosticSink sink = revalidate(*p, {"AXIAL", 0b1, {0, 0, 0}, {10, 0, 0}});
  auto found = of(sink, DiagCode::stop_initially_violated);
  ASSERT_EQ(found.size(), 1u);
  expect_at(*found[0], 5, 1);
  EXPECT_NE(found[0]->message.find("starts at position 10 "), std::string::npos);

  DiagnosticSink inside = revalidate(*p, {"AXIAL", 0b1, {0, 0, 0}, {11, 0, 0}});
  EXPECT_TRUE(of(inside, DiagCode::stop_initially_violated).empty());
}

TEST(BehaviorSections, SymmetricEigenvalues) {
  Stiffness6 m{};
  m[0][0] = 2;
  m[0][1] = m[1][0] = 1;
  m[1][1] = 2;
  m[5][5] = -3;
  std::size_t n = 0;
  auto eig = symmetric_block_eigenvalues(m, 0b100011, n);
  ASSERT_EQ(n, 3u);
  EXPECT_NEAR(eig[0], -3, 1e-12);
  EXPECT_NEAR(eig[1], 1, 1e-12);
  EXPECT_NEAR(eig[2], 3, 1e-12);
}

}  // namespace
}  // namespace clinch
