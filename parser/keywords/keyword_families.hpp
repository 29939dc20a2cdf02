// One function per keyword family: each returns the KeywordSpecs (parameters, data mode, handler)
// of its keywords. The registry concatenates them.
#pragma once

#include <vector>

#include "parser/keyword_spec.hpp"

namespace clinch {

// *HEADING and the keywords of input-syntax.md §9 (no effect), and the known-but-unsupported
// keywords of §9 (E0202).
std::vector<KeywordSpec> general_keyword_specs();
// *NODE, *ELEMENT, *NSET, *ELSET, *PART, *ASSEMBLY, *INSTANCE and their ends (node_element.cpp,
// sets.cpp, parts_assembly.cpp).
std::vector<KeywordSpec> geometry_keyword_specs();
// *ORIENTATION, *CONNECTOR SECTION, *SPRING, *SECTION CONTROLS.
std::vector<KeywordSpec> section_keyword_specs();
// The sections of held elements, *MATERIAL and its sub-options, *SURFACE, *DISPLAY BODY
// (structure.cpp).
std::vector<KeywordSpec> structure_keyword_specs();
// *RIGID BODY (rigid_body.cpp).
std::vector<KeywordSpec> rigid_body_keyword_specs();
// *KINEMATIC COUPLING, *COUPLING, *KINEMATIC, *DISTRIBUTING (coupling.cpp).
std::vector<KeywordSpec> coupling_keyword_specs();
// *MPC, *EQUATION (mpc_equation.cpp).
std::vector<KeywordSpec> mpc_equation_keyword_specs();
// *CONNECTOR BEHAVIOR and its sub-options except derived components, potentials and friction.
std::vector<KeywordSpec> behavior_keyword_specs();
// *CONNECTOR DERIVED COMPONENT, *CONNECTOR POTENTIAL, *CONNECTOR FRICTION, *FRICTION.
std::vector<KeywordSpec> potential_friction_keyword_specs();
// *AMPLITUDE, *STEP, *END STEP, *STATIC, *CONTROLS, *BOUNDARY, *CLOAD, *CONNECTOR MOTION,
// *CONNECTOR LOAD, *OUTPUT, *ELEMENT OUTPUT, *NODE OUTPUT, *NODE PRINT, *EL PRINT.
std::vector<KeywordSpec> history_keyword_specs();

}  // namespace clinch
