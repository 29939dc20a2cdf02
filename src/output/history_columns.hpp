// Which history columns a run writes and how each gets its value (cli-contract.md "History
// table", output-variables.md §1–§4, keywords.md §17–§18): requests carried across steps (OP,
// print replacement), expanded to `<VAR>@<where>` columns over the union of all steps, the
// default request when the deck has none, and per-request FREQUENCY with repetition of values
// that are not due.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "src/assembly/connector_system.hpp"
#include "src/behavior/potential/derived_component.hpp"
#include "src/model/model.hpp"

namespace clinch {

class HistoryColumns {
 public:
  HistoryColumns(const Model& model, const AnalysisPlan& plan);
  // Not copyable or movable: the name index points at names_.
  HistoryColumns(const HistoryColumns&) = delete;
  HistoryColumns& operator=(const HistoryColumns&) = delete;

  const std::vector<std::string>& names() const { return names_; }
  // Makes the requests of step `step` (0-based) current.
  void begin_step(std::size_t step);
  // True when a row is due at increment `increment` of the current step, which ends at
  // `step_time` (`last`: the step's last).
  bool due(int increment, double step_time, bool last) const;
  // Fills `values` (one per column) for the current state; columns of requests that are not due
  // keep their previous value.
  void evaluate(ConnectorSystem& system, int increment, double step_time, bool last,
                std::vector<double>& values);

 private:
  enum class Source : std::uint8_t { Connector, Spring, Node, Model };
  struct Term {  // one contribution to a column (a total sums several)
    Source source = Source::Connector;
    std::int32_t index = 0;  // connector, spring (global indices), or global node
  };
  struct Column {
    std::string_view variable;  // canonical identifier (OutputVariableInfo::name)
    int component = 0;          // 1…6, 0 for scalars
    // Its terms, terms_[first_term, first_term + term_count): one array for every column keeps
    // the setup of 10⁶ columns to two flat arrays (docs/performance.md).
    std::uint32_t first_term = 0, term_count = 0;
    std::int32_t derived = -1;  // CDERF/CDERU: index into derived_
    // CDERF: the force of its first context (derived-components-and-potentials.md §4).
    enum class DerivedForce : std::uint8_t { Elastic, Friction, Connector };
    DerivedForce derived_force = DerivedForce::Elastic;
  };
  struct Request {
    int frequency = 1;
    std::optional<double> time_interval;  // TIME INTERVAL or NUMBER INTERVAL in step time
    std::vector<std::size_t> columns;
    bool due(int increment, double step_time, bool last) const;
  };
  // Hash and equality of column indices by their names in names_, and of a name with an index:
  // the set of columns can be searched by name without holding a second copy of every name.
  struct NameHash {
    using is_transparent = void;
    const std::vector<std::string>* names;
    std::size_t operator()(std::string_view name) const {
      return std::hash<std::string_view>{}(name);
    }
    std::size_t operator()(std::size_t index) const { return (*this)((*names)[index]); }
  };
  struct NameEqual {
    using is_transparent = void;
    const std::vector<std::string>* names;
    std::string_view name(std::string_view text) const { return text; }
    std::string_view name(std::size_t index) const { return (*names)[index]; }
    template <typename A, typename B>
    bool operator()(const A& a, const B& b) const {
      return name(a) == name(b);
    }
  };
  // The index of the column called `name`, added with `column` and `terms` when there is none
  // yet.
  std::size_t column(const std::string& name, Column column, std::span<const Term> terms);
  void expand_steps();
  void add_load_factor_column();
  std::vector<Request> expand_step(const Step* step,
                                   const std::vector<const OutputRequest*>& outputs,
                                   const std::vector<const PrintRequest*>& prints,
                                   bool default_request);
  void element_columns(const OutputIdentifier& id, std::span<const std::int32_t> elements,
                       Request& request, bool totals, bool totals_only, const std::string& set);
  void derived_columns(const OutputIdentifier& id, std::span<const std::int32_t> elements,
                       Request& request);
  std::int32_t derived_component(std::int32_t behavior_index, const ConnectorBehavior& behavior,
                                 const std::string& key);
  void node_columns(const OutputIdentifier& id, const std::vector<std::int32_t>& nodes,
                    Request& request, bool totals, bool totals_only, const std::string& set);
  void total_columns(std::string_view variable, const std::array<std::vector<Term>, 7>& sums,
                     Request& request, const std::string& set);
  // The part of a column from elements a distributed model holds on one rank each (springs, and
  // connectors under a plan with a share of them): whether it has one, and the sum of those this
  // rank holds.
  struct RankPart {
    bool present = false;
    double sum = 0.0;
  };
  // A column's value but for its rank part, which goes to `part`.
  double value(const Column& column, ConnectorSystem& system, RankPart& part);
  double connector_term(const Column& column, const ConnectorOutput& out) const;
  std::vector<std::size_t> part_columns_;  // of the row being evaluated, with their sums
  std::vector<double> part_sums_;
  std::vector<std::uint64_t> evaluated_in_row_;  // per column: the row_ that last evaluated it
  std::uint64_t row_ = 0;
  // The section of connector element `e`.
  const ConnectorSection& section_of(std::int32_t e) const {
    return model_.sections.connector_sections[static_cast<std::size_t>(
        model_.sections.section_of_element[static_cast<std::size_t>(e)])];
  }

  const Model& model_;
  const AnalysisPlan& plan_;
  std::vector<DofMask> active_;
  std::vector<std::string> names_;
  std::unordered_set<std::size_t, NameHash, NameEqual> column_of_name_{0, NameHash{&names_},
                                                                       NameEqual{&names_}};
  bool index_names_ = true;  // false while the default output is built (its names are unique)
  std::vector<Column> columns_;
  std::vector<Term> terms_;
  std::vector<std::vector<Request>> step_requests_;
  std::size_t step_ = 0;
  std::vector<DerivedComponent> derived_;  // compiled once per (behaviour, name)
  // The current row's evaluation of the last connector read: a connector's columns are adjacent
  // in the default output and in each identifier of a request, so each is evaluated about once
  // per row without holding every connector's output (a map of them took 0.5 kB per connector).
  std::int32_t output_connector_ = -1;
  ConnectorOutput output_;
  std::map<std::pair<std::int32_t, std::string>, std::int32_t> derived_index_;
};

}  // namespace clinch
