// Writes a deck of N connectors for the `clinch check` throughput benchmark
// (scripts/bench_check.sh): a chain of N+1 nodes on a helix, N CONN3D2 elements joining
// neighbours, node and element sets (explicit and GENERATE), one *CONNECTOR SECTION with an
// AXIAL type and a behaviour, boundary conditions and one step with history output.
// Usage: generate_connector_deck N > deck.inp
#include <cmath>
#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s N\n", argv[0]);
    return 3;
  }
  const long n = std::atol(argv[1]);
  if (n < 1) return 3;
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
    for (long j = i; j < i + 16 && j <= n; ++j) std::printf(j + 1 < i + 16 && j < n ? "%ld, " : "%ld\n", j);
  }
  std::printf("*CONNECTOR SECTION, ELSET=CHAIN, BEHAVIOR=SPRING\nAXIAL,\n");
  std::printf("*CONNECTOR BEHAVIOR, NAME=SPRING\n*CONNECTOR ELASTICITY, COMPONENT=1\n<k>\n");
  std::printf("*BOUNDARY\nFIXED, 1, 3\n%s", interior ? "MIDDLE, 1, 2\n" : "");
  std::printf("*STEP, NLGEOM=NO\n*STATIC\n0.1, 1.0\n*BOUNDARY\nTIP, 1, 1, 0.5\n");
  std::printf("*OUTPUT, HISTORY, FREQUENCY=1\n*ELEMENT OUTPUT, ELSET=EVERY10\nCTF, CU\n");
  std::printf("*NODE OUTPUT, NSET=TIP\nU, RF\n*END STEP\n");
  return 0;
}
