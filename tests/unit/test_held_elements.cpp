// Element types clinch holds as their nodes (src/model/element_library.hpp): every type reads with
// the node count of the Abaqus element library, long elements go on over lines ending with a
// comma, a wrong count is an error at its line, a deformable block is refused once (for the
// elements no rigid body carries), and the sections, materials and surfaces around them are
// kept. The expected node counts below are typed from the Abaqus Analysis User's Guide element
// tables, independently of the library table.
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "parser/deck_reader.hpp"
#include "src/model/element_library.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch {
namespace {

std::unique_ptr<CheckedDeck> read(const std::string& text) { return read_checked_deck(text); }

// 27 nodes on a line, enough for every type.
std::string nodes_text() {
  std::string text = "*NODE\n";
  for (int n = 1; n <= 27; ++n) text += std::to_string(n) + ", " + std::to_string(n) + ".\n";
  return text;
}

// The element line of `label` with nodes 1…count, split as Abaqus writes it: 16 entries a line,
// each full line ending with a comma.
std::string element_lines(int label, int count) {
  std::string text = std::to_string(label);
  int entries = 1;
  for (int n = 1; n <= count; ++n) {
    if (entries == 16) {
      text += ",\n";
      entries = 0;
    } else {
      text += ", ";
    }
    text += std::to_string(n);
    ++entries;
  }
  return text + "\n";
}

constexpr const char* kStep = "*STEP\n*STATIC\n*END STEP\n";

const std::vector<std::pair<std::string, int>> kManualNodeCounts = {
    {"C3D4", 4},   {"C3D6", 6},   {"C3D8", 8},   {"C3D8R", 8},  {"C3D8I", 8},   {"C3D10", 10},
    {"C3D10M", 10}, {"C3D15", 15}, {"C3D20", 20}, {"C3D20R", 20}, {"S3", 3},      {"S3R", 3},
    {"S4", 4},     {"S4R", 4},    {"S8R", 8},    {"STRI3", 3},  {"M3D3", 3},    {"M3D4", 4},
    {"M3D4R", 4},  {"R3D3", 3},   {"R3D4", 4},   {"R2D2", 2},   {"RAX2", 2},    {"RB3D2", 2},
    {"B21", 2},    {"B22", 3},    {"B31", 2},    {"B32", 3},    {"B33", 2},     {"T2D2", 2},
    {"T3D2", 2},   {"T3D3", 3},   {"CPS3", 3},   {"CPS4", 4},   {"CPS4R", 4},   {"CPS6", 6},
    {"CPS8", 8},   {"CPS8R", 8},  {"CPE3", 3},   {"CPE4", 4},   {"CPE4R", 4},   {"CPE6", 6},
    {"CPE8", 8},   {"CPE8R", 8},  {"CAX3", 3},   {"CAX4", 4},   {"CAX4R", 4},   {"CAX6", 6},
    {"CAX8", 8},   {"CAX8R", 8},  {"MASS", 1},   {"ROTARYI", 1}, {"C3D20RH", 20}, {"S9R5", 9},
};

TEST(HeldElements, EveryListedTypeReadsWithItsNodeCount) {
  for (const auto& [type, count] : kManualNodeCounts) {
    const ElementTypeInfo* info = find_element_type(type);
    ASSERT_NE(info, nullptr) << type;
    EXPECT_EQ(info->nodes, count) << type;
    auto deck = read(nodes_text() + "*ELEMENT, TYPE=" + type + ", ELSET=E\n" +
                     element_lines(7, count) + element_lines(8, count) + kStep);
    const Part& root = deck->model.parts[0];
    ASSERT_EQ(root.element_blocks.size(), 1u) << type;
    const ElementBlock& block = root.element_blocks[0];
    EXPECT_EQ(block.type, type);
    EXPECT_EQ(block.count, 2) << type << "\n" << deck->dump();
    ASSERT_EQ(block.nodes.size(), static_cast<std::size_t>(2 * count)) << type;
    // Nodes 1…count of the flat deck are the global nodes 0…count−1, in element order.
    for (int k = 0; k < count; ++k) {
      EXPECT_EQ(block.element_nodes(1)[static_cast<std::size_t>(k)], k) << type;
    }
    // Exactly one diagnostic for the block: the refusal, or the note of a point inertia.
    ASSERT_EQ(deck->sink.diagnostics().size(), 1u) << type << "\n" << deck->dump();
    const Diagnostic& d = deck->sink.diagnostics()[0];
    const bool inertia = type == "MASS" || type == "ROTARYI";
    EXPECT_EQ(d.code, inertia ? DiagCode::inertia_ignored : DiagCode::deformable_element) << type;
    EXPECT_EQ(d.loc.line, 29u) << type;  // the *ELEMENT line
    EXPECT_EQ(d.loc.column, 16u) << type;  // the TYPE= value
  }
}

TEST(HeldElements, TwentyNodesGoOnOverTwoLinesAsAbaqusWritesThem) {
  auto deck = read(nodes_text() +
                   "*ELEMENT, TYPE=C3D20R\n"
                   "1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,\n"
                   "   16, 17, 18, 19, 20\n"
                   "2, 20, 19, 18, 17, 16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5,\n"
                   "   4, 3, 2, 1\n" +
                   std::string(kStep));
  const ElementBlock& block = deck->model.parts[0].element_blocks.at(0);
  ASSERT_EQ(block.count, 2) << deck->dump();
  EXPECT_EQ(block.element_nodes(0)[19], 19);  // node label 20
  EXPECT_EQ(block.element_nodes(1)[0], 19);
  EXPECT_EQ(block.element_nodes(1)[19], 0);
  EXPECT_EQ(deck->with(DiagCode::deformable_element).size(), 1u);
}

TEST(HeldElements, AWrongNodeCountIsAnErrorAtItsLine) {
  auto deck = read(nodes_text() +
                   "*ELEMENT, TYPE=C3D8R\n"
                   "1, 1, 2, 3, 4, 5, 6, 7\n"           // line 30: one node short
                   "2, 1, 2, 3, 4, 5, 6, 7, 8, 9\n" +  // line 31: one node too many
                   std::string(kStep));
  const Diagnostic& few = deck->one(DiagCode::missing_field);
  EXPECT_EQ(few.loc.line, 30u);
  EXPECT_NE(few.message.find("C3D8R element 1 has 8 nodes; 7 given"), std::string::npos)
      << few.message;
  const Diagnostic& many = deck->one(DiagCode::too_many_fields);
  EXPECT_EQ(many.loc.line, 31u);
  EXPECT_EQ(many.loc.column, 28u);  // the ninth node
  // Neither element is kept; the empty block is not refused.
  EXPECT_EQ(deck->model.parts[0].element_blocks.at(0).count, 0);
  EXPECT_TRUE(deck->with(DiagCode::deformable_element).empty()) << deck->dump();
}

TEST(HeldElements, AnUndefinedNodeIsNamedAtItsField) {
  auto deck = read(nodes_text() + "*ELEMENT, TYPE=S4R\n1, 1, 2, 3, 99\n" + kStep);
  const Diagnostic& d = deck->one(DiagCode::undefined_node);
  EXPECT_EQ(d.loc.line, 30u);
  EXPECT_EQ(d.loc.column, 13u);
}

TEST(HeldElements, InstancesCopyTheNodesAndSetsNameThem) {
  auto deck = read(
      "*PART, NAME=P\n*NODE\n1, 0.\n2, 1.\n3, 1., 1.\n4, 0., 1.\n5, 5.\n"
      "*ELEMENT, TYPE=R3D4, ELSET=SKIN\n1, 1, 2, 3, 4\n*NSET, NSET=SKIN_NODES, ELSET=SKIN\n"
      "*END PART\n*ASSEMBLY, NAME=A\n*INSTANCE, NAME=I1, PART=P\n*END INSTANCE\n"
      "*INSTANCE, NAME=I2, PART=P\n*END INSTANCE\n*END ASSEMBLY\n" +
      std::string(kStep));
  const Model& model = deck->model;
  const Set& set = model.parts[1].node_sets.at("SKIN_NODES");
  EXPECT_EQ(set.members, (std::vector<std::int32_t>{0, 1, 2, 3}));  // node 5 is not on it
  // Nodes of both instances are on a held element; node 5 of each is not.
  const auto& held = model.structure.node_on_held_element;
  ASSERT_EQ(held.size(), 10u);
  EXPECT_TRUE(held[0] && held[3] && held[5] && held[8]);
  EXPECT_FALSE(held[4] || held[9]);
  // One refusal for the part's block, not one per instance or per element.
  EXPECT_EQ(deck->with(DiagCode::deformable_element).size(), 1u) << deck->dump();
}

// *RIGID BODY lifts the refusal for the elements its ELSET carries: an instance made rigid needs
// no formulation, while the other instance of the same part is still refused, once, for its
// copy of the block (1 of 2 elements), naming the type and the rigid body that would make it run.
TEST(HeldElements, ARigidBodyLiftsTheRefusalForItsElementsOnly) {
  const std::string part =
      "*PART, NAME=P\n*NODE\n1, 0.\n2, 1.\n3, 1., 1.\n4, 0., 1.\n"
      "*ELEMENT, TYPE=R3D4, ELSET=SKIN\n1, 1, 2, 3, 4\n*END PART\n"
      "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=I1, PART=P\n*END INSTANCE\n"
      "*INSTANCE, NAME=I2, PART=P\n*END INSTANCE\n*NODE\n100, 0., 0., 5.\n";
  auto both = read(part +
                   "*NSET, NSET=R1\n100\n*RIGID BODY, REF NODE=R1, ELSET=I1.SKIN\n"
                   "*NODE\n101, 1., 0., 5.\n*RIGID BODY, REF NODE=101, ELSET=I2.SKIN\n"
                   "*END ASSEMBLY\n" + std::string(kStep));
  EXPECT_TRUE(both->with(DiagCode::deformable_element).empty()) << both->dump();
  EXPECT_EQ(both->model.constraints.followers.size(), 8u);

  auto one = read(part + "*RIGID BODY, REF NODE=100, ELSET=I1.SKIN\n*END ASSEMBLY\n" +
                  std::string(kStep));
  const Diagnostic& d = one->one(DiagCode::deformable_element);
  EXPECT_EQ(d.loc.line, 7u);  // the part's *ELEMENT line
  EXPECT_NE(d.message.find("1 rigid element (of 2, the others in a rigid body) of type R3D4 "
                           "would be deformable"),
            std::string::npos)
      << d.message;
  EXPECT_NE(d.message.find("make its part a rigid body (*RIGID BODY)"), std::string::npos);
}

TEST(HeldElements, SectionsMaterialsAndSurfacesAreKept) {
  auto deck = read(
      "*NODE\n1, 0.\n2, 1.\n3, 1., 1.\n4, 0., 1.\n"
      "*ELEMENT, TYPE=S4R, ELSET=PLATE\n1, 1, 2, 3, 4\n"
      "*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL\n2.5, 5\n"
      "*MATERIAL, NAME=STEEL\n*DENSITY\n7.85e-9,\n*ELASTIC\n210000., 0.3\n"
      "*PLASTIC\n250., 0.\n300., 0.1\n"
      "*SURFACE, NAME=TOP, TYPE=ELEMENT\nPLATE, SPOS\n"
      "*SURFACE, NAME=CORNERS, TYPE=NODE\n1,\n3, 0.5\n" +
      std::string(kStep));
  const StructureModel& s = deck->model.structure;
  ASSERT_EQ(s.sections.size(), 1u);
  EXPECT_EQ(s.sections[0].kind, ElementSection::Kind::Shell);
  EXPECT_EQ(s.sections[0].elements, (std::vector<std::int32_t>{0}));
  ASSERT_EQ(s.sections[0].rows.size(), 1u);
  EXPECT_EQ(s.sections[0].rows[0].values, (std::vector<double>{2.5, 5.0}));
  ASSERT_EQ(s.sections[0].material_index, 0);
  const Material& steel = s.materials[0];
  ASSERT_EQ(steel.options.size(), 3u);
  EXPECT_EQ(steel.options[0].keyword, "DENSITY");
  EXPECT_EQ(steel.options[0].rows[0].values, (std::vector<double>{7.85e-9}));
  EXPECT_EQ(steel.options[1].rows[0].values, (std::vector<double>{210000., 0.3}));
  EXPECT_EQ(steel.options[2].rows.size(), 2u);
  ASSERT_EQ(s.surfaces.size(), 2u);
  ASSERT_EQ(s.surfaces[0].faces.size(), 1u);
  EXPECT_EQ(s.surfaces[0].faces[0].face, "SPOS");
  EXPECT_EQ(s.surfaces[1].nodes, (std::vector<std::int32_t>{0, 2}));
  EXPECT_EQ(deck->sink.diagnostics().size(), 1u) << deck->dump();  // the refusal only
}

TEST(HeldElements, BadMaterialAndSectionDataAreNamedAtTheirField) {
  auto deck = read(
      "*NODE\n1, 0.\n2, 1.\n*ELEMENT, TYPE=T3D2, ELSET=BAR\n1, 1, 2\n"
      "*SOLID SECTION, ELSET=BAR, MATERIAL=ALU\n1.\n"  // line 6: no material ALU
      "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., nu\n"  // line 10: not a number
      "*SURFACE, NAME=S\nBAR, S9\n" +                   // line 12: no face S9
      std::string(kStep));
  EXPECT_EQ(deck->one(DiagCode::undefined_material).loc.line, 6u);
  EXPECT_EQ(deck->one(DiagCode::expected_number).loc.line, 10u);
  EXPECT_EQ(deck->one(DiagCode::invalid_value).loc.line, 12u);
}

TEST(HeldElements, AMaterialOptionOutsideAMaterialIsAtTheWrongLevel) {
  auto deck = read("*NODE\n1, 0.\n*ELASTIC\n1., 0.3\n" + std::string(kStep));
  EXPECT_EQ(deck->one(DiagCode::wrong_level).loc.line, 3u);
}

}  // namespace
}  // namespace clinch
