#include "src/output/history_columns.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include "src/model/output_variables.hpp"
#include "src/model/potential_queries.hpp"

namespace clinch {
namespace {

// A whole-model column: LPF (docs/riks.md) or an energy (energy_balance.hpp).
double model_value(std::string_view variable, const ConnectorSystem& system) {
  if (variable == "LPF") return system.load_factor();
  const ModelEnergies e = system.energies();
  if (variable == "ALLKE") return e.kinetic;
  if (variable == "ALLIE") return e.internal;
  if (variable == "ALLFD") return e.frictional;
  if (variable == "ALLVD") return e.viscous;
  if (variable == "ALLSD") return e.stabilization;
  if (variable == "ALLWK") return e.work;
  return e.total();  // ETOTAL
}

std::string set_label(const TargetRef& set, bool element) {
  if (set.is_label) return describe(set, element);
  return set.instance_display.empty() ? set.set_display
                                      : set.instance_display + "." + set.set_display;
}

// Connector quantities of output-variables.md §2 that clinch run produces (CV and CA: 0 outside
// a dynamic step); every other connector identifier is 0 for the behaviours a run accepts.
double connector_value(const ConnectorOutput& out, std::string_view variable, int component) {
  if (variable == "CUPEQ" && component == 0) return out.scalar_equivalent_plastic();
  // friction.md §6: the scalar outputs of a coupled friction definition. Damage (behaviors.md
  // §7): CDMG and the criteria, as scalars (component 0), per component and coupled.
  if (variable == "CUPEQC" || variable == "CSFC" || variable == "CNFC" || variable == "CASUC" ||
      variable == "CDMG" || variable == "CDIF" || variable == "CDIM" || variable == "CDIP" ||
      variable == "CDIFC" || variable == "CDIMC" || variable == "CDIPC") {
    return out.history_value(variable, component);
  }
  if (component < 1) return 0.0;
  const int i = component - 1;
  if (variable == "CTF") return out.total[i];
  if (variable == "CEF") return out.elastic[i];
  if (variable == "CRF") return out.multiplier[i];
  if (variable == "CCF") return out.applied[i];
  if (variable == "CU") return out.change[i];
  if (variable == "CCU") return out.constitutive[i];
  if (variable == "CUE") return out.constitutive[i] - out.history_value("CUP", component);
  if (variable == "CSF") return out.friction[i];
  if (variable == "CVF") return out.viscous[i];
  if (variable == "CUP" || variable == "CUPEQ" || variable == "CALPHAF" || variable == "CNF" ||
      variable == "CSLIPST" || variable == "CASU") {
    return out.history_value(variable, component);
  }
  if (variable == "CP") return out.position[i];
  if (variable == "CV") return out.velocity[i];
  if (variable == "CA") return out.acceleration[i];
  if (variable == "CSLST") return out.status[static_cast<std::size_t>(i)];
  return 0.0;
}

}  // namespace

HistoryColumns::HistoryColumns(const Model& model, const AnalysisPlan& plan)
    : model_(model), plan_(plan), active_(active_dofs(model)) {
  expand_steps();
}

std::size_t HistoryColumns::column(const std::string& name, Column c, std::span<const Term> terms) {
  if (index_names_) {
    if (const auto it = column_of_name_.find(std::string_view(name)); it != column_of_name_.end()) {
      return *it;
    }
  }
  names_.push_back(name);
  c.first_term = static_cast<std::uint32_t>(terms_.size());
  c.term_count = static_cast<std::uint32_t>(terms.size());
  terms_.insert(terms_.end(), terms.begin(), terms.end());
  columns_.push_back(c);
  if (index_names_) column_of_name_.insert(names_.size() - 1);
  return names_.size() - 1;
}

void HistoryColumns::expand_steps() {
  bool any_request = false;
  for (const Step& step : model_.history.steps) {
    for (const OutputRequest& r : step.outputs) any_request |= !r.field;
    any_request |= !step.prints.empty();
  }
  if (!any_request) {
    // The default output (output-variables.md §4), the same in every step: one column per
    // connector, variable and component, so no name repeats. Built once and without the name
    // index, which over 10⁶ connectors took longer than the columns themselves.
    index_names_ = false;
    const std::vector<Request> requests = expand_step(nullptr, {}, {}, true);
    index_names_ = true;
    step_requests_.assign(model_.history.steps.size(), requests);
    add_load_factor_column();
    return;
  }
  // Requests carry over (keywords.md §13, §17, §18): history_requests_in_force for *OUTPUT; the
  // first *NODE PRINT (*EL PRINT) of a step replaces the earlier ones.
  const std::vector<std::vector<const OutputRequest*>> in_force =
      history_requests_in_force(model_.history);
  std::vector<const PrintRequest*> node_prints, element_prints;
  for (std::size_t s = 0; s < model_.history.steps.size(); ++s) {
    const Step& step = model_.history.steps[s];
    bool new_node_prints = false, new_element_prints = false;
    for (const PrintRequest& p : step.prints) {
      bool& replaced = p.node ? new_node_prints : new_element_prints;
      std::vector<const PrintRequest*>& list = p.node ? node_prints : element_prints;
      if (!replaced) list.clear();
      replaced = true;
      list.push_back(&p);
    }
    std::vector<const PrintRequest*> prints = node_prints;
    prints.insert(prints.end(), element_prints.begin(), element_prints.end());
    step_requests_.push_back(expand_step(&step, in_force[s], prints, false));
  }
  add_load_factor_column();
}

// A model with a Riks step has the column LPF in every step (docs/riks.md): the load
// proportionality factor there, the fraction of the step's ramps elsewhere.
void HistoryColumns::add_load_factor_column() {
  const auto& steps = model_.history.steps;
  if (std::none_of(steps.begin(), steps.end(),
                   [](const Step& s) { return s.procedure && s.procedure->riks; })) {
    return;
  }
  Column c;
  c.variable = "LPF";
  const Term term{Source::Model, 0};
  const std::size_t column_index = column("LPF", c, std::span(&term, 1));
  for (std::vector<Request>& requests : step_requests_) {
    requests.push_back(Request{1, std::nullopt, {column_index}});
  }
}

std::vector<HistoryColumns::Request> HistoryColumns::expand_step(
    const Step* step, const std::vector<const OutputRequest*>& outputs,
    const std::vector<const PrintRequest*>& prints, bool default_request) {
  std::vector<Request> requests;
  // `among`: the elements of an *ELEMENT OUTPUT, VARIABLE=PRESELECT block (else every connector).
  auto default_columns = [&](Request& request, const std::vector<std::int32_t>* among = nullptr) {
    // output-variables.md §4: CTF, CU, then the variables of the behaviours in use, per
    // connector in label order.
    std::vector<std::int32_t> connectors;
    if (among) {
      for (std::int32_t e : *among) {
        if (plan_.connector_of_element[static_cast<std::size_t>(e)] >= 0) connectors.push_back(e);
      }
    } else {
      connectors.reserve(plan_.connector_total);
      for (std::size_t e = 0; e < plan_.connector_of_element.size(); ++e) {
        if (plan_.connector_of_element[e] >= 0) connectors.push_back(static_cast<std::int32_t>(e));
      }
    }
    std::size_t least = names_.size();  // CTF and CU of every component
    for (std::int32_t e : connectors) {
      const ConnectorSection& section = section_of(e);
      const auto components = static_cast<unsigned>(section.available | section.constrained);
      least += 2 * static_cast<std::size_t>(std::popcount(components));
    }
    // Reserved once rather than regrown (and rehashed) step by step over 10⁶ connectors.
    names_.reserve(least);
    columns_.reserve(least);
    terms_.reserve(terms_.size() + least - names_.size());
    if (index_names_) column_of_name_.reserve(least);
    std::sort(connectors.begin(), connectors.end(), [&](std::int32_t a, std::int32_t b) {
      const Element& ea = model_.elements[static_cast<std::size_t>(a)];
      const Element& eb = model_.elements[static_cast<std::size_t>(b)];
      return std::tie(ea.instance, ea.label) < std::tie(eb.instance, eb.label);
    });
    // Elements a *CONNECTOR MOTION drives in some step: their reaction (CRF) is the force of the
    // actuator, which the total force CTF no longer shows (output-variables.md §4).
    std::vector<bool> driven(model_.elements.size(), false);
    auto mark_driven = [&](const std::vector<ConnectorCondition>& motions) {
      for (const ConnectorCondition& m : motions) {
        for (std::int32_t e : m.resolved) driven[static_cast<std::size_t>(e)] = true;
      }
    };
    mark_driven(model_.history.model_motions);
    for (const Step& step : model_.history.steps) mark_driven(step.motions);
    // Per behaviour, once: its features (connectors share a few behaviours).
    std::vector<std::optional<BehaviorFeatures>> features_of(model_.behaviors.behaviors.size());
    std::vector<const char*> variables;
    OutputIdentifier id;
    for (std::int32_t e : connectors) {
      const std::int32_t s = model_.sections.section_of_element[static_cast<std::size_t>(e)];
      const std::int32_t b = section_of(e).behavior_index;
      if (b >= 0 && !features_of[static_cast<std::size_t>(b)]) {
        features_of[static_cast<std::size_t>(b)] =
            behavior_features(model_.behaviors.behaviors[static_cast<std::size_t>(b)]);
      }
      const BehaviorFeatures features =
          b >= 0 ? *features_of[static_cast<std::size_t>(b)] : BehaviorFeatures{};
      variables.assign({"CTF", "CU"});
      if (features.plasticity) variables.insert(variables.end(), {"CUP", "CUPEQ"});
      // Damage: CDMG and the criteria in use, as scalars (§4).
      if (features.damage) variables.push_back("CDMG");
      if (features.force_criterion) variables.push_back("CDIF");
      if (features.motion_criterion) variables.push_back("CDIM");
      if (features.plastic_motion_criterion) variables.push_back("CDIP");
      bool stops = b >= 0 && !model_.behaviors.behaviors[static_cast<std::size_t>(b)].locks.empty();
      stops |= plan_.section_stops[static_cast<std::size_t>(s)] != nullptr;
      if (stops)
        variables.insert(variables.end(), {"CRF", "CSLST"});
      else if (driven[static_cast<std::size_t>(e)])
        variables.push_back("CRF");
      if (features.friction) variables.insert(variables.end(), {"CSF", "CNF", "CASU"});
      if (features.kinematic_hardening) variables.push_back("CALPHAF");
      for (const char* v : variables) {
        id.variable = v;
        const std::string_view name = v;
        const bool scalar =
            name == "CUPEQ" || name == "CDMG" || name == "CDIF" || name == "CDIM" || name == "CDIP";
        id.components = scalar ? 0 : 0b111111;  // the scalars of §1.2
        element_columns(id, std::span(&e, 1), request, false, false, "");
      }
    }
  };
  for (const OutputRequest* r : outputs) {
    Request request;
    request.frequency = r->frequency;
    request.time_interval = output_time_interval(*r, *step);
    if (r->variables != OutputRequest::Variables::Listed) default_columns(request);
    for (const ElementOutputRequest& block : r->elements) {
      if (!block.has_elset) continue;
      if (block.preselect) default_columns(request, &block.resolved);
      for (const OutputIdentifier& id : block.identifiers) {
        element_columns(id, block.resolved, request, false, false, "");
      }
    }
    for (const NodeOutputRequest& block : r->nodes) {
      if (!block.has_nset) continue;
      for (const OutputIdentifier& id : block.identifiers) {
        node_columns(id, block.resolved, request, false, false, "");
      }
    }
    // Whole-model energies: one column each, named as the variable (docs/dynamics.md).
    for (const OutputIdentifier& id : r->energies) {
      Column c;
      c.variable = output_variable_info(id.variable)->name;
      const Term term{Source::Model, 0};
      request.columns.push_back(column(std::string(c.variable), c, std::span(&term, 1)));
    }
    requests.push_back(std::move(request));
  }
  for (const PrintRequest* p : prints) {
    Request request;
    request.frequency = p->frequency;
    if (p->has_set || p->all) {
      const bool totals = p->totals != PrintRequest::Totals::No;
      const bool only = p->totals == PrintRequest::Totals::Only;
      const std::string set = set_label(p->set, !p->node);
      for (const OutputIdentifier& id : p->identifiers) {
        if (p->node)
          node_columns(id, p->resolved, request, totals, only, set);
        else
          element_columns(id, p->resolved, request, totals, only, set);
      }
    }
    requests.push_back(std::move(request));
  }
  if (default_request) {
    Request request;
    default_columns(request);
    requests.push_back(std::move(request));
  }
  return requests;
}

// TOTALS=YES/ONLY (keywords.md §18): one column per component, `<VAR>@<set>`, summing the terms.
void HistoryColumns::total_columns(std::string_view variable,
                                   const std::array<std::vector<Term>, 7>& sums, Request& request,
                                   const std::string& set) {
  for (int k = 1; k <= 6; ++k) {
    const std::vector<Term>& terms = sums[static_cast<std::size_t>(k)];
    if (terms.empty()) continue;
    request.columns.push_back(
        column(output_column_label(variable, k) + "@" + set, {variable, k}, terms));
  }
}

void HistoryColumns::element_columns(const OutputIdentifier& id,
                                     std::span<const std::int32_t> elements, Request& request,
                                     bool totals, bool totals_only, const std::string& set) {
  const OutputVariableInfo* info = output_variable_info(id.variable);
  if (!info) return;
  if (info->producer == OutputProducer::Derived) {
    derived_columns(id, elements, request);
    return;
  }
  const bool spring_variable = info->kind == OutputKind::Spring;
  const std::string_view variable = info->name;
  std::array<std::vector<Term>, 7> sums;
  for (std::int32_t e : elements) {
    const Element& element = model_.elements[static_cast<std::size_t>(e)];
    if (is_spring_or_dashpot(element.type) != spring_variable) continue;
    const std::string where = qualified_label(model_, element.instance, element.label);
    if (spring_variable) {
      const Term term{Source::Spring, plan_.spring_of_element[static_cast<std::size_t>(e)]};
      if (totals) sums[1].push_back(term);
      if (!totals_only) {
        request.columns.push_back(
            column(output_column_label(id.variable, 1) + "@" + where, {variable, 1}, {&term, 1}));
      }
      continue;
    }
    const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
    if (c < 0) continue;
    const ConnectorSection& section = section_of(e);
    const Term term{Source::Connector, c};
    if (id.components == 0) {
      if (!totals_only) {
        request.columns.push_back(column(id.variable + "@" + where, {variable, 0}, {&term, 1}));
      }
      continue;
    }
    const ComponentMask defined = section.available | section.constrained;
    for (int k = 1; k <= 6; ++k) {
      if (!(id.components & defined & (1u << (k - 1)))) continue;
      if (totals) sums[static_cast<std::size_t>(k)].push_back(term);
      if (!totals_only) {
        request.columns.push_back(
            column(output_column_label(id.variable, k) + "@" + where, {variable, k}, {&term, 1}));
      }
    }
  }
  if (totals) total_columns(variable, sums, request, set);
}

// CDERF-<name> / CDERU-<name> (derived-components-and-potentials.md §4): one column per element
// and derived component; a bare request lists every derived component with a context of its kind.
void HistoryColumns::derived_columns(const OutputIdentifier& id,
                                     std::span<const std::int32_t> elements, Request& request) {
  const bool force = id.variable == "CDERF";
  for (std::int32_t e : elements) {
    const std::int32_t c = plan_.connector_of_element[static_cast<std::size_t>(e)];
    if (c < 0) continue;
    const std::int32_t b = section_of(e).behavior_index;
    if (b < 0) continue;
    const ConnectorBehavior& behavior = model_.behaviors.behaviors[static_cast<std::size_t>(b)];
    std::vector<std::int32_t> terms;
    if (id.derived_name.empty()) {
      terms = derived_output_terms(behavior, force);
    } else if (const std::string key = name_key(id.derived_name, false);
               first_derived_context(behavior, key, force)) {
      terms.push_back(find_derived_component(behavior, key));
    }
    const Element& element = model_.elements[static_cast<std::size_t>(e)];
    const std::string where = qualified_label(model_, element.instance, element.label);
    for (std::int32_t t : terms) {
      const Name& name = behavior.derived_terms[static_cast<std::size_t>(t)].name;
      Column column_data{output_variable_info(id.variable)->name, 0};
      const Term term{Source::Connector, c};
      column_data.derived = derived_component(b, behavior, name.key);
      if (const auto use = first_derived_context(behavior, name.key, true); force && use) {
        // A friction potential acts on the friction force, a CONTACT FORCE on the connector
        // force the contact measure reads (friction.md §2.2; with the friction force included).
        if (use->kind == DerivedContextKind::FrictionPotential) {
          column_data.derived_force = Column::DerivedForce::Friction;
        } else if (use->kind == DerivedContextKind::ContactForce) {
          column_data.derived_force = Column::DerivedForce::Connector;
        }
      }
      request.columns.push_back(
          column(output_column_label(id.variable, 0, name.display) + "@" + where, column_data,
                 {&term, 1}));
    }
  }
}

std::int32_t HistoryColumns::derived_component(std::int32_t behavior_index,
                                               const ConnectorBehavior& behavior,
                                               const std::string& key) {
  const auto cache_key = std::make_pair(behavior_index, key);
  if (const auto it = derived_index_.find(cache_key); it != derived_index_.end()) {
    return it->second;
  }
  derived_.push_back(DerivedComponent::compile(behavior, key));
  const auto index = static_cast<std::int32_t>(derived_.size() - 1);
  derived_index_.emplace(cache_key, index);
  return index;
}

void HistoryColumns::node_columns(const OutputIdentifier& id,
                                  const std::vector<std::int32_t>& nodes, Request& request,
                                  bool totals, bool totals_only, const std::string& set) {
  const OutputVariableInfo* info = output_variable_info(id.variable);
  if (!info) return;
  std::array<std::vector<Term>, 7> sums;
  for (std::int32_t n : nodes) {
    // A DOF that is not active at the node has no column (output-variables.md §3).
    const auto components =
        static_cast<std::uint8_t>(id.components & active_[static_cast<std::size_t>(n)]);
    const Node& node = model_.nodes[static_cast<std::size_t>(n)];
    const std::string where = qualified_label(model_, node.instance, node.label);
    const Term term{Source::Node, n};
    for (int k = 1; k <= 6; ++k) {
      if (!(components & (1u << (k - 1)))) continue;
      if (totals) sums[static_cast<std::size_t>(k)].push_back(term);
      if (!totals_only) {
        request.columns.push_back(
            column(output_column_label(id.variable, k) + "@" + where, {info->name, k}, {&term, 1}));
      }
    }
  }
  if (totals) total_columns(info->name, sums, request, set);
}

void HistoryColumns::begin_step(std::size_t step) { step_ = step; }

// §17: every FREQUENCY-th increment and the step's last, or the increments that end at a multiple
// of the request's time interval (the time stepper ends increments there) and the step's last.
bool HistoryColumns::Request::due(int increment, double step_time, bool last) const {
  if (increment == 0) return true;
  if (time_interval) {
    const double k = std::round(step_time / *time_interval);
    return last || (k >= 1 && std::abs(step_time - k * *time_interval) <= 1e-9 * step_time);
  }
  return frequency > 0 && (last || increment % frequency == 0);
}

bool HistoryColumns::due(int increment, double step_time, bool last) const {
  if (increment == 0) return true;  // the initial state, also before the first request
  return std::any_of(step_requests_[step_].begin(), step_requests_[step_].end(),
                     [&](const Request& r) { return r.due(increment, step_time, last); });
}

// A connector's contribution to column `c`.
double HistoryColumns::connector_term(const Column& c, const ConnectorOutput& out) const {
  if (c.derived >= 0) {
    // §4: CDERF on the force of the context (plasticity: the elastic-plastic force), CDERU on
    // the constitutive motions.
    const DerivedComponent& g = derived_[static_cast<std::size_t>(c.derived)];
    if (c.variable != "CDERF") return g.value(out.constitutive);
    if (c.derived_force == Column::DerivedForce::Friction) return g.value(out.friction);
    if (c.derived_force == Column::DerivedForce::Connector) {
      return g.value(out.elastic + out.viscous + out.friction + out.multiplier);
    }
    return g.value(out.elastic);
  }
  return connector_value(out, c.variable, c.component);
}

double HistoryColumns::value(const Column& c, ConnectorSystem& system, RankPart& part) {
  double sum = 0;
  for (const Term& t : std::span(terms_).subspan(c.first_term, c.term_count)) {
    switch (t.source) {
      case Source::Connector: {
        // Under a plan with a share of the connectors only the rank that holds one has its
        // results.
        const bool shared = plan_.shared;
        part.present = part.present || shared;
        if (!system.holds_connector(static_cast<std::size_t>(t.index))) break;
        // The connector's results once per run of its columns: an element has many.
        if (t.index != output_connector_) {
          output_ = system.connector_output(static_cast<std::size_t>(t.index));
          output_connector_ = t.index;
        }
        (shared ? part.sum : sum) += connector_term(c, output_);
        break;
      }
      case Source::Spring: {
        // Only the rank that evaluates a spring holds its result (a distributed model).
        part.present = true;
        if (!system.holds_spring(static_cast<std::size_t>(t.index))) break;
        const SpringResult& spring = system.spring_output(static_cast<std::size_t>(t.index));
        part.sum += c.variable == "S" ? spring.force : c.variable == "E" ? spring.delta : 0.0;
        break;
      }
      case Source::Node: {
        // Under vectors by rows only the rank that owns a node's rows gives its values.
        const bool by_rows = system.vectors_by_rows();
        part.present = part.present || by_rows;
        double& into = by_rows ? part.sum : sum;
        if (c.variable == "U" || c.variable == "UT" || c.variable == "UR") {
          into += system.nodal_value(t.index, c.component);
        } else if (c.variable == "RF" || c.variable == "RT" || c.variable == "RM") {
          into += system.reaction(t.index, c.component);
        } else if (c.variable == "CF" || c.variable == "CM") {
          into += system.applied_load(t.index, c.component);
        } else if (c.variable == "V" || c.variable == "VT" || c.variable == "VR") {
          into += system.nodal_rate(t.index, c.component, 1);
        } else if (c.variable == "A" || c.variable == "AT" || c.variable == "AR") {
          into += system.nodal_rate(t.index, c.component, 2);
        }
        break;
      }
      case Source::Model:
        sum += model_value(c.variable, system);
        break;
    }
  }
  return sum;
}

void HistoryColumns::evaluate(ConnectorSystem& system, int increment, double step_time, bool last,
                              std::vector<double>& values) {
  values.resize(columns_.size(), 0.0);
  output_connector_ = -1;  // the state has changed since the last row
  part_columns_.clear();
  part_sums_.clear();
  // Requests share columns (a PRESELECT request and one that lists CU): each is evaluated once.
  evaluated_in_row_.resize(columns_.size(), 0);
  ++row_;
  for (const Request& r : step_requests_[step_]) {
    if (!r.due(increment, step_time, last)) continue;
    for (std::size_t c : r.columns) {
      if (evaluated_in_row_[c] == row_) continue;
      evaluated_in_row_[c] = row_;
      RankPart part;
      values[c] = value(columns_[c], system, part);
      if (!part.present) continue;
      part_columns_.push_back(c);
      part_sums_.push_back(part.sum);
    }
  }
  // Each rank holds the results of its own elements under a distributed model: the rank parts
  // of the due columns, and only those, are summed over the ranks (docs/parallel.md).
  if (plan_.shared) system.sum_over_ranks(std::span<double>(part_sums_));
  for (std::size_t k = 0; k < part_columns_.size(); ++k) {
    values[part_columns_[k]] += part_sums_[k];
  }
}

}  // namespace clinch
