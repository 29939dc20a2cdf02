// Plain data for amplitudes, steps and everything in them: procedure, controls, boundary
// conditions, loads, connector motions and loads, output requests (keywords.md §8–§18). The
// history keyword handlers fill it in deck order; resolve_history resolves references and checks
// the rules that need the whole model. It stores the global nodes or elements each condition,
// load and output request targets (`resolved`; empty when the reference is in error), and the
// run reads those instead of resolving the names again. Steps hold their *effective* NLGEOM and
// controls (what carries over from earlier steps, keywords.md §13), so the step driver reads one
// step at a time.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "src/model/name.hpp"
#include "src/model/references.hpp"

namespace clinch {

// ---- *AMPLITUDE (keywords.md §8) --------------------------------------------------------------

enum class AmplitudeDefinition : std::uint8_t {
  Tabular,
  SmoothStep,
  EquallySpaced,
  Periodic,   // A0 + Σ [Aₙ cos nω(t − t0) + Bₙ sin nω(t − t0)] for t ≥ t0
  Modulated,  // A0 + A sin ω1(t − t0) sin ω2(t − t0) for t > t0
  Decay,      // A0 + A exp(−(t − t0)/td) for t ≥ t0
};

inline bool is_formula(AmplitudeDefinition d) {
  return d == AmplitudeDefinition::Periodic || d == AmplitudeDefinition::Modulated ||
         d == AmplitudeDefinition::Decay;
}

// The constants of an amplitude given by a formula (PERIODIC, MODULATED, DECAY); A0 before t0.
struct AmplitudeFormula {
  double start_time = 0;  // t0
  double initial = 0;     // A0
  double magnitude = 0;   // A (MODULATED, DECAY)
  double omega = 0;       // ω (PERIODIC), ω1 (MODULATED)
  double omega2 = 0;      // ω2 (MODULATED)
  double decay_time = 0;  // td (DECAY)
  std::vector<double> cosines, sines;  // Aₙ, Bₙ, n = 1…N (PERIODIC)
};

struct Amplitude {
  Name name;
  SourceLoc loc;  // keyword line
  AmplitudeDefinition definition = AmplitudeDefinition::Tabular;
  bool total_time = false;    // TIME=TOTAL TIME (default STEP TIME)
  bool absolute = false;      // VALUE=ABSOLUTE (default RELATIVE)
  double fixed_interval = 0;  // EQUALLY SPACED
  double begin = 0;
  double scale_x = 1, scale_y = 1, shift_x = 0, shift_y = 0;
  // Points after SCALEX/SCALEY/SHIFTX/SHIFTY (and, for EQUALLY SPACED, after generating the
  // times), in data order. Empty for a formula.
  std::vector<double> times, values;
  // PERIODIC, MODULATED, DECAY: the constants after SCALEX/SCALEY/SHIFTX/SHIFTY.
  AmplitudeFormula formula;
  std::int32_t step = -1;  // step it was defined in (−1: model data)
  bool valid = true;       // the data were read without error
  bool used = false;       // referenced by a condition or load (W0501 otherwise), set by validation
};

// ---- Conditions and loads (keywords.md §9–§13) ------------------------------------------------

enum class ConditionKind : std::uint8_t { Boundary, Motion, Load, ConnectorLoad, Gravity };
const char* condition_keyword(ConditionKind kind);  // "*BOUNDARY", "*CONNECTOR MOTION", ...

// One keyword block of a condition or load: what its parameters say for all its data lines.
struct ConditionBlock {
  ConditionKind kind = ConditionKind::Boundary;
  SourceLoc loc;                      // keyword line
  bool op_new = false;                // OP=NEW
  Name amplitude;                     // AMPLITUDE= (empty: the step's default)
  std::int32_t amplitude_index = -1;  // into HistoryModel::amplitudes, set by validation
  bool fixed = false;                 // FIXED (BC and motion)
  bool explicit_type = false;  // TYPE=DISPLACEMENT written (always RAMP without amplitude, §13)
  // *BOUNDARY, TYPE=VELOCITY (1) or ACCELERATION (2) in a *DYNAMIC step (docs/dynamics.md):
  // the value is that rate of the DOF; 0: its displacement.
  int rate_order = 0;
};

// *BOUNDARY data line. DOFs as a mask (bit d − 1 for DOF d) because the named types are not
// ranges (XSYMM = 1, 5, 6).
struct BoundaryCondition {
  std::int32_t block = -1;             // into the owner's ConditionBlock list
  TargetRef target;                    // node or node set
  std::vector<std::int32_t> resolved;  // global nodes of target, set by validation
  std::uint8_t dofs = 0;
  int first_dof = 0, last_dof = 0;  // range form; 0 for a named type
  std::string named_type;           // "ENCASTRE", ... (empty: range form)
  double magnitude = 0;             // 0 when blank, ignored with FIXED
  SourceLoc loc;                    // column 1 of the line
  SourceLoc dof_loc;                // field 2
  SourceLoc magnitude_loc;          // field 4 (invalid when blank)
};

// *CLOAD data line.
struct ConcentratedLoad {
  std::int32_t block = -1;
  TargetRef target;
  std::vector<std::int32_t> resolved;  // global nodes of target, set by validation
  int dof = 0;
  double magnitude = 0;
  SourceLoc loc, dof_loc;
};

// *INITIAL CONDITIONS, TYPE=ROTATING VELOCITY, a pair of data lines: the nodes turn at `omega`
// about the axis from point `a` to point `b` (right-hand rule) and translate at `translation`:
// v = translation + ω (b − a)/|b − a| × (x − a), with x a node's original coordinates; a node with
// rotational DOFs turns at ω (b − a)/|b − a| (docs/dynamics.md, docs/decisions.md).
struct RotatingVelocity {
  TargetRef target;
  double omega = 0;
  std::array<double, 3> a{}, b{}, translation{};
  SourceLoc loc;
};

// *DLOAD data line of type GRAV (docs/dynamics.md "Gravity"): the acceleration g along
// `direction` (a unit vector) on the masses of the MASS elements of `target` (every MASS element
// when the line names none).
struct GravityLoad {
  std::int32_t block = -1;
  std::optional<TargetRef> target;     // empty: the whole model
  std::vector<std::int32_t> resolved;  // global elements, set by validation
  double magnitude = 0;
  std::array<double, 3> direction{};
  SourceLoc loc, direction_loc;
};

// *CONNECTOR MOTION and *CONNECTOR LOAD data line.
struct ConnectorCondition {
  std::int32_t block = -1;
  TargetRef target;                    // element or element set
  std::vector<std::int32_t> resolved;  // global elements of target, set by validation
  int component = 0;                   // 1…6
  double magnitude = 0;
  SourceLoc loc, component_loc, magnitude_loc;
};

// ---- Procedure and controls (keywords.md §15, §16) --------------------------------------------

// *STATIC, RIKS with its data line, defaults resolved (docs/riks.md; the manual's *STATIC data
// line for the Riks method). Arc lengths are in the scaled load-displacement space of
// src/solver/arc_length_problem.hpp.
struct RiksSettings {
  double initial_arc = 1.0;  // Δl_in (default: the total arc length)
  double arc_period = 1.0;   // l_period, the total arc length scale factor
  double min_arc = 1e-5;     // Δl_min (default: min(Δl_in, 1e-5·l_period))
  std::optional<double> max_arc;  // Δl_max (none: no limit)
  std::optional<double> max_lpf;  // λ_end: the step ends once |LPF| reaches it
  // The step ends once DOF `dof` of the monitored node crosses `displacement`.
  std::optional<TargetRef> node;
  int dof = 0;
  double displacement = 0;
  std::int32_t resolved_node = -1;  // global node, set by validation
  std::array<SourceLoc, 8> field_loc{};  // fields 1–8 (invalid when blank)
};

// *STATIC, STABILIZE (docs/stabilization.md): viscous forces c M* v on the free DOFs, with the
// damping factor c from the dissipated energy fraction or given (FACTOR), adapted within the
// step unless ALLSDTOL=0 (docs/decisions.md "Automatic stabilization").
struct StaticStabilization {
  SourceLoc loc;                   // the STABILIZE parameter
  double energy_fraction = 2e-4;   // STABILIZE=value
  std::optional<double> factor;    // FACTOR: c itself, from the first increment on
  double allsdtol = 0.05;          // ALLSDTOL: adaptive when > 0; the warning's fraction
  bool allsdtol_given = false;
  bool continue_previous = false;  // CONTINUE=YES: c of the previous step's end
};

// *STATIC with its data line, defaults resolved (§15).
struct StaticProcedure {
  SourceLoc loc;                         // keyword line
  bool direct = false;                   // DIRECT: fixed increments, no cutback
  bool no_stop = false;                  // DIRECT=NO STOP
  double initial_increment = 1.0;        // Δt₀ (reduced to T when larger, W0808)
  double period = 1.0;                   // T
  double min_increment = 1e-5;           // ignored with DIRECT
  double max_increment = 1.0;            // ignored with DIRECT
  SourceLoc data_loc;                    // the data line (invalid when absent)
  std::array<SourceLoc, 4> field_loc{};  // fields 1–4 (invalid when blank)
  std::optional<RiksSettings> riks;      // RIKS: the data line is the Riks method's
  std::optional<StaticStabilization> stabilize;  // STABILIZE
};

// *DYNAMIC (implicit, docs/dynamics.md): the integration operator with its defaults resolved
// from APPLICATION (docs/decisions.md "Implicit dynamics"); the step's time data (data line,
// DIRECT) are in the step's StaticProcedure, which both procedures share.
struct DynamicProcedure {
  enum class Application : std::uint8_t { TransientFidelity, ModerateDissipation, QuasiStatic };
  SourceLoc loc;  // keyword line
  Application application = Application::TransientFidelity;
  bool backward_euler = false;  // QUASI-STATIC: backward Euler instead of HHT
  double alpha = -0.05, beta = 0.275625, gamma = 0.55;
  bool initial_acceleration = true;  // INITIAL=YES: a₀ from equilibrium at the step start
  std::optional<double> haftol;      // HAFTOL (automatic incrementation only)
  SourceLoc haftol_loc;
  bool explicit_integration = false;  // EXPLICIT: refused at the parameter, nothing more to say
};

// *FREQUENCY (docs/dynamics.md "Natural frequencies"): the eigenvalues and mode shapes of the
// tangent stiffness of the base state with the lumped mass, as the data line asks for them
// (docs/decisions.md "Natural frequencies"). Frequencies in cycles/time, the shift in
// (cycles/time)²; none: the field was blank.
struct FrequencyProcedure {
  enum class Normalization : std::uint8_t { Displacement, Mass };
  SourceLoc loc;                   // keyword line
  std::string eigensolver = "LANCZOS";
  Normalization normalization = Normalization::Displacement;
  std::optional<int> eigenvalues;  // the number requested (none: every one in the range)
  std::optional<double> min_frequency, max_frequency, shift;
};

// *INITIAL CONDITIONS, TYPE=VELOCITY data line: the velocity of DOF `dof` (1–6) of the nodes.
struct InitialVelocity {
  TargetRef target;
  std::vector<std::int32_t> resolved;  // global nodes, set by validation
  int dof = 0;
  double value = 0;
  SourceLoc loc, dof_loc;
};

// PARAMETERS=FIELD (§16): one set for translational and one for rotational fields.
struct FieldControls {
  double residual = 0.005;             // Rₙ
  double correction = 0.01;            // Cₙ
  double initial_flux = 0.01;          // q̄₀
  std::optional<double> user_flux;     // q̄ᵤ
  double alternate_residual = 0.02;    // Rₚ
  double zero_flux = 1e-5;             // ε
  double zero_flux_correction = 1e-3;  // C_ε
  double linear_residual = 1e-8;       // ε_l
};

// PARAMETERS=TIME INCREMENTATION (§16). The values clinch ignores are not stored.
struct TimeIncrementationControls {
  int i0 = 4, ir = 8, ip = 9, ic = 16, il = 10, ig = 4, ia = 5;
  double df = 0.25, dc = 0.5, db = 0.75, dd = 1.5;
};

// PARAMETERS=LINE SEARCH (§16; not confirmed: Abaqus defaults).
struct LineSearchControls {
  int max_iterations = 0;  // N_ls (0: off)
  double s_max = 1.0, s_min = 1e-4, f_s = 0.25, eta = 0.10;
  bool given = false;  // the deck has PARAMETERS=LINE SEARCH (its N_ls wins over clinch's choice)
};

struct Controls {
  FieldControls translation;  // FIELD=DISPLACEMENT (and connector forces)
  FieldControls rotation;     // FIELD=ROTATION (and connector moments)
  TimeIncrementationControls time;
  LineSearchControls line_search;
};

// ---- Output requests (keywords.md §17, §18; output-variables.md) ------------------------------

// One identifier on an output data line, as classified by parse_output_identifier
// (output_variables.hpp). Connector components and nodal DOFs share one numbering: bit i − 1
// stands for component i (connectors, output-variables.md §1.1) or DOF i (nodes: U1–U3 = 1–3,
// UR1–UR3 = 4–6; RF/RM and CF/CM likewise).
struct OutputIdentifier {
  std::string text;  // as written
  SourceLoc loc;
  std::string variable;             // canonical: "CTF", "U", "RF", "CDMG", "CSFC", "CDERF", "S"
  std::uint8_t components = 0;      // requested components; 0 = one scalar column (CDMG, CSFC)
  bool explicit_component = false;  // CTF2, CTM1, U1: that component must exist (E0902)
  std::string derived_name;         // CDERF-<name> / CDERU-<name> (empty: every derived component)
};

struct ElementOutputRequest {
  SourceLoc loc;
  TargetRef elset;
  bool has_elset = false;
  // VARIABLE=PRESELECT or ALL on the block: the default connector variables of
  // output-variables.md §4 for the elements of elset, besides the identifiers listed.
  bool preselect = false;
  std::vector<std::int32_t> resolved;  // global elements of elset, set by validation
  std::vector<OutputIdentifier> identifiers;
};

struct NodeOutputRequest {
  SourceLoc loc;
  TargetRef nset;
  bool has_nset = false;
  std::vector<std::int32_t> resolved;  // global nodes of nset, set by validation
  std::vector<OutputIdentifier> identifiers;
};

// *OUTPUT with the *ELEMENT OUTPUT / *NODE OUTPUT blocks that follow it.
struct OutputRequest {
  enum class Op : std::uint8_t { Add, New, Replace };
  enum class Variables : std::uint8_t { Listed, Preselect, All };
  SourceLoc loc;
  bool field = false;  // FIELD: accepted and ignored (W0902)
  Name name;           // NAME= or H-Output-<k>
  Op op = Op::Add;
  Variables variables = Variables::Listed;
  int frequency = 1;  // every n-th increment (0: none), plus the last of the step
  std::optional<int> number_interval;
  std::optional<double> time_interval;
  std::vector<ElementOutputRequest> elements;
  std::vector<NodeOutputRequest> nodes;
  std::vector<OutputIdentifier> energies;  // *ENERGY OUTPUT: whole-model energies
};

// *NODE PRINT / *EL PRINT (§18).
struct PrintRequest {
  enum class Totals : std::uint8_t { No, Yes, Only };
  bool node = true;  // *NODE PRINT (else *EL PRINT)
  SourceLoc loc;
  TargetRef set;
  bool has_set = false;
  // No NSET (ELSET): every node (element) of the model, as Abaqus prints; `set` then only names
  // the TOTALS columns (ALL-NODES, ALL-ELEMENTS).
  bool all = false;
  std::vector<std::int32_t> resolved;  // global nodes (elements) of set, set by validation
  int frequency = 1;
  SourceLoc frequency_loc;  // the FREQUENCY value (invalid when defaulted)
  Totals totals = Totals::No;
  std::vector<OutputIdentifier> identifiers;
};

// ---- Steps (keywords.md §14) ------------------------------------------------------------------

enum class StepAmplitude : std::uint8_t { Ramp, Step };
enum class Unsymmetric : std::uint8_t { Automatic, Yes, No };

struct Step {
  Name name;                 // NAME= or Step-<n>
  SourceLoc loc;             // keyword line
  std::string description;   // first data line
  bool nlgeom = false;       // effective: once on, stays on (W0804)
  int max_increments = 100;  // INC
  SourceLoc inc_loc;
  StepAmplitude amplitude = StepAmplitude::Ramp;  // the procedure's default unless given
  bool amplitude_given = false;                    // *STEP, AMPLITUDE=
  Unsymmetric unsymmetric = Unsymmetric::Automatic;
  SourceLoc unsymmetric_loc;
  bool extrapolation = true;  // EXTRAPOLATION=LINEAR (false: NO)

  // The time data of the step's procedure: *STATIC's, or *DYNAMIC's (then `dynamic` is set).
  std::optional<StaticProcedure> procedure;
  std::optional<DynamicProcedure> dynamic;
  std::optional<FrequencyProcedure> frequency;  // *FREQUENCY: a linear perturbation step
  // *STEP, PERTURBATION (docs/perturbation.md): a linear response about the base state, which
  // the next general step continues from. *FREQUENCY is one whether or not the flag is given.
  bool perturbation = false;
  SourceLoc perturbation_loc;  // the PERTURBATION parameter (invalid when absent)
  SourceLoc nlgeom_loc;        // NLGEOM on this *STEP line (invalid when absent)
  bool procedure_refused = false;  // its procedure keyword is one clinch does not run (E0202)
  Controls controls;  // effective controls (carried over, §13)

  std::vector<ConditionBlock> blocks;
  std::vector<BoundaryCondition> boundaries;
  std::vector<ConcentratedLoad> loads;
  std::vector<GravityLoad> gravity;
  std::vector<ConnectorCondition> motions;
  std::vector<ConnectorCondition> connector_loads;

  std::vector<OutputRequest> outputs;
  std::vector<PrintRequest> prints;

  bool closed = false;  // its *END STEP was read
  SourceLoc end_loc;
  bool placeholder = false;  // created for a *STEP whose keyword line had errors

  // The step names its procedure (*STATIC, *DYNAMIC or *FREQUENCY), or one clinch refuses.
  bool has_procedure() const { return procedure || frequency || procedure_refused; }
  // A linear perturbation step: its conditions and response do not carry into later steps.
  bool is_perturbation() const { return perturbation || frequency.has_value(); }

  // OP=NEW on some block of this kind: the step's blocks of that kind are the complete set (§13).
  bool replaces(ConditionKind kind) const;
};

struct HistoryModel {
  std::vector<Amplitude> amplitudes;
  std::unordered_map<std::string, std::int32_t> amplitude_by_key;

  // Model-data *BOUNDARY and *CONNECTOR MOTION (zero values, no amplitude).
  std::vector<ConditionBlock> model_blocks;
  std::vector<BoundaryCondition> model_boundaries;
  std::vector<ConnectorCondition> model_motions;
  std::vector<InitialVelocity> initial_velocities;  // *INITIAL CONDITIONS, TYPE=VELOCITY
  std::vector<RotatingVelocity> rotating_velocities;  // TYPE=ROTATING VELOCITY

  std::vector<Step> steps;
  std::unordered_map<std::string, std::int32_t> step_by_key;

  int output_requests = 0;           // numbering of H-Output-<k>
  bool field_output_warned = false;  // W0902 once per deck
};

// The history *OUTPUT requests in force in each step (keywords.md §13, §17): they carry over;
// OP=NEW drops the earlier ones, OP=REPLACE the one of the same name. FIELD requests are left out.
std::vector<std::vector<const OutputRequest*>> history_requests_in_force(
    const HistoryModel& history);

// The step time between the rows of `request` in `step` (keywords.md §17): TIME INTERVAL, or the
// step's period over NUMBER INTERVAL; none when the request counts increments or the step has no
// time of its own (a Riks step's time is its arc length, a *FREQUENCY step has none).
std::optional<double> output_time_interval(const OutputRequest& request, const Step& step);

// The distinct output time intervals of the requests in force in step `s`: its increments end
// at each multiple of them (keywords.md §17).
std::vector<double> output_time_intervals(const HistoryModel& history, std::size_t s);

}  // namespace clinch
