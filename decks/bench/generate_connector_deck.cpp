// Writes a deck of N connectors for the `clinch check` throughput benchmark
// (scripts/bench_check.sh).
//
// Default mode: a chain of N+1 nodes on a helix, N CONN3D2 elements joining neighbours, node and
// element sets (explicit and GENERATE), one *CONNECTOR SECTION with an AXIAL type and a
// behaviour, boundary conditions and one step with history output.
//
// --mix: the same chain, written the way users' decks are: the elements come in blocks of
// kSectionSize, each block its own *ELEMENT, ELSET=Sk with its own pair of *ORIENTATIONs (node a
// and node b) and its own *CONNECTOR SECTION. The sections cycle through every connection type
// clinch v1 accepts on CONN3D2 (connection-types.md table 2.1: each assembled type, and every
// basic type in some translational/rotational pair), with behaviours on the available components
// only: BUSHING with six elastic components coupled (21 terms) or uncoupled, with stops, or with
// the coupled plasticity of the spot weld (decks/bench/spot_weld_behavior.inp); uncoupled
// plasticity and stops on some of the others; WELD and BEAM without behaviour.
//
// --default-output: no history output request, so that `clinch run` writes its default columns
// (CTF, CU, ... of every connector), one increment and, in the chain, the tip held transversely
// so that the run solves: the setup benchmark
// (scripts/bench_setup.sh) times the run's setup, not its increments.
//
// Usage: generate_connector_deck N [--mix] [--default-output] > deck.inp
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

namespace {

// Orientation b is orientation a turned by this angle (degrees) about its local 1-axis: EULER is
// singular between aligned frames (euler-singular-initial), and the angle stays far from CARDAN's
// gimbal lock.
constexpr double kTwistDegrees = 15.0;
constexpr long kSectionSize = 50;

struct Combination {
  const char* types;         // the section's first data line
  const char* behaviors[4];  // one per section in turn; nullptr ends the list (none: no BEHAVIOR=)
};

// BUSHING comes twice in the cycle: spot welds dominate users' connector counts.
constexpr Combination kCombinations[] = {
    {"BUSHING", {"B6C", "B6U", "B6P", "B6S"}},
    {"WELD", {nullptr}},
    {"HINGE", {"B4S", nullptr}},
    {"CARTESIAN, ROTATION", {"B6U", "B6C", nullptr}},
    {"SLOT, REVOLUTE", {"B14P", nullptr}},
    {"CYLINDRICAL", {"B14P", nullptr}},
    {"PLANAR", {"B234", nullptr}},
    {"TRANSLATOR", {"B1PS", nullptr}},
    {"UJOINT", {"B46", nullptr}},
    {"BEAM", {nullptr}},
    {"SLIDE-PLANE, UNIVERSAL", {"B2346", nullptr}},
    {"RADIAL-THRUST, CARDAN", {"B13456", nullptr}},
    {"AXIAL", {"B1PS", nullptr}},
    {"LINK, EULER", {"B456", nullptr}},
    {"JOIN, FLEXION-TORSION", {"B45", nullptr}},
    {"PROJECTION CARTESIAN, PROJECTION FLEXION-TORSION", {"B6U", "B6P", nullptr}},
    {"CARTESIAN, ALIGN", {"B123C", nullptr}},
    {"BUSHING", {"B6P", "B6U", "B6C", "B6S"}},
};
constexpr long kCombinationCount = sizeof kCombinations / sizeof kCombinations[0];

// The behaviours some section names: only those are written (an unused one draws a warning).
std::set<std::string> used;

// Without the history output request, the run writes every connector's default columns.
bool default_output = false;

// The one step: `load` (a *CLOAD or *BOUNDARY block) in ten increments with a request for some
// elements' and the tip's history, or in one increment with the default output.
void step(const char* load) {
  std::printf("*STEP, NLGEOM=NO\n*STATIC\n%s\n%s", default_output ? "1.0, 1.0" : "0.1, 1.0",
              load);
  if (!default_output) {
    std::printf("*OUTPUT, HISTORY, FREQUENCY=1\n*ELEMENT OUTPUT, ELSET=EVERY10\nCTF, CU\n");
    std::printf("*NODE OUTPUT, NSET=TIP\nU, RF\n");
  }
  std::printf("*END STEP\n");
}

bool elastic(const char* name, const int* components, int count) {
  if (!used.count(name)) return false;
  std::printf("*CONNECTOR BEHAVIOR, NAME=%s\n", name);
  for (int i = 0; i < count; ++i) {
    const int c = components[i];
    std::printf("*CONNECTOR ELASTICITY, COMPONENT=%d\n%s\n", c, c <= 3 ? "<k>" : "<kr>");
  }
  return true;
}

void isotropic_plasticity(int component) {
  std::printf(
      "*CONNECTOR PLASTICITY, COMPONENT=%d\n*CONNECTOR HARDENING, DEFINITION=TABULAR\n"
      "400., 0.\n600., 0.5\n700., 2.0\n",
      component);
}

// The behaviours the sections name. Stop limits are positions (lengths, or angles in radians),
// wide enough that no connector starts outside them (stop-initially-violated).
void behaviors() {
  const int six[] = {1, 2, 3, 4, 5, 6};
  // Coupled: the upper triangle column by column (behaviors.md 4.3), diagonally dominant.
  if (used.count("B6C"))
    std::printf(
        "*CONNECTOR BEHAVIOR, NAME=B6C\n*CONNECTOR ELASTICITY\n"
        "<k>, 1.0e4, <k>, 1.0e4, 1.0e4, 2.0e5, 0., 0.\n"
        "0., <kr>, 0., 0., 0., 1.0e5, <kr>, 0.\n"
        "0., 0., 1.0e5, 1.0e5, 5.0e5\n");
  elastic("B6U", six, 6);
  if (elastic("B6S", six, 6))
    std::printf(
        "*CONNECTOR STOP, COMPONENT=1\n-100., 100.\n*CONNECTOR STOP, COMPONENT=4\n-3., 3.\n");
  // The spot weld: coupled plasticity with the elliptical potential over derived components.
  if (elastic("B6P", six, 6))
    std::printf(
        "*CONNECTOR PLASTICITY\n*CONNECTOR HARDENING, DEFINITION=TABULAR\n"
        "40000., 0.\n60000., 0.5\n70000., 2.0\n"
        "*CONNECTOR POTENTIAL, EXPONENT=1.5\nnormal, 0.02, , MACAULEY, ,\nshear,  0.05, , ABS, ,\n"
        "*CONNECTOR DERIVED COMPONENT, NAME=normal, OPERATOR=MACAULEY SUM\n3\n1.0\n"
        "*CONNECTOR DERIVED COMPONENT, NAME=normal\n4, 5\n<or_n>, <or_n>\n"
        "*CONNECTOR DERIVED COMPONENT, NAME=shear\n6\n<or_s>\n"
        "*CONNECTOR DERIVED COMPONENT, NAME=shear\n1, 2\n1.0, 1.0\n");
  const int c4[] = {4};
  if (elastic("B4S", c4, 1)) std::printf("*CONNECTOR STOP, COMPONENT=4\n-3., 3.\n");
  const int c14[] = {1, 4};
  if (elastic("B14P", c14, 2)) isotropic_plasticity(1);
  const int c1[] = {1};
  if (elastic("B1PS", c1, 1)) {
    isotropic_plasticity(1);
    std::printf("*CONNECTOR STOP, COMPONENT=1\n-100., 100.\n");
  }
  const int c234[] = {2, 3, 4};
  elastic("B234", c234, 3);
  const int c46[] = {4, 6};
  elastic("B46", c46, 2);
  const int c2346[] = {2, 3, 4, 6};
  elastic("B2346", c2346, 4);
  const int c13456[] = {1, 3, 4, 5, 6};
  elastic("B13456", c13456, 5);
  const int c456[] = {4, 5, 6};
  elastic("B456", c456, 3);
  // FLEXION-TORSION's component 6 is the sweep angle: a behaviour there draws sweep-behaviour.
  const int c45[] = {4, 5};
  elastic("B45", c45, 2);
  // Coupled over CARTESIAN's three components: the rotational rows stay zero
  // (coupled-stiffness-ignored otherwise).
  if (used.count("B123C"))
    std::printf(
        "*CONNECTOR BEHAVIOR, NAME=B123C\n*CONNECTOR ELASTICITY\n"
        "<k>, 1.0e4, <k>, 1.0e4, 1.0e4, 2.0e5, 0., 0.\n"
        "0., 0., 0., 0., 0., 0., 0., 0.\n"
        "0., 0., 0., 0., 0.\n");
}

const char* section_behavior(long s) {
  const Combination& combination = kCombinations[s % kCombinationCount];
  long variants = 0;
  while (variants < 4 && combination.behaviors[variants] != nullptr) ++variants;
  return variants ? combination.behaviors[(s / kCombinationCount) % variants] : nullptr;
}

void mixed(long n) {
  const long sections = (n + kSectionSize - 1) / kSectionSize;
  for (long s = 0; s < sections; ++s)
    if (const char* behavior = section_behavior(s)) used.insert(behavior);
  std::printf("*HEADING\n%ld connectors of every connection type (clinch check benchmark)\n", n);
  std::printf("*PARAMETER\nk = 1.0e5\nkr = 1.0e6\n");
  if (used.count("B6P"))  // the spot weld's potential weights
    std::printf("r_n  = sqrt(30.68/19.63)\nor_n = 1.0/r_n\nor_s = 1.0/(2.0*r_n)\n");
  std::printf("*NODE, NSET=ALLN\n");
  for (long i = 1; i <= n + 1; ++i) {
    const double t = 0.01 * static_cast<double>(i);
    std::printf("%ld, %.9e, %.9e, %.9e\n", i, 50.0 * std::cos(t), 50.0 * std::sin(t),
                0.1 * static_cast<double>(i));
  }
  for (long s = 0; s < sections; ++s) {
    const long first = s * kSectionSize + 1;
    const long last = first + kSectionSize - 1 < n ? first + kSectionSize - 1 : n;
    std::printf("*ELEMENT, TYPE=CONN3D2, ELSET=S%ld\n", s + 1);
    for (long e = first; e <= last; ++e) std::printf("%ld, %ld, %ld\n", e, e, e + 1);
    // Each section's local 1-axis turned about z by its own angle; b twisted about that axis.
    const double theta = 0.37 * static_cast<double>(s);
    const double c = std::cos(theta), sn = std::sin(theta);
    std::printf("*ORIENTATION, NAME=OA%ld\n%.9f, %.9f, 0., %.9f, %.9f, 0.\n", s + 1, c, sn, -sn, c);
    std::printf("*ORIENTATION, NAME=OB%ld\n%.9f, %.9f, 0., %.9f, %.9f, 0.\n1, %g\n", s + 1, c, sn,
                -sn, c, kTwistDegrees);
    const char* behavior = section_behavior(s);
    std::printf("*CONNECTOR SECTION, ELSET=S%ld%s%s\n%s,\nOA%ld, OB%ld\n", s + 1,
                behavior ? ", BEHAVIOR=" : "", behavior ? behavior : "",
                kCombinations[s % kCombinationCount].types, s + 1, s + 1);
  }
  std::printf("*ELSET, ELSET=ALLC, GENERATE\n1, %ld, 1\n", n);
  std::printf("*NSET, NSET=FIXED\n1\n*NSET, NSET=TIP\n%ld\n", n + 1);
  std::printf("*ELSET, ELSET=EVERY10, GENERATE\n1, %ld, 10\n", n - (n - 1) % 10);
  behaviors();
  std::printf("*BOUNDARY\nFIXED, ENCASTRE\n");
  step("*CLOAD\nTIP, 1, 1.0\n");
}

}  // namespace

int main(int argc, char** argv) {
  bool mix = false;
  for (int i = 2; i < argc; ++i) {
    if (std::strcmp(argv[i], "--mix") == 0) {
      mix = true;
    } else if (std::strcmp(argv[i], "--default-output") == 0) {
      default_output = true;
    } else {
      argc = 0;  // usage below
    }
  }
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s N [--mix] [--default-output]\n", argv[0]);
    return 3;
  }
  const long n = std::atol(argv[1]);
  if (n < 1) return 3;
  if (mix) {
    mixed(n);
    return 0;
  }
  std::printf("*HEADING\nconnector chain of %ld elements (clinch check benchmark)\n", n);
  std::printf("*PARAMETER\nk = 1.0e4\n");
  std::printf("*NODE, NSET=ALLN\n");
  for (long i = 1; i <= n + 1; ++i) {
    const double t = 0.01 * static_cast<double>(i);
    std::printf("%ld, %.9e, %.9e, %.9e\n", i, 50.0 * std::cos(t), 50.0 * std::sin(t),
                0.1 * static_cast<double>(i));
  }
  std::printf("*ELEMENT, TYPE=CONN3D2, ELSET=CHAIN\n");
  for (long i = 1; i <= n; ++i) std::printf("%ld, %ld, %ld\n", i, i, i + 1);
  std::printf("*NSET, NSET=FIXED\n1\n*NSET, NSET=TIP\n%ld\n", n + 1);
  std::printf("*ELSET, ELSET=EVERY10, GENERATE\n1, %ld, 10\n", n - (n - 1) % 10);
  // The interior nodes 2..n (none in a 1-connector chain, the baseline of scripts/bench_check.sh).
  const bool interior = n >= 2;
  if (interior) std::printf("*NSET, NSET=MIDDLE\n");
  for (long i = 2; i <= n; i += 16) {
    for (long j = i; j < i + 16 && j <= n; ++j)
      std::printf(j + 1 < i + 16 && j < n ? "%ld, " : "%ld\n", j);
  }
  std::printf("*CONNECTOR SECTION, ELSET=CHAIN, BEHAVIOR=SPRING\nAXIAL,\n");
  std::printf("*CONNECTOR BEHAVIOR, NAME=SPRING\n*CONNECTOR ELASTICITY, COMPONENT=1\n<k>\n");
  std::printf("*BOUNDARY\nFIXED, 1, 3\n%s", interior ? "MIDDLE, 1, 2\n" : "");
  // The tip's transverse DOFs, free for `clinch check`, would leave a run singular.
  if (default_output) std::printf("TIP, 2, 3\n");
  step("*BOUNDARY\nTIP, 1, 1, 0.5\n");
  return 0;
}
