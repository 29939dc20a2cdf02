// The closed-form reaction of the lattice benchmark (decks/bench/generate_lattice.cpp,
// docs/benchmarks.md), checked on tiny lattices by summing every spring's nodal forces under
// the homogeneous stretch u = (εx, 0, 0): the stretch must be an equilibrium state under the
// benchmark's supports, the reaction must equal the plane-crossing formula, and no rigid mode may
// be left.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <vector>

#include "base/small_types.hpp"

namespace clinch {
namespace {

constexpr double kStiffness = 1.0e3;

struct Spring {
  int first;
  int second;
};

struct Lattice {
  int n = 0;
  std::vector<Vector3> position;
  std::vector<Spring> springs;

  int label(int i, int j, int k) const { return (i * n + j) * n + k; }
  int index(int node, int axis) const { return static_cast<int>(position[node][axis] + 0.5); }
  bool on_face(int node, int axis) const {
    const int i = index(node, axis);
    return i == 0 || i == n - 1;
  }
};

// Spacing 1; each node joined to the 13 neighbours with a lexicographically positive offset.
Lattice make_lattice(int n) {
  Lattice lattice;
  lattice.n = n;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) lattice.position.emplace_back(i, j, k);
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        for (int a = 0; a <= 1; ++a) {
          for (int b = -1; b <= 1; ++b) {
            for (int c = -1; c <= 1; ++c) {
              if (a == 0 && (b < 0 || (b == 0 && c <= 0))) continue;
              const int i2 = i + a, j2 = j + b, k2 = k + c;
              if (i2 >= n || j2 < 0 || j2 >= n || k2 < 0 || k2 >= n) continue;
              lattice.springs.push_back({lattice.label(i, j, k), lattice.label(i2, j2, k2)});
            }
          }
        }
      }
    }
  }
  return lattice;
}

using SpringLaw = std::function<double(double)>;

double linear_law(double delta) { return kStiffness * delta; }
// The smooth law the benchmark's nonlinear table samples.
double cubic_law(double delta) { return kStiffness * (delta + delta * delta * delta / 0.01); }
double cubic_slope(double delta) { return kStiffness * (1.0 + 3.0 * delta * delta / 0.01); }

Vector3 stretched(const Vector3& x, double strain) {
  return {(1.0 + strain) * x.x(), x.y(), x.z()};
}

// Internal nodal forces of all springs under the homogeneous stretch (keywords.md §7, NLGEOM:
// −F n at the first node, +F n at the second).
std::vector<Vector3> nodal_forces(const Lattice& lattice, double strain, const SpringLaw& law) {
  std::vector<Vector3> force(lattice.position.size(), Vector3::Zero());
  for (const Spring& s : lattice.springs) {
    const Vector3 d0 = lattice.position[s.second] - lattice.position[s.first];
    const Vector3 d = stretched(lattice.position[s.second], strain) -
                      stretched(lattice.position[s.first], strain);
    const Vector3 f = law(d.norm() - d0.norm()) * d.normalized();
    force[s.first] -= f;
    force[s.second] += f;
  }
  return force;
}

// The formula the generator writes to --reference: (N − |b|)(N − |c|) springs of offset (1, b, c)
// cross any plane between two x-layers.
double closed_form_reaction(int n, double strain, const SpringLaw& law) {
  double reaction = 0.0;
  for (int b = -1; b <= 1; ++b) {
    for (int c = -1; c <= 1; ++c) {
      const double count = (n - std::abs(b)) * (n - std::abs(c));
      const double length0 = std::sqrt(1.0 + b * b + c * c);
      const double length = std::hypot(1.0 + strain, b, c);
      reaction += count * law(length - length0) * (1.0 + strain) / length;
    }
  }
  return reaction;
}

struct Case {
  int n;
  double strain;
  SpringLaw law;
};

std::vector<Case> cases() {
  std::vector<Case> list;
  for (int n : {2, 3, 4}) {
    list.push_back({n, 0.01, linear_law});
    list.push_back({n, 0.15, cubic_law});
  }
  return list;
}

TEST(LatticeReference, HomogeneousStretchIsInEquilibriumUnderTheSupports) {
  for (const Case& c : cases()) {
    const Lattice lattice = make_lattice(c.n);
    const std::vector<Vector3> force = nodal_forces(lattice, c.strain, c.law);
    for (std::size_t node = 0; node < force.size(); ++node) {
      for (int axis = 0; axis < 3; ++axis) {
        // A free DOF (not on an x-face for u1, not on a roller face for u2, u3) must be balanced.
        // Forces are sums of at most 26 terms of size ≤ 500, so 1e-9 is round-off with margin;
        // a missing neighbour would leave a term of order 10.
        if (lattice.on_face(static_cast<int>(node), axis)) continue;
        EXPECT_NEAR(force[node][axis], 0.0, 1e-9) << "N=" << c.n << " node " << node;
      }
    }
  }
}

TEST(LatticeReference, ReactionOnTheXMaxFaceMatchesThePlaneCrossingFormula) {
  for (const Case& c : cases()) {
    const Lattice lattice = make_lattice(c.n);
    const std::vector<Vector3> force = nodal_forces(lattice, c.strain, c.law);
    double reaction = 0.0;
    double clamp = 0.0;
    for (std::size_t node = 0; node < force.size(); ++node) {
      const int i = lattice.index(static_cast<int>(node), 0);
      if (i == c.n - 1) reaction += force[node].x();
      if (i == 0) clamp += force[node].x();
    }
    const double exact = closed_form_reaction(c.n, c.strain, c.law);
    // Two summation orders of the same few hundred terms: round-off only, relative 1e-12.
    EXPECT_NEAR(reaction, exact, 1e-12 * exact) << "N=" << c.n;
    EXPECT_NEAR(clamp, -exact, 1e-12 * exact) << "N=" << c.n;
    EXPECT_GT(exact, 0.0);
  }
}

// Tangent k′ nnᵀ + (F/ℓ)(I − nnᵀ) (keywords.md §7) assembled at the stretched state, with the
// benchmark's supports removed: positive definite means no rigid mode or mechanism is left.
TEST(LatticeReference, ConstrainedTangentHasNoZeroEnergyMode) {
  for (int n : {3, 4}) {  // N = 2 has no free DOF
    for (double strain : {0.0, 0.15}) {
      const Lattice lattice = make_lattice(n);
      const int size = 3 * static_cast<int>(lattice.position.size());
      Eigen::MatrixXd k = Eigen::MatrixXd::Zero(size, size);
      for (const Spring& s : lattice.springs) {
        const Vector3 d0 = lattice.position[s.second] - lattice.position[s.first];
        const Vector3 d = stretched(lattice.position[s.second], strain) -
                          stretched(lattice.position[s.first], strain);
        const double length = d.norm();
        const Vector3 unit = d / length;
        const double force = cubic_law(length - d0.norm());
        const Matrix3 block = cubic_slope(length - d0.norm()) * unit * unit.transpose() +
                              force / length * (Matrix3::Identity() - unit * unit.transpose());
        const int p = 3 * s.first, q = 3 * s.second;
        k.block<3, 3>(p, p) += block;
        k.block<3, 3>(q, q) += block;
        k.block<3, 3>(p, q) -= block;
        k.block<3, 3>(q, p) -= block;
      }
      std::vector<int> free;
      for (int node = 0; node < static_cast<int>(lattice.position.size()); ++node) {
        for (int axis = 0; axis < 3; ++axis) {
          if (!lattice.on_face(node, axis)) free.push_back(3 * node + axis);
        }
      }
      Eigen::MatrixXd reduced(free.size(), free.size());
      for (std::size_t r = 0; r < free.size(); ++r) {
        for (std::size_t c = 0; c < free.size(); ++c) reduced(r, c) = k(free[r], free[c]);
      }
      const Eigen::VectorXd eigenvalues =
          Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(reduced).eigenvalues();
      // Spring stiffnesses are ≥ 1e3 / √3 per unit length; a mechanism would give an eigenvalue
      // at round-off level (≈ 1e-12 of the largest), so 1.0 separates the two cleanly.
      EXPECT_GT(eigenvalues.minCoeff(), 1.0) << "N=" << n << " strain " << strain;
    }
  }
}

}  // namespace
}  // namespace clinch
