#include "src/cli/keyword_notes.hpp"

namespace clinch {
namespace {

// Refusals that several behaviour options share (parser/keywords/behavior_option_common.cpp).
constexpr KeywordRefusal kFieldDependence{
    "DEPENDENCIES greater than 0, or a field variable given in a data line",
    "field-variable-dependent data is not implemented"};
constexpr KeywordRefusal kTemperatureDependence{
    "rows for more than one temperature", "temperature-dependent data is not implemented"};
constexpr KeywordRefusal kExplicitOnly{"REGULARIZE, RTOL", "Abaqus/Explicit only"};

}  // namespace

const std::vector<KeywordNotes>& all_keyword_notes() {
  static const std::vector<KeywordNotes> notes = {
      {"HEADING", "The title of the analysis (its first line is copied to the .log).",
       "Free text; the first line is the title."},
      {"PARAMETER",
       "Defines named values (`name = expression`) used as `<name>` in later fields.",
       "One definition per line: `name = expression` (arithmetic, `sqrt`, `sin`, ...)."},
      {"PART", "Opens a part: nodes, elements, sets, orientations and sections of one piece.",
       ""},
      {"END PART", "Closes the part.", ""},
      {"ASSEMBLY", "Opens the assembly, where instances place parts and connectors join them.",
       ""},
      {"END ASSEMBLY", "Closes the assembly.", ""},
      {"INSTANCE", "Places a part in the assembly; its labels become `instance.label`.",
       "Optional: a translation (x, y, z) on the first line, a rotation (axis point a, axis "
       "point b, angle in degrees) on the second.",
       {{"LIBRARY=, INSTANCE=", "instances of other models or libraries are not implemented"}}},
      {"END INSTANCE", "Closes the instance.", ""},
      {"NODE", "Defines nodes by their coordinates.",
       "`label, x, y, z` (missing coordinates are 0).",
       {{"SYSTEM=C or S", "only rectangular coordinates (SYSTEM=R) are implemented"}}},
      {"ELEMENT",
       "Defines connector (CONN3D2, CONN2D2), spring (SPRINGA, SPRING1, SPRING2) and dashpot "
       "(DASHPOTA, DASHPOT1, DASHPOT2) elements, which clinch analyses, and reads the solids "
       "(C3D4-C3D20R, their H variants, SC6R, SC8R), shells (S3, S3R, S4, S4R, S8R, S9R5, STRI3, "
       "STRI65), membranes (M3D3-M3D9R), rigid elements (R3D3, R3D4, R2D2, RAX2, RB3D2, RB2D2), "
       "beams (B21-B33, PIPE21-PIPE32), trusses (T2D2-T3D3), planar continua (CPS, CPE, CAX) "
       "and point elements (MASS, ROTARYI) as their nodes.",
       "`label, node a[, node b]`; node b may be left out of a CONN3D2 or CONN2D2 (connected to "
       "ground) and is absent for SPRING1 and DASHPOT1. Other types: `label`, then every node of "
       "the element; an element with more than 15 nodes goes on over lines that end with a "
       "comma (16 entries a line).",
       {{"a block of solid, shell, membrane, rigid, beam, truss or planar elements outside a "
         "rigid body",
         "refused once per block at TYPE= (for the elements no *RIGID BODY carries): clinch has "
         "no formulation for a deformable element; make its part a rigid body (*RIGID BODY) or "
         "remove it"},
        {"TYPE= other types (cohesive, gasket, gap, heat transfer, acoustic, user elements, ...)",
         "not read"}},
       {{"TYPE=MASS, ROTARYI", "inertia only, which a *STATIC step does not use"}}},
      {"NSET", "Defines a node set.",
       "Node labels or set names, or `first, last, increment` with GENERATE."},
      {"ELSET", "Defines an element set.",
       "Element labels or set names, or `first, last, increment` with GENERATE."},
      {"ORIENTATION",
       "Defines a local coordinate system for connector sections and springs.",
       "Line 1: `a1, a2, a3, b1, b2, b3[, c1, c2, c3]`: a point a on the local 1-axis, a point b "
       "in the 1-2 plane and the origin c (default 0); with DEFINITION=NODES three node labels. "
       "Line 2 (optional): `axis, angle`, an extra rotation in degrees about local axis 1, 2 or "
       "3.",
       {{"SYSTEM=CYLINDRICAL, SPHERICAL, Z RECTANGULAR or USER",
         "connector and spring orientations are rectangular"},
        {"DEFINITION=OFFSET TO NODES", "it needs the nodes of continuum elements"},
        {"LOCAL DIRECTIONS", "not implemented for connector and spring orientations"}}},
      {"CONNECTOR SECTION",
       "Gives an element set its connection type(s), orientations and connector behaviour.",
       "Line 1: one assembled or basic connection type, or a translational and a rotational "
       "basic type (`Hinge,`; `Cartesian, Cardan`). Line 2 (optional): the orientation at node a "
       "and at node b.",
       {},
       {{"ELIMINATION", "Abaqus/Explicit only"}}},
      {"SPRING", "Properties of SPRINGA, SPRING1 and SPRING2 elements.",
       "Line 1: the degrees of freedom (SPRING1: `dof`; SPRING2: `dof1, dof2`; SPRINGA: blank). "
       "Then the stiffness, or with NONLINEAR rows of `force, relative displacement`.",
       {kFieldDependence, kTemperatureDependence},
       {{"a DOF line of SPRINGA", "Abaqus ignores it: the direction is the line between the nodes"}}},
      {"DASHPOT", "Properties of DASHPOTA, DASHPOT1 and DASHPOT2 elements.",
       "Line 1: the degrees of freedom (DASHPOT1: `dof`; DASHPOT2: `dof1, dof2`; DASHPOTA: "
       "blank). Then the coefficient, or with NONLINEAR rows of `force, relative velocity`.",
       {kFieldDependence, kTemperatureDependence}},
      {"SECTION CONTROLS",
       "Element deletion, maximum degradation and viscous regularisation of connector damage "
       "(named by `*CONNECTOR SECTION, CONTROLS=`).",
       "",
       {{"any parameter other than NAME, ELEMENT DELETION, MAX DEGRADATION and VISCOSITY",
         "they control elements clinch does not have"}}},
      {"SOLID SECTION",
       "Gives the solid, planar or truss elements of ELSET= their material; read and kept, and "
       "in a rigid body their mass with the material's *DENSITY (docs/dynamics.md).",
       "Optional: the thickness of planar elements, the area of trusses."},
      {"SHELL SECTION",
       "Gives the shell elements of ELSET= their material; read and kept, and in a rigid body "
       "their mass with the material's *DENSITY (docs/dynamics.md).",
       "`thickness[, integration points]`."},
      {"MEMBRANE SECTION",
       "Gives the membrane elements of ELSET= their material; read and kept, and in a rigid body "
       "their mass with the material's *DENSITY (docs/dynamics.md).",
       "`thickness`."},
      {"BEAM SECTION",
       "Gives the beam elements of ELSET= their profile (SECTION=) and material; read and kept, "
       "and in a rigid body their mass with the material's *DENSITY for the profiles RECT, "
       "CIRC, PIPE and THICK PIPE (docs/dynamics.md).",
       "Line 1: the profile dimensions; line 2: the direction of the n1 axis."},
      {"TRUSS SECTION",
       "Gives the truss elements of ELSET= their material; read and kept, and in a rigid body "
       "their mass with the material's *DENSITY (docs/dynamics.md).",
       "`cross-sectional area`."},
      {"MASS",
       "The mass of the MASS elements of ELSET=: a point mass in each translation, the inertia "
       "of *DYNAMIC and *FREQUENCY steps (docs/dynamics.md).",
       "`mass`.",
       {{"ALPHA, ORIENTATION, COMPOSITE", "not implemented"}},
       {{"the whole keyword when no step is *DYNAMIC or *FREQUENCY", "a static step has no inertia"}}},
      {"ROTARY INERTIA",
       "The rotary inertia of the ROTARYI elements of ELSET=, the full tensor in the global "
       "axes: the inertia of *DYNAMIC and *FREQUENCY steps (docs/dynamics.md).",
       "`I11, I22, I33, I12, I13, I23`.",
       {{"ALPHA, ORIENTATION, COMPOSITE", "not implemented"}},
       {{"the whole keyword when no step is *DYNAMIC or *FREQUENCY", "a static step has no inertia"}}},
      {"MATERIAL",
       "Opens a named material; the options that follow (*ELASTIC, *DENSITY, ...) belong to it. "
       "Read and kept for the sections of held elements.",
       ""},
      {"ELASTIC", "Elastic moduli of the material; read and kept.",
       "Rows of numbers (ISOTROPIC: `E, nu`)."},
      {"DENSITY", "Mass density of the material; read and kept.", "`density`."},
      {"PLASTIC", "Yield stress against plastic strain of the material; read and kept.",
       "Rows of `yield stress, plastic strain`."},
      {"EXPANSION", "Thermal expansion of the material; read and kept.",
       "Rows of numbers (ISO: `alpha`)."},
      {"DAMPING", "Rayleigh or structural damping of the material (ALPHA=, BETA=, ...); read and "
       "kept.", ""},
      {"CONDUCTIVITY", "Thermal conductivity of the material; read and kept.",
       "Rows of numbers."},
      {"SPECIFIC HEAT", "Specific heat of the material; read and kept.", "Rows of numbers."},
      {"SURFACE",
       "Defines a named surface of element faces (TYPE=ELEMENT) or nodes (TYPE=NODE); read and "
       "kept.",
       "TYPE=ELEMENT: `element or element set, face` (S1-S6, SPOS, SNEG; none: the whole "
       "exterior). TYPE=NODE: `node or node set[, area]`.",
       {{"TYPE=SEGMENTS, CYLINDER, REVOLUTION, CUTTING SURFACE or EULERIAN MATERIAL",
         "analytical and Eulerian surfaces are not read"}}},
      {"DISPLAY BODY",
       "Shows an instance as a display body that follows up to three nodes; read and kept.",
       "Optional: `node 1[, node 2, node 3]`."},
      {"RIGID BODY",
       "Makes nodes and elements a rigid body that follows its reference node: nodes of the "
       "ELSET's elements, TIE NSET and NSET (CalculiX) in translation and rotation, PIN NSET in "
       "translation; the ELSET's elements need no section then. REF NODE= is required (as in "
       "Abaqus/Standard: clinch does not generate a node as CalculiX does without it). "
       "Connectors, loads and boundary conditions on any node of the body act on the body.",
       "Abaqus/Explicit's rigid element thickness (ignored with a warning).",
       {{"POSITION=CENTER OF MASS",
         "needs the masses of the body, which a static analysis does not have"},
        {"ROT NODE= in a deck with a step under NLGEOM",
         "its equations are linearised (small rotations)"}},
       {{"ISOTHERMAL, ALPHA", "temperatures play no part in clinch's mechanical steps"},
        {"DENSITY, NODAL THICKNESS, OFFSET", "Abaqus/Explicit only"},
        {"ANALYTICAL SURFACE", "an analytical surface has no nodes: no effect on the motion"}}},
      {"KINEMATIC COUPLING",
       "Makes DOFs of nodes follow the rigid motion of a reference node (REF NODE=).",
       "`node or node set, first DOF[, last DOF]` (last DOF: the first when blank).",
       {{"ORIENTATION= with some but not all translations or rotations",
         "the constrained DOFs would depend on the local system, which clinch does not "
         "transform"}}},
      {"COUPLING",
       "Couples the nodes of a surface (SURFACE=, within INFLUENCE RADIUS=) to a reference node "
       "(REF NODE=); *KINEMATIC or *DISTRIBUTING follows at once.",
       "",
       {{"ORIENTATION= with some but not all translations or rotations",
         "the constrained DOFs would depend on the local system, which clinch does not "
         "transform"},
        {"a face without a node table (C3D5, C3D15, SC6R, ..., or the whole exterior)",
         "clinch knows the faces of C3D4/6/8/10/20, shells and R3D3/R3D4"}}},
      {"KINEMATIC",
       "The method of the *COUPLING above: the coupling nodes follow the reference node's rigid "
       "motion in the DOFs listed.",
       "Optional: `first DOF[, last DOF]` (none: every DOF)."},
      {"DISTRIBUTING",
       "The method of the *COUPLING above: the reference node moves with the weighted average "
       "motion of the coupling nodes (small displacements).",
       "Optional: `first DOF[, last DOF]`; every translation is always coupled (none or a blank "
       "first field: every DOF).",
       {{"COUPLING=STRUCTURAL", "it also couples the rotations of the coupling nodes"},
        {"an element-based SURFACE=", "its weights need the faces' tributary areas"},
        {"a deck with a step under NLGEOM", "the distributing map is linearised"}}},
      {"MPC",
       "Multi-point constraints: BEAM (node a follows node b as on a rigid beam), TIE (every "
       "DOF of a equal to b's), PIN (translations equal) and LINK (the distance from a to b "
       "stays constant); DOFs of the first node are eliminated.",
       "`type, a, b`: a and b nodes, or a node set a matched entry by entry with a node set b "
       "of the same size, or with a single node b.",
       {{"types other than BEAM, LINK, PIN and TIE (REVOLUTE, UNIVERSAL, SLIDER, ELBOW, ...)",
         "a connector element models these joints"},
        {"USER (MODE=)", "clinch has no user subroutines"}},
       {{"ALPHA", "temperatures play no part in clinch's mechanical steps"},
        {"MODE without USER", "it applies to user subroutine MPC only"}}},
      {"EQUATION",
       "Linear constraint equations Σ A_i u_i = 0; the first term's DOF is eliminated.",
       "Per equation: a line with the number of terms N, then the N terms `node or node set, "
       "DOF, coefficient`, at most four a line. Node sets expand the equation entry by entry "
       "(sets of one size; a single node repeats).",
       {{"a rotational DOF (4-6) in a model with an NLGEOM=YES step",
         "finite rotations do not add up like the components of a vector"}}},
      {"CONNECTOR BEHAVIOR",
       "Opens a named connector behaviour; the options that follow (elasticity, damping, stops, "
       "plasticity, friction, damage, ...) belong to it.",
       "",
       {},
       {{"INTEGRATION, REGULARIZE, RTOL", "Abaqus/Explicit only"}}},
      {"CONNECTOR CONSTITUTIVE REFERENCE",
       "The reference positions from which elastic and plastic motions are measured.",
       "One line: the reference values of components 1 to 6 (lengths, then angles in degrees; "
       "blank fields are 0)."},
      {"CONNECTOR DAMPING",
       "Viscous damping of connector components (force against velocity: Δu/Δt in *STATIC, the "
       "velocity of the operator in *DYNAMIC): linear, nonlinear or coupled.",
       "Linear: the coefficient. NONLINEAR: rows of `force, velocity`. Coupled (no COMPONENT): "
       "the upper triangle of the damping matrix of the available components.",
       {{"TYPE=RAYLEIGH", "give the coefficient with TYPE=VISCOUS"},
        {"INDEPENDENT COMPONENTS", "damping against another component's velocity is not implemented"},
        {"UNSYMM", "unsymmetric damping matrices are not implemented"},
        {"FREQUENCY DEPENDENCE=ON", "for frequency-domain procedures, which clinch does not run"},
        kFieldDependence,
        kTemperatureDependence},
       {{"TYPE=STRUCTURAL", "it acts only in steady-state dynamics"}, kExplicitOnly}},
      {"CONNECTOR ELASTICITY",
       "Elasticity of connector components: linear, nonlinear (tabulated), coupled or RIGID.",
       "Linear: the stiffness. NONLINEAR: rows of `force, relative motion`. Coupled (no "
       "COMPONENT): the upper triangle of the stiffness matrix of the available components. "
       "RIGID: the components on one line (none: all available ones).",
       {{"UNSYMM", "unsymmetric stiffness matrices are not implemented"},
        {"INDEPENDENT COMPONENTS", "elasticity against another component's motion is not implemented"},
        {"FREQUENCY DEPENDENCE=ON", "for frequency-domain procedures, which clinch does not run"},
        kFieldDependence,
        kTemperatureDependence},
       {kExplicitOnly}},
      {"CONNECTOR STOP", "Limits a component's motion to a range (a one-sided contact).",
       "One line: `lower, upper`, the limits of the component's position (radians for "
       "rotations); a blank field is no limit."},
      {"CONNECTOR LOCK",
       "Locks components once a criterion on a component's motion or force is met.",
       "One line: `p_L, p_U, F_L, F_U`, bounds on the tested component's position and total "
       "force (a blank field is no bound); LOCK= names the component to lock, or ALL.",
       {kFieldDependence}},
      {"CONNECTOR FAILURE",
       "Releases components when a component's force or position leaves its range.",
       "One line: `p_L, p_U, F_L, F_U` as for *CONNECTOR LOCK; RELEASE= names the component "
       "released, or ALL."},
      {"CONNECTOR PLASTICITY",
       "Plasticity of a component (COMPONENT=) or coupled through a *CONNECTOR POTENTIAL.",
       "None; *CONNECTOR HARDENING and *CONNECTOR POTENTIAL follow it."},
      {"CONNECTOR HARDENING",
       "Isotropic (tabular or exponential law) or kinematic (Ziegler, Armstrong–Frederick) "
       "hardening of the preceding *CONNECTOR PLASTICITY.",
       "ISOTROPIC TABULAR: rows of `yield force, equivalent plastic motion`. EXPONENTIAL LAW: "
       "`F0, Q_inf, b`. KINEMATIC PARAMETERS: `F0, C, gamma`; HALF CYCLE: rows of `force, "
       "plastic motion`.",
       {{"DEFINITION=STABILIZED", "cyclic test data of the stabilised loop is not implemented"},
        {"kinematic hardening with a coupled (potential) plasticity",
         "the coupled return mapping is isotropic only"},
        {"HALF CYCLE with more than two rows", "only the two-point (linear) half cycle is implemented"},
        {"rate-dependent rows", "rate-dependent hardening is not implemented"},
        kFieldDependence,
        kTemperatureDependence}},
      {"CONNECTOR DAMAGE INITIATION",
       "When damage starts: on force, motion or plastic motion of a component or of a potential.",
       "FORCE: `F_L, F_U`; MOTION: the lower and upper limits of the motion; PLASTIC MOTION: "
       "the equivalent plastic motion at initiation (one row).",
       {{"PLASTIC MOTION with more than one row", "mode-mix and rate dependence are not implemented"},
        {"CRITERION=FORCE in a behaviour that also has friction or RIGID elasticity",
         "`clinch run` cannot run it; `clinch check` refuses it too, so that check passes only "
         "what run accepts"},
        kFieldDependence,
        kTemperatureDependence},
       {{"RATE FILTER FACTOR, RATE INTERPOLATION, REGULARIZE, RTOL", "Abaqus/Explicit only"}}},
      {"CONNECTOR DAMAGE EVOLUTION",
       "How damage grows after initiation: by motion (linear, exponential or tabular softening) "
       "or by dissipated energy.",
       "With AFFECTED COMPONENTS, first the affected components. TYPE=MOTION, LINEAR: `du_f`, the "
       "motion past initiation at full damage; EXPONENTIAL: `du_f, a`; TABULAR: rows of "
       "`damage, motion past initiation`. TYPE=ENERGY: the energy dissipated at full damage.",
       {kFieldDependence, kTemperatureDependence}},
      {"CONNECTOR DERIVED COMPONENT",
       "A named scalar made of components (weighted sum, Macaulay sum, ...), used by potentials "
       "and friction.",
       "Pairs of lines: the component numbers, then their coefficients.",
       {{"INDEPENDENT COMPONENTS", "derived components of other components' motions are not implemented"},
        {"temperature-dependent coefficients", "temperature-dependent data is not implemented"}}},
      {"CONNECTOR POTENTIAL",
       "A potential (SUM or MAX of terms over components and derived components) for coupled "
       "plasticity, damage or friction.",
       "One term per line: `component (1-6) or derived component name, scale R, exponent, "
       "function (ABS, MACAULEY or NONE), shift, sign`; blank fields take their defaults."},
      {"CONNECTOR FRICTION",
       "Friction on a component, through a *CONNECTOR POTENTIAL, or predefined for the "
       "connection type (see Refused for the types), with its contact force.",
       "Optional: the internal contact force as rows of `F_int, accumulated slip` (one row: "
       "a constant force). PREDEFINED SLOT and SLIDE-PLANE take no geometric data.",
       {{"PREDEFINED on a connection type other than SLOT, SLIDE-PLANE",
         "for HINGE, CYLINDRICAL, TRANSLATOR, PLANAR, UJOINT and SLIPRING the manual's contact "
         "force and geometric data line could not be found (the others have none); use "
         "COMPONENT= or a *CONNECTOR POTENTIAL with CONTACT FORCE="},
        {"INDEPENDENT COMPONENTS", "not implemented"},
        {"more than five *CONNECTOR FRICTION in one behaviour", "combine them"},
        {"temperature-dependent internal contact force", "temperature-dependent data is not implemented"}}},
      {"FRICTION",
       "The friction coefficient of the preceding *CONNECTOR FRICTION: constant, tabulated "
       "against slip rate or contact force, or static–kinetic exponential decay.",
       "Rows of `mu, slip rate, contact force`; EXPONENTIAL DECAY: `mu_s, mu_k, d_c`.",
       {{"ROUGH, LAGRANGE, USER", "not meaningful for connector friction"},
        {"ANISOTROPIC", "use a *CONNECTOR POTENTIAL for directional friction"},
        {"EXPONENTIAL DECAY with TEST DATA", "give mu_s, mu_k and d_c"},
        {"*FRICTION outside a *CONNECTOR BEHAVIOR", "surface contact is not implemented"},
        kTemperatureDependence},
       {kExplicitOnly}},
      {"STEP",
       "Opens a step; NLGEOM chooses finite rotations, INC the increment limit. PERTURBATION "
       "makes it a linear perturbation step about the base state (docs/perturbation.md).",
       "Optional: a description line.",
       {{"SOLVER, MONOTONIC, INCF", "not implemented"},
        {"EXTRAPOLATION=PARABOLIC", "use LINEAR or NO"}},
       {{"CONVERT SDI", "it has no effect in clinch"}}},
      {"END STEP", "Closes the step.", ""},
      {"STATIC",
       "A static procedure with automatic incrementation (cutbacks) or fixed increments "
       "(DIRECT). With RIKS, the modified Riks method: the load proportionality factor (LPF "
       "column) scales the step's loads, found with the state on an arc length (docs/riks.md). "
       "With STABILIZE, automatic stabilization: viscous forces on the free DOFs with a damping "
       "factor from the dissipated energy fraction or FACTOR, adaptive unless ALLSDTOL=0, and "
       "the ALLSD energy column (docs/stabilization.md).",
       "`initial increment, step time, minimum increment, maximum increment`; with RIKS "
       "`initial arc length, total arc length, minimum and maximum arc length, maximum LPF, "
       "node, DOF, displacement`.",
       {{"LONG TERM, ADAPTIVE", "not implemented"},
        {"STABILIZE with RIKS", "refused: the arc length passes the limit points itself"},
        {"a non-zero *BOUNDARY or *CONNECTOR MOTION value in a RIKS step",
         "the LPF scales loads (*CLOAD, *CONNECTOR LOAD)"}}},
      {"DYNAMIC",
       "Implicit dynamics with the Hilber–Hughes–Taylor operator (APPLICATION=TRANSIENT "
       "FIDELITY, the default, or MODERATE DISSIPATION) or backward Euler (QUASI-STATIC); "
       "ALPHA, BETA, GAMMA and INITIAL as the manual defines them; fixed increments with DIRECT, "
       "else automatic incrementation held to the half-increment residual (HAFTOL, or the "
       "APPLICATION's default) (docs/dynamics.md).",
       "`time increment, step time, minimum increment, maximum increment`.",
       {{"EXPLICIT, SUBSPACE, ADIABATIC, NOHAF, STABILIZE and the other explicit or "
         "stabilization parameters",
         "not implemented"},
        {"the mass of a rigid body's beams of profiles other than RECT, CIRC, PIPE and THICK "
         "PIPE, pyramids (C3D5) and axisymmetric elements",
         "clinch computes it from the density and volume of solids, shells, membranes, plane "
         "stress and plane strain elements, trusses and those beams only; give it as MASS and "
         "ROTARYI elements on the body's nodes"}}},
      {"ENERGY OUTPUT",
       "Whole-model energies as history columns: ALLKE, ALLIE, ALLFD, ALLVD, ALLSD, ALLWK, "
       "ETOTAL (docs/dynamics.md; ALLSD: docs/stabilization.md).",
       "The energies to write; none, or VARIABLE=PRESELECT or ALL: all six, and ALLSD in a "
       "step with STABILIZE.",
       {{"ELSET (energies of an element set)", "not implemented"},
        {"ALLSE, ALLPD, ALLDMD and the other energies",
         "ALLIE holds the elastic, plastic and damage work together"}}},
      {"FREQUENCY",
       "Natural frequencies and mode shapes about the base state (the converged state of the "
       "steps before; a linear perturbation step that leaves it unchanged): the tangent "
       "stiffness there with the lumped mass of MASS and ROTARYI elements and of rigid bodies' elements with a density. The eigenvalue table "
       "goes to the log and the modes to <job>.modes.csv (docs/dynamics.md). EIGENSOLVER="
       "LANCZOS, SUBSPACE and AMS are all read as a request for eigenpairs; NORMALIZATION="
       "DISPLACEMENT or MASS.",
       "LANCZOS and AMS: `number of eigenvalues, minimum frequency, maximum frequency, shift "
       "point`; SUBSPACE: `number of eigenvalues, maximum frequency, shift point` "
       "(cycles/time, the shift in (cycles/time)²).",
       {{"RESIDUAL MODES", "not implemented"},
        {"*BOUNDARY, *CLOAD, *CONNECTOR MOTION and *CONNECTOR LOAD in the step",
         "the step keeps the conditions of its base state"},
        {"the mass of a rigid body's beams of profiles other than RECT, CIRC, PIPE and THICK "
         "PIPE, pyramids (C3D5) and axisymmetric elements",
         "clinch computes it from the density and volume of solids, shells, membranes, plane "
         "stress and plane strain elements, trusses and those beams only; give it as MASS and "
         "ROTARYI elements on the body's nodes"}},
       {{"ACOUSTIC COUPLING, DAMPING PROJECTION, SIM, BIAS, NUMBER INTERVAL, PROPERTY "
         "EVALUATION, STORAGE, SOLVER",
         "clinch has no acoustics, frequency-dependent properties or solver options to set"},
        {"block size, number of vectors, iteration limits (the fields after the shift) and data "
         "lines after the first",
         "they tune Abaqus's own eigensolver"}}},
      {"INITIAL CONDITIONS",
       "With TYPE=VELOCITY or ROTATING VELOCITY: the nodal velocities at the start of the "
       "analysis, read by the first *DYNAMIC step (docs/dynamics.md).",
       "VELOCITY: `node or set, DOF, velocity`. ROTATING VELOCITY, pairs of lines: `node or set, "
       "ω, x, y, z of a first point on the axis`, then `x, y, z of a second point[, vx, vy, vz]` "
       "(docs/decisions.md).",
       {{"TYPE other than VELOCITY and ROTATING VELOCITY (STRESS, TEMPERATURE, ...)",
         "not implemented"},
        {"USER, FILE, STEP, INC, INTERPOLATE", "not implemented"}}},
      {"CONTROLS",
       "Newton convergence criteria (FIELD), time incrementation and line search.",
       "With PARAMETERS=: the rows the manual gives for that parameter set.",
       {{"PARAMETERS=CONSTRAINTS or DIRECT CYCLIC", "not implemented"}}},
      {"BOUNDARY",
       "Fixes or prescribes nodal degrees of freedom (ENCASTRE, PINNED, ... or values); in a "
       "*DYNAMIC step TYPE=VELOCITY or ACCELERATION prescribes that rate (docs/dynamics.md).",
       "`node or set, first DOF, last DOF, value`, or `node or set, ENCASTRE`.",
       {{"TYPE=VELOCITY or ACCELERATION outside a *DYNAMIC step",
         "static steps prescribe displacements"},
        {"USER, SUBMODEL, LOAD CASE, REGION TYPE", "not implemented"},
        {"non-zero values in model data", "prescribe them in a step"}}},
      {"CLOAD", "Concentrated nodal forces and moments.",
       "`node or set, DOF, magnitude`.",
       {{"FOLLOWER, USER, LOAD CASE, CROSS SECTIONAL, SUBMODEL, SYSTEM", "not implemented"}}},
      {"CONNECTOR MOTION",
       "Prescribes a connector component's motion; in a *DYNAMIC step TYPE=VELOCITY or "
       "ACCELERATION prescribes its rate (docs/dynamics.md).",
       "`element or set, component, value`.",
       {{"TYPE=VELOCITY or ACCELERATION outside a *DYNAMIC step",
         "static steps prescribe displacements"},
        {"USER", "not implemented"}}},
      {"CONNECTOR LOAD", "Applies a force or moment on a connector component.",
       "`element or set, component, magnitude`."},
      {"DLOAD",
       "Gravity (GRAV) on the masses of MASS elements, in any step, with OP and AMPLITUDE as "
       "*CLOAD (docs/dynamics.md).",
       "`element or set (blank: every MASS element), GRAV, g, direction x, y, z`.",
       {{"load types other than GRAV", "connector models have no surfaces or volumes to load"},
        {"FOLLOWER, USER, LOAD CASE, ORIENTATION, REF NODE, CONSTANT RESULTANT, SUBMODEL",
         "not implemented"}}},
      {"AMPLITUDE",
       "A time variation for loads and prescribed motions (the definitions not refused below).",
       "TABULAR and SMOOTH STEP: pairs `time, value`, four per line. EQUALLY SPACED: values "
       "(FIXED INTERVAL= the spacing, BEGIN= the first time). PERIODIC: `N, omega, t0, A0`, "
       "then `A1, B1, ..., AN, BN`. MODULATED: `A0, A, t0, omega1, omega2`. DECAY: "
       "`A0, A, t0, td`.",
       {{"DEFINITION=SOLUTION DEPENDENT, BUBBLE, USER, ACTUATOR",
         "they need superplastic forming, underwater shock, user subroutines or co-simulation"}},
       {{"SMOOTH", "it smooths time derivatives, which a static analysis does not use"},
        {"FIXED INTERVAL, BEGIN without DEFINITION=EQUALLY SPACED", "they belong to that form"}}},
      {"OUTPUT",
       "Opens an output request: HISTORY requests go to <job>.history.csv; FIELD requests are "
       "read and have no output.",
       "",
       {{"TIME POINTS", "output at listed times is not implemented"}},
       {{"FILTER, MODE LIST, SENSITIVITY, DIAGNOSTICS", "they have no effect in clinch"},
        {"a FIELD request", "clinch writes history output only"}}},
      {"ELEMENT OUTPUT", "The element (connector, spring) variables of a history request.",
       "Output identifiers (CTF, CU, CUE, CUP, CSF, CDMG, ...)."},
      {"NODE OUTPUT", "The nodal variables of a history request.",
       "Output identifiers (U, UR, RF, RM, ...)."},
      {"NODE PRINT",
       "Nodal variables printed at increments; clinch writes them as history columns (sums "
       "with TOTALS=).",
       "Output identifiers."},
      {"EL PRINT",
       "Element variables printed at increments; clinch writes them as history columns (sums "
       "with TOTALS=).",
       "Output identifiers; a blank line starts a new table."},
  };
  return notes;
}

const KeywordNotes* find_keyword_notes(std::string_view canonical_name) {
  for (const KeywordNotes& note : all_keyword_notes()) {
    if (note.name == canonical_name) return &note;
  }
  return nullptr;
}

}  // namespace clinch
