// Writes the lattice deck of the clinch-vs-CalculiX benchmark (scripts/bench_lattice.sh): an
// N×N×N grid of nodes (spacing h = 1, edge L = N − 1), each joined to its 13 forward neighbours by
// a SPRINGA spring or an AXIAL CONN3D2 connector, clamped in x on x = 0, pulled to u1 = ε·L on
// x = L, with rollers on the four side faces. Under these conditions the homogeneous stretch
// u = (εx, 0, 0) is the exact solution (docs/benchmarks.md), so the reaction on x = L has a
// closed form, which --reference writes as JSON.
// The irregular lattice (--jitter, --patch) moves every node by a seeded random fraction of the
// spacing in each direction and pulls only a centred square patch of the face x = L (set PULL):
// no closed form, and Newton must iterate; its JSON has "reaction": null.
// Usage: generate_lattice --n N --element springa|axial --law linear|nonlinear --out FILE.inp
//                         [--reference FILE.json] [--jitter F] [--patch P] [--seed S]
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr double kSpacing = 1.0;
constexpr double kStiffness = 1.0e3;
constexpr double kLinearStrain = 0.01;
constexpr double kNonlinearStrain = 0.15;
// Nonlinear law F(Δ) = k (Δ + Δ³/Δc²), sampled on |Δ| ≤ kTableHalfWidth; the largest spring
// elongation is ε·h = 0.15, well inside the table, so neither code extrapolates.
constexpr double kCubicScale = 0.1;
constexpr double kTableHalfWidth = 0.5;
constexpr int kTableIntervals = 40;
constexpr int kLabelsPerLine = 10;

struct Options {
  long n = 0;
  bool axial = false;
  bool nonlinear = false;
  std::string out;
  std::string reference;
  double jitter = 0.0;  // largest node move per direction, as a fraction of the spacing
  double patch = 1.0;   // side of the pulled square of x = L, as a fraction of the face's side
  std::uint64_t seed = 1;

  bool irregular() const { return jitter > 0.0 || patch < 1.0; }
};

// splitmix64: the same jitter from the same seed on every platform.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double symmetric() {  // uniform in [−1, 1)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
  }

 private:
  std::uint64_t state_;
};

struct Offset {
  int a, b, c;
};

// The 13 offsets of the 26-neighbourhood that are lexicographically positive.
std::vector<Offset> forward_offsets() {
  std::vector<Offset> offsets;
  for (int a = -1; a <= 1; ++a) {
    for (int b = -1; b <= 1; ++b) {
      for (int c = -1; c <= 1; ++c) {
        if (a > 0 || (a == 0 && b > 0) || (a == 0 && b == 0 && c > 0)) offsets.push_back({a, b, c});
      }
    }
  }
  return offsets;
}

// Table points as printed in the deck, read back, so that the reference uses the very numbers
// both codes interpolate.
struct Table {
  std::vector<double> force;
  std::vector<double> elongation;

  double operator()(double delta) const {
    std::size_t s = 1;
    while (s + 1 < elongation.size() && delta > elongation[s]) ++s;
    const double t = (delta - elongation[s - 1]) / (elongation[s] - elongation[s - 1]);
    return force[s - 1] + t * (force[s] - force[s - 1]);
  }
};

// A real with a decimal point always: CalculiX takes a *SPRING line without one for a DOF line.
std::string real_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", value);
  if (std::strchr(text, '.')) return text;
  const char* exponent = std::strchr(text, 'e');
  const int mantissa = static_cast<int>(exponent ? exponent - text : std::strlen(text));
  char with_point[40];
  std::snprintf(with_point, sizeof with_point, "%.*s.%s", mantissa, text, text + mantissa);
  return with_point;
}

double printed(double value) { return std::strtod(real_text(value).c_str(), nullptr); }

Table nonlinear_table() {
  Table table;
  for (int p = 0; p <= kTableIntervals; ++p) {
    const double delta = printed(kSpacing * kTableHalfWidth * (2.0 * p / kTableIntervals - 1.0));
    const double r = delta / (kCubicScale * kSpacing);
    table.elongation.push_back(delta);
    table.force.push_back(printed(kStiffness * (delta + delta * r * r)));
  }
  return table;
}

bool parse(int argc, char** argv, Options& options) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--n") {
      options.n = std::atol(value.c_str());
    } else if (key == "--element" && (value == "springa" || value == "axial")) {
      options.axial = value == "axial";
    } else if (key == "--law" && (value == "linear" || value == "nonlinear")) {
      options.nonlinear = value == "nonlinear";
    } else if (key == "--out") {
      options.out = value;
    } else if (key == "--reference") {
      options.reference = value;
    } else if (key == "--jitter") {
      options.jitter = std::atof(value.c_str());
    } else if (key == "--patch") {
      options.patch = std::atof(value.c_str());
    } else if (key == "--seed") {
      options.seed = std::strtoull(value.c_str(), nullptr, 10);
    } else {
      return false;
    }
  }
  // A jitter of half the spacing or more could make two nodes meet.
  return argc % 2 == 1 && options.n >= 2 && !options.out.empty() && options.jitter >= 0.0 &&
         options.jitter < 0.5 && options.patch > 0.0 && options.patch <= 1.0;
}

class DeckWriter {
 public:
  DeckWriter(const Options& options, std::FILE* file)
      : options_(options), n_(options.n), file_(file) {}

  void write(const Table& table) const {
    const double length = kSpacing * static_cast<double>(n_ - 1);
    const double strain = options_.nonlinear ? kNonlinearStrain : kLinearStrain;
    std::fprintf(file_, "*HEADING\n%ldx%ldx%ld %s%s lattice, %s law, stretch %g",
                 n_, n_, n_, options_.irregular() ? "irregular " : "",
                 options_.axial ? "AXIAL connector" : "SPRINGA",
                 options_.nonlinear ? "nonlinear" : "linear", strain);
    if (options_.irregular()) {
      std::fprintf(file_, " (jitter %g, patch %g, seed %llu)", options_.jitter, options_.patch,
                   static_cast<unsigned long long>(options_.seed));
    }
    std::fprintf(file_, " (clinch benchmark)\n*NODE, NSET=NALL\n");
    Random random(options_.seed);
    const double jitter = options_.jitter * kSpacing;
    for (long i = 0; i < n_; ++i) {
      for (long j = 0; j < n_; ++j) {
        for (long k = 0; k < n_; ++k) {
          if (!options_.irregular()) {
            std::fprintf(file_, "%ld, %.1f, %.1f, %.1f\n", label(i, j, k), kSpacing * i,
                         kSpacing * j, kSpacing * k);
            continue;
          }
          const double x = kSpacing * i + jitter * random.symmetric();
          const double y = kSpacing * j + jitter * random.symmetric();
          const double z = kSpacing * k + jitter * random.symmetric();
          std::fprintf(file_, "%ld, %s, %s, %s\n", label(i, j, k), real_text(x).c_str(),
                       real_text(y).c_str(), real_text(z).c_str());
        }
      }
    }
    write_elements();
    write_face("XMIN", [](long i, long, long) { return i == 0; });
    write_face("XMAX", [this](long i, long, long) { return i == n_ - 1; });
    write_face("YMIN", [](long, long j, long) { return j == 0; });
    write_face("YMAX", [this](long, long j, long) { return j == n_ - 1; });
    write_face("ZMIN", [](long, long, long k) { return k == 0; });
    write_face("ZMAX", [this](long, long, long k) { return k == n_ - 1; });
    // The centred square of x = L whose side is `patch` times the face's (at least one node).
    const double half = 0.5 * options_.patch * static_cast<double>(n_ - 1) + 1e-9;
    const double centre = 0.5 * static_cast<double>(n_ - 1);
    const char* pulled = options_.irregular() ? "PULL" : "XMAX";
    if (options_.irregular()) {
      write_face(pulled, [this, half, centre](long i, long j, long k) {
        return i == n_ - 1 && std::abs(static_cast<double>(j) - centre) <= half &&
               std::abs(static_cast<double>(k) - centre) <= half;
      });
    }
    write_behavior(table);
    std::fprintf(file_, "*BOUNDARY\nXMIN, 1, 1\nYMIN, 2, 2\nYMAX, 2, 2\nZMIN, 3, 3\nZMAX, 3, 3\n");
    // Both laws under NLGEOM: CalculiX solves a SPRINGA step without it neither as small-strain
    // nor as large-strain (docs/benchmarks.md). Linear: one increment; nonlinear: automatic
    // increments from 0.1, with the minimum increment written out so both codes use the same.
    std::fprintf(file_, options_.nonlinear ? "*STEP, NLGEOM\n*STATIC\n0.1, 1.0, 1.e-5, 1.0\n"
                                           : "*STEP, NLGEOM\n*STATIC\n");
    std::fprintf(file_, "*BOUNDARY\n%s, 1, 1, %s\n", pulled, real_text(strain * length).c_str());
    std::fprintf(file_, "*NODE PRINT, NSET=%s, TOTALS=ONLY\nRF\n*END STEP\n", pulled);
  }

 private:
  long label(long i, long j, long k) const { return 1 + i * n_ * n_ + j * n_ + k; }

  void write_elements() const {
    std::fprintf(file_, "*ELEMENT, TYPE=%s, ELSET=LATTICE\n",
                 options_.axial ? "CONN3D2" : "SPRINGA");
    const std::vector<Offset> offsets = forward_offsets();
    long element = 0;
    for (long i = 0; i < n_; ++i) {
      for (long j = 0; j < n_; ++j) {
        for (long k = 0; k < n_; ++k) {
          for (const Offset& o : offsets) {
            const long i2 = i + o.a, j2 = j + o.b, k2 = k + o.c;
            if (i2 >= n_ || j2 < 0 || j2 >= n_ || k2 < 0 || k2 >= n_) continue;
            std::fprintf(file_, "%ld, %ld, %ld\n", ++element, label(i, j, k), label(i2, j2, k2));
          }
        }
      }
    }
  }

  template <typename InFace>
  void write_face(const char* name, InFace in_face) const {
    std::fprintf(file_, "*NSET, NSET=%s\n", name);
    int on_line = 0;
    for (long i = 0; i < n_; ++i) {
      for (long j = 0; j < n_; ++j) {
        for (long k = 0; k < n_; ++k) {
          if (!in_face(i, j, k)) continue;
          if (on_line == kLabelsPerLine) {
            std::fputc('\n', file_);
            on_line = 0;
          }
          std::fprintf(file_, on_line ? ", %ld" : "%ld", label(i, j, k));
          ++on_line;
        }
      }
    }
    std::fputc('\n', file_);
  }

  // The blank first data line of *SPRING is the SPRINGA DOF line (keywords.md §7); CalculiX
  // drops it as a blank line, so both codes read the same property lines.
  void write_behavior(const Table& table) const {
    if (options_.axial) {
      std::fprintf(file_, "*CONNECTOR SECTION, ELSET=LATTICE, BEHAVIOR=LATTICE\nAXIAL,\n");
      std::fprintf(file_, "*CONNECTOR BEHAVIOR, NAME=LATTICE\n");
      std::fprintf(file_,
                   options_.nonlinear
                       ? "*CONNECTOR ELASTICITY, COMPONENT=1, NONLINEAR, EXTRAPOLATION=LINEAR\n"
                       : "*CONNECTOR ELASTICITY, COMPONENT=1\n");
    } else {
      std::fprintf(file_, "*SPRING, ELSET=LATTICE%s\n\n", options_.nonlinear ? ", NONLINEAR" : "");
    }
    if (!options_.nonlinear) {
      std::fprintf(file_, "%s\n", real_text(kStiffness).c_str());
      return;
    }
    for (std::size_t p = 0; p < table.force.size(); ++p) {
      std::fprintf(file_, "%s, %s\n", real_text(table.force[p]).c_str(),
                   real_text(table.elongation[p]).c_str());
    }
  }

  const Options& options_;
  long n_;
  std::FILE* file_;
};

// The force through the plane between two x-layers: every spring with a = 1 crosses it once,
// and (N − |b|)(N − |c|) springs have the offset (1, b, c). The stretched spring (1 + ε, b, c)h
// has length l and x-direction cosine (1 + ε)h / l (keywords.md §7, NLGEOM).
double closed_form_reaction(const Options& options, const Table& table) {
  const double strain = options.nonlinear ? kNonlinearStrain : kLinearStrain;
  const double stretched = (1.0 + strain) * kSpacing;
  double reaction = 0.0;
  for (int b = -1; b <= 1; ++b) {
    for (int c = -1; c <= 1; ++c) {
      const double count =
          static_cast<double>((options.n - std::abs(b)) * (options.n - std::abs(c)));
      const double length0 = kSpacing * std::sqrt(1.0 + b * b + c * c);
      const double length = std::hypot(stretched, kSpacing * b, kSpacing * c);
      const double delta = length - length0;
      const double force = options.nonlinear ? table(delta) : kStiffness * delta;
      reaction += count * force * stretched / length;
    }
  }
  return reaction;
}

void write_reference(const Options& options, const Table& table, long elements, std::FILE* file) {
  const double strain = options.nonlinear ? kNonlinearStrain : kLinearStrain;
  const long n = options.n;
  const char* formula =
      options.irregular()
          ? "none: irregular lattice (jittered nodes, patch pulled)"
      : options.nonlinear
          ? "R = sum_{b,c in -1..1} (N-|b|)(N-|c|) F(l-l0) (1+e)h/l, l0 = h sqrt(1+b^2+c^2), "
            "l = h sqrt((1+e)^2+b^2+c^2), F the piecewise linear table of the deck"
          : "R = sum_{b,c in -1..1} (N-|b|)(N-|c|) k (l-l0) (1+e)h/l, l0 = h sqrt(1+b^2+c^2), "
            "l = h sqrt((1+e)^2+b^2+c^2)";
  char reaction[32] = "null";
  if (!options.irregular()) {
    std::snprintf(reaction, sizeof reaction, "%.17g", closed_form_reaction(options, table));
  }
  std::fprintf(file,
               "{\n  \"n\": %ld,\n  \"element\": \"%s\",\n  \"law\": \"%s\",\n  \"nlgeom\": %s,\n"
               "  \"spacing\": %.17g,\n  \"length\": %.17g,\n  \"strain\": %.17g,\n"
               "  \"displacement\": %.17g,\n  \"stiffness\": %.17g,\n  \"nodes\": %ld,\n"
               "  \"elements\": %ld,\n  \"dofs\": %ld,\n  \"free_dofs\": %ld,\n"
               "  \"jitter\": %.17g,\n  \"patch\": %.17g,\n  \"seed\": %llu,\n"
               "  \"reaction_set\": \"%s\",\n  \"reaction\": %s,\n  \"formula\": \"%s\"\n}\n",
               n, options.axial ? "axial" : "springa", options.nonlinear ? "nonlinear" : "linear",
               "true", kSpacing, kSpacing * (n - 1), strain, strain * kSpacing * (n - 1),
               kStiffness, n * n * n, elements, 3 * n * n * n, 3 * n * n * n - 6 * n * n,
               options.jitter, options.patch, static_cast<unsigned long long>(options.seed),
               options.irregular() ? "PULL" : "XMAX", reaction, formula);
}

long element_count(long n) {
  long count = 0;
  for (const Offset& o : forward_offsets())
    count += (n - std::abs(o.a)) * (n - std::abs(o.b)) * (n - std::abs(o.c));
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!parse(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: %s --n N --element springa|axial --law linear|nonlinear --out FILE.inp "
                 "[--reference FILE.json] [--jitter F (0 <= F < 0.5)] [--patch P (0 < P <= 1)] "
                 "[--seed S]\n",
                 argv[0]);
    return 3;
  }
  const Table table = nonlinear_table();
  std::FILE* deck = std::fopen(options.out.c_str(), "w");
  if (!deck) {
    std::fprintf(stderr, "cannot write %s\n", options.out.c_str());
    return 3;
  }
  DeckWriter(options, deck).write(table);
  if (std::fclose(deck) != 0) return 3;
  if (options.reference.empty()) return 0;
  std::FILE* reference = std::fopen(options.reference.c_str(), "w");
  if (!reference) {
    std::fprintf(stderr, "cannot write %s\n", options.reference.c_str());
    return 3;
  }
  write_reference(options, table, element_count(options.n), reference);
  return std::fclose(reference) == 0 ? 0 : 3;
}
