#include "src/resolve/resolve_output_requests.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <unordered_map>

#include "base/diagnostic.hpp"
#include "base/suggest.hpp"
#include "src/model/connection_types.hpp"
#include "src/model/model.hpp"
#include "src/model/output_variables.hpp"
#include "src/model/potential_queries.hpp"
#include "src/resolve/reference_lookup.hpp"

namespace clinch {
namespace {

constexpr std::uint8_t kTranslations = 0b000111;
constexpr std::uint8_t kRotations = 0b111000;
constexpr std::uint8_t kAll = 0b111111;

int single_component(std::uint8_t mask) { return std::countr_zero(mask) + 1; }

bool produces(const BehaviorFeatures& f, OutputProducer producer) {
  switch (producer) {
    case OutputProducer::Always:
    case OutputProducer::Derived:
    case OutputProducer::StaticZero:
      return true;
    case OutputProducer::Elasticity:
      return f.elasticity || f.plasticity || f.damage;
    case OutputProducer::Plasticity:
      return f.plasticity;
    case OutputProducer::KinematicHardening:
      return f.kinematic_hardening;
    case OutputProducer::Damage:
      return f.damage;
    case OutputProducer::ForceCriterion:
      return f.force_criterion;
    case OutputProducer::MotionCriterion:
      return f.motion_criterion;
    case OutputProducer::PlasticMotionCriterion:
      return f.plastic_motion_criterion;
    case OutputProducer::StopsOrLocks:
      // CSLST is 4 on every component of an element deleted by damage (output-variables.md §2).
      return f.stops_or_locks || f.damage;
    case OutputProducer::Friction:
      return f.friction;
  }
  return true;
}

// Expands the requests of each step into columns, reporting as it goes.
class OutputValidator {
 public:
  OutputValidator(Model& model, const std::vector<DofMask>& active, DiagnosticSink& sink)
      : model_(model), active_(active), sink_(sink) {}

  // The resolved sets are stored in the requests: the history writer reads them.
  void run(std::vector<Step>& steps) {
    for (Step& step : steps) {
      set_columns_.clear();
      target_columns_.clear();
      for (OutputRequest& request : step.outputs) {
        for (ElementOutputRequest& block : request.elements) {
          if (!block.has_elset) continue;
          std::vector<std::int32_t>& elements = block.resolved;
          if (!resolve_elements(model_, block.elset, elements, sink_) || request.field) continue;
          drop_held_elements(elements);
          for (const OutputIdentifier& id : block.identifiers) {
            element_identifier(id, block.elset, elements, false);
          }
        }
        for (NodeOutputRequest& block : request.nodes) {
          if (!block.has_nset) continue;
          std::vector<std::int32_t>& nodes = block.resolved;
          if (!resolve_nodes(model_, block.nset, nodes, sink_) || request.field) continue;
          for (const OutputIdentifier& id : block.identifiers) {
            node_identifier(id, block.nset, nodes, PrintRequest::Totals::No);
          }
        }
      }
      for (PrintRequest& print : step.prints) {
        std::vector<std::int32_t>& members = print.resolved;
        if (print.all) {
          const std::size_t count = print.node ? model_.nodes.size() : model_.elements.size();
          for (std::size_t i = 0; i < count; ++i) members.push_back(static_cast<std::int32_t>(i));
        } else if (!print.has_set) {
          continue;
        }
        if (print.node) {
          if (!print.all && !resolve_nodes(model_, print.set, members, sink_)) continue;
          for (const OutputIdentifier& id : print.identifiers) {
            node_identifier(id, print.set, members, print.totals);
          }
        } else {
          if (!print.all && !resolve_elements(model_, print.set, members, sink_)) continue;
          drop_held_elements(members);
          for (const OutputIdentifier& id : print.identifiers) {
            element_identifier(id, print.set, members, print.totals != PrintRequest::Totals::No,
                               print.totals == PrintRequest::Totals::Only);
          }
        }
      }
    }
  }

 private:
  // Held elements (solids, shells, masses, ...) have no output variables: a request names
  // the connectors, springs and dashpots among its elements.
  void drop_held_elements(std::vector<std::int32_t>& elements) const {
    std::erase_if(elements, [&](std::int32_t e) {
      return model_.elements[static_cast<std::size_t>(e)].type == ElementType::Held;
    });
  }

  // W0903: a column produced twice in one step is written once; the second request is warned
  // about, once per identifier (output-variables.md §1.2). A column is a variable label (CTF1,
  // CDERF-normal, U2, …) at a target. Set totals are few and keyed by their names; element and
  // node columns by numbers (label id, node or element, index), so that a request over 10⁵
  // elements formats no names unless it repeats one.
  void add_set_column(const std::string& column, const OutputIdentifier& id, bool& reported) {
    auto [it, inserted] = set_columns_.emplace(column, id.loc);
    if (!inserted && !reported) report_duplicate(column, id, it->second, reported);
  }

  int label_id(const std::string& label) {
    auto [it, inserted] = label_ids_.emplace(label, static_cast<int>(labels_.size()));
    if (inserted) labels_.push_back(label);
    return it->second;
  }

  void add_target_column(int label, bool node, std::int32_t index, const OutputIdentifier& id,
                         bool& reported) {
    const std::uint64_t key = (static_cast<std::uint64_t>(label) << 33) |
                              (static_cast<std::uint64_t>(node) << 32) |
                              static_cast<std::uint32_t>(index);
    auto [it, inserted] = target_columns_.emplace(key, &id);
    if (inserted || reported) return;
    const auto i = static_cast<std::size_t>(index);
    const std::string where =
        node ? qualified_label(model_, model_.nodes[i].instance, model_.nodes[i].label)
             : qualified_label(model_, model_.elements[i].instance, model_.elements[i].label);
    report_duplicate(labels_[static_cast<std::size_t>(label)] + "@" + where, id, it->second->loc,
                     reported);
  }

  void report_duplicate(const std::string& column, const OutputIdentifier& id, SourceLoc first,
                        bool& reported) {
    reported = true;
    sink_
        .report(DiagCode::output_duplicate, id.loc,
                fmt::format("column {} is already requested", column))
        .notes.push_back({first, "first requested here"});
  }

  // Label ids of an identifier's columns by component (0: the variable's own name), looked up
  // once per identifier.
  struct ComponentLabels {
    std::array<int, 7> id;
    ComponentLabels() { id.fill(-1); }
  };
  int component_label(ComponentLabels& labels, const std::string& variable, int component) {
    int& id = labels.id[static_cast<std::size_t>(component)];
    if (id < 0) {
      id = label_id(component == 0 ? variable : output_column_label(variable, component));
    }
    return id;
  }

  std::string set_label(const TargetRef& set, bool element) const {
    if (set.is_label) return describe(set, element);
    return set.instance_display.empty() ? set.set_display
                                        : set.instance_display + "." + set.set_display;
  }

  const ConnectorSection* section_of(std::int32_t element) const {
    const auto& sections = model_.sections;
    if (static_cast<std::size_t>(element) >= sections.section_of_element.size()) return nullptr;
    const std::int32_t s = sections.section_of_element[static_cast<std::size_t>(element)];
    if (s < 0 || static_cast<std::size_t>(s) >= sections.connector_sections.size()) return nullptr;
    const ConnectorSection& section = sections.connector_sections[static_cast<std::size_t>(s)];
    return section.valid ? &section : nullptr;
  }

  const ConnectorBehavior* behavior_of(const ConnectorSection& section) const {
    const std::int32_t b = section.behavior_index;
    if (b < 0 || static_cast<std::size_t>(b) >= model_.behaviors.behaviors.size()) return nullptr;
    return &model_.behaviors.behaviors[static_cast<std::size_t>(b)];
  }

  // E0902 (output-variables.md §1.2, §6): an explicitly requested component, or a rotational
  // alias (CTM), that the element's connection type does not define.
  void component_missing(const OutputIdentifier& id, const ConnectorSection& section,
                         std::uint8_t defined) {
    std::string why;
    const int c = single_component(id.components);
    if (section.two_d && id.explicit_component && c >= 3 && c <= 5) {
      why = "CONN2D2 has components 1, 2, 6 only";
    } else if ((id.components & kTranslations) == 0 && (defined & kRotations) == 0) {
      why = fmt::format("{} has no rotational components", connection_display(section));
    } else if ((id.components & kRotations) == 0 && (defined & kTranslations) == 0) {
      why = fmt::format("{} has no translational components", connection_display(section));
    } else {
      why = fmt::format("{} does not define component {} (components: {})",
                        connection_display(section), c, component_list(defined));
    }
    sink_
        .report(DiagCode::output_component_not_available, id.loc,
                fmt::format("{} is not available: {}", id.text, why))
        .notes.push_back({section.keyword_loc, "section defined here"});
  }

  // CDERF-<name> / CDERU-<name> (derived-components-and-potentials.md §4): the name must be a
  // derived component of the element's behaviour with a context of the right kind. Returns the
  // display names of the columns.
  std::vector<std::string> derived_columns(const OutputIdentifier& id,
                                           const ConnectorBehavior* behavior,
                                           std::vector<const ConnectorBehavior*>& reported) {
    std::vector<std::string> names;
    const bool force = id.variable == "CDERF";
    if (!behavior) return names;
    if (id.derived_name.empty()) {
      for (std::int32_t t : derived_output_terms(*behavior, force)) {
        names.push_back(behavior->derived_terms[static_cast<std::size_t>(t)].name.display);
      }
      return names;
    }
    const std::string key = name_key(id.derived_name, false);
    const std::int32_t term = find_derived_component(*behavior, key);
    const bool first_report =
        std::find(reported.begin(), reported.end(), behavior) == reported.end();
    if (term < 0) {
      if (first_report) {
        reported.push_back(behavior);
        Diagnostic& d =
            sink_.report(DiagCode::undefined_derived_component, id.loc,
                         fmt::format("undefined derived component '{}' in connector behavior '{}'",
                                     id.derived_name, behavior->name.display));
        std::vector<std::string> candidates;
        for (std::int32_t t : derived_component_first_terms(*behavior)) {
          candidates.push_back(behavior->derived_terms[static_cast<std::size_t>(t)].name.display);
        }
        if (auto guess = closest_match(id.derived_name, candidates)) {
          d.notes.push_back({id.loc, fmt::format("did you mean '{}'?", *guess)});
        }
      }
      return names;
    }
    if (!first_derived_context(*behavior, key, force)) {
      if (first_report) {
        reported.push_back(behavior);
        sink_
            .report(DiagCode::cder_no_context, id.loc,
                    fmt::format("derived component '{}' is not used in any {} context of "
                                "connector behavior '{}'; {} has no value",
                                id.derived_name, force ? "force" : "motion", behavior->name.display,
                                id.text))
            .notes.push_back({behavior->derived_terms[static_cast<std::size_t>(term)].loc,
                              "derived component defined here"});
      }
      return names;
    }
    names.push_back(behavior->derived_terms[static_cast<std::size_t>(term)].name.display);
    return names;
  }

  void element_identifier(const OutputIdentifier& id, const TargetRef& set,
                          const std::vector<std::int32_t>& elements, bool totals,
                          bool totals_only = false) {
    const OutputVariableInfo* info = output_variable_info(id.variable);
    if (!info) return;
    const bool spring_variable = info->kind == OutputKind::Spring;
    std::size_t matching = 0, without_producer = 0;
    bool duplicate_reported = false;
    std::vector<const ConnectorSection*> reported_sections;
    std::vector<const ConnectorBehavior*> reported_behaviors;
    std::uint8_t total_components = 0;
    ComponentLabels labels;
    const ConnectorBehavior* last_behavior = nullptr;
    BehaviorFeatures features;
    for (std::int32_t e : elements) {
      const Element& element = model_.elements[static_cast<std::size_t>(e)];
      if (is_spring_or_dashpot(element.type) != spring_variable)
        continue;  // not defined for this kind
      ++matching;
      if (spring_variable) {
        total_components |= 1;
        if (!totals_only) {
          add_target_column(component_label(labels, id.variable, 1), false, e, id,
                            duplicate_reported);
        }
        continue;
      }
      const ConnectorSection* section = section_of(e);
      if (!section) continue;  // E0514 or a section error was reported
      const ConnectorBehavior* behavior = behavior_of(*section);
      if (behavior != last_behavior) {  // features of a null behaviour: the default
        features = behavior ? behavior_features(*behavior) : BehaviorFeatures{};
        last_behavior = behavior;
      }
      // A section whose behaviour was refused or is undefined, or lost an option to a misspelt
      // keyword, was reported there: its outputs are not "always 0" (input-syntax.md §10).
      const bool behavior_lost =
          behavior ? behavior->misspelt_option : !section->behavior.empty();
      if (!produces(features, info->producer) && !behavior_lost) ++without_producer;
      if (info->producer == OutputProducer::Derived) {
        std::vector<std::string> names = derived_columns(id, behavior, reported_behaviors);
        if (names.empty() && (id.derived_name.empty() || !behavior) && !behavior_lost) {
          ++without_producer;
        }
        for (const std::string& name : names) {
          if (!totals_only) {
            add_target_column(label_id(output_column_label(id.variable, 0, name)), false, e, id,
                              duplicate_reported);
          }
        }
        continue;
      }
      const std::uint8_t defined =
          static_cast<std::uint8_t>(section->available | section->constrained);
      if (id.components == 0) {
        if (!totals_only) {
          add_target_column(component_label(labels, id.variable, 0), false, e, id,
                            duplicate_reported);
        }
        continue;
      }
      const bool chosen = id.explicit_component || id.components != kAll;
      if (chosen && (id.components & defined) == 0) {
        if (std::find(reported_sections.begin(), reported_sections.end(), section) ==
            reported_sections.end()) {
          reported_sections.push_back(section);
          component_missing(id, *section, defined);
        }
        continue;
      }
      for (int c = 1; c <= 6; ++c) {
        if (!(id.components & defined & (1u << (c - 1)))) continue;
        total_components |= static_cast<std::uint8_t>(1u << (c - 1));
        if (!totals_only) {
          add_target_column(component_label(labels, id.variable, c), false, e, id,
                            duplicate_reported);
        }
      }
    }
    const std::string set_name = set_label(set, true);
    if (!elements.empty() && matching == 0) {
      sink_.report(DiagCode::output_no_behavior, id.loc,
                   fmt::format("{} is not defined for the elements of '{}' (no {} elements); "
                               "no column is written",
                               id.text, set_name, spring_variable ? "spring" : "connector"));
      return;
    }
    if (without_producer > 0) {
      std::string why = info->producer_text;
      if (info->producer == OutputProducer::Derived) {
        why = fmt::format("derived component used in a {} context",
                          id.variable == "CDERF" ? "force" : "motion");
      }
      sink_.report(DiagCode::output_no_behavior, id.loc,
                   fmt::format("{} for {} element{} of '{}' is always 0 (no {})", id.text,
                               without_producer, without_producer == 1 ? "" : "s", set_name, why));
    }
    if (totals) {
      for (int c = 1; c <= 6; ++c) {
        if (!(total_components & (1u << (c - 1)))) continue;
        add_set_column(output_column_label(id.variable, spring_variable ? 1 : c) + "@" + set_name,
                       id, duplicate_reported);
      }
    }
  }

  void node_identifier(const OutputIdentifier& id, const TargetRef& set,
                       const std::vector<std::int32_t>& nodes, PrintRequest::Totals totals) {
    bool duplicate_reported = false;
    std::uint8_t total_components = 0;
    ComponentLabels labels;
    for (std::int32_t n : nodes) {
      // A DOF that is not active at the node has no column (output-variables.md §3).
      const std::uint8_t components =
          static_cast<std::uint8_t>(id.components & active_[static_cast<std::size_t>(n)]);
      total_components |= components;
      if (totals == PrintRequest::Totals::Only) continue;
      for (int c = 1; c <= 6; ++c) {
        if (!(components & (1u << (c - 1)))) continue;
        add_target_column(component_label(labels, id.variable, c), true, n, id, duplicate_reported);
      }
    }
    if (totals == PrintRequest::Totals::No) return;
    const std::string set_name = set_label(set, false);
    for (int c = 1; c <= 6; ++c) {
      if (!(total_components & (1u << (c - 1)))) continue;
      add_set_column(output_column_label(id.variable, c) + "@" + set_name, id, duplicate_reported);
    }
  }

  const Model& model_;
  const std::vector<DofMask>& active_;
  DiagnosticSink& sink_;
  std::unordered_map<std::string, SourceLoc> set_columns_;
  // The identifier that first asked for each column (the model outlives the validation). A
  // pointer rather than its location keeps a map node at 24 bytes: a request over 10⁵ elements
  // inserts over 10⁶ of them.
  std::unordered_map<std::uint64_t, const OutputIdentifier*> target_columns_;
  std::unordered_map<std::string, int> label_ids_;  // column labels of the whole deck
  std::vector<std::string> labels_;
};

}  // namespace

void resolve_output_requests(Model& model, const std::vector<DofMask>& active,
                             DiagnosticSink& sink) {
  OutputValidator(model, active, sink).run(model.history.steps);
}

}  // namespace clinch
