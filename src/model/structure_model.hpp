// Plain data for what surrounds the connectors in a meshed model: the sections of held elements
// (*SOLID, *SHELL, *MEMBRANE, *BEAM, *TRUSS SECTION, *MASS, *ROTARY INERTIA), *MATERIAL with its
// options, *SURFACE and *DISPLAY BODY (keywords.md). clinch reads and keeps them so that a later
// rigid body can carry the elements; none of them enters an analysis today. The reader fills what
// the deck says; resolve_structure fills the fields marked "resolved".
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "src/model/name.hpp"
#include "src/model/references.hpp"

namespace clinch {

// One data line of numbers as read (an empty field is kept as 0 with `given` false).
struct NumberRow {
  SourceLoc loc;
  std::vector<double> values;
  std::vector<bool> given;
};

// A parameter as written on a keyword line (canonical name, value text; empty for a flag).
struct KeptParameter {
  std::string name;
  std::string value;
};

// A sub-option of *MATERIAL: *ELASTIC, *DENSITY, *PLASTIC, *EXPANSION, *DAMPING, ...
struct MaterialOption {
  std::string keyword;  // canonical, e.g. "ELASTIC"
  SourceLoc loc;
  std::vector<KeptParameter> parameters;
  std::vector<NumberRow> rows;
};

struct Material {
  Name name;
  SourceLoc keyword_loc;
  std::vector<MaterialOption> options;
  bool used = false;  // named by a section (resolved)
};

// A section of held elements.
struct ElementSection {
  enum class Kind : std::uint8_t { Solid, Shell, Membrane, Beam, Truss, Mass, RotaryInertia };
  Kind kind = Kind::Solid;
  std::string keyword;  // canonical, e.g. "SOLID SECTION" (messages)
  SourceLoc keyword_loc;
  TargetRef elset;
  Name material;  // MATERIAL= (empty for *MASS, *ROTARY INERTIA and a beam of SECTION= given
                  // with its own data)
  std::vector<KeptParameter> parameters;  // every other parameter (SECTION=, ORIENTATION=, ...)
  std::vector<NumberRow> rows;            // data lines
  // Resolved.
  std::int32_t material_index = -1;
  std::vector<std::int32_t> elements;  // global element indices
};

// *SURFACE: TYPE=ELEMENT (element or element set with a face S1…S6, SPOS, SNEG, or none for the
// whole exterior) or TYPE=NODE (node or node set with an optional area).
struct Surface {
  enum class Type : std::uint8_t { Element, Node };
  Name name;
  SourceLoc keyword_loc;
  std::int32_t part = 0;  // scope, as for sets
  Type type = Type::Element;
  struct Item {
    TargetRef target;
    std::string face;  // TYPE=ELEMENT: "S1"…"S6", "SPOS", "SNEG" ("" for the exterior)
    double area = 1.0;  // TYPE=NODE: the optional second field
  };
  std::vector<Item> items;
  // Resolved: TYPE=ELEMENT faces (global element, face), TYPE=NODE global nodes.
  struct Face {
    std::int32_t element;
    std::string face;
  };
  std::vector<Face> faces;
  std::vector<std::int32_t> nodes;
};

// *DISPLAY BODY: an instance shown as a rigid display body that follows up to three nodes.
struct DisplayBody {
  SourceLoc keyword_loc;
  Name instance;  // INSTANCE=
  std::vector<TargetRef> reference_nodes;
  // Resolved.
  std::int32_t instance_index = -1;
  std::vector<std::int32_t> nodes;
};

struct StructureModel {
  std::vector<ElementSection> sections;
  std::vector<Material> materials;
  std::unordered_map<std::string, std::int32_t> material_by_key;  // model-wide names
  std::vector<Surface> surfaces;
  std::unordered_map<std::string, std::int32_t> surface_by_key;  // scoped_name_key(part, key)
  std::vector<DisplayBody> display_bodies;
  // Resolved: per global node, whether a held element other than MASS and ROTARYI uses it.
  // Such an element is refused while deformable, so a condition on its node is not reported
  // again (a rigid body will give the node its DOFs).
  std::vector<bool> node_on_held_element;
};

}  // namespace clinch
