// *RIGID BODY, *KINEMATIC COUPLING and *COUPLING (*KINEMATIC, *DISTRIBUTING) into the flat lists
// the analysis eliminates (src/model/constraint_model.hpp; docs/constraints.md). Runs before the
// history is resolved, because active_dofs() reads the followers and equations.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <string_view>

#include "base/diagnostic.hpp"
#include "src/model/element_library.hpp"
#include "src/model/model.hpp"
#include "src/resolve/reference_lookup.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

constexpr DofMask kTranslations3 = 0x07, kRotations3 = 0x38;
constexpr DofMask kTranslations2 = 0x03, kRotations2 = 0x20;  // 2-D: DOFs 1, 2 and 6

DofMask translations(const Model& model) {
  return model.dimension == 2 ? kTranslations2 : kTranslations3;
}
DofMask rotations(const Model& model) {
  return model.dimension == 2 ? kRotations2 : kRotations3;
}

std::string dof_list(DofMask mask) {
  std::string out;
  for (int d = 1; d <= 6; ++d) {
    if (!(mask & (1u << (d - 1)))) continue;
    if (!out.empty()) out += ", ";
    out += std::to_string(d);
  }
  return out;
}

std::string node_name(const Model& model, std::int32_t n) {
  const Node& node = model.nodes[static_cast<std::size_t>(n)];
  return qualified_label(model, node.instance, node.label);
}

class ConstraintResolver {
 public:
  ConstraintResolver(Model& model, DiagnosticSink& sink)
      : model_(model), constraints_(model.constraints), sink_(sink) {}

  void run() {
    for (RigidBodyDefinition& body : constraints_.rigid_bodies) {
      for_each_copy(body.part, [&] { resolve_body(body); });
    }
    for (const ReferenceRecord& record : references_) check_reference_in_other_body(record);
    for (CouplingDefinition& coupling : constraints_.couplings) {
      for_each_copy(coupling.part, [&] { resolve_coupling(coupling); });
    }
  }

 private:
  // Who made a DOF of a node dependent: the source and the DOFs.
  struct Claim {
    std::int32_t source;
    DofMask dofs;
  };
  // A body's reference node, for the check that no other body holds it.
  struct ReferenceRecord {
    std::int32_t node, source;
    SourceLoc loc;
  };

  // A definition written inside a part holds for each instance of the part (input-syntax.md
  // §7): it is resolved once per instance, its references narrowed to that instance's copies.
  // After an error in one copy the others are left out (they would repeat it).
  template <typename F>
  void for_each_copy(std::int32_t part, F resolve) {
    if (part == 0) {
      instance_ = -1;
      resolve();
      return;
    }
    for (std::size_t i = 1; i < model_.instances.size(); ++i) {
      if (model_.instances[i].part != part) continue;
      instance_ = static_cast<std::int32_t>(i);
      const std::size_t errors = sink_.error_count();
      resolve();
      if (sink_.error_count() != errors) break;
    }
    instance_ = -1;
  }

  // The nodes (elements) a reference denotes, narrowed to the instance being resolved.
  bool nodes_of(const TargetRef& ref, std::vector<std::int32_t>& out) {
    if (!resolve_nodes(model_, ref, out, sink_)) return false;
    narrow(out, false);
    return true;
  }
  bool elements_of(const TargetRef& ref, std::vector<std::int32_t>& out) {
    if (!resolve_elements(model_, ref, out, sink_)) return false;
    narrow(out, true);
    return true;
  }
  void narrow(std::vector<std::int32_t>& v, bool elements) const {
    if (instance_ < 0) return;
    std::erase_if(v, [&](std::int32_t i) {
      const std::int32_t owner = elements ? model_.elements[static_cast<std::size_t>(i)].instance
                                          : model_.nodes[static_cast<std::size_t>(i)].instance;
      return owner != instance_;
    });
  }

  std::int32_t add_source(std::string keyword, SourceLoc loc) {
    constraints_.sources.push_back({std::move(keyword), loc});
    return static_cast<std::int32_t>(constraints_.sources.size()) - 1;
  }

  // Records that `source` makes `dofs` of `node` dependent; false (reported) when another
  // definition already does: a DOF tied twice (the manual's rigid body: "a node cannot appear
  // in more than one rigid body definition"; a kinematic coupling node likewise).
  bool claim(std::int32_t node, DofMask dofs, std::int32_t source) {
    auto& list = claims_[node];
    for (const Claim& other : list) {
      const DofMask both = static_cast<DofMask>(other.dofs & dofs);
      if (!both || other.source == source) continue;
      const ConstraintSource& here = constraints_.sources[static_cast<std::size_t>(source)];
      const ConstraintSource& there = constraints_.sources[static_cast<std::size_t>(other.source)];
      sink_
          .report(DiagCode::constraint_conflict, here.loc,
                  fmt::format("node {} is already constrained by {} {} (DOF{} {}); a DOF can "
                              "follow one definition only",
                              node_name(model_, node),
                              there.keyword == here.keyword ? "another" : "a", there.keyword,
                              std::has_single_bit(both) ? "" : "s", dof_list(both)))
          .notes.push_back({there.loc, fmt::format("the {} is here", there.keyword)});
      return false;
    }
    list.push_back({source, dofs});
    return true;
  }

  // REF NODE= and ROT NODE=: a node, or a node set of exactly one node.
  std::int32_t single_node(const TargetRef& ref, std::string_view param) {
    std::vector<std::int32_t> nodes;
    if (!nodes_of(ref, nodes)) return -1;
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    if (nodes.size() != 1) {
      sink_.report(DiagCode::invalid_value, ref.loc,
                   fmt::format("{} must name one node; {} holds {}", param, describe(ref, false),
                               nodes.size()));
      return -1;
    }
    return nodes[0];
  }

  // The nodes of global element `e` (held elements), or false for an analysed element.
  bool element_nodes(std::int32_t e, std::vector<std::int32_t>& out) const {
    const Element& element = model_.elements[static_cast<std::size_t>(e)];
    if (element.type != ElementType::Held) return false;
    const Instance& instance = model_.instances[static_cast<std::size_t>(element.instance)];
    const Part& part = model_.parts[static_cast<std::size_t>(instance.part)];
    const std::int32_t local = e - instance.element_offset;
    const ElementBlock* block = part.block_of(local);
    if (!block) return false;
    for (std::int32_t n : block->element_nodes(local - block->first_element)) {
      if (n != kGround) out.push_back(n + instance.node_offset);
    }
    return true;
  }

  bool collect_nodes(const std::optional<TargetRef>& ref, std::vector<std::int32_t>& out) {
    if (!ref) return true;
    std::vector<std::int32_t> nodes;
    if (!nodes_of(*ref, nodes)) return false;
    if (nodes.empty()) {
      sink_.report(DiagCode::empty_set, ref->loc, fmt::format("{} is empty", describe(*ref, false)));
      return false;
    }
    out.insert(out.end(), nodes.begin(), nodes.end());
    return true;
  }

  static void sort_unique(std::vector<std::int32_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }

  void resolve_body(RigidBodyDefinition& body) {
    bool ok = true;
    if (body.ref_node) body.reference = single_node(*body.ref_node, "REF NODE");
    if (body.rot_node) body.rotation_node = single_node(*body.rot_node, "ROT NODE");
    ok = body.reference >= 0 && (!body.rot_node || body.rotation_node >= 0);
    std::vector<std::int32_t> tie, pin;
    std::vector<std::int32_t> elements;
    if (body.elset) {
      if (!elements_of(*body.elset, elements)) {
        ok = false;
      } else if (elements.empty()) {
        sink_.report(DiagCode::empty_set, body.elset->loc,
                     fmt::format("{} is empty", describe(*body.elset, true)));
        ok = false;
      }
      for (std::int32_t e : elements) {
        if (element_nodes(e, tie)) continue;
        const Element& element = model_.elements[static_cast<std::size_t>(e)];
        sink_.report(DiagCode::wrong_element_kind, body.elset->loc,
                     fmt::format("{} contains element {} of type {}: clinch analyses connectors, "
                                 "springs and dashpots as deformable, so they cannot be part of a "
                                 "rigid body; join them to a node of the body instead",
                                 describe(*body.elset, true), element.label,
                                 element_type_name(model_, e)));
        ok = false;
        break;
      }
    }
    ok = collect_nodes(body.tie_nset, tie) && ok;
    ok = collect_nodes(body.nset, tie) && ok;
    ok = collect_nodes(body.pin_nset, pin) && ok;
    if (!ok) return;
    body.elements.insert(body.elements.end(), elements.begin(), elements.end());
    sort_unique(tie);
    sort_unique(pin);
    // A PIN NSET node redefines a node of the ELSET's elements as a pin node (the manual's
    // *RIGID BODY, PIN NSET); a node named in both PIN NSET and TIE NSET is ambiguous.
    if (body.tie_nset || body.nset) {
      std::vector<std::int32_t> named_tie;
      collect_nodes(body.tie_nset, named_tie);
      collect_nodes(body.nset, named_tie);
      for (std::int32_t n : named_tie) {
        if (std::binary_search(pin.begin(), pin.end(), n)) {
          sink_.report(DiagCode::constraint_conflict, body.pin_nset->loc,
                       fmt::format("node {} is in both PIN NSET and {} of this rigid body; name "
                                   "it in one of them",
                                   node_name(model_, n), body.tie_nset ? "TIE NSET" : "NSET"));
          return;
        }
      }
    }
    std::vector<std::int32_t> tie_only;
    std::set_difference(tie.begin(), tie.end(), pin.begin(), pin.end(),
                        std::back_inserter(tie_only));
    // The reference node cannot follow itself: when the body's sets hold it, it is left out.
    auto drop_reference = [&](std::vector<std::int32_t>& v) {
      v.erase(std::remove(v.begin(), v.end(), body.reference), v.end());
    };
    drop_reference(tie_only);
    drop_reference(pin);
    body.tie_nodes = std::move(tie_only);
    body.pin_nodes = std::move(pin);
    if (body.rotation_node >= 0 && (body.rotation_node == body.reference ||
                                    std::binary_search(body.tie_nodes.begin(),
                                                       body.tie_nodes.end(), body.rotation_node) ||
                                    std::binary_search(body.pin_nodes.begin(),
                                                       body.pin_nodes.end(), body.rotation_node))) {
      sink_.report(DiagCode::constraint_conflict, body.rot_node->loc,
                   fmt::format("ROT NODE {} must be a node of its own, neither the reference "
                               "node nor a node of the body",
                               node_name(model_, body.rotation_node)));
      return;
    }
    if (body.rotation_node >= 0 && model_.dimension == 2) {
      // The rotation about z would be the ROT NODE's third translation, which a
      // two-dimensional model does not have.
      sink_.report(DiagCode::unsupported_option, body.rot_node->loc,
                   "ROT NODE is not supported in a two-dimensional model (its third translation "
                   "would carry the rotation); leave it out: the reference node's rotation is "
                   "DOF 6");
      return;
    }
    const std::int32_t source = add_source("*RIGID BODY", body.keyword_loc);
    const DofMask all = static_cast<DofMask>(translations(model_) | rotations(model_));
    for (std::int32_t n : body.tie_nodes) add_follower(n, body.reference, all, source);
    for (std::int32_t n : body.pin_nodes) {
      add_follower(n, body.reference, translations(model_), source);
    }
    references_.push_back({body.reference, source, body.ref_node->loc});
    if (body.rotation_node >= 0) add_rotation_node(body, source);
  }

  void add_follower(std::int32_t node, std::int32_t reference, DofMask dofs,
                    std::int32_t source) {
    if (!claim(node, dofs, source)) return;
    constraints_.followers.push_back({node, reference, dofs, true, source});
  }

  // CalculiX's ROT NODE: its translations are the body's rotations, θ_ref,k − u_rot,k = 0, so
  // that the reference node's rotations are eliminated in favour of them.
  void add_rotation_node(const RigidBodyDefinition& body, std::int32_t source) {
    for (int k = 0; k < 3; ++k) {
      const int rotation = 4 + k, translation = 1 + k;
      if (!claim(body.reference, static_cast<DofMask>(1u << (rotation - 1)), source)) return;
      LinearConstraint equation;
      equation.terms = {{body.reference, rotation, 1.0}, {body.rotation_node, translation, -1.0}};
      equation.exact_under_nlgeom = false;
      equation.source = source;
      constraints_.equations.push_back(std::move(equation));
    }
  }

  // A reference node of one body that is a node of another body appears in two rigid body
  // definitions, which the manual's *RIGID BODY forbids.
  void check_reference_in_other_body(const ReferenceRecord& record) {
    auto it = claims_.find(record.node);
    if (it == claims_.end()) return;
    for (const Claim& other : it->second) {
      if (other.source == record.source) continue;
      const ConstraintSource& there = constraints_.sources[static_cast<std::size_t>(other.source)];
      sink_
          .report(DiagCode::constraint_conflict, record.loc,
                  fmt::format("the reference node {} of this rigid body is a node of another {}; "
                              "a node can belong to one rigid body only",
                              node_name(model_, record.node), there.keyword))
          .notes.push_back({there.loc, fmt::format("the {} is here", there.keyword)});
      return;
    }
  }

  // ---------------------------------------------------------------------------------------
  // Couplings

  // The DOFs of a coupling's ranges (none: every DOF), within the model's DOFs.
  DofMask coupling_dofs(const std::vector<DofRange>& ranges) const {
    const DofMask available = static_cast<DofMask>(translations(model_) | rotations(model_));
    if (ranges.empty()) return available;
    DofMask mask = 0;
    for (const DofRange& range : ranges) {
      for (int d = range.first; d <= range.last; ++d) mask |= static_cast<DofMask>(1u << (d - 1));
    }
    return static_cast<DofMask>(mask & available);
  }

  // The surface SURFACE= names: in the coupling's scope, or "Instance.Surface" at assembly level
  // (then only that instance's nodes). −1 (reported) when there is none.
  const Surface* find_surface(const CouplingDefinition& coupling, std::int32_t& instance) {
    const StructureModel& structure = model_.structure;
    const Name& name = *coupling.surface;
    auto it = structure.surface_by_key.find(scoped_name_key(coupling.part, name.key));
    if (it == structure.surface_by_key.end()) {
      const std::size_t dot = name.key.rfind('.');
      if (coupling.part == 0 && dot != std::string::npos) {
        auto inst = model_.instance_by_key.find(name.key.substr(0, dot));
        if (inst != model_.instance_by_key.end()) {
          instance = inst->second;
          const std::int32_t part = model_.instances[static_cast<std::size_t>(instance)].part;
          it = structure.surface_by_key.find(scoped_name_key(part, name.key.substr(dot + 1)));
        }
      }
    }
    if (it == structure.surface_by_key.end()) {
      sink_.report(DiagCode::undefined_surface, name.loc,
                   fmt::format("undefined surface '{}'", name.display));
      return nullptr;
    }
    return &structure.surfaces[static_cast<std::size_t>(it->second)];
  }

  // The nodes of a surface with their area factors (TYPE=NODE: the data line's area, 1 by
  // default; TYPE=ELEMENT: the face nodes, factor 0 for "not known"). False after a report.
  bool surface_nodes(const CouplingDefinition& coupling, const Surface& surface,
                     std::int32_t instance, std::vector<std::int32_t>& nodes,
                     std::vector<double>& areas) {
    if (surface.type == Surface::Type::Node) {
      std::vector<std::int32_t> members;
      for (const Surface::Item& item : surface.items) {
        members.clear();
        if (!nodes_of(item.target, members)) return false;
        for (std::int32_t n : members) {
          nodes.push_back(n);
          areas.push_back(item.area);
        }
      }
    } else {
      if (coupling.kind == CouplingDefinition::Kind::Distributing) {
        // The manual weighs each node of an element-based surface by its tributary area;
        // clinch does not integrate face areas.
        sink_.report(DiagCode::unsupported_option, coupling.surface->loc,
                     fmt::format("{}: a distributing coupling on an element-based surface is not "
                                 "supported by clinch (its weights need the faces' tributary "
                                 "areas); use a node-based surface (*SURFACE, TYPE=NODE)",
                                 coupling.display()));
        return false;
      }
      for (const Surface::Face& face : surface.faces) {
        if (!face_nodes(face, surface, nodes)) return false;
      }
      areas.assign(nodes.size(), 1.0);
    }
    if (instance >= 0) {
      std::vector<std::int32_t> kept_nodes;
      std::vector<double> kept_areas;
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (model_.nodes[static_cast<std::size_t>(nodes[i])].instance != instance) continue;
        kept_nodes.push_back(nodes[i]);
        kept_areas.push_back(areas[i]);
      }
      nodes = std::move(kept_nodes);
      areas = std::move(kept_areas);
    }
    return true;
  }

  bool face_nodes(const Surface::Face& face, const Surface& surface,
                  std::vector<std::int32_t>& out) {
    const Element& element = model_.elements[static_cast<std::size_t>(face.element)];
    const Instance& instance = model_.instances[static_cast<std::size_t>(element.instance)];
    const Part& part = model_.parts[static_cast<std::size_t>(instance.part)];
    const std::int32_t local = face.element - instance.element_offset;
    const ElementBlock* block = part.block_of(local);
    const ElementTypeInfo* info = block ? find_element_type(block->type) : nullptr;
    std::span<const int> positions =
        info ? face_node_positions(*info, face.face) : std::span<const int>();
    if (positions.empty()) {
      sink_.report(DiagCode::unsupported_option, surface.keyword_loc,
                   fmt::format("surface '{}': clinch does not know the nodes of face '{}' of "
                               "element {} (type {}); name the faces S1-S6 of C3D4/6/8/10/20 "
                               "elements or SPOS/SNEG of shells and R3D3/R3D4, or use a "
                               "node-based surface",
                               surface.name.display, face.face.empty() ? "(exterior)" : face.face,
                               element.label, element_type_name(model_, face.element)));
      return false;
    }
    auto nodes = block->element_nodes(local - block->first_element);
    for (int p : positions) {
      const std::int32_t n = nodes[static_cast<std::size_t>(p - 1)];
      if (n != kGround) out.push_back(n + instance.node_offset);
    }
    return true;
  }

  void resolve_coupling(CouplingDefinition& coupling) {
    if (coupling.refused) return;
    if (coupling.kind != CouplingDefinition::Kind::KinematicCoupling && !coupling.method_given) {
      sink_.report(DiagCode::missing_parameter, coupling.keyword_loc,
                   fmt::format("{} needs *KINEMATIC or *DISTRIBUTING right after it",
                               coupling.display()));
      return;
    }
    coupling.reference = single_node(*coupling.ref_node, "REF NODE");
    if (coupling.reference < 0) return;
    std::vector<std::int32_t> nodes;
    std::vector<double> areas;
    std::vector<DofMask> masks;  // *KINEMATIC COUPLING: per node line
    if (coupling.kind == CouplingDefinition::Kind::KinematicCoupling) {
      std::vector<std::int32_t> members;
      for (const auto& line : coupling.node_lines) {
        members.clear();
        if (!nodes_of(line.target, members)) return;
        const DofMask mask = coupling_dofs({line.dofs});
        for (std::int32_t n : members) {
          nodes.push_back(n);
          masks.push_back(mask);
        }
      }
    } else {
      std::int32_t instance = instance_;
      const Surface* surface = find_surface(coupling, instance);
      if (!surface || !surface_nodes(coupling, *surface, instance, nodes, areas)) return;
    }
    const SourceLoc where = coupling.kind == CouplingDefinition::Kind::KinematicCoupling
                                ? coupling.keyword_loc
                                : coupling.surface->loc;
    // The coupling nodes: within INFLUENCE RADIUS of the reference node, the reference node
    // itself left out, each once (a node on several faces or lines: its DOFs joined).
    const Vec3 x_ref = model_.nodes[static_cast<std::size_t>(coupling.reference)].x;
    std::map<std::int32_t, std::pair<DofMask, double>> chosen;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (nodes[i] == coupling.reference) continue;
      if (coupling.influence_radius &&
          distance(model_.nodes[static_cast<std::size_t>(nodes[i])].x, x_ref) >
              *coupling.influence_radius) {
        continue;
      }
      auto [it, inserted] = chosen.try_emplace(
          nodes[i], masks.empty() ? DofMask{0} : masks[i], areas.empty() ? 1.0 : areas[i]);
      if (!inserted && !masks.empty()) it->second.first |= masks[i];
    }
    if (chosen.empty()) {
      sink_.report(DiagCode::degenerate_coupling, where,
                   fmt::format("{} has no coupling node{}", coupling.display(),
                               coupling.influence_radius ? " within its INFLUENCE RADIUS" : ""));
      return;
    }
    const std::int32_t source =
        add_source(coupling.kind == CouplingDefinition::Kind::KinematicCoupling
                       ? "*KINEMATIC COUPLING"
                       : coupling.display(),
                   coupling.keyword_loc);
    for (const auto& [n, entry] : chosen) {
      coupling.nodes.push_back(n);
      coupling.weights.push_back(entry.second);
    }
    if (coupling.kind == CouplingDefinition::Kind::Distributing) {
      build_distributing(coupling, source);
      return;
    }
    const DofMask method_dofs = coupling_dofs(coupling.dof_ranges);
    if (coupling.orientation && !find_orientation(coupling)) return;
    if (coupling.orientation) {
      // The DOFs in a local system are the same set as in the global one only for all
      // translations, all rotations or all six (the manual's *KINEMATIC COUPLING, ORIENTATION).
      DofMask used = 0;
      if (coupling.kind == CouplingDefinition::Kind::KinematicCoupling) {
        for (const auto& [n, entry] : chosen) used |= entry.first;
      } else {
        used = method_dofs;
      }
      const DofMask t = translations(model_), r = rotations(model_);
      bool uniform = true;
      if (coupling.kind == CouplingDefinition::Kind::KinematicCoupling) {
        for (const auto& [n, entry] : chosen) uniform = uniform && entry.first == used;
      }
      if (!uniform || (used != t && used != r && used != (t | r))) {
        sink_.report(DiagCode::unsupported_option, coupling.orientation_loc,
                     fmt::format("ORIENTATION with DOFs {} is not supported by clinch: a local "
                                 "system matters only when some but not all translations or "
                                 "rotations are coupled; couple all translations, all rotations "
                                 "or all six",
                                 dof_list(used)));
        return;
      }
    }
    for (const auto& [n, entry] : chosen) {
      const DofMask mask =
          coupling.kind == CouplingDefinition::Kind::KinematicCoupling ? entry.first : method_dofs;
      if (mask) add_follower(n, coupling.reference, mask, source);
    }
  }

  // The *ORIENTATION that ORIENTATION= names (in the coupling's scope), marked used; false after
  // reporting an undefined one.
  bool find_orientation(const CouplingDefinition& coupling) {
    SectionModel& sections = model_.sections;
    auto it = sections.orientation_by_key.find(
        scoped_name_key(coupling.part, coupling.orientation->key));
    if (it == sections.orientation_by_key.end()) {
      sink_.report(DiagCode::undefined_orientation, coupling.orientation->loc,
                   fmt::format("undefined orientation '{}'", coupling.orientation->display));
      return false;
    }
    sections.orientations[static_cast<std::size_t>(it->second)].used = true;
    return true;
  }

  static double distance(const Vec3& a, const Vec3& b) {
    return length_of({a[0] - b[0], a[1] - b[1], a[2] - b[2]});
  }

  // The distributing coupling (the manual's "Distributing coupling elements", load distribution,
  // linearised): with normalised weights ŵ_n, centroid x̄ = Σ ŵ_n x_n, arms r_n = x_n − x̄,
  // r_R = x_R − x̄ and T = Σ ŵ_n (|r_n|² I − r_n r_nᵀ), the force distribution
  // F_n = ŵ_n (F_R + (T⁻¹ (M_R + r_R × F_R)) × r_n) is, by virtual work, the motion
  //   θ_R = Θ = T⁻¹ Σ ŵ_n r_n × u_n,   u_R = Σ ŵ_n u_n + Θ × r_R.
  // Each reference DOF becomes one LinearConstraint (first term the reference DOF).
  void build_distributing(const CouplingDefinition& coupling, std::int32_t source) {
    const Vec3 x_ref = model_.nodes[static_cast<std::size_t>(coupling.reference)].x;
    const std::size_t count = coupling.nodes.size();
    std::vector<Vec3> x(count);
    std::vector<double> w(count);
    double r0 = coupling.influence_radius.value_or(0.0);
    for (std::size_t i = 0; i < count; ++i) {
      x[i] = model_.nodes[static_cast<std::size_t>(coupling.nodes[i])].x;
      if (!coupling.influence_radius) r0 = std::max(r0, distance(x[i], x_ref));
    }
    // The weighting methods of the manual's "Coupling constraints" (r: distance from the
    // reference node, r0: the influence radius, or the distance of the farthest coupling node).
    for (std::size_t i = 0; i < count; ++i) {
      const double q = r0 > 0 ? distance(x[i], x_ref) / r0 : 0.0;
      double factor = 1.0;
      switch (coupling.weighting) {
        case CouplingDefinition::Weighting::Uniform: factor = 1.0; break;
        case CouplingDefinition::Weighting::Linear: factor = 1.0 - q; break;
        case CouplingDefinition::Weighting::Quadratic: factor = 1.0 - q * q; break;
        case CouplingDefinition::Weighting::Cubic: factor = 1.0 - 3 * q * q + 2 * q * q * q; break;
      }
      w[i] = std::max(0.0, factor) * coupling.weights[i];
    }
    double total = 0;
    for (double wi : w) total += wi;
    if (!(total > 0)) {
      sink_.report(DiagCode::degenerate_coupling, coupling.keyword_loc,
                   fmt::format("{}: every coupling node has weight 0", coupling.display()));
      return;
    }
    Vec3 centroid{};
    for (std::size_t i = 0; i < count; ++i) {
      w[i] /= total;
      for (int k = 0; k < 3; ++k) centroid[k] += w[i] * x[i][k];
    }
    std::vector<Vec3> r(count);
    Mat3 t{};
    double scale = 0;
    for (std::size_t i = 0; i < count; ++i) {
      for (int k = 0; k < 3; ++k) r[i][k] = x[i][k] - centroid[k];
      const double rr = r[i][0] * r[i][0] + r[i][1] * r[i][1] + r[i][2] * r[i][2];
      scale = std::max(scale, rr);
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) t[a][b] += w[i] * ((a == b ? rr : 0.0) - r[i][a] * r[i][b]);
      }
    }
    const Vec3 r_ref{x_ref[0] - centroid[0], x_ref[1] - centroid[1], x_ref[2] - centroid[2]};
    const bool two_d = model_.dimension == 2;
    const DofMask dofs = static_cast<DofMask>(coupling_dofs(coupling.dof_ranges) |
                                              translations(model_));
    const bool wants_rotation = (dofs & rotations(model_)) != 0;
    const double tol = geometry_tolerance(model_.nodes);
    const bool offset = length_of(r_ref) > tol;
    // B_n = ŵ_n T⁻¹ [r_n]×: Θ = Σ B_n u_n. In 2-D only Θ_3 = Σ ŵ_n (r_n × u_n)_3 / T_33.
    std::vector<Mat3> b(count, Mat3{});
    if (wants_rotation || offset) {
      Mat3 inverse{};
      if (!invert(t, scale, two_d, inverse)) {
        sink_.report(DiagCode::degenerate_coupling, coupling.keyword_loc,
                     fmt::format("{}: its coupling nodes {} (T = Σ w r rᵀ is singular), so the "
                                 "{} cannot follow them; add coupling nodes off that line, or "
                                 "release the rotations and place the reference node at their "
                                 "centroid",
                                 coupling.display(),
                                 count == 1 ? "are one node" : "lie on one line",
                                 wants_rotation ? "rotations of the reference node"
                                                : "offset reference node"));
        return;
      }
      for (std::size_t i = 0; i < count; ++i) {
        const Mat3 skew{{{0, -r[i][2], r[i][1]}, {r[i][2], 0, -r[i][0]}, {-r[i][1], r[i][0], 0}}};
        for (int a = 0; a < 3; ++a) {
          for (int c = 0; c < 3; ++c) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += inverse[a][k] * skew[k][c];
            b[i][a][c] = w[i] * sum;
          }
        }
      }
    }
    const int n_translations = two_d ? 2 : 3;
    // Translations: u_R = Σ (ŵ_n I − [r_R]× B_n) u_n.
    const Mat3 skew_ref{{{0, -r_ref[2], r_ref[1]}, {r_ref[2], 0, -r_ref[0]},
                         {-r_ref[1], r_ref[0], 0}}};
    for (int k = 0; k < n_translations; ++k) {
      LinearConstraint equation = reference_term(coupling.reference, k + 1, source);
      for (std::size_t i = 0; i < count; ++i) {
        for (int j = 0; j < n_translations; ++j) {
          double c = k == j ? w[i] : 0.0;
          if (offset) {
            for (int m = 0; m < 3; ++m) c -= skew_ref[k][m] * b[i][m][j];
          }
          add_term(equation, coupling.nodes[i], j + 1, c);
        }
      }
      finish_equation(std::move(equation), coupling.reference, k + 1, source);
    }
    // Rotations asked for: θ_R = Σ B_n u_n.
    for (int k = 3; k < 6; ++k) {
      if (!(dofs & (1u << k)) || (two_d && k != 5)) continue;
      LinearConstraint equation = reference_term(coupling.reference, k + 1, source);
      for (std::size_t i = 0; i < count; ++i) {
        for (int j = 0; j < n_translations; ++j) {
          add_term(equation, coupling.nodes[i], j + 1, b[i][k - 3][j]);
        }
      }
      finish_equation(std::move(equation), coupling.reference, k + 1, source);
    }
  }

  // T⁻¹ (3-D), or in 2-D the inverse of T_33 alone; false when T is singular relative to
  // `scale` (the largest |r|², so that the test does not depend on units).
  static bool invert(const Mat3& t, double scale, bool two_d, Mat3& out) {
    constexpr double kSingular = 1e-10;
    if (!(scale > 0)) return false;
    if (two_d) {
      if (t[2][2] <= kSingular * scale) return false;
      out = Mat3{};
      out[2][2] = 1.0 / t[2][2];
      return true;
    }
    const double det = t[0][0] * (t[1][1] * t[2][2] - t[1][2] * t[2][1]) -
                       t[0][1] * (t[1][0] * t[2][2] - t[1][2] * t[2][0]) +
                       t[0][2] * (t[1][0] * t[2][1] - t[1][1] * t[2][0]);
    if (!(std::abs(det) > kSingular * scale * scale * scale)) return false;
    for (int a = 0; a < 3; ++a) {
      for (int c = 0; c < 3; ++c) {
        const int a1 = (c + 1) % 3, a2 = (c + 2) % 3, c1 = (a + 1) % 3, c2 = (a + 2) % 3;
        out[a][c] = (t[a1][c1] * t[a2][c2] - t[a1][c2] * t[a2][c1]) / det;
      }
    }
    return true;
  }

  static LinearConstraint reference_term(std::int32_t reference, int dof, std::int32_t source) {
    LinearConstraint equation;
    equation.terms.push_back({reference, dof, 1.0});
    equation.exact_under_nlgeom = false;
    equation.source = source;
    return equation;
  }

  // Σ … − c u_n,j: the coupling-node terms carry the coefficients with their sign flipped.
  static void add_term(LinearConstraint& equation, std::int32_t node, int dof, double c) {
    if (c != 0.0) equation.terms.push_back({node, dof, -c});
  }

  void finish_equation(LinearConstraint equation, std::int32_t reference, int dof,
                       std::int32_t source) {
    // Round-off terms (|c| below 1e-14 of the largest) are dropped: they are zero in exact
    // arithmetic (e.g. the cross terms of a symmetric pattern).
    double largest = 0;
    for (std::size_t i = 1; i < equation.terms.size(); ++i) {
      largest = std::max(largest, std::abs(equation.terms[i].coefficient));
    }
    std::erase_if(equation.terms, [&](const LinearTerm& term) {
      return std::abs(term.coefficient) < 1e-14 * largest;
    });
    if (!claim(reference, static_cast<DofMask>(1u << (dof - 1)), source)) return;
    constraints_.equations.push_back(std::move(equation));
  }

  Model& model_;
  ConstraintModel& constraints_;
  DiagnosticSink& sink_;
  std::map<std::int32_t, std::vector<Claim>> claims_;
  std::vector<ReferenceRecord> references_;  // every body's (each instance's copy)
  std::int32_t instance_ = -1;  // the instance a part-level definition is resolved for
};

}  // namespace

void resolve_rigid_bodies(Model& model, DiagnosticSink& sink) {
  ConstraintResolver(model, sink).run();
}

}  // namespace clinch
