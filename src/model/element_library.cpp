#include "src/model/element_library.hpp"

namespace clinch {
namespace {

using F = ElementFamily;
constexpr ElementType kHeld = ElementType::Held;

// Abaqus Analysis User's Guide, element library: node counts of the stress/displacement
// elements. Hybrid (H) and other variants with the same nodes are listed with their base type.
constexpr ElementTypeInfo kTypes[] = {
    {"CONN3D2", ElementType::Conn3D2, 2, F::Analysed},
    {"CONN2D2", ElementType::Conn2D2, 2, F::Analysed},
    {"SPRINGA", ElementType::SpringA, 2, F::Analysed},
    {"SPRING1", ElementType::Spring1, 1, F::Analysed},
    {"SPRING2", ElementType::Spring2, 2, F::Analysed},
    {"DASHPOTA", ElementType::DashpotA, 2, F::Analysed},
    {"DASHPOT1", ElementType::Dashpot1, 1, F::Analysed},
    {"DASHPOT2", ElementType::Dashpot2, 2, F::Analysed},
    // Three-dimensional solids.
    {"C3D4", kHeld, 4, F::Solid}, {"C3D4H", kHeld, 4, F::Solid},
    {"C3D5", kHeld, 5, F::Solid}, {"C3D5H", kHeld, 5, F::Solid},
    {"C3D6", kHeld, 6, F::Solid}, {"C3D6H", kHeld, 6, F::Solid},
    {"C3D8", kHeld, 8, F::Solid}, {"C3D8H", kHeld, 8, F::Solid},
    {"C3D8I", kHeld, 8, F::Solid}, {"C3D8IH", kHeld, 8, F::Solid},
    {"C3D8R", kHeld, 8, F::Solid}, {"C3D8RH", kHeld, 8, F::Solid},
    {"C3D8S", kHeld, 8, F::Solid}, {"C3D8HS", kHeld, 8, F::Solid},
    {"C3D10", kHeld, 10, F::Solid}, {"C3D10H", kHeld, 10, F::Solid},
    {"C3D10HS", kHeld, 10, F::Solid}, {"C3D10M", kHeld, 10, F::Solid},
    {"C3D10MH", kHeld, 10, F::Solid}, {"C3D10I", kHeld, 10, F::Solid},
    {"C3D15", kHeld, 15, F::Solid}, {"C3D15H", kHeld, 15, F::Solid},
    {"C3D20", kHeld, 20, F::Solid}, {"C3D20H", kHeld, 20, F::Solid},
    {"C3D20R", kHeld, 20, F::Solid}, {"C3D20RH", kHeld, 20, F::Solid},
    {"CSS8", kHeld, 8, F::Solid}, {"SC6R", kHeld, 6, F::Solid}, {"SC8R", kHeld, 8, F::Solid},
    // Shells.
    {"S3", kHeld, 3, F::Shell}, {"S3R", kHeld, 3, F::Shell}, {"S3RS", kHeld, 3, F::Shell},
    {"STRI3", kHeld, 3, F::Shell}, {"STRI65", kHeld, 6, F::Shell},
    {"S4", kHeld, 4, F::Shell}, {"S4R", kHeld, 4, F::Shell}, {"S4RS", kHeld, 4, F::Shell},
    {"S4RSW", kHeld, 4, F::Shell}, {"S4R5", kHeld, 4, F::Shell},
    {"S8R", kHeld, 8, F::Shell}, {"S8R5", kHeld, 8, F::Shell}, {"S9R5", kHeld, 9, F::Shell},
    // Membranes.
    {"M3D3", kHeld, 3, F::Membrane}, {"M3D4", kHeld, 4, F::Membrane},
    {"M3D4R", kHeld, 4, F::Membrane}, {"M3D6", kHeld, 6, F::Membrane},
    {"M3D8", kHeld, 8, F::Membrane}, {"M3D8R", kHeld, 8, F::Membrane},
    {"M3D9", kHeld, 9, F::Membrane}, {"M3D9R", kHeld, 9, F::Membrane},
    // Rigid elements.
    {"R3D3", kHeld, 3, F::Rigid}, {"R3D4", kHeld, 4, F::Rigid}, {"R2D2", kHeld, 2, F::Rigid},
    {"RAX2", kHeld, 2, F::Rigid}, {"RB3D2", kHeld, 2, F::Rigid}, {"RB2D2", kHeld, 2, F::Rigid},
    // Beams.
    {"B21", kHeld, 2, F::Beam}, {"B21H", kHeld, 2, F::Beam}, {"B22", kHeld, 3, F::Beam},
    {"B22H", kHeld, 3, F::Beam}, {"B23", kHeld, 2, F::Beam}, {"B23H", kHeld, 2, F::Beam},
    {"B31", kHeld, 2, F::Beam}, {"B31H", kHeld, 2, F::Beam}, {"B31OS", kHeld, 2, F::Beam},
    {"B32", kHeld, 3, F::Beam}, {"B32H", kHeld, 3, F::Beam}, {"B32OS", kHeld, 3, F::Beam},
    {"B33", kHeld, 2, F::Beam}, {"B33H", kHeld, 2, F::Beam},
    {"PIPE21", kHeld, 2, F::Beam}, {"PIPE22", kHeld, 3, F::Beam},
    {"PIPE31", kHeld, 2, F::Beam}, {"PIPE32", kHeld, 3, F::Beam},
    // Trusses.
    {"T2D2", kHeld, 2, F::Truss}, {"T2D2H", kHeld, 2, F::Truss}, {"T2D3", kHeld, 3, F::Truss},
    {"T3D2", kHeld, 2, F::Truss}, {"T3D2H", kHeld, 2, F::Truss}, {"T3D3", kHeld, 3, F::Truss},
    // Plane stress, plane strain and axisymmetric continua.
    {"CPS3", kHeld, 3, F::Planar}, {"CPS4", kHeld, 4, F::Planar},
    {"CPS4I", kHeld, 4, F::Planar}, {"CPS4R", kHeld, 4, F::Planar},
    {"CPS6", kHeld, 6, F::Planar}, {"CPS6M", kHeld, 6, F::Planar},
    {"CPS8", kHeld, 8, F::Planar}, {"CPS8R", kHeld, 8, F::Planar},
    {"CPE3", kHeld, 3, F::Planar}, {"CPE3H", kHeld, 3, F::Planar},
    {"CPE4", kHeld, 4, F::Planar}, {"CPE4H", kHeld, 4, F::Planar},
    {"CPE4I", kHeld, 4, F::Planar}, {"CPE4R", kHeld, 4, F::Planar},
    {"CPE6", kHeld, 6, F::Planar}, {"CPE6M", kHeld, 6, F::Planar},
    {"CPE8", kHeld, 8, F::Planar}, {"CPE8H", kHeld, 8, F::Planar},
    {"CPE8R", kHeld, 8, F::Planar},
    {"CAX3", kHeld, 3, F::Planar}, {"CAX3H", kHeld, 3, F::Planar},
    {"CAX4", kHeld, 4, F::Planar}, {"CAX4H", kHeld, 4, F::Planar},
    {"CAX4I", kHeld, 4, F::Planar}, {"CAX4R", kHeld, 4, F::Planar},
    {"CAX6", kHeld, 6, F::Planar}, {"CAX6M", kHeld, 6, F::Planar},
    {"CAX8", kHeld, 8, F::Planar}, {"CAX8H", kHeld, 8, F::Planar},
    {"CAX8R", kHeld, 8, F::Planar},
    // Point inertia.
    {"MASS", kHeld, 1, F::Mass}, {"ROTARYI", kHeld, 1, F::RotaryInertia},
};

}  // namespace

const ElementTypeInfo* find_element_type(std::string_view name) {
  for (const ElementTypeInfo& info : kTypes) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::span<const ElementTypeInfo> element_types() { return kTypes; }

namespace {

// Tetrahedra (C3D4, C3D10): corners, then the mid-side nodes of the face's edges.
constexpr int kTet[4][6] = {{1, 2, 3, 5, 6, 7}, {1, 4, 2, 8, 9, 5},
                            {2, 4, 3, 9, 10, 6}, {3, 4, 1, 10, 8, 7}};
// Wedges (C3D6): two triangles and three quadrilaterals.
constexpr int kWedgeTri[2][3] = {{1, 2, 3}, {4, 6, 5}};
constexpr int kWedgeQuad[3][4] = {{1, 4, 5, 2}, {2, 5, 6, 3}, {3, 6, 4, 1}};
// Hexahedra (C3D8, C3D20): corners, then the mid-side nodes.
constexpr int kHex[6][8] = {{1, 2, 3, 4, 9, 10, 11, 12},   {5, 8, 7, 6, 16, 15, 14, 13},
                            {1, 5, 6, 2, 17, 13, 18, 9},   {2, 6, 7, 3, 18, 14, 19, 10},
                            {3, 7, 8, 4, 19, 15, 20, 11},  {4, 8, 5, 1, 20, 16, 17, 12}};
constexpr int kAllNodes[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};

int face_number(std::string_view face) {
  if (face.size() == 2 && face[0] == 'S' && face[1] >= '1' && face[1] <= '6') {
    return face[1] - '0';
  }
  return 0;
}

}  // namespace

std::span<const int> face_node_positions(const ElementTypeInfo& info, std::string_view face) {
  const bool side = face == "SPOS" || face == "SNEG";
  const int n = face_number(face);
  switch (info.family) {
    case F::Shell:
    case F::Membrane:
    case F::Rigid:
      // Surface elements of three-dimensional models: both sides hold every node.
      if (side && info.nodes <= 9 && (info.family != F::Rigid || info.name.substr(0, 3) == "R3D")) {
        return std::span<const int>(kAllNodes, static_cast<std::size_t>(info.nodes));
      }
      return {};
    case F::Solid:
      if (n == 0) return {};
      if ((info.nodes == 4 || info.nodes == 10) && n <= 4 && info.name.substr(0, 3) == "C3D") {
        return std::span<const int>(kTet[n - 1], info.nodes == 4 ? 3 : 6);
      }
      if (info.nodes == 6 && info.name.substr(0, 3) == "C3D" && n <= 5) {
        return n <= 2 ? std::span<const int>(kWedgeTri[n - 1], 3)
                      : std::span<const int>(kWedgeQuad[n - 3], 4);
      }
      if ((info.nodes == 8 || info.nodes == 20) && info.name.substr(0, 3) == "C3D") {
        return std::span<const int>(kHex[n - 1], info.nodes == 8 ? 4 : 8);
      }
      return {};
    default:
      return {};
  }
}

std::string_view element_family_name(ElementFamily family) {
  switch (family) {
    case F::Analysed: return "connector";
    case F::Solid: return "solid";
    case F::Shell: return "shell";
    case F::Membrane: return "membrane";
    case F::Rigid: return "rigid";
    case F::Beam: return "beam";
    case F::Truss: return "truss";
    case F::Planar: return "planar continuum";
    case F::Mass: return "point mass";
    case F::RotaryInertia: return "rotary inertia";
  }
  return "element";
}

}  // namespace clinch
