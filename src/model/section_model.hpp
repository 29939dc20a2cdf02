// Plain data for *ORIENTATION, *CONNECTOR SECTION, *SPRING and *SECTION CONTROLS
// (keywords.md §4–§7, connection-types.md §1.3). The reader fills what the deck says;
// resolve_sections resolves element sets, names and element-dependent rules and fills the
// resolved fields (marked "filled by validation").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "src/model/geometry.hpp"
#include "src/model/name.hpp"
#include "src/model/references.hpp"

namespace clinch {

// Bit (i − 1) stands for component i (1…6).
using ComponentMask = std::uint8_t;
inline bool has_component(ComponentMask mask, int component) {
  return component >= 1 && component <= 6 && ((mask >> (component - 1)) & 1u);
}
inline ComponentMask component_bit(int component) {
  return static_cast<ComponentMask>(1u << (component - 1));
}

// Local directions e1, e2, e3 (global components), triad[k] = e_(k+1).
using Triad = std::array<Vec3, 3>;

// *ORIENTATION (keywords.md §6). Inside a part the triad is in part coordinates; each instance
// rotates it (orientation_triad.hpp: placed_triad).
struct Orientation {
  enum class Definition : std::uint8_t { Coordinates, Nodes };
  Name name;
  SourceLoc keyword_loc;
  std::int32_t part = 0;  // scope (input-syntax.md §4): 0 = flat model or assembly
  Definition definition = Definition::Coordinates;
  // COORDINATES: points a, b, c (c defaults to the origin). NODES: filled by validation from the
  // initial coordinates of the nodes.
  Vec3 a{}, b{}, c{};
  std::array<TargetRef, 3> nodes;  // NODES: na, nb, nc (nc optional)
  bool has_node_c = false;
  SourceLoc a_loc, b_loc;  // first field of point a and of point b (E0706)
  int axis = 1;            // data line 2: extra rotation about local axis `axis`
  double angle_degrees = 0;
  bool data_ok = false;  // data line 1 was read without errors
  bool valid = false;    // the triad is defined (filled by validation for NODES)
  Triad triad{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  bool used = false;  // referenced by a section or spring (W0501 otherwise)
};

// *SECTION CONTROLS (keywords.md §5): how damage ends in the connectors of the sections that name
// them (behaviors.md §7.4): deletion, the largest damage, viscous regularisation.
struct SectionControls {
  Name name;
  SourceLoc keyword_loc;
  bool element_deletion = true;
  double max_degradation = 1.0;
  double viscosity = 0.0;
  bool used = false;
};

struct ConnectorSection {
  TargetRef elset;  // ELSET= (scope: the part where the section is written)
  SourceLoc keyword_loc;
  Name behavior;                     // BEHAVIOR= (empty: none); loc = the value
  std::int32_t behavior_index = -1;  // into BehaviorModel::behaviors, set by validation
  Name controls;                     // CONTROLS=
  std::int32_t controls_index = -1;  // into SectionModel::controls, set by validation
  // The connection: one assembled type, or up to one translational and one rotational basic
  // type (canonical names, e.g. "CARTESIAN", "CARDAN"; empty when absent). ACCELEROMETER is
  // stored as CARTESIAN (connection-types.md §1.5 rule 4).
  std::vector<std::string> type_names;
  SourceLoc type_loc;                // first field of data line 1
  std::vector<SourceLoc> type_locs;  // each type field, parallel to type_names
  // 3-D masks after reading; validation replaces them by the CONN2D2 masks for 2-D sections.
  ComponentMask available = 0;
  ComponentMask constrained = 0;
  bool valid = false;  // the type line was understood
  bool two_d = false;  // the elements are CONN2D2 (filled by validation)
  // Line 2: [a, b], always two entries (empty names where blank or absent).
  std::vector<Name> orientations = std::vector<Name>(2);
  // Resolved orientations at a and b (−1: none/default), filled by validation.
  std::array<std::int32_t, 2> orientation_index{-1, -1};
  std::vector<std::int32_t> elements;  // global element indices, filled by validation
};

// One data line of *SPRING or *DASHPOT as read: the DOF line's integers, or a property line's
// numbers (keywords.md §7). Which lines are which depends on the element type, so validation
// decides.
struct SpringValue {
  std::optional<double> value;  // empty field: nullopt
  SourceLoc loc;
};
struct SpringLine {
  SourceLoc loc;                    // column 1 of the line
  std::vector<SpringValue> values;  // numbers in field order (property lines)
  bool ok = true;                   // every field was a number
};

// The words that name a *SPRING or a *DASHPOT block and its data in messages.
struct DiscreteElementWords {
  std::string_view keyword;      // "*SPRING"
  std::string_view element;      // "spring"
  std::string_view coefficient;  // "spring stiffness"
  std::string_view motion;       // "relative displacement"
  std::string_view motions;      // "relative displacements"
};

// A *SPRING, or a *DASHPOT, which has the same layout with a dashpot coefficient or a force
// against relative velocity (behaviors.md §8: v = Δu/Δt in a static step).
struct SpringProperty {
  TargetRef elset;
  SourceLoc keyword_loc;
  bool dashpot = false;
  bool nonlinear = false;
  Name orientation;                     // ORIENTATION= (empty: global axes)
  SourceLoc orientation_param_loc;      // the parameter name (W0702)
  std::int32_t orientation_index = -1;  // filled by validation
  // First data line (the DOF line position).
  bool has_first_line = false;
  bool first_line_blank = false;
  bool first_line_real = false;  // holds a real number: SPRINGA property line (W0703)
  bool first_line_ok = true;     // integers only (when not real-like)
  SourceLoc first_line_loc;
  std::vector<std::int64_t> first_line_integers;
  std::vector<SourceLoc> first_line_locs;
  SpringLine first_line_as_property;       // the first line read as numbers (when real-like)
  bool data_ok = true;                     // false: the block was rejected (only ELSET is used)
  std::vector<SpringLine> property_lines;  // data lines 2…
  // Filled by validation.
  ElementType type = ElementType::SpringA;
  std::array<int, 2> dofs{0, 0};  // SPRING1: dofs[0]; SPRING2: both
  double stiffness = 0;           // linear
  struct Point {
    double force = 0, delta = 0;
    SourceLoc loc;
  };
  std::vector<Point> table;  // nonlinear: F at Δ (a dashpot: at v), strictly increasing
  bool valid = false;
  std::vector<std::int32_t> elements;

  const DiscreteElementWords& words() const {
    static constexpr DiscreteElementWords kSpring{"*SPRING", "spring", "spring stiffness",
                                                  "relative displacement",
                                                  "relative displacements"};
    static constexpr DiscreteElementWords kDashpot{"*DASHPOT", "dashpot", "dashpot coefficient",
                                                   "relative velocity", "relative velocities"};
    return dashpot ? kDashpot : kSpring;
  }
};

struct SectionModel {
  std::vector<ConnectorSection> connector_sections;
  // Global element index → connector section index (−1: none), filled by validation.
  std::vector<std::int32_t> section_of_element;
  std::vector<SpringProperty> springs;  // *SPRING and *DASHPOT blocks in deck order
  // Global element index → springs index (−1: none), filled by validation.
  std::vector<std::int32_t> spring_of_element;
  std::vector<Orientation> orientations;
  // scoped_name_key(part, name key) → index into orientations.
  std::unordered_map<std::string, std::int32_t> orientation_by_key;
  std::vector<SectionControls> controls;
  std::unordered_map<std::string, std::int32_t> controls_by_key;  // model-wide names
};

// Key of a part-scoped name (orientations are local to their part, input-syntax.md §4).
inline std::string scoped_name_key(std::int32_t part, const std::string& key) {
  return std::to_string(part) + '\x1f' + key;
}

}  // namespace clinch
