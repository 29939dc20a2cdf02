// Plain data for nodes, elements, sets, parts and instances. A flat deck has one implicit part
// (index 0, the "root") and one implicit instance of it; in a part–assembly deck the root part
// holds the assembly-level definitions and instances 1.. place the parts (input-syntax.md §7).
// After reading, Model::nodes/elements hold every node and element in global numbering.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

#include "src/model/label_index.hpp"
#include <vector>

#include "src/model/name.hpp"

namespace clinch {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<std::array<double, 3>, 3>;

enum class ElementType : std::uint8_t {
  Conn3D2, Conn2D2, SpringA, Spring1, Spring2, DashpotA, Dashpot1, Dashpot2,
  Held  // any other type: its nodes are kept in an ElementBlock, it has no formulation
};
const char* element_type_name(ElementType type);
inline bool is_connector(ElementType t) {
  return t == ElementType::Conn3D2 || t == ElementType::Conn2D2;
}
// Springs and dashpots: discrete elements with one force and one relative motion (S11, E11).
inline bool is_spring_or_dashpot(ElementType t) {
  return !is_connector(t) && t != ElementType::Held;
}
inline bool is_dashpot(ElementType t) {
  return t == ElementType::DashpotA || t == ElementType::Dashpot1 || t == ElementType::Dashpot2;
}
// The spring type with the same nodes and kinematics: a DASHPOTA acts along the line of its
// nodes like a SPRINGA, a DASHPOT1/2 on its DOFs like a SPRING1/2 (keywords.md §7).
inline ElementType spring_form(ElementType t) {
  switch (t) {
    case ElementType::DashpotA: return ElementType::SpringA;
    case ElementType::Dashpot1: return ElementType::Spring1;
    case ElementType::Dashpot2: return ElementType::Spring2;
    default: return t;
  }
}

constexpr std::int32_t kGround = -1;  // connector end connected to ground (keywords.md §3)

struct Node {
  std::int32_t label = 0;
  std::int32_t instance = 0;  // global arrays: instance that owns it (0 = root)
  Vec3 x{};
  std::uint32_t line = 0;     // data line of the definition (file from `file`)
  std::uint32_t file = 0;
  SourceLoc loc() const { return {file, line, 1}; }
};

// connection-types.md §2.2: the length below which two points coincide, tol = 1e-8 × max(1,
// diagonal of the bounding box of `nodes`). `clinch check` and the analysis plan both use it, so
// that what check passes, run accepts. The diagonal is computed with scaling, exact for any finite
// coordinates; a diagonal that overflows even so counts as 1.
double geometry_tolerance(const std::vector<Node>& nodes);

// |x|, computed with scaling: neither overflow nor underflow of the squares for coordinates
// between about 1e-300 and 1e300.
double length_of(const Vec3& x);

struct Element;
struct Model;
// The type of global element `e` as written: "CONN3D2", or a held element's block type ("C3D8R").
std::string_view element_type_name(const Model& model, std::int32_t e);

struct Element {
  std::int32_t label = 0;
  std::int32_t instance = 0;
  ElementType type = ElementType::Conn3D2;
  // Part-local node indices while reading a part; global indices in Model::elements.
  // kGround for a grounded connector end, and for the unused second node of SPRING1.
  std::array<std::int32_t, 2> nodes{kGround, kGround};
  std::uint32_t line = 0;
  std::uint32_t file = 0;
  std::uint32_t keyword_line = 0;  // the *ELEMENT line (E0514 is reported there)
  std::array<std::uint16_t, 2> node_columns{0, 0};  // columns of the node fields (diagnostics)
  SourceLoc loc() const { return {file, line, 1}; }
  SourceLoc keyword_loc() const { return {file, keyword_line, 1}; }
};

// A node or element set: members are indices into the owning part's arrays (global indices for
// root-part sets, which may also hold members of instances).
struct Set {
  Name name;
  std::vector<std::int32_t> members;
  bool defined_ok = true;  // false when its definition failed (later uses stay silent)
  // UNSORTED on a *NSET/*ELSET line of the set: members are kept in ascending order all the
  // same, so what matches sets entry by entry (*MPC, *EQUATION) refuses it (invalid: not given).
  SourceLoc unsorted_loc;
};

// A set definition step recorded while reading and replayed in deck order once every label is
// known (labels may refer to later definitions; a set name copies the members it has at that
// point, input-syntax.md §7.4).
struct SetOperation {
  enum class Kind : std::uint8_t { Labels, SetName, Range, ElementNodes };
  Kind kind = Kind::Labels;
  bool element_set = false;  // target is an element set
  std::string target_key;    // set being defined
  std::string source_key;    // SetName / ElementNodes: the set named on the line
  std::string source_display;
  std::string instance_key;  // INSTANCE= or a qualifier: labels of that instance
  std::string instance_display;
  std::int32_t first = 0, last = 0, increment = 1;  // Range
  SourceLoc loc;
  // Labels: consecutive labels of one block share one operation (16 bytes a label), so a set
  // of a million labels costs what its labels cost.
  struct LabelItem {
    std::int32_t label;
    SourceLoc loc;
  };
  std::vector<LabelItem> labels;
};

// One *ELEMENT block of a type clinch holds as nodes only (solids, shells, beams, rigid elements,
// masses, ...: src/model/element_library.hpp). Its elements are also in Part::elements (type Held,
// no nodes there) at indices first_element … first_element + count − 1, in order; their nodes are
// here, nodes_per_element per element.
struct ElementBlock {
  // What the block is made of for an analysis. None: left deformable, which clinch cannot run
  // (src/check/deformable_elements.cpp); RigidOnly: carried by a rigid body, only its nodes count.
  enum class Formulation : std::uint8_t { None, RigidOnly };
  std::string type;  // canonical type name, e.g. "C3D8R"
  std::uint8_t family = 0;  // ElementFamily (element_library.hpp)
  int nodes_per_element = 0;
  SourceLoc keyword_loc;  // the *ELEMENT line
  SourceLoc type_loc;     // the TYPE= value
  std::int32_t first_element = 0;
  std::int32_t count = 0;
  // Node labels while reading; part-local node indices (root part: global) after resolve,
  // kGround where a label is not defined (reported) or waits for an instance qualifier.
  std::vector<std::int32_t> nodes;
  std::vector<SourceLoc> node_locs;  // the field of each node (diagnostics)
  struct QualifiedNode {  // an "Inst.label" field (root part only)
    std::int32_t position;  // into nodes
    std::string instance_key, instance_display;
    std::int32_t label;
  };
  std::vector<QualifiedNode> qualified;
  Formulation formulation = Formulation::None;
  // The nodes of element `k` of the block (0 ≤ k < count).
  std::span<const std::int32_t> element_nodes(std::int32_t k) const {
    return {nodes.data() + static_cast<std::size_t>(k) * nodes_per_element,
            static_cast<std::size_t>(nodes_per_element)};
  }
};

struct Part {
  Name name;  // empty for the root part
  SourceLoc loc;
  std::vector<Node> nodes;
  std::vector<Element> elements;
  LabelIndex node_index;     // label → index in nodes
  LabelIndex element_index;  // label → index in elements
  std::unordered_map<std::string, Set> node_sets;                 // key → set
  std::unordered_map<std::string, Set> element_sets;
  std::vector<SetOperation> set_operations;
  std::vector<ElementBlock> element_blocks;  // blocks of held elements, in deck order
  // The block holding element `e` (part-local index), or nullptr for analysed elements.
  const ElementBlock* block_of(std::int32_t e) const;
  // Node fields of element lines that are instance-qualified (root part only): resolved once
  // instances are placed.
  struct QualifiedNode {
    std::int32_t element;
    int slot;
    std::string instance_key, instance_display;
    std::int32_t label;
    SourceLoc loc;
  };
  std::vector<QualifiedNode> qualified_nodes;
};

struct Instance {
  Name name;  // empty for the root instance
  SourceLoc loc;
  std::int32_t part = 0;
  Vec3 translation{};
  Mat3 rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Vec3 axis_point{};  // point a of the rotation axis (after translation)
  std::int32_t node_offset = 0;
  std::int32_t element_offset = 0;
  // Places a part coordinate: x' = a + R (x + t − a) (input-syntax.md §7.2).
  Vec3 place(const Vec3& x) const;
  Vec3 rotate(const Vec3& v) const;
};

}  // namespace clinch
