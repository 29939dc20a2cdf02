// The model: plain data for everything a deck defines. The parser fills it; the validators and,
// later, the analysis plan read it. Nothing here reads deck text.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "src/model/behavior_model.hpp"
#include "src/model/constraint_model.hpp"
#include "src/model/geometry.hpp"
#include "src/model/history_model.hpp"
#include "src/model/section_model.hpp"
#include "src/model/structure_model.hpp"

namespace clinch {

struct Model {
  // Geometry. parts[0] and instances[0] are the root (flat deck or assembly level).
  std::vector<Part> parts;
  std::vector<Instance> instances;
  bool part_assembly = false;  // the deck uses *PART/*ASSEMBLY
  std::unordered_map<std::string, std::int32_t> part_by_key;
  std::unordered_map<std::string, std::int32_t> instance_by_key;

  // Global numbering, filled by resolve_geometry() (src/resolve/): every node and element of
  // every instance.
  std::vector<Node> nodes;
  std::vector<Element> elements;
  int dimension = 3;  // 2 when the model has CONN2D2 elements (keywords.md, DOF numbering)

  std::string heading;  // first *HEADING data line

  SectionModel sections;
  StructureModel structure;  // sections, materials, surfaces of held elements
  ConstraintModel constraints;  // rigid bodies, couplings, MPCs, equations
  BehaviorModel behaviors;
  HistoryModel history;

  Model();
};

}  // namespace clinch
