// Nodes, elements, sets and instances (input-syntax.md §7, keywords.md §2–§3), read through the
// whole reader. Coordinates of placed instances are compared with hand calculations to 1e-12
// (the rotation is built from cos/sin of exact angles: round-off is a few ulps).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/resolve/reference_lookup.hpp"

namespace clinch {
namespace {

struct Read {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
};

std::unique_ptr<Read> read(const std::string& text) {
  auto r = std::make_unique<Read>();
  read_deck_text("deck.inp", text + "*STEP\n*STATIC\n*END STEP\n", r->sources, r->model, r->sink);
  return r;
}

std::string listing(const Read& r) {
  std::string out;
  for (const Diagnostic& d : r.sink.diagnostics()) out += render_text(d, r.sources);
  return out;
}

std::vector<std::int32_t> labels_of(const Model& model, const Set& set, bool element) {
  std::vector<std::int32_t> labels;
  for (std::int32_t m : set.members) {
    labels.push_back(element ? model.elements[m].label : model.nodes[m].label);
  }
  return labels;
}

TEST(Geometry, SetsByLabelNameAndGenerate) {
  auto r = read(
      "*NODE, NSET=ALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n3, 2., 0., 0.\n4, 3., 0., 0.\n"
      "*NSET, NSET=A\n3, 1, 3\n*NSET, NSET=B, GENERATE\n2, 4, 2\n*NSET, NSET=C\nA, B\n"
      "*NSET, NSET=A\n4\n");
  EXPECT_FALSE(r->sink.has_errors()) << listing(*r);
  const Part& root = r->model.parts[0];
  EXPECT_EQ(labels_of(r->model, root.node_sets.at("A"), false),
            (std::vector<std::int32_t>{1, 3, 4}));  // duplicates dropped, extended later
  EXPECT_EQ(labels_of(r->model, root.node_sets.at("B"), false), (std::vector<std::int32_t>{2, 4}));
  // A set name copies the members the set has at that point: 4 was added to A afterwards.
  EXPECT_EQ(labels_of(r->model, root.node_sets.at("C"), false),
            (std::vector<std::int32_t>{1, 2, 3, 4}));
}

TEST(Geometry, ForwardLabelReferencesResolve) {
  auto r = read(
      "*NSET, NSET=LATER\n7\n*ELEMENT, TYPE=SPRINGA, ELSET=S\n1, 7, 8\n"
      "*SPRING, ELSET=S\n\n10.\n*NODE\n7, 0., 0., 0.\n8, 1., 0., 0.\n");
  EXPECT_FALSE(r->sink.has_errors()) << listing(*r);
  ASSERT_EQ(r->model.elements.size(), 1u);
  EXPECT_EQ(r->model.nodes[r->model.elements[0].nodes[1]].label, 8);
}

TEST(Geometry, ConnectorToGround) {
  auto r = read(
      "*NODE\n10, 0., 0., 0.\n21, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n2, 10\n3, , 21\n"
      "*CONNECTOR SECTION, ELSET=C\nCARTESIAN,\n");
  EXPECT_FALSE(r->sink.has_errors()) << listing(*r);
  ASSERT_EQ(r->model.elements.size(), 2u);
  EXPECT_EQ(r->model.elements[0].nodes[1], kGround);  // node b omitted: b is ground
  EXPECT_EQ(r->model.elements[1].nodes[0], kGround);  // first field empty: a is ground
  EXPECT_EQ(r->model.nodes[r->model.elements[1].nodes[1]].label, 21);
}

TEST(Geometry, InstancesArePlacedTranslationFirst) {
  // x' = a + R (x + t − a): part node (1, 0, 0), t = (0, 0, 5), 90° about the z axis through
  // a = (0, 0, 0) → (0, 1, 5).
  auto r = read(
      "*PART, NAME=Bolt\n*NODE\n477, 1., 0., 0.\n*NSET, NSET=Tip\n477\n*END PART\n"
      "*ASSEMBLY, NAME=A\n*INSTANCE, NAME=\"bolt 1\", PART=Bolt\n0., 0., 5.\n"
      "0., 0., 0., 0., 0., 1., 90.\n*END INSTANCE\n*INSTANCE, NAME=bolt2, PART=Bolt\n"
      "*END INSTANCE\n*NODE\n1, 9., 9., 9.\n*ELEMENT, TYPE=CONN3D2, ELSET=W\n"
      "10, \"bolt 1\".477, bolt2.477\n*CONNECTOR SECTION, ELSET=W\nCARTESIAN,\n"
      "*NSET, NSET=Both\nbolt2.Tip, 1\n*END ASSEMBLY\n");
  EXPECT_FALSE(r->sink.has_errors()) << listing(*r);
  const Model& m = r->model;
  ASSERT_EQ(m.nodes.size(), 3u);  // root node 1, then the two instance copies
  const Element& e = m.elements.at(0);
  const Node& a = m.nodes[e.nodes[0]];
  EXPECT_EQ(a.instance, 1);
  EXPECT_NEAR(a.x[0], 0.0, 1e-12);
  EXPECT_NEAR(a.x[1], 1.0, 1e-12);
  EXPECT_NEAR(a.x[2], 5.0, 1e-12);
  const Node& b = m.nodes[e.nodes[1]];
  EXPECT_EQ(b.instance, 2);
  EXPECT_EQ(b.x, (Vec3{1.0, 0.0, 0.0}));
  EXPECT_EQ(qualified_label(m, b.instance, b.label), "bolt2.477");
  EXPECT_EQ(m.parts[0].node_sets.at("BOTH").members.size(), 2u);
}

TEST(Geometry, PartLevelReferencesDenoteEveryInstance) {
  auto r = read(
      "*PART, NAME=P\n*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n"
      "5, 1, 2\n*CONNECTOR SECTION, ELSET=C\nAXIAL,\n*END PART\n*ASSEMBLY, NAME=A\n"
      "*INSTANCE, NAME=P-1, PART=P\n*END INSTANCE\n*INSTANCE, NAME=P-2, PART=P\n0., 2., 0.\n"
      "*END INSTANCE\n*END ASSEMBLY\n");
  EXPECT_FALSE(r->sink.has_errors()) << listing(*r);
  TargetRef ref;
  ref.set_key = "C";
  ref.set_display = "C";
  ref.part = 1;
  std::vector<std::int32_t> out;
  DiagnosticSink sink;
  ASSERT_TRUE(resolve_elements(r->model, ref, out, sink));
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(r->model.elements[out[0]].instance, 1);
  EXPECT_EQ(r->model.elements[out[1]].instance, 2);
  EXPECT_DOUBLE_EQ(r->model.nodes[r->model.elements[out[1]].nodes[0]].x[1], 2.0);
}

TEST(Geometry, UndefinedReferencesNameTheField) {
  auto r = read("*NODE\n1, 0., 0., 0.\n*NSET, NSET=A\n1, 99, Missing\n");
  std::vector<DiagCode> codes;
  for (const Diagnostic& d : r->sink.diagnostics()) codes.push_back(d.code);
  EXPECT_NE(std::find(codes.begin(), codes.end(), DiagCode::undefined_node), codes.end());
  EXPECT_NE(std::find(codes.begin(), codes.end(), DiagCode::undefined_set), codes.end());
  for (const Diagnostic& d : r->sink.diagnostics()) {
    if (d.code == DiagCode::undefined_node) {
      EXPECT_EQ(d.loc.column, 4u);
    }
    if (d.code == DiagCode::undefined_set) {
      EXPECT_EQ(d.loc.column, 8u);
    }
  }
}

}  // namespace
}  // namespace clinch

namespace clinch {
namespace {

// Found by fuzzing: an element line whose qualified node field was read before a later field
// failed left a dangling qualified reference behind.
TEST(Geometry, RejectedElementLeavesNoQualifiedReference) {
  auto r = read("*NODE\n1, 0., 0., 0.\n*ELEMENT, TYPE=CONN3D2\n11, bolt1-4.477, 1E*dn\n");
  ASSERT_EQ(r->model.elements.size(), 0u);
  bool bad_field = false;
  for (const Diagnostic& d : r->sink.diagnostics()) {
    if (d.loc.line == 4 && d.loc.column == 18) bad_field = true;
  }
  EXPECT_TRUE(bad_field) << listing(*r);
}

}  // namespace
}  // namespace clinch
