// The references of the meshed model around the connectors (src/model/structure_model.hpp): the
// element sets and materials of the sections of held elements, the members of surfaces and the
// instances of display bodies, and which nodes held elements use.
#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "src/model/element_library.hpp"
#include "src/model/model.hpp"
#include "src/resolve/reference_lookup.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

void resolve_section(Model& model, ElementSection& section, DiagnosticSink& sink) {
  std::vector<std::int32_t> members;
  if (!resolve_elements(model, section.elset, members, sink)) return;
  if (members.empty()) {
    sink.report(DiagCode::empty_set, section.elset.loc,
                fmt::format("{} is empty", describe(section.elset, true)));
  }
  for (std::int32_t e : members) {
    const Element& element = model.elements[static_cast<std::size_t>(e)];
    if (element.type != ElementType::Held) {
      sink.report(DiagCode::wrong_element_kind, section.elset.loc,
                  fmt::format("{} contains element {} of type {}; *{} is for solid, shell, "
                              "membrane, beam, truss and point elements",
                              describe(section.elset, true), element.label,
                              element_type_name(model, e), section.keyword));
      return;
    }
    section.elements.push_back(e);
  }
  if (section.material.empty()) return;
  StructureModel& structure = model.structure;
  auto it = structure.material_by_key.find(section.material.key);
  if (it == structure.material_by_key.end()) {
    sink.report(DiagCode::undefined_material, section.material.loc,
                fmt::format("undefined material '{}'", section.material.display));
    return;
  }
  section.material_index = it->second;
  structure.materials[static_cast<std::size_t>(it->second)].used = true;
}

void resolve_surface(Model& model, Surface& surface, DiagnosticSink& sink) {
  std::vector<std::int32_t> members;
  for (const Surface::Item& item : surface.items) {
    members.clear();
    if (surface.type == Surface::Type::Node) {
      if (!resolve_nodes(model, item.target, members, sink)) continue;
      surface.nodes.insert(surface.nodes.end(), members.begin(), members.end());
    } else {
      if (!resolve_elements(model, item.target, members, sink)) continue;
      for (std::int32_t e : members) surface.faces.push_back({e, item.face});
    }
  }
}

void resolve_display_body(Model& model, DisplayBody& body, DiagnosticSink& sink) {
  body.instance_index =
      find_instance(model, body.instance.key, body.instance.display, body.instance.loc, sink);
  std::vector<std::int32_t> nodes;
  for (const TargetRef& ref : body.reference_nodes) {
    nodes.clear();
    if (resolve_nodes(model, ref, nodes, sink)) {
      body.nodes.insert(body.nodes.end(), nodes.begin(), nodes.end());
    }
  }
}

// Every node a held element of an instance uses, MASS and ROTARYI aside (they give a node no
// DOF and are not refused).
void mark_held_nodes(Model& model) {
  std::vector<bool>& marked = model.structure.node_on_held_element;
  marked.assign(model.nodes.size(), false);
  for (const Instance& instance : model.instances) {
    for (const ElementBlock& block : model.parts[instance.part].element_blocks) {
      if (is_inertia_only(static_cast<ElementFamily>(block.family))) continue;
      for (std::int32_t n : block.nodes) {
        if (n == kGround) continue;
        // The root part's block nodes are global (instance 0 has offset 0 and qualified
        // labels are global); a part's are local to each of its instances.
        const std::int32_t global = n + instance.node_offset;
        if (global >= 0 && static_cast<std::size_t>(global) < marked.size()) {
          marked[static_cast<std::size_t>(global)] = true;
        }
      }
    }
  }
}

}  // namespace

void resolve_structure(Model& model, DiagnosticSink& sink) {
  for (ElementSection& section : model.structure.sections) resolve_section(model, section, sink);
  for (Surface& surface : model.structure.surfaces) resolve_surface(model, surface, sink);
  for (DisplayBody& body : model.structure.display_bodies) {
    resolve_display_body(model, body, sink);
  }
  mark_held_nodes(model);
}

}  // namespace clinch
