// Unit tests of the connection-type library (connection-types.md §2.1), the *ORIENTATION triad
// (keywords.md §6), and *CONNECTOR SECTION / *SPRING / *SECTION CONTROLS reading and
// resolve_sections: stored data, and each diagnostic with its code, line and column.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/external_decks.hpp"
#include "parser/deck_reader.hpp"
#include "tests/unit/checked_deck.hpp"
#include "base/diagnostic.hpp"
#include "parser/source_manager.hpp"
#include "src/model/connection_types.hpp"
#include "src/model/model.hpp"
#include "src/model/orientation_triad.hpp"

namespace clinch {
namespace {

// ---------------------------------------------------------------------------------------------
// Helpers

struct Parsed : CheckedDeck {
  // Every diagnostic except the ones listed (for "nothing else was reported" checks).
  std::size_t count_other_than(std::initializer_list<DiagCode> codes) const {
    std::size_t n = 0;
    for (const Diagnostic& d : sink.diagnostics()) {
      if (std::find(codes.begin(), codes.end(), d.code) == codes.end()) ++n;
    }
    return n;
  }
};

constexpr const char* kStep = "*STEP\n*STATIC\n*END STEP\n";

// Two nodes one unit apart and connector element 1 in set C.
std::string two_nodes(const char* element_type = "CONN3D2") {
  return std::string("*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=") + element_type +
         ", ELSET=C\n1, 1, 2\n";
}

std::unique_ptr<Parsed> parse(const std::string& text) {
  auto p = std::make_unique<Parsed>();
  read_deck_text("deck.inp", text, p->sources, p->model, p->sink);
  return p;
}

void expect_at(const Diagnostic& d, std::uint32_t line, std::uint32_t column) {
  EXPECT_EQ(d.loc.line, line) << d.message;
  EXPECT_EQ(d.loc.column, column) << d.message;
}

ComponentMask mask_of(const std::string& list) {
  ComponentMask mask = 0;
  for (char c : list) {
    if (c >= '1' && c <= '6') mask = static_cast<ComponentMask>(mask | component_bit(c - '0'));
  }
  return mask;
}

void expect_vec(const Vec3& actual, const Vec3& expected, const char* what) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(actual[k], expected[k], 1e-12) << what << " component " << k;
  }
}

// ---------------------------------------------------------------------------------------------
// The master table (connection-types.md §2.1), transcribed independently of the library.

struct Row {
  const char* name;
  ConnectionKind kind;
  const char* available;
  const char* constrained;
  OrientationUse a, b;
  bool three_d_only;
  V1Support v1;
  const char* available_2d;  // nullptr: not allowed on CONN2D2
  const char* constrained_2d;
};

constexpr auto T = ConnectionKind::Translational;
constexpr auto R = ConnectionKind::Rotational;
constexpr auto A = ConnectionKind::Assembled;
constexpr auto req = OrientationUse::Required;
constexpr auto opt = OrientationUse::Optional;
constexpr auto ign = OrientationUse::Ignored;
constexpr auto yes = V1Support::Supported;
constexpr auto no = V1Support::Unsupported;

const Row kRows[] = {
    {"AXIAL", T, "1", "", opt, opt, false, yes, "1", ""},
    {"CARTESIAN", T, "123", "", opt, ign, false, yes, "12", ""},
    {"JOIN", T, "", "123", opt, ign, false, yes, "", "12"},
    {"LINK", T, "", "1", ign, ign, false, yes, "", "1"},
    {"SLOT", T, "1", "23", req, ign, false, yes, "1", "2"},
    {"SLIDE-PLANE", T, "23", "1", req, ign, true, yes, nullptr, nullptr},
    {"RADIAL-THRUST", T, "13", "", req, ign, true, yes, nullptr, nullptr},
    {"PROJECTION CARTESIAN", T, "123", "", req, opt, true, yes, nullptr, nullptr},
    {"ACCELEROMETER", T, "123", "", opt, ign, false, V1Support::Converted, "12", ""},
    {"ALIGN", R, "", "456", opt, opt, false, yes, "", "6"},
    {"CARDAN", R, "456", "", opt, opt, true, yes, nullptr, nullptr},
    {"EULER", R, "456", "", opt, opt, true, yes, nullptr, nullptr},
    {"ROTATION", R, "456", "", opt, opt, false, yes, "6", ""},
    {"REVOLUTE", R, "4", "56", req, opt, true, yes, nullptr, nullptr},
    {"UNIVERSAL", R, "46", "5", req, opt, true, yes, nullptr, nullptr},
    {"FLEXION-TORSION", R, "456", "", req, opt, true, yes, nullptr, nullptr},
    {"PROJECTION FLEXION-TORSION", R, "456", "", req, opt, true, yes, nullptr, nullptr},
    {"CONSTANT VELOCITY", R, "45", "6", req, opt, true, no, nullptr, nullptr},
    {"ROTATION ACCELEROMETER", R, "", "", opt, opt, true, no, nullptr, nullptr},
    {"FLOW-CONVERTER", R, "", "", ign, ign, true, no, nullptr, nullptr},
    {"BEAM", A, "", "123456", opt, opt, false, yes, "", "126"},
    {"WELD", A, "", "123456", opt, opt, false, yes, "", "126"},
    {"BUSHING", A, "123456", "", req, opt, true, yes, nullptr, nullptr},
    {"CYLINDRICAL", A, "14", "2356", req, opt, true, yes, nullptr, nullptr},
    {"HINGE", A, "4", "12356", req, opt, true, yes, nullptr, nullptr},
    {"PLANAR", A, "234", "156", req, opt, true, yes, nullptr, nullptr},
    {"TRANSLATOR", A, "1", "23456", req, opt, true, yes, nullptr, nullptr},
    {"UJOINT", A, "46", "1235", req, opt, true, yes, nullptr, nullptr},
    {"CVJOINT", A, "45", "1236", req, opt, true, no, nullptr, nullptr},
    {"RETRACTOR", A, "", "", ign, ign, true, no, nullptr, nullptr},
    {"SLIPRING", A, "", "", ign, ign, true, no, nullptr, nullptr},
};

TEST(ConnectionTypes, EveryTypeMatchesTheMasterTable) {
  EXPECT_EQ(connection_types().size(), std::size(kRows));
  for (const Row& row : kRows) {
    SCOPED_TRACE(row.name);
    const ConnectionTypeInfo* info = find_connection_type(row.name);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->name, row.name);
    EXPECT_EQ(info->kind, row.kind);
    EXPECT_EQ(info->available, mask_of(row.available));
    EXPECT_EQ(info->constrained, mask_of(row.constrained));
    EXPECT_EQ(info->available & info->constrained, 0);
    EXPECT_EQ(info->orientation_a, row.a);
    EXPECT_EQ(info->orientation_b, row.b);
    EXPECT_EQ(info->three_d_only, row.three_d_only);
    EXPECT_EQ(info->support, row.v1);
    EXPECT_EQ(info->allowed_2d, row.available_2d != nullptr);
    if (row.available_2d) {
      EXPECT_EQ(info->available_2d, mask_of(row.available_2d));
      EXPECT_EQ(info->constrained_2d, mask_of(row.constrained_2d));
      // 2-D masks are the 3-D ones restricted to components 1, 2, 6.
      EXPECT_EQ(info->available_2d, info->available & kComponents2D);
      EXPECT_EQ(info->constrained_2d, info->constrained & kComponents2D);
    }
  }
}

TEST(ConnectionTypes, AssembledTypesAreTheUnionOfTheirParts) {
  auto parts = [](const char* x, const char* y) {
    const ConnectionTypeInfo* types[] = {find_connection_type(x), find_connection_type(y)};
    return summarize_connection(types, false);
  };
  struct Case {
    const char* assembled;
    const char* t;
    const char* r;
  };
  for (const Case& c : {Case{"BEAM", "JOIN", "ALIGN"}, Case{"WELD", "JOIN", "ALIGN"},
                        Case{"BUSHING", "PROJECTION CARTESIAN", "PROJECTION FLEXION-TORSION"},
                        Case{"CYLINDRICAL", "SLOT", "REVOLUTE"}, Case{"HINGE", "JOIN", "REVOLUTE"},
                        Case{"PLANAR", "SLIDE-PLANE", "REVOLUTE"},
                        Case{"TRANSLATOR", "SLOT", "ALIGN"}, Case{"UJOINT", "JOIN", "UNIVERSAL"}}) {
    SCOPED_TRACE(c.assembled);
    const ConnectionTypeInfo* info = find_connection_type(c.assembled);
    ASSERT_NE(info, nullptr);
    const ConnectionSummary summary = parts(c.t, c.r);
    EXPECT_EQ(info->available, summary.available);
    EXPECT_EQ(info->constrained, summary.constrained);
  }
}

TEST(ConnectionTypes, SpellingIsNormalised) {
  const char* same[][2] = {{"constant_velocity", "CONSTANT VELOCITY"},
                           {"Constant Velocity", "CONSTANT VELOCITY"},
                           {"CONSTANT-VELOCITY", "CONSTANT VELOCITY"},
                           {"ConstantVelocity", "CONSTANT VELOCITY"},
                           {"slide plane", "SLIDE-PLANE"},
                           {"SLIDE_PLANE", "SLIDE-PLANE"},
                           {"projection-cartesian", "PROJECTION CARTESIAN"},
                           {"Projection Flexion_Torsion", "PROJECTION FLEXION-TORSION"},
                           {"u-joint", "UJOINT"},
                           {"hinge", "HINGE"}};
  for (auto& pair : same) {
    const ConnectionTypeInfo* info = find_connection_type(pair[0]);
    ASSERT_NE(info, nullptr) << pair[0];
    EXPECT_EQ(info->name, pair[1]) << pair[0];
  }
  EXPECT_EQ(find_connection_type("HINGEE"), nullptr);
  EXPECT_EQ(find_connection_type(""), nullptr);
  EXPECT_EQ(find_connection_type("-_ "), nullptr);
  EXPECT_EQ(suggest_connection_type("HINGEE").value_or(""), "HINGE");
  EXPECT_EQ(suggest_connection_type("cardam").value_or(""), "CARDAN");
  EXPECT_EQ(converted_type().name, "CARTESIAN");
  EXPECT_EQ(component_list(mask_of("126")), "1, 2, 6");
  EXPECT_EQ(component_list(0), "none");
}

TEST(ConnectionTypes, SummaryTakesTheStrongestOrientationUse) {
  const ConnectionTypeInfo* slot_cardan[] = {find_connection_type("SLOT"),
                                             find_connection_type("CARDAN")};
  ConnectionSummary s = summarize_connection(slot_cardan, false);
  EXPECT_EQ(s.available, mask_of("1456"));
  EXPECT_EQ(s.constrained, mask_of("23"));
  EXPECT_EQ(s.orientation_a, OrientationUse::Required);
  EXPECT_EQ(s.orientation_b, OrientationUse::Optional);
  const ConnectionTypeInfo* slot_align[] = {find_connection_type("SLOT"),
                                            find_connection_type("ALIGN")};
  s = summarize_connection(slot_align, true);
  EXPECT_EQ(s.available, mask_of("1"));
  EXPECT_EQ(s.constrained, mask_of("26"));
}

// ---------------------------------------------------------------------------------------------
// Orientation triad (keywords.md §6), against hand-computed vectors.

TEST(OrientationTriad, GeneralPoints) {
  // A = (1, 1, 0), Bv = (0, 1, 1): e1 = (1,1,0)/√2, A × Bv = (1,−1,1) → e3 = (1,−1,1)/√3,
  // e2 = e3 × e1 = (−1, 1, 2)/√6.
  Triad t;
  ASSERT_EQ(orientation_triad({1, 1, 0}, {0, 1, 1}, {0, 0, 0}, 1, 0, t), TriadStatus::Ok);
  const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0), r6 = std::sqrt(6.0);
  expect_vec(t[0], {1 / r2, 1 / r2, 0}, "e1");
  expect_vec(t[1], {-1 / r6, 1 / r6, 2 / r6}, "e2");
  expect_vec(t[2], {1 / r3, -1 / r3, 1 / r3}, "e3");
  // The origin c shifts both points: the same triad.
  Triad shifted;
  ASSERT_EQ(orientation_triad({2, 3, -1}, {1, 3, 0}, {1, 2, -1}, 1, 0, shifted), TriadStatus::Ok);
  for (int k = 0; k < 3; ++k) expect_vec(shifted[k], t[k], "shifted");
}

TEST(OrientationTriad, Ori30OfTheWorkedExamples) {
  // connection-types.md §5: ORI30 = global axes rotated 30° about Z.
  Triad t;
  ASSERT_EQ(orientation_triad({0.8660254037844387, 0.5, 0}, {-0.5, 0.8660254037844387, 0},
                              {0, 0, 0}, 1, 0, t),
            TriadStatus::Ok);
  expect_vec(t[0], {0.8660254037844387, 0.5, 0}, "e1");
  expect_vec(t[1], {-0.5, 0.8660254037844387, 0}, "e2");
  expect_vec(t[2], {0, 0, 1}, "e3");
  // The same triad from the global axes and the extra rotation `3, 30.`.
  Triad r;
  ASSERT_EQ(orientation_triad({1, 0, 0}, {0, 1, 0}, {0, 0, 0}, 3, 30, r), TriadStatus::Ok);
  for (int k = 0; k < 3; ++k) expect_vec(r[k], t[k], "rotated");
}

TEST(OrientationTriad, ExtraRotationAboutEachAxis) {
  const Triad g{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const double c = std::cos(M_PI / 6), s = 0.5;  // 30°
  // k = 1: e2' = cos e2 + sin e3, e3' = −sin e2 + cos e3.
  Triad t = rotate_about_local_axis(g, 1, 30);
  expect_vec(t[0], {1, 0, 0}, "k1 e1");
  expect_vec(t[1], {0, c, s}, "k1 e2");
  expect_vec(t[2], {0, -s, c}, "k1 e3");
  // k = 2: e3' = cos e3 + sin e1, e1' = −sin e3 + cos e1.
  t = rotate_about_local_axis(g, 2, 30);
  expect_vec(t[0], {c, 0, -s}, "k2 e1");
  expect_vec(t[1], {0, 1, 0}, "k2 e2");
  expect_vec(t[2], {s, 0, c}, "k2 e3");
  // k = 3: e1' = cos e1 + sin e2, e2' = −sin e1 + cos e2.
  t = rotate_about_local_axis(g, 3, 30);
  expect_vec(t[0], {c, s, 0}, "k3 e1");
  expect_vec(t[1], {-s, c, 0}, "k3 e2");
  expect_vec(t[2], {0, 0, 1}, "k3 e3");
  // On a general triad: 90° about k = 1 maps e2 → e3 and e3 → −e2.
  Triad base;
  ASSERT_EQ(orientation_triad({1, 1, 0}, {0, 1, 1}, {0, 0, 0}, 1, 0, base), TriadStatus::Ok);
  t = rotate_about_local_axis(base, 1, 90);
  expect_vec(t[0], base[0], "k1 90 e1");
  expect_vec(t[1], base[2], "k1 90 e2");
  expect_vec(t[2], {-base[1][0], -base[1][1], -base[1][2]}, "k1 90 e3");
  // Negative angle undoes a positive one.
  t = rotate_about_local_axis(rotate_about_local_axis(base, 2, 37.5), 2, -37.5);
  for (int k = 0; k < 3; ++k) expect_vec(t[k], base[k], "undo");
}

TEST(OrientationTriad, DegenerateInputs) {
  Triad t;
  EXPECT_EQ(orientation_triad({1, 1, 1}, {0, 1, 0}, {1, 1, 1}, 1, 0, t),
            TriadStatus::PointAAtOrigin);
  EXPECT_EQ(orientation_triad({1, 0, 0}, {3, 0, 0}, {0, 0, 0}, 1, 0, t), TriadStatus::PointBOnAxis);
  EXPECT_EQ(orientation_triad({1, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1, 0, t), TriadStatus::PointBOnAxis);
  EXPECT_EQ(orientation_triad({1, 0, 0}, {-2, 0, 0}, {0, 0, 0}, 1, 0, t),
            TriadStatus::PointBOnAxis);
}

TEST(OrientationTriad, ReadFromTheDeck) {
  auto p = parse(two_nodes() +
                 "*ORIENTATION, NAME=\"Datum csys-1\"\n 1., 1., 0., 0., 1., 1.\n 3, 30.\n"
                 "*CONNECTOR SECTION, ELSET=C\n CARTESIAN\n \"Datum csys-1\"\n" +
                 kStep);
  ASSERT_EQ(p->model.sections.orientations.size(), 1u);
  const Orientation& o = p->model.sections.orientations[0];
  EXPECT_TRUE(o.valid);
  EXPECT_TRUE(o.used);
  EXPECT_EQ(o.axis, 3);
  EXPECT_DOUBLE_EQ(o.angle_degrees, 30);
  Triad expected;
  ASSERT_EQ(orientation_triad({1, 1, 0}, {0, 1, 1}, {0, 0, 0}, 3, 30, expected), TriadStatus::Ok);
  for (int k = 0; k < 3; ++k) expect_vec(o.triad[k], expected[k], "deck");
  EXPECT_EQ(p->model.sections.connector_sections[0].orientation_index[0], 0);
  EXPECT_EQ(p->model.sections.connector_sections[0].orientation_index[1], -1);
  EXPECT_EQ(p->sink.error_count() + p->sink.warning_count(), 0u) << p->dump();
}

TEST(OrientationTriad, NodesDefinition) {
  auto p = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 1., 1., 0.\n4, 0., 1., 1.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*ORIENTATION, NAME=ON, DEFINITION=NODES\n 3, 4, 1\n"
      "*ORIENTATION, NAME=BAD, DEFINITION=NODES\n 2, 2\n"
      "*CONNECTOR SECTION, ELSET=C\n SLOT\n ON, BAD\n" +
      std::string(kStep));
  const Orientation& on = p->model.sections.orientations.at(0);
  ASSERT_TRUE(on.valid) << p->dump();
  const double r2 = std::sqrt(2.0), r6 = std::sqrt(6.0);
  expect_vec(on.triad[0], {1 / r2, 1 / r2, 0}, "e1");
  expect_vec(on.triad[1], {-1 / r6, 1 / r6, 2 / r6}, "e2");
  const Diagnostic& d = p->one(DiagCode::degenerate_geometry);
  EXPECT_NE(d.message.find("point b lies on the local 1-axis"), std::string::npos);
  expect_at(d, 11, 5);  // field 2 (point b) with NODES
}

// ---------------------------------------------------------------------------------------------
// *CONNECTOR SECTION reading and validation

TEST(ConnectorSection, StoresTypesMasksAndReferences) {
  auto p = parse(two_nodes() +
                 "*ORIENTATION, NAME=OX\n1., 0., 0., 0., 1., 0.\n"
                 "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\n slot, Cardan\n OX, OX\n"
                 "*CONNECTOR BEHAVIOR, NAME=B\n" +
                 kStep);
  ASSERT_EQ(p->model.sections.connector_sections.size(), 1u);
  const ConnectorSection& s = p->model.sections.connector_sections[0];
  EXPECT_TRUE(s.valid);
  EXPECT_FALSE(s.two_d);
  EXPECT_EQ(s.type_names, (std::vector<std::string>{"SLOT", "CARDAN"}));
  EXPECT_EQ(available_components(s), mask_of("1456"));
  EXPECT_EQ(constrained_components(s), mask_of("23"));
  EXPECT_EQ(connection_display(s), "SLOT, CARDAN");
  EXPECT_EQ(s.behavior_index, 0);
  EXPECT_TRUE(p->model.behaviors.behaviors.at(0).used);
  EXPECT_EQ(s.elements, (std::vector<std::int32_t>{0}));
  ASSERT_EQ(p->model.sections.section_of_element.size(), p->model.elements.size());
  EXPECT_EQ(p->model.sections.section_of_element[0], 0);
  EXPECT_EQ(s.type_loc.line, 9u);
  EXPECT_EQ(s.type_locs.at(1).column, 8u);
  EXPECT_EQ(p->sink.error_count() + p->sink.warning_count(), 0u) << p->dump();
}

TEST(ConnectorSection, Conn2d2UsesComponents126AndSetsTheDimension) {
  auto p = parse(
      "*NODE\n1, 0., 0.\n2, 1., 0.\n*ELEMENT, TYPE=CONN2D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C\n CARTESIAN, ROTATION\n" +
      std::string(kStep));
  const ConnectorSection& s = p->model.sections.connector_sections.at(0);
  EXPECT_EQ(p->model.dimension, 2);
  EXPECT_TRUE(s.two_d);
  EXPECT_TRUE(s.valid);
  EXPECT_EQ(s.available, mask_of("126"));
  EXPECT_EQ(s.constrained, 0);
  EXPECT_EQ(p->sink.error_count(), 0u) << p->dump();

  auto beam = parse(
      "*NODE\n1, 0., 0.\n2, 1., 0.\n*ELEMENT, TYPE=CONN2D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C\n BEAM\n" +
      std::string(kStep));
  EXPECT_EQ(beam->model.sections.connector_sections.at(0).constrained, mask_of("126"));
  EXPECT_EQ(beam->model.sections.connector_sections.at(0).available, 0);
}

TEST(ConnectorSection, EachCombinationRuleError) {
  struct Case {
    const char* line;
    DiagCode code;
    std::uint32_t column;
    const char* text;
  };
  const Case cases[] = {
      {" CARTESIAN, SLOT", DiagCode::invalid_type_combination, 13,
       "connection types 'CARTESIAN' and 'SLOT' are both translational"},
      {" REVOLUTE, EULER", DiagCode::invalid_type_combination, 12,
       "connection types 'REVOLUTE' and 'EULER' are both rotational"},
      {" ALIGN, JOIN", DiagCode::invalid_type_combination, 9,
       "the translational type 'JOIN' must come before the rotational type 'ALIGN'"},
      {" SLOT, HINGE", DiagCode::invalid_type_combination, 8,
       "assembled connection type 'HINGE' cannot be combined with 'SLOT'"},
      {" HINGEE", DiagCode::unknown_connection_type, 2, "unknown connection type 'HINGEE'"},
      {" RETRACTOR", DiagCode::unsupported_connection_type, 2,
       "connection type 'RETRACTOR' is not supported by clinch"},
      {" JOIN, ROTATION ACCELEROMETER", DiagCode::unsupported_connection_type, 8,
       "connection type 'ROTATION ACCELEROMETER' is not supported by clinch"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.line);
    auto p = parse(two_nodes() + "*CONNECTOR SECTION, ELSET=C\n" + c.line + "\n" + kStep);
    const Diagnostic& d = p->one(c.code);
    expect_at(d, 7, c.column);
    EXPECT_NE(d.message.find(c.text), std::string::npos) << d.message;
    const ConnectorSection& s = p->model.sections.connector_sections.at(0);
    EXPECT_FALSE(s.valid);
    EXPECT_EQ(s.available, 0);
    // The element has its (invalid) section: no "missing section" cascade.
    EXPECT_TRUE(p->with(DiagCode::missing_section).empty()) << p->dump();
  }
  // A valid pair for contrast.
  auto ok = parse(two_nodes() + "*CONNECTOR SECTION, ELSET=C\n AXIAL, ROTATION\n" + kStep);
  EXPECT_EQ(ok->sink.error_count(), 0u) << ok->dump();
}

TEST(ConnectorSection, TypeInvalidOnConn2d2) {
  for (const char* type : {"CARDAN", "SLIDE-PLANE", "HINGE", "BUSHING", "EULER"}) {
    SCOPED_TRACE(type);
    auto p = parse(
        "*NODE\n1, 0., 0.\n2, 1., 0.\n*ELEMENT, TYPE=CONN2D2, ELSET=C\n1, 1, 2\n"
        "*ORIENTATION, NAME=OX\n1., 0., 0., 0., 1., 0.\n"
        "*CONNECTOR SECTION, ELSET=C\n " +
        std::string(type) + "\n OX\n" + kStep);
    const Diagnostic& d = p->one(DiagCode::type_dimension_mismatch);
    expect_at(d, 9, 2);
    EXPECT_FALSE(p->model.sections.connector_sections.at(0).valid);
  }
}

TEST(ConnectorSection, AccelerometerBecomesCartesian) {
  auto p = parse(two_nodes() + "*CONNECTOR SECTION, ELSET=C\n accelerometer\n" + kStep);
  const Diagnostic& d = p->one(DiagCode::accelerometer_converted);
  EXPECT_EQ(d.severity, Severity::Warning);
  const ConnectorSection& s = p->model.sections.connector_sections.at(0);
  EXPECT_EQ(s.type_names, std::vector<std::string>{"CARTESIAN"});
  EXPECT_EQ(s.available, mask_of("123"));
}

TEST(ConnectorSection, MixedDimensionsAndMissingSections) {
  auto p = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=A\n1, 1, 2\n"
      "*ELEMENT, TYPE=CONN2D2, ELSET=B\n2, 1, 2\n3, 2, 1\n" +
      std::string(kStep));
  expect_at(p->one(DiagCode::mixed_dimensions), 6, 1);
  const Diagnostic& missing = *p->with(DiagCode::missing_section).at(1);
  expect_at(missing, 6, 1);
  EXPECT_NE(missing.message.find("connector element 2 has no *CONNECTOR SECTION (and 1 more"),
            std::string::npos);
  EXPECT_EQ(p->model.dimension, 2);
}

TEST(ConnectorSection, PartLevelSectionAppliesToEveryInstance) {
  auto p = parse(
      "*PART, NAME=P\n*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*ORIENTATION, NAME=O\n0., 1., 0., -1., 0., 0.\n"
      "*CONNECTOR SECTION, ELSET=C\n SLOT\n O\n*END PART\n"
      "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=I1, PART=P\n*END INSTANCE\n"
      "*INSTANCE, NAME=I2, PART=P\n*END INSTANCE\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=W\n9, I1.1, I2.2\n"
      "*CONNECTOR SECTION, ELSET=W\n SLOT\n O\n*END ASSEMBLY\n" +
      std::string(kStep));
  const auto& sections = p->model.sections.connector_sections;
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[0].elements.size(), 2u);  // one element per instance
  // Orientations are part-local: the assembly-level section cannot see O.
  const Diagnostic& d = p->one(DiagCode::undefined_orientation);
  expect_at(d, 22, 2);
  for (std::size_t e = 0; e < p->model.elements.size(); ++e) {
    EXPECT_GE(p->model.sections.section_of_element[e], 0);
  }
}

TEST(ConnectorSection, OrientationDefaultedAndIgnored) {
  auto p = parse(two_nodes() +
                 "*ORIENTATION, NAME=OX\n1., 0., 0., 0., 1., 0.\n"
                 "*CONNECTOR SECTION, ELSET=C\n HINGE\n , OX\n" +
                 kStep);
  const Diagnostic& defaulted = p->one(DiagCode::orientation_defaulted);
  expect_at(defaulted, 9, 2);
  EXPECT_EQ(defaulted.severity, Severity::Warning);
  EXPECT_TRUE(p->with(DiagCode::orientation_ignored).empty());
  auto q = parse(two_nodes() +
                 "*ORIENTATION, NAME=OX\n1., 0., 0., 0., 1., 0.\n"
                 "*CONNECTOR SECTION, ELSET=C\n JOIN\n , OX\n" +
                 kStep);
  expect_at(q->one(DiagCode::orientation_ignored), 10, 4);
}

// ---------------------------------------------------------------------------------------------
// *SPRING

TEST(Spring, LinearSpringaWithBlankDofLine) {
  auto p = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S\n\n10.\n" +
      std::string(kStep));
  ASSERT_EQ(p->model.sections.springs.size(), 1u);
  const SpringProperty& s = p->model.sections.springs[0];
  EXPECT_TRUE(s.valid) << p->dump();
  EXPECT_EQ(s.type, ElementType::SpringA);
  EXPECT_DOUBLE_EQ(s.stiffness, 10.0);
  EXPECT_EQ(p->model.sections.spring_of_element.at(0), 0);
  EXPECT_EQ(p->sink.error_count() + p->sink.warning_count(), 0u) << p->dump();
}

TEST(Spring, Spring2DofsAndTable) {
  auto p = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRING2, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S, NONLINEAR\n1, 4\n-10., -1.\n0., 0.\n\n"
      "20., 1.\n" +
      std::string(kStep));
  const SpringProperty& s = p->model.sections.springs.at(0);
  EXPECT_TRUE(s.valid) << p->dump();
  EXPECT_EQ(s.dofs[0], 1);
  EXPECT_EQ(s.dofs[1], 4);
  ASSERT_EQ(s.table.size(), 3u);
  EXPECT_DOUBLE_EQ(s.table[2].force, 20.);
  EXPECT_DOUBLE_EQ(s.table[2].delta, 1.);
  EXPECT_EQ(p->sink.error_count() + p->sink.warning_count(), 0u) << p->dump();
}

TEST(Spring, TableChecks) {
  // Not increasing: at the Δ field of the offending line.
  auto p = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S, NONLINEAR\n\n0., 0.\n5., 1.\n6.,   1.\n" +
      std::string(kStep));
  const Diagnostic& d = p->one(DiagCode::table_not_increasing);
  expect_at(d, 10, 7);
  EXPECT_NE(d.message.find("relative displacements must increase (1.0 after 1.0)"),
            std::string::npos);
  EXPECT_FALSE(p->model.sections.springs.at(0).valid);

  // F(0) by interpolation: (−10 at −1, 30 at 1) gives 10 at 0.
  auto w = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S, NONLINEAR\n\n-10., -1.\n30., 1.\n" +
      std::string(kStep));
  const Diagnostic& offset = w->one(DiagCode::nonlinear_elasticity_offset);
  EXPECT_NE(offset.message.find("force 10.0 at zero"), std::string::npos) << offset.message;
  expect_at(offset, 8, 1);

  // Table entirely at positive Δ: F(0) is the first force (constant extrapolation).
  auto e = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S, NONLINEAR\n\n0., 1.\n10., 2.\n" +
      std::string(kStep));
  EXPECT_TRUE(e->with(DiagCode::nonlinear_elasticity_offset).empty()) << e->dump();

  // One point only.
  auto one = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S, NONLINEAR\n\n0., 0.\n" +
      std::string(kStep));
  expect_at(one->one(DiagCode::table_not_increasing), 8, 1);
}

TEST(Spring, CalculixDecksWithoutBlankLine) {
  auto p = parse(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
      "1, 1, 2\n*SPRING, ELSET=S\n1.5e3\n" +
      std::string(kStep));
  expect_at(p->one(DiagCode::springa_missing_blank_line), 7, 1);
  EXPECT_DOUBLE_EQ(p->model.sections.springs.at(0).stiffness, 1500.);
  EXPECT_TRUE(p->model.sections.springs.at(0).valid);
}

TEST(Spring, ExternalCalculixDecksAreClean) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  for (const char* name :
       {"ccx-spring1.inp", "ccx-spring2.inp", "ccx-spring6.inp", "ccx-spring7.inp"}) {
    SCOPED_TRACE(name);
    std::ifstream in(std::string(CLINCH_SHARED_DIR) + "/external-decks/" + name);
    ASSERT_TRUE(in.good());
    std::stringstream text;
    text << in.rdbuf();
    auto p = parse(text.str());
    EXPECT_EQ(p->sink.error_count(), 0u) << p->dump();
    ASSERT_EQ(p->model.sections.springs.size(), 1u);
    EXPECT_TRUE(p->model.sections.springs[0].valid) << p->dump();
  }
}

// ---------------------------------------------------------------------------------------------
// *SECTION CONTROLS

TEST(SectionControls, DefaultsAndReference) {
  auto p = parse(two_nodes() +
                 "*SECTION CONTROLS, NAME=SC, ELEMENT DELETION=YES, "
                 "MAX DEGRADATION=1.0, VISCOSITY=0.\n"
                 "*CONNECTOR SECTION, ELSET=C, CONTROLS=sc\n AXIAL\n" +
                 kStep);
  ASSERT_EQ(p->model.sections.controls.size(), 1u);
  EXPECT_TRUE(p->model.sections.controls[0].used);
  EXPECT_EQ(p->model.sections.connector_sections.at(0).controls_index, 0);
  EXPECT_EQ(p->sink.error_count() + p->sink.warning_count(), 0u) << p->dump();
}

// ---------------------------------------------------------------------------------------------
// The adapy fragment: instance-qualified nodes of instances that the fragment does not define.

TEST(ExternalFragment, AdapyBushingFragmentReportsUndefinedInstances) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  std::ifstream in(std::string(CLINCH_SHARED_DIR) +
                   "/external-decks/adapy-conn-bushing-fragment.inp");
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  auto p = parse(text.str());
  bool bolt = false;
  for (const Diagnostic* d : p->with(DiagCode::undefined_instance)) {
    if (d->message.find("bolt1-3") != std::string::npos) bolt = true;
  }
  EXPECT_TRUE(bolt) << p->dump();
  // Both sections were read as BUSHING with a quoted orientation name.
  ASSERT_EQ(p->model.sections.connector_sections.size(), 2u);
  const ConnectorSection& s = p->model.sections.connector_sections[0];
  EXPECT_EQ(s.type_names, std::vector<std::string>{"BUSHING"});
  EXPECT_EQ(s.orientations.at(0).display, "Datum csys-1");
}

}  // namespace
}  // namespace clinch
