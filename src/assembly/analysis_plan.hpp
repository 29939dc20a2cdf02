// The analysis plan (ARCHITECTURE.md principle 9): what a run needs from the model, built once.
// Active DOFs and their equations, one record per connector and spring with its kinematics, law
// stack and equations, one multiplier per connector component that can ever be constrained
// (connection constraints, RIGID elasticity, stops, locks, connector motions), the size of the
// laws' history and what the laws ask of the procedure. Nothing here changes during the analysis
// (assembly_pattern.hpp says where each element's entries go).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "src/assembly/dependent_dofs.hpp"
#include "src/assembly/dof_map.hpp"
#include "src/assembly/equation_layout.hpp"
#include "src/assembly/nodal_inertia.hpp"
#include "src/behavior/behavior.hpp"
#include "src/behavior/elastic/spring_law.hpp"
#include "src/kinematics/connector_kinematics.hpp"
#include "src/linalg/linear_solver.hpp"
#include "src/model/model.hpp"

namespace clinch {

constexpr int kMaxLocalEquations = 18;  // 12 nodal columns + 6 multipliers

// The equations of one element, in local order (AssemblyPattern says where its entries go).
struct LocalEquations {
  std::array<int, kMaxLocalEquations> equation{};
  int count = 0;
};

// The equations of an element with dependent DOFs once they are condensed
// (constrained_elements.hpp).
struct ElementExpansion {
  // Its independent nodal equations, those its dependent DOFs depend on, then its multipliers.
  std::vector<int> equations;
  std::vector<std::int16_t> place;  // per local row: its place in `equations`, −1 if dependent
  std::vector<std::int16_t> term_place;  // the places of the dependent rows' gradients, in order
};

// A connector's laws in the order of behaviors.md §1.3, each with the offset of its history in
// the analysis state's history array.
struct LawSlot {
  const Behavior* law = nullptr;
  std::size_t history = 0;
  // The law's part of a history array of the analysis state (trial or converged).
  std::span<const double> history_in(std::span<const double> histories) const {
    return histories.subspan(history, law->history_size());
  }
};
struct LawStack {
  // elastic-plastic, damage, damping, five friction definitions
  static constexpr int kMaxLaws = 8;
  std::array<LawSlot, kMaxLaws> slots{};
  int count = 0;
  bool needs_connector_forces = false;  // some law reads the constraint forces
  bool symmetric = true;                // every law's tangent is symmetric
  const LawSlot* begin() const { return slots.data(); }
  const LawSlot* end() const { return slots.data() + count; }
  bool empty() const { return count == 0; }
};

struct ConnectorStopLimits {
  std::optional<double> lower, upper;  // on the position p_i (behaviors.md §5.1)
};
// The stop limits of components 1…6 of a section's connectors, shared by them.
using ConnectorStops = std::array<ConnectorStopLimits, 6>;

struct ConnectorLockRule {
  int component = 0;  // tested component
  ComponentMask locks = 0;
  ConnectorCriterionBounds bounds;
};

// *CONNECTOR FAILURE (behaviors.md §5.3): a criterion on `component`, releasing `releases`.
struct ConnectorReleaseRule {
  int component = 0;
  ComponentMask releases = 0;
  ConnectorCriterionBounds bounds;
};

struct ConnectorRecord {
  std::int32_t element = 0;  // global element index
  std::int32_t section = 0;
  std::array<std::int32_t, 2> nodes{kGround, kGround};
  std::size_t kinematics = 0;  // into AnalysisPlan::kinematics
  LawStack laws;
  ComponentMask available = 0, constrained = 0, rigid = 0;
  Vector6 reference = Vector6::Zero();    // ref_i: u = p − ref (behaviors.md §3)
  const ConnectorStops* stops = nullptr;  // into AnalysisPlan::stop_tables; null: no stops
  std::vector<ConnectorLockRule> locks;
  std::vector<ConnectorReleaseRule> failures;
  // Local columns 0…11 of [u_a, θ_a, u_b, θ_b] that have an equation, in order; then the
  // components that own a multiplier.
  std::array<std::int8_t, 12> columns{};
  int column_count = 0;
  std::array<std::int8_t, 6> multiplier_components{};
  int multiplier_count = 0;
  LocalEquations local;
  std::int32_t expansion = -1;  // into AnalysisPlan::expansions when a DOF is dependent

  // The stop limits of component i (1…6); neither limit when the connector has no stops.
  const ConnectorStopLimits& stop(int i) const {
    static const ConnectorStopLimits kNone;
    return stops ? (*stops)[static_cast<std::size_t>(i - 1)] : kNone;
  }
};

// A spring or dashpot element: a dashpot has the nodes and kinematics of the spring `type`, and
// its law gives the force against the rate of Δ (behaviors.md §8).
struct SpringRecord {
  std::int32_t element = 0;
  ElementType type = ElementType::SpringA;  // SPRINGA, SPRING1 or SPRING2 (spring_form)
  bool dashpot = false;
  std::array<std::int32_t, 2> nodes{kGround, kGround};
  std::size_t law = 0;  // into AnalysisPlan::spring_laws
  // SPRINGA: the initial vector between the nodes. SPRING1/2: the direction of the DOF at each
  // node (global axis or the orientation's local axis), and whether it is a rotation.
  Vector3 d0 = Vector3::Zero();
  std::array<Vector3, 2> direction{Vector3::Zero(), Vector3::Zero()};
  bool rotational = false;
  LocalEquations local;
  std::int32_t expansion = -1;           // into AnalysisPlan::expansions when a DOF is dependent
  std::array<std::int8_t, 6> columns{};  // SPRINGA: 0–2 node 1, 3–5 node 2; SPRING1/2: 0–2 / 3–5
  int column_count = 0;
};

struct AnalysisPlan {
  // Some step runs with NLGEOM=NO (the connectors keep their linearised kinematics); false when
  // the deck is NLGEOM throughout, which the system then is from the start.
  bool small_displacement = true;
  DofMap dofs;
  std::vector<ConnectorKinematics> kinematics;
  // What the laws of the model ask of the procedure, merged (procedure_needs.hpp).
  ProcedureNeeds procedure_needs;
  std::vector<std::unique_ptr<Behavior>> behaviors;          // the laws of each section's behaviour
  std::vector<std::unique_ptr<ConnectorStops>> stop_tables;  // one per section that has stops
  // Per connector section: its stops (into stop_tables), null when it has none.
  std::vector<const ConnectorStops*> section_stops;
  // Every connector of the model (connector_total of them, in element order), or in a rank's plan
  // (build_analysis_plan with a share) the connectors first_connector … first_connector +
  // connectors.size() − 1 of them. The plan's, the state's and the system's arrays per connector
  // follow this plan's records; a connector's global index (connector_of_element, the conditions,
  // the history columns) is first_connector plus its place here.
  std::vector<ConnectorRecord> connectors;
  std::size_t first_connector = 0, connector_total = 0;
  std::vector<std::int32_t> connector_of_element;     // global element → global connector (−1)
  std::vector<std::optional<SpringLaw>> spring_laws;  // per *SPRING (empty when invalid)
  // Every spring of the model (spring_total of them, in element order), or in a rank's plan
  // (build_analysis_plan with a share) the springs first_spring … first_spring + springs.size()
  // − 1 of them.
  std::vector<SpringRecord> springs;
  std::size_t first_spring = 0, spring_total = 0;
  std::vector<std::int32_t> spring_of_element;  // global element → spring (−1)
  // The DOFs kinematic constraints eliminate, and the elements that have some.
  DependentDofs dependents;
  std::vector<ElementExpansion> expansions;
  // The nodes with MASS or ROTARYI elements, when some step is *DYNAMIC or *FREQUENCY (empty
  // otherwise: a static step does not use inertia).
  std::vector<NodeInertia> inertia;
  // In a rank's plan over its own equations (layout.local) `inertia` holds the nodes the rank
  // holds, the owned_inertia it owns first: it adds their inertia to its rows, and a ghost's
  // record gives the ghost the finite rotary rates its owner computes.
  std::size_t owned_inertia = 0;
  // Some node turns its rotary inertia under NLGEOM (rotary_inertia_finite.hpp), on any rank.
  bool finite_rotary_inertia = false;
  bool dynamic = false;  // some step is *DYNAMIC (the state keeps velocities, accelerations)
  // Some *STATIC step has STABILIZE (stabilization_damping.hpp).
  bool stabilized = false;
  // The run keeps the whole-model energies (energy_balance.hpp): a dynamic or stabilized step, or
  // a step requests them (*ENERGY OUTPUT).
  bool energies = false;
  std::size_t history_size = 0;
  double length_scale = 1.0;  // L̄: largest initial connector length (keywords.md §16)
  bool two_d = false;
  bool has_multipliers = false;
  // Every law of every connector of the model returns a symmetric tangent.
  bool all_laws_symmetric = true;
  // This plan holds one rank's share of the connectors and springs (build_analysis_plan), and
  // how many multipliers the connectors of each rank's share have.
  bool shared = false;
  std::vector<int> share_multipliers;
  // Which equations the vectors of this rank run over: with layout.local, those of its own rows
  // and the ghosts its elements read, numbered by `dofs` (equation_layout.hpp); solved_layout
  // the same for Newton's unknowns and the solver's rows, the equations less the dependent ones
  // (equal to layout when no DOF is dependent).
  EquationLayout layout, solved_layout;

  // Appends `law` to the stack of connector record `c`, with history of its own.
  void add_law(std::size_t c, const Behavior& law);
  // True when every law of every connector returns a symmetric tangent.
  bool laws_symmetric() const { return all_laws_symmetric; }
  const SpringRecord& spring(std::size_t s) const { return springs[s - first_spring]; }
  // The inertia this plan adds to the equations: of the nodes a rank owns, or of every node.
  std::span<const NodeInertia> own_inertia() const {
    return layout.local ? std::span<const NodeInertia>(inertia.data(), owned_inertia)
                        : std::span<const NodeInertia>(inertia);
  }
  // Connector `c` (global index), of those whose records this plan holds.
  bool holds_connector(std::size_t c) const {
    return c >= first_connector && c < first_connector + connectors.size();
  }
};

// The record of spring element `e` of the model (a rank's plan holds only its share of them).
SpringRecord spring_record(const Model& model, const DofMap& dofs, std::int32_t e);

struct PlanShare {
  int rank = 0, ranks = 1;
  // The vectors by rows too (equation_layout.hpp).
  bool local_vectors = false;
};
// Builds the plan of a validated model (no errors). Returns nullopt with `error` when the model
// asks for something clinch run cannot do yet. With `share` (a distributed model under assembly
// by rows, docs/parallel.md), the plan of rank `rank` of `ranks`: the records of its share of
// the connectors and of the springs (share_of of each, in element order), over the rank's own
// equations when the share asks for local vectors and nothing needs them whole.
std::optional<AnalysisPlan> build_analysis_plan(const Model& model, std::string* error,
                                                const PlanShare* share = nullptr);

}  // namespace clinch
