// resolve_sections (resolve.hpp): the rules of keywords.md §3–§7 and connection-types.md §1–§2
// that need the complete geometry. Resolves the element sets of *CONNECTOR SECTION and *SPRING,
// fills section_of_element / spring_of_element, resolves BEHAVIOR=, CONTROLS= and orientation
// names, applies the CONN2D2 rules, and gives the check-time warnings of connection-types.md §2.2.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <tuple>

#include "base/diagnostic.hpp"
#include "base/fold_name.hpp"
#include "base/suggest.hpp"
#include "src/model/connection_types.hpp"
#include "src/model/model.hpp"
#include "src/model/orientation_triad.hpp"
#include "src/resolve/reference_lookup.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

double dot(const Vec3& x, const Vec3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }

// "1.0", "20.0", "-10", "0.035": integral values keep one decimal, as the spec's examples do.
std::string number_text(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15) {
    return fmt::format("{:.1f}", value);
  }
  return fmt::format("{}", value);
}

// "did you mean" for a name among `candidates` (display spellings); a match that differs only in
// case is named as such (input-syntax.md §4).
void suggest_name(Diagnostic& diagnostic, SourceLoc loc, const std::string& display,
                  const std::vector<std::string>& candidates) {
  auto guess = closest_match(display, candidates);
  if (!guess) return;
  if (fold_name(*guess) == fold_name(display)) {
    diagnostic.notes.push_back(
        {loc, fmt::format("did you mean \"{}\"? (quoted names are case-sensitive)", *guess)});
  } else {
    diagnostic.notes.push_back({loc, fmt::format("did you mean '{}'?", *guess)});
  }
}

// Diagnostics that would repeat once per element are given once per group, for the first
// element, with the count of the others.
struct ElementGroup {
  std::int32_t first = -1;
  std::size_t count = 0;
  void add(std::int32_t element) {
    if (first < 0) first = element;
    ++count;
  }
};

std::string more_text(std::size_t count, std::string_view where) {
  if (count <= 1) return {};
  return fmt::format(" (and {} more {}{})", count - 1, count == 2 ? "element" : "elements", where);
}

class SectionValidator {
 public:
  SectionValidator(Model& model, DiagnosticSink& sink) : model_(model), sink_(sink) {}

  void run() {
    const std::size_t n = model_.elements.size();
    model_.sections.section_of_element.assign(n, -1);
    model_.sections.spring_of_element.assign(n, -1);
    tolerance_ = geometry_tolerance(model_.nodes);
    check_dimensions();
    for (Orientation& orientation : model_.sections.orientations) {
      if (orientation.definition == Orientation::Definition::Nodes && orientation.data_ok) {
        resolve_orientation_nodes(orientation);
      }
    }
    auto& sections = model_.sections.connector_sections;
    for (std::size_t s = 0; s < sections.size(); ++s) validate_connector_section(s);
    auto& springs = model_.sections.springs;
    for (std::size_t s = 0; s < springs.size(); ++s) validate_spring(s);
    check_springa_geometry();
    check_missing_sections();
    // An orientation a coupling names is used (resolve_rigid_bodies reports an undefined one).
    for (const CouplingDefinition& coupling : model_.constraints.couplings) {
      if (!coupling.orientation) continue;
      auto it = model_.sections.orientation_by_key.find(
          scoped_name_key(coupling.part, coupling.orientation->key));
      if (it != model_.sections.orientation_by_key.end()) {
        model_.sections.orientations[static_cast<std::size_t>(it->second)].used = true;
      }
    }
    for (const Orientation& orientation : model_.sections.orientations) {
      if (!orientation.used && !orientation.name.empty()) {
        sink_.report(DiagCode::defined_but_unused, orientation.keyword_loc,
                     fmt::format("orientation '{}' is not used by any *CONNECTOR SECTION or "
                                 "*SPRING",
                                 orientation.name.display));
      }
    }
  }

 private:
  bool node_ok(std::int32_t index) const {
    return index >= 0 && static_cast<std::size_t>(index) < model_.nodes.size();
  }

  std::string element_label(const Element& element) const {
    return qualified_label(model_, element.instance, element.label);
  }

  // keywords.md §3: a model with CONN2D2 is two-dimensional; mixing with CONN3D2 is E0710.
  void check_dimensions() {
    std::int32_t first_2d = -1, first_3d = -1;
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const ElementType type = model_.elements[e].type;
      if (type == ElementType::Conn2D2 && first_2d < 0) first_2d = static_cast<std::int32_t>(e);
      if (type == ElementType::Conn3D2 && first_3d < 0) first_3d = static_cast<std::int32_t>(e);
    }
    if (first_2d >= 0) model_.dimension = 2;
    if (first_2d < 0 || first_3d < 0) return;
    const bool later_is_2d = first_2d > first_3d;
    const Element& later = model_.elements[static_cast<std::size_t>(std::max(first_2d, first_3d))];
    const Element& earlier =
        model_.elements[static_cast<std::size_t>(std::min(first_2d, first_3d))];
    sink_
        .report(DiagCode::mixed_dimensions, later.keyword_loc(),
                later_is_2d ? "CONN2D2 elements cannot be mixed with CONN3D2 elements"
                            : "CONN3D2 elements cannot be mixed with CONN2D2 elements")
        .notes.push_back({earlier.keyword_loc(), fmt::format("{} elements are defined here",
                                                             element_type_name(earlier.type))});
  }

  // DEFINITION=NODES: the initial coordinates of the nodes give a, b, c (keywords.md §6).
  void resolve_orientation_nodes(Orientation& orientation) {
    std::array<Vec3*, 3> points = {&orientation.a, &orientation.b, &orientation.c};
    orientation.c = {0, 0, 0};
    const int count = orientation.has_node_c ? 3 : 2;
    for (int k = 0; k < count; ++k) {
      const TargetRef& ref = orientation.nodes[static_cast<std::size_t>(k)];
      if (orientation.part == 0) {
        std::vector<std::int32_t> found;
        if (!resolve_nodes(model_, ref, found, sink_) || found.empty() || !node_ok(found[0])) {
          return;
        }
        *points[static_cast<std::size_t>(k)] = model_.nodes[static_cast<std::size_t>(found[0])].x;
        continue;
      }
      if (static_cast<std::size_t>(orientation.part) >= model_.parts.size()) return;
      const Part& part = model_.parts[static_cast<std::size_t>(orientation.part)];
      const std::int32_t index = part.node_index.find(ref.label);
      if (index == LabelIndex::kMissing || static_cast<std::size_t>(index) >= part.nodes.size()) {
        sink_.report(
            DiagCode::undefined_node, ref.loc,
            fmt::format("node {} is not defined in part '{}'", ref.label, part.name.display));
        return;
      }
      // Part coordinates: each instance turns the triad (placed_triad).
      *points[static_cast<std::size_t>(k)] = part.nodes[static_cast<std::size_t>(index)].x;
    }
    const TriadStatus status =
        orientation_triad(orientation.a, orientation.b, orientation.c, orientation.axis,
                          orientation.angle_degrees, orientation.triad);
    if (status == TriadStatus::PointAAtOrigin) {
      sink_.report(DiagCode::degenerate_geometry, orientation.a_loc,
                   fmt::format("orientation '{}': point a coincides with the origin c",
                               orientation.name.display));
    } else if (status == TriadStatus::PointBOnAxis) {
      sink_.report(DiagCode::degenerate_geometry, orientation.b_loc,
                   fmt::format("orientation '{}': point b lies on the local 1-axis",
                               orientation.name.display));
    }
    orientation.valid = status == TriadStatus::Ok;
  }

  // An orientation name in the scope of `part`: its index, or −1 after E0504.
  std::int32_t find_orientation(const Name& name, std::int32_t part) {
    SectionModel& sections = model_.sections;
    auto it = sections.orientation_by_key.find(scoped_name_key(part, name.key));
    if (it != sections.orientation_by_key.end()) {
      sections.orientations[static_cast<std::size_t>(it->second)].used = true;
      return it->second;
    }
    Diagnostic& d = sink_.report(DiagCode::undefined_orientation, name.loc,
                                 fmt::format("undefined orientation '{}'", name.display));
    std::vector<std::string> candidates;
    for (const Orientation& o : sections.orientations) {
      if (o.part == part) candidates.push_back(o.name.display);
    }
    suggest_name(d, name.loc, name.display, candidates);
    return -1;
  }

  // Resolves a section's or spring's ELSET and reports the set-level errors shared by both.
  bool resolve_set(const TargetRef& elset, std::vector<std::int32_t>& out, bool connector) {
    if (!elset.is_label && elset.set_key.empty()) {
      (connector ? connector_set_failed_ : spring_set_failed_) = true;  // ELSET= was bad
      return false;
    }
    if (!resolve_elements(model_, elset, out, sink_)) {
      // The set might have held the elements that now lack a section (input-syntax.md §10).
      (connector ? connector_set_failed_ : spring_set_failed_) = true;
      return false;
    }
    if (out.empty()) {
      sink_.report(DiagCode::empty_set, elset.loc,
                   fmt::format("{} is empty", describe(elset, true)));
      return false;
    }
    return true;
  }

  void validate_connector_section(std::size_t s) {
    ConnectorSection& section = model_.sections.connector_sections[s];
    section.elements.clear();
    std::vector<std::int32_t> members;
    const bool have_elements = resolve_set(section.elset, members, true);
    bool wrong_kind_reported = false;
    std::map<std::int32_t, ElementGroup> duplicates;  // first section → elements
    for (std::int32_t index : members) {
      if (index < 0 || static_cast<std::size_t>(index) >= model_.elements.size()) continue;
      const Element& element = model_.elements[static_cast<std::size_t>(index)];
      if (!is_connector(element.type)) {
        if (!wrong_kind_reported) {
          wrong_kind_reported = true;
          sink_.report(DiagCode::wrong_element_kind, section.elset.loc,
                       fmt::format("{} contains element {} of type {}; *CONNECTOR SECTION needs "
                                   "connector elements",
                                   describe(section.elset, true), element_label(element),
                                   element_type_name(model_, index)));
        }
        continue;
      }
      std::int32_t& owner = model_.sections.section_of_element[static_cast<std::size_t>(index)];
      if (owner >= 0) {
        if (owner != static_cast<std::int32_t>(s)) duplicates[owner].add(index);
        continue;
      }
      owner = static_cast<std::int32_t>(s);
      section.elements.push_back(index);
      if (element.type == ElementType::Conn2D2) section.two_d = true;
    }
    for (const auto& [first_section, group] : duplicates) {
      const Element& element = model_.elements[static_cast<std::size_t>(group.first)];
      sink_
          .report(DiagCode::duplicate_section, section.keyword_loc,
                  fmt::format("element {} already has a *CONNECTOR SECTION{}",
                              element_label(element), more_text(group.count, "")))
          .notes.push_back(
              {model_.sections.connector_sections[static_cast<std::size_t>(first_section)]
                   .keyword_loc,
               "first *CONNECTOR SECTION is here"});
    }
    resolve_behavior(section);
    resolve_controls(section);
    const std::int32_t scope = section.elset.part;
    for (std::size_t end = 0; end < 2; ++end) {
      if (section.orientations.size() > end && !section.orientations[end].empty()) {
        section.orientation_index[end] = find_orientation(section.orientations[end], scope);
      }
    }
    if (!section.valid) return;
    apply_dimension(section);
    if (!section.valid) return;
    check_euler(section);
    if (have_elements) check_element_geometry(section);
  }

  void resolve_behavior(ConnectorSection& section) {
    if (section.behavior.empty()) return;
    BehaviorModel& behaviors = model_.behaviors;
    auto it = behaviors.by_key.find(section.behavior.key);
    // -1: the block of that name was refused and reported (input-syntax.md §10).
    if (it != behaviors.by_key.end() && it->second < 0) return;
    if (it != behaviors.by_key.end() &&
        static_cast<std::size_t>(it->second) < behaviors.behaviors.size()) {
      ConnectorBehavior& behavior = behaviors.behaviors[static_cast<std::size_t>(it->second)];
      behavior.used = true;
      if (behavior.referable) {
        section.behavior_index = it->second;
        return;
      }
      return;  // its definition already failed: no second error here (input-syntax.md §10)
    }
    Diagnostic& d =
        sink_.report(DiagCode::undefined_behavior, section.behavior.loc,
                     fmt::format("undefined connector behavior '{}'", section.behavior.display));
    std::vector<std::string> candidates;
    for (const ConnectorBehavior& b : behaviors.behaviors) {
      if (b.referable) candidates.push_back(b.name.display);
    }
    suggest_name(d, section.behavior.loc, section.behavior.display, candidates);
  }

  void resolve_controls(ConnectorSection& section) {
    if (section.controls.empty()) return;
    SectionModel& sections = model_.sections;
    auto it = sections.controls_by_key.find(section.controls.key);
    if (it != sections.controls_by_key.end()) {
      section.controls_index = it->second;
      sections.controls[static_cast<std::size_t>(it->second)].used = true;
      return;
    }
    Diagnostic& d =
        sink_.report(DiagCode::undefined_section_controls, section.controls.loc,
                     fmt::format("undefined section controls '{}'", section.controls.display));
    std::vector<std::string> candidates;
    for (const SectionControls& c : sections.controls) candidates.push_back(c.name.display);
    suggest_name(d, section.controls.loc, section.controls.display, candidates);
  }

  // CONN2D2 (connection-types.md §2.1): only nine types, components 1, 2, 6, and an
  // orientation whose e3 is ±z (keywords.md §6).
  void apply_dimension(ConnectorSection& section) {
    std::vector<const ConnectionTypeInfo*> infos;
    for (std::size_t k = 0; k < section.type_names.size(); ++k) {
      const ConnectionTypeInfo* info = find_connection_type(section.type_names[k]);
      if (!info) continue;
      infos.push_back(info);
      if (section.two_d && !info->allowed_2d) {
        sink_.report(DiagCode::type_dimension_mismatch,
                     k < section.type_locs.size() ? section.type_locs[k] : section.type_loc,
                     fmt::format("connection type '{}' is not available for CONN2D2", info->name));
        section.valid = false;
      }
    }
    const ConnectionSummary summary = summarize_connection(infos, section.two_d);
    section.available = section.valid ? summary.available : 0;
    section.constrained = section.valid ? summary.constrained : 0;
    if (!section.two_d || !section.valid) return;
    for (std::size_t end = 0; end < 2; ++end) {
      const std::int32_t index = section.orientation_index[end];
      if (index < 0) continue;
      const Orientation& orientation =
          model_.sections.orientations[static_cast<std::size_t>(index)];
      if (!orientation.valid) continue;
      const Vec3& e3 = orientation.triad[2];
      if (std::fabs(e3[0]) > 1e-8 || std::fabs(e3[1]) > 1e-8 ||
          std::fabs(std::fabs(e3[2]) - 1.0) > 1e-8) {
        sink_
            .report(DiagCode::degenerate_geometry, section.orientations[end].loc,
                    fmt::format("orientation '{}' is used by CONN2D2 elements, but its local "
                                "3-axis is not the global z axis",
                                orientation.name.display))
            .notes.push_back({orientation.keyword_loc, "orientation defined here"});
      }
    }
  }

  const Orientation* orientation_at(const ConnectorSection& section, std::size_t end) const {
    const std::int32_t index = section.orientation_index[end];
    if (index < 0) return nullptr;
    return &model_.sections.orientations[static_cast<std::size_t>(index)];
  }

  // connection-types.md §2.2: EULER is singular when e3 at a and b are parallel, which includes
  // aligned initial frames. R33 = e3a·e3b does not depend on the instance (both orientations
  // come from the section's scope and turn together).
  void check_euler(const ConnectorSection& section) {
    for (std::size_t k = 0; k < section.type_names.size(); ++k) {
      if (section.type_names[k] != "EULER") continue;
      const Orientation* a = orientation_at(section, 0);
      const Orientation* b = orientation_at(section, 1);
      if ((a && !a->valid) || (b && !b->valid)) return;
      const Vec3 e3a = a ? a->triad[2] : Vec3{0, 0, 1};
      const Vec3 e3b = b ? b->triad[2] : e3a;  // default at b: a's initial directions
      const double r33 = std::clamp(dot(e3a, e3b), -1.0, 1.0);
      const double sin_beta = std::sqrt(std::max(0.0, 1.0 - r33 * r33));
      if (sin_beta < 1e-3) {
        sink_.report(DiagCode::euler_singular_initial,
                     k < section.type_locs.size() ? section.type_locs[k] : section.type_loc,
                     fmt::format("EULER angles are singular in the initial configuration: the "
                                 "local 3-axes at nodes a and b are parallel (|sin beta0| = {:.3g}"
                                 " < 1e-3)",
                                 sin_beta));
      }
    }
  }

  // Initial relative position d0 = x_b − x_a; a grounded end sits on the other node (§1.2).
  bool initial_offset(const Element& element, Vec3& d0) const {
    const std::int32_t a = element.nodes[0], b = element.nodes[1];
    const bool a_ok = node_ok(a), b_ok = node_ok(b);
    if (!a_ok && !b_ok) return false;
    if ((a != kGround && !a_ok) || (b != kGround && !b_ok)) return false;
    if (!a_ok || !b_ok) {
      d0 = {0, 0, 0};
      return true;
    }
    const Vec3& xa = model_.nodes[static_cast<std::size_t>(a)].x;
    const Vec3& xb = model_.nodes[static_cast<std::size_t>(b)].x;
    d0 = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
    return true;
  }

  // Per-element checks of connection-types.md §2.2 (AXIAL, LINK, RADIAL-THRUST).
  void check_element_geometry(const ConnectorSection& section) {
    const bool axial = std::find(section.type_names.begin(), section.type_names.end(), "AXIAL") !=
                       section.type_names.end();
    const bool link = std::find(section.type_names.begin(), section.type_names.end(), "LINK") !=
                      section.type_names.end();
    const bool radial = std::find(section.type_names.begin(), section.type_names.end(),
                                  "RADIAL-THRUST") != section.type_names.end();
    if (!axial && !link && !radial) return;
    const Orientation* ori_a = orientation_at(section, 0);
    const Orientation* ori_b = orientation_at(section, 1);
    // An orientation whose own definition failed counts as given (no follow-up error).
    const bool has_orientation = ori_a || ori_b;
    ElementGroup axial_group, link_group, radial_group;
    for (std::int32_t index : section.elements) {
      const Element& element = model_.elements[static_cast<std::size_t>(index)];
      Vec3 d0{};
      if (!initial_offset(element, d0)) continue;
      const double l0 = length_of(d0);
      if (axial && !has_orientation && l0 <= tolerance_) axial_group.add(index);
      if (link && l0 <= tolerance_) link_group.add(index);
      if (radial && (!ori_a || ori_a->valid)) {
        const Vec3 e3 = ori_a ? placed_triad(model_, *ori_a, element.instance)[2] : Vec3{0, 0, 1};
        const double along = dot(e3, d0);
        const Vec3 radial_part = {d0[0] - along * e3[0], d0[1] - along * e3[1],
                                  d0[2] - along * e3[2]};
        if (length_of(radial_part) <= tolerance_) {
          radial_group.add(index);
        }
      }
    }
    const SourceLoc section_loc = section.type_loc.valid() ? section.type_loc : section.keyword_loc;
    auto report = [&](const ElementGroup& group, DiagCode code, const std::string& text) {
      if (group.first < 0) return;
      const Element& element = model_.elements[static_cast<std::size_t>(group.first)];
      Diagnostic& d =
          sink_.report(code, element.loc(), text + more_text(group.count, " of this section"));
      d.notes.push_back({section_loc, "section defined here"});
    };
    auto label_of = [&](const ElementGroup& group) {
      return group.first < 0
                 ? std::string()
                 : element_label(model_.elements[static_cast<std::size_t>(group.first)]);
    };
    report(axial_group, DiagCode::axial_direction_undefined,
           fmt::format("AXIAL connector element {} has zero initial length (coincident or "
                       "grounded nodes) and no orientation; its direction is undefined",
                       label_of(axial_group)));
    report(link_group, DiagCode::link_zero_length,
           fmt::format("LINK connector element {} has zero initial length", label_of(link_group)));
    report(radial_group, DiagCode::radial_thrust_on_axis,
           fmt::format("RADIAL-THRUST connector element {} starts with node b on the axis of "
                       "node a; the radial direction is undefined there",
                       label_of(radial_group)));
  }

  // ------------------------------------------------------------------------------------------
  // *SPRING (keywords.md §7) and *DASHPOT (the same layout, behaviors.md §8)

  void validate_spring(std::size_t s) {
    SpringProperty& spring = model_.sections.springs[s];
    const DiscreteElementWords& words = spring.words();
    spring.elements.clear();
    std::vector<std::int32_t> members;
    if (!resolve_set(spring.elset, members, false)) return;
    bool wrong_kind_reported = false;
    bool mixed_reported = false;
    bool have_type = false;
    std::map<std::int32_t, ElementGroup> duplicates;
    for (std::int32_t index : members) {
      if (index < 0 || static_cast<std::size_t>(index) >= model_.elements.size()) continue;
      const Element& element = model_.elements[static_cast<std::size_t>(index)];
      if (!is_spring_or_dashpot(element.type) || is_dashpot(element.type) != spring.dashpot) {
        if (!wrong_kind_reported) {
          wrong_kind_reported = true;
          sink_.report(DiagCode::wrong_element_kind, spring.elset.loc,
                       fmt::format("{} contains element {} of type {}; {} needs {} elements",
                                   describe(spring.elset, true), element_label(element),
                                   element_type_name(model_, index), words.keyword,
                                   words.element));
        }
        continue;
      }
      if (!have_type) {
        have_type = true;
        spring.type = element.type;
      } else if (element.type != spring.type) {
        if (!mixed_reported) {
          mixed_reported = true;
          sink_.report(DiagCode::wrong_element_kind, spring.elset.loc,
                       fmt::format("{} mixes {} and {} elements; {} needs elements of one type",
                                   describe(spring.elset, true), element_type_name(spring.type),
                                   element_type_name(element.type), words.keyword));
        }
        // Claimed anyway, so that it does not also get "no *SPRING" (input-syntax.md §10).
        std::int32_t& other = model_.sections.spring_of_element[static_cast<std::size_t>(index)];
        if (other < 0) other = static_cast<std::int32_t>(s);
        continue;
      }
      std::int32_t& owner = model_.sections.spring_of_element[static_cast<std::size_t>(index)];
      if (owner >= 0) {
        if (owner != static_cast<std::int32_t>(s)) duplicates[owner].add(index);
        continue;
      }
      owner = static_cast<std::int32_t>(s);
      spring.elements.push_back(index);
    }
    for (const auto& [first, group] : duplicates) {
      const Element& element = model_.elements[static_cast<std::size_t>(group.first)];
      sink_
          .report(DiagCode::duplicate_section, spring.keyword_loc,
                  fmt::format("element {} already has a {}{}", element_label(element),
                              words.keyword, more_text(group.count, "")))
          .notes.push_back({model_.sections.springs[static_cast<std::size_t>(first)].keyword_loc,
                            fmt::format("first {} is here", words.keyword)});
    }
    if (!have_type || !spring.data_ok) return;
    if (!spring.orientation.empty()) {
      spring.orientation_index = find_orientation(spring.orientation, spring.elset.part);
      if (spring_form(spring.type) == ElementType::SpringA) {
        sink_.report(
            DiagCode::orientation_ignored, spring.orientation_param_loc,
            fmt::format("ORIENTATION is ignored for {} elements", element_type_name(spring.type)));
      }
    }
    std::vector<const SpringLine*> properties;
    if (!check_dof_line(spring, properties)) return;
    for (const SpringLine& line : spring.property_lines) properties.push_back(&line);
    for (const SpringLine* line : properties) {
      if (!line->ok) return;  // already reported by the reader
    }
    spring.valid =
        spring.nonlinear ? check_table(spring, properties) : check_linear(spring, properties);
  }

  // The DOF line (§7 data line 1); collects the property lines that precede the repeated ones.
  bool check_dof_line(SpringProperty& spring, std::vector<const SpringLine*>& properties) {
    const char* type_name = element_type_name(spring.type);
    const DiscreteElementWords& words = spring.words();
    if (spring_form(spring.type) == ElementType::SpringA) {
      if (spring.first_line_blank) return true;
      if (spring.first_line_real) {
        // CalculiX decks drop blank lines; the real on line 1 is the first property line.
        sink_.report(DiagCode::springa_missing_blank_line, spring.first_line_loc,
                     fmt::format("no blank line after {} for {}; the first line is read as {}",
                                 words.keyword, type_name,
                                 spring.nonlinear ? std::string("the first table point")
                                                  : fmt::format("the {}", words.coefficient)));
        properties.push_back(&spring.first_line_as_property);
        return true;
      }
      // Abaqus ignores the DOF line of SPRINGA and DASHPOTA (the manual's *SPRING: "this line
      // can be left blank"): their direction is the line between their nodes.
      if (!spring.first_line_ok) return false;
      sink_.report(DiagCode::springa_dof_line_ignored, spring.first_line_loc,
                   fmt::format("the DOF line of {} after {} is ignored (its direction is the "
                               "line between its nodes)",
                               type_name, words.keyword));
      return true;
    }
    const std::size_t needed = spring_form(spring.type) == ElementType::Spring1 ? 1 : 2;
    if (!spring.first_line_ok) return false;
    if (spring.first_line_blank || spring.first_line_real ||
        spring.first_line_integers.size() != needed) {
      sink_.report(DiagCode::spring_dof_line, spring.first_line_loc,
                   fmt::format("{} needs a DOF line '{}' after {}", type_name,
                               needed == 1 ? "dof" : "dof1, dof2", words.keyword));
      return false;
    }
    bool ok = true;
    for (std::size_t k = 0; k < needed; ++k) {
      const std::int64_t dof = spring.first_line_integers[k];
      const SourceLoc loc = spring.first_line_locs[k];
      if (dof < 1 || dof > 6) {
        sink_.report(DiagCode::value_out_of_range, loc,
                     fmt::format("DOF {} is out of range (1-6)", dof));
        ok = false;
      } else if (model_.dimension == 2 && dof >= 3 && dof <= 5) {
        sink_.report(
            DiagCode::spring_dof_line, loc,
            fmt::format("DOF {} does not exist in a two-dimensional model (DOFs 1, 2, 6)", dof));
        ok = false;
      } else {
        spring.dofs[k] = static_cast<int>(dof);
      }
    }
    return ok;
  }

  // Linear: one line `k [, frequency] [, temperature]`, dependence not supported (E0713).
  bool check_linear(SpringProperty& spring, const std::vector<const SpringLine*>& lines) {
    if (lines.empty()) return false;
    const DiscreteElementWords& words = spring.words();
    bool ok = true;
    if (lines.size() > 1) {
      sink_.report(DiagCode::unsupported_dependencies, lines[1]->loc,
                   fmt::format("temperature-dependent {} data is not supported (a linear {} "
                               "takes one {} line)",
                               words.element, words.keyword, words.coefficient));
      ok = false;
    }
    const SpringLine& line = *lines[0];
    if (line.values.empty() || !line.values[0].value) {
      sink_.report(DiagCode::missing_field, line.values.empty() ? line.loc : line.values[0].loc,
                   fmt::format("missing value for '{}' of {}", words.coefficient, words.keyword));
      return false;
    }
    static constexpr const char* kWhat[] = {"", "frequency", "temperature"};
    for (std::size_t k = 1; k < line.values.size() && k < 3; ++k) {
      if (line.values[k].value) {
        sink_.report(DiagCode::unsupported_dependencies, line.values[k].loc,
                     fmt::format("{}-dependent {} data is not supported", kWhat[k], words.element));
        ok = false;
      }
    }
    const double k = *line.values[0].value;
    if (k < 0) {
      sink_.report(DiagCode::negative_stiffness, line.values[0].loc,
                   fmt::format("negative {} {}", words.coefficient, number_text(k)));
    }
    spring.stiffness = k;
    return ok;
  }

  // Nonlinear: `F, Δ [, temperature]` lines, Δ strictly increasing, at least two points.
  bool check_table(SpringProperty& spring, const std::vector<const SpringLine*>& lines) {
    const DiscreteElementWords& words = spring.words();
    bool ok = true;
    spring.table.clear();
    for (const SpringLine* line : lines) {
      if (line->values.size() < 2 || !line->values[0].value || !line->values[1].value) {
        const bool force_missing = line->values.empty() || !line->values[0].value;
        SourceLoc where = line->loc;
        if (force_missing && !line->values.empty()) where = line->values[0].loc;
        if (!force_missing && line->values.size() >= 2) where = line->values[1].loc;
        sink_.report(
            DiagCode::missing_field, where,
            fmt::format("missing value for '{}' of {}",
                        force_missing ? std::string_view("force") : words.motion, words.keyword));
        ok = false;
        continue;
      }
      if (line->values.size() > 2 && line->values[2].value) {
        sink_.report(DiagCode::unsupported_dependencies, line->values[2].loc,
                     fmt::format("temperature-dependent {} data is not supported", words.element));
        ok = false;
        continue;
      }
      const double force = *line->values[0].value;
      const double delta = *line->values[1].value;
      if (!spring.table.empty() && !(delta > spring.table.back().delta)) {
        sink_.report(DiagCode::table_not_increasing, line->values[1].loc,
                     fmt::format("{} must increase ({} after {})", words.motions,
                                 number_text(delta), number_text(spring.table.back().delta)));
        ok = false;
        continue;
      }
      spring.table.push_back({force, delta, line->loc});
    }
    if (!ok) return false;
    if (spring.table.size() < 2) {
      sink_.report(DiagCode::table_not_increasing,
                   spring.table.empty() ? spring.keyword_loc : spring.table.front().loc,
                   fmt::format("a nonlinear {} table needs at least 2 points", words.element));
      return false;
    }
    // W0701: F(0) ≠ 0 (constant extrapolation outside the table, keywords.md §7).
    const auto& t = spring.table;
    double f0 = t.front().force;
    if (0 >= t.back().delta) {
      f0 = t.back().force;
    } else if (0 > t.front().delta) {
      for (std::size_t k = 0; k + 1 < t.size(); ++k) {
        if (0 <= t[k + 1].delta) {
          f0 = t[k].force +
               (t[k + 1].force - t[k].force) * (0 - t[k].delta) / (t[k + 1].delta - t[k].delta);
          break;
        }
      }
    }
    if (f0 != 0) {
      sink_.report(DiagCode::nonlinear_elasticity_offset, t.front().loc,
                   fmt::format("{} table gives force {} at zero {}", words.element, number_text(f0),
                               words.motion));
    }
    return true;
  }

  // keywords.md §3: coincident initial positions of a SPRINGA leave its direction undefined.
  void check_springa_geometry() {
    for (const Element& element : model_.elements) {
      if (spring_form(element.type) != ElementType::SpringA) continue;
      if (!node_ok(element.nodes[0]) || !node_ok(element.nodes[1])) continue;
      if (element.nodes[0] == element.nodes[1]) continue;  // reported by the element reader
      const Vec3& x1 = model_.nodes[static_cast<std::size_t>(element.nodes[0])].x;
      const Vec3& x2 = model_.nodes[static_cast<std::size_t>(element.nodes[1])].x;
      if (length_of({x2[0] - x1[0], x2[1] - x1[1], x2[2] - x1[2]}) > tolerance_) continue;
      SourceLoc loc = element.loc();
      if (element.node_columns[1] > 0) loc.column = element.node_columns[1];
      sink_.report(DiagCode::degenerate_geometry, loc,
                   fmt::format("{} element {} joins two nodes at the same position; its "
                               "direction is undefined",
                               element_type_name(element.type), element_label(element)));
    }
  }

  // E0514 at the *ELEMENT line, once per block (keywords.md §3).
  void check_missing_sections() {
    struct Missing {
      SourceLoc loc;
      ElementGroup group;
      bool connector;
    };
    std::vector<Missing> missing;
    std::map<std::tuple<std::uint32_t, std::uint32_t, bool>, std::size_t> by_block;
    const auto& sections = model_.sections;
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
      const Element& element = model_.elements[e];
      if (element.type == ElementType::Held) continue;  // their sections: resolve_structure
      const bool connector = is_connector(element.type);
      const bool has =
          connector ? sections.section_of_element[e] >= 0 : sections.spring_of_element[e] >= 0;
      if (has || (connector ? connector_set_failed_ : spring_set_failed_)) continue;
      auto key = std::make_tuple(element.file, element.keyword_line, connector);
      auto [it, inserted] = by_block.emplace(key, missing.size());
      if (inserted) missing.push_back({element.keyword_loc(), {}, connector});
      missing[it->second].group.add(static_cast<std::int32_t>(e));
    }
    for (const Missing& m : missing) {
      const Element& element = model_.elements[static_cast<std::size_t>(m.group.first)];
      const bool dashpot = is_dashpot(element.type);
      sink_.report(
          DiagCode::missing_section, m.loc,
          fmt::format("{} element {} has no {}{}",
                      m.connector ? "connector" : (dashpot ? "dashpot" : "spring"),
                      element_label(element),
                      m.connector ? "*CONNECTOR SECTION" : (dashpot ? "*DASHPOT" : "*SPRING"),
                      more_text(m.group.count, " of this *ELEMENT block")));
    }
  }

  Model& model_;
  DiagnosticSink& sink_;
  double tolerance_ = 1e-8;
  bool connector_set_failed_ = false;
  bool spring_set_failed_ = false;
};

}  // namespace

void resolve_sections(Model& model, DiagnosticSink& sink) { SectionValidator(model, sink).run(); }

}  // namespace clinch
