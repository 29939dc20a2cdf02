// The mass properties of every element shape whose mass clinch computes (element_mass.hpp),
// against closed forms that do not use clinch's quadrature: a rectangular box
// (m = ρabc, I = m/12 diag(b² + c², a² + c², a² + b²)) filled by each solid shape; a
// parallelepiped (an affine cube) and a distorted tetrahedron against the exact moments of a
// tetrahedron, ∫ x xᵀ dV = V/20 (Σ xᵢxᵢᵀ + s sᵀ), s = Σ xᵢ; a rectangular plate in a rotated
// plane filled by each surface shape (with the thickness term); a rod for the trusses, and for
// the beams a box, a cylinder and a tube (their profile's inertia across the axis). The
// quadrature is exact for these straight-edged elements, so the tolerance is round-off: 1e-12
// of each quantity's scale. The bodies sit away from the origin so that the moments about the
// centre are not the difference of two large numbers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

#include "src/model/element_mass.hpp"

namespace clinch {
namespace {

struct Props {
  double mass = 0;
  Vector3 centre = Vector3::Zero();
  Matrix3 inertia = Matrix3::Zero();  // about the centre
};

// Several elements' properties as one body's (the parallel-axis theorem).
Props combine(const std::vector<ElementMassProperties>& parts) {
  Props p;
  for (const auto& e : parts) {
    p.mass += e.mass;
    p.centre += e.mass * e.centre;
  }
  p.centre /= p.mass;
  for (const auto& e : parts) {
    const Vector3 d = e.centre - p.centre;
    p.inertia += e.rotary + e.mass * (d.squaredNorm() * Matrix3::Identity() - d * d.transpose());
  }
  return p;
}

void expect_props(const Props& got, const Props& want, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_NEAR(got.mass, want.mass, 1e-12 * want.mass);
  const double length = std::sqrt(want.inertia.norm() / want.mass);
  EXPECT_LT((got.centre - want.centre).norm(), 1e-12 * (want.centre.norm() + length));
  EXPECT_LT((got.inertia - want.inertia).norm(), 1e-12 * want.inertia.norm());
}

ElementMassProperties of(ElementShape shape, const std::vector<Vector3>& x, double density,
                         double section = 1.0, std::optional<BeamProfile> profile = {}) {
  ElementMassData data;
  data.density = density;
  data.section = section;
  data.beam = profile;
  return element_mass_properties(shape, x, data);
}

// Inertia about the centre from a second moment about the origin.
Props from_moments(double mass, const Vector3& first, const Matrix3& second) {
  Props p;
  p.mass = mass;
  p.centre = first / mass;
  const Matrix3 spread = second - mass * p.centre * p.centre.transpose();
  p.inertia = spread.trace() * Matrix3::Identity() - spread;
  return p;
}

// The exact mass properties of tetrahedra (the closed form of the header).
Props tetrahedra(const std::vector<std::array<Vector3, 4>>& tets, double density) {
  double mass = 0;
  Vector3 first = Vector3::Zero();
  Matrix3 second = Matrix3::Zero();
  for (const auto& t : tets) {
    const double v = std::abs((t[1] - t[0]).dot((t[2] - t[0]).cross(t[3] - t[0]))) / 6;
    Vector3 s = Vector3::Zero();
    Matrix3 q = Matrix3::Zero();
    for (const Vector3& x : t) {
      s += x;
      q += x * x.transpose();
    }
    mass += density * v;
    first += density * v * s / 4;
    second += density * v / 20 * (q + s * s.transpose());
  }
  return from_moments(mass, first, second);
}

const Vector3 kOrigin(10.0, -5.0, 3.0);
constexpr double kA = 0.8, kB = 0.5, kC = 0.3, kDensity = 7.8;

Vector3 box(double u, double v, double w) { return kOrigin + Vector3(u * kA, v * kB, w * kC); }

Props box_props() {
  Props p;
  p.mass = kDensity * kA * kB * kC;
  p.centre = box(0.5, 0.5, 0.5);
  p.inertia.diagonal() << kB * kB + kC * kC, kA * kA + kC * kC, kA * kA + kB * kB;
  p.inertia *= p.mass / 12;
  return p;
}

Vector3 mid(const Vector3& a, const Vector3& b) { return 0.5 * (a + b); }

// Corners of the unit cube in hexahedron order, mapped by `place`.
template <typename F>
std::array<Vector3, 8> hex_corners(F place) {
  constexpr int c[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::array<Vector3, 8> x;
  for (int i = 0; i < 8; ++i) x[i] = place(c[i][0], c[i][1], c[i][2]);
  return x;
}

std::vector<Vector3> with_midsides(const std::vector<Vector3>& corners,
                                   const std::vector<std::array<int, 2>>& edges) {
  std::vector<Vector3> x = corners;
  for (const auto& e : edges) x.push_back(mid(corners[e[0]], corners[e[1]]));
  return x;
}

const std::vector<std::array<int, 2>> kHexEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
const std::vector<std::array<int, 2>> kTetEdges{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
const std::vector<std::array<int, 2>> kWedgeEdges{{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                                                  {5, 3}, {0, 3}, {1, 4}, {2, 5}};

// The cube's six Kuhn tetrahedra (corner indices of hex_corners) and two wedges.
constexpr int kKuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                             {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
constexpr int kWedges[2][6] = {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 4, 6, 7}};

TEST(ElementMass, SolidsFillABox) {
  const auto h = hex_corners([](int u, int v, int w) { return box(u, v, w); });
  const std::vector<Vector3> hex(h.begin(), h.end());
  expect_props(combine({of(ElementShape::Hex8, hex, kDensity)}), box_props(), "C3D8");
  expect_props(combine({of(ElementShape::Hex20, with_midsides(hex, kHexEdges), kDensity)}),
               box_props(), "C3D20");
  for (const bool quadratic : {false, true}) {
    std::vector<ElementMassProperties> tets, wedges;
    for (const auto& t : kKuhn) {
      const std::vector<Vector3> x{h[t[0]], h[t[1]], h[t[2]], h[t[3]]};
      tets.push_back(quadratic ? of(ElementShape::Tet10, with_midsides(x, kTetEdges), kDensity)
                               : of(ElementShape::Tet4, x, kDensity));
    }
    for (const auto& w : kWedges) {
      std::vector<Vector3> x;
      for (const int i : w) x.push_back(h[i]);
      wedges.push_back(quadratic
                           ? of(ElementShape::Wedge15, with_midsides(x, kWedgeEdges), kDensity)
                           : of(ElementShape::Wedge6, x, kDensity));
    }
    expect_props(combine(tets), box_props(), quadratic ? "C3D10" : "C3D4");
    expect_props(combine(wedges), box_props(), quadratic ? "C3D15" : "C3D6");
  }
}

TEST(ElementMass, DistortedSolidsAgainstTetrahedra) {
  // A parallelepiped: the unit cube under an affine map with shear in every direction.
  Matrix3 a;
  a << 0.9, 0.3, -0.2, 0.1, 0.7, 0.25, -0.15, 0.2, 0.6;
  const auto h =
      hex_corners([&](int u, int v, int w) { return Vector3(kOrigin + a * Vector3(u, v, w)); });
  std::vector<std::array<Vector3, 4>> kuhn;
  for (const auto& t : kKuhn) kuhn.push_back({h[t[0]], h[t[1]], h[t[2]], h[t[3]]});
  const std::vector<Vector3> hex(h.begin(), h.end());
  expect_props(combine({of(ElementShape::Hex8, hex, kDensity)}), tetrahedra(kuhn, kDensity),
               "affine C3D8");
  expect_props(combine({of(ElementShape::Hex20, with_midsides(hex, kHexEdges), kDensity)}),
               tetrahedra(kuhn, kDensity), "affine C3D20");
  // One tetrahedron of no symmetry.
  const std::array<Vector3, 4> t{kOrigin, kOrigin + Vector3(1.1, 0.2, -0.1),
                                 kOrigin + Vector3(0.3, 0.9, 0.2),
                                 kOrigin + Vector3(-0.2, 0.4, 0.8)};
  const std::vector<Vector3> x(t.begin(), t.end());
  expect_props(combine({of(ElementShape::Tet4, x, kDensity)}), tetrahedra({t}, kDensity), "C3D4");
  expect_props(combine({of(ElementShape::Tet10, with_midsides(x, kTetEdges), kDensity)}),
               tetrahedra({t}, kDensity), "C3D10");
}

// A plate of sides a (along e1) and b (along e2), thickness t, in a rotated plane.
TEST(ElementMass, SurfacesFillARotatedPlate) {
  const double a = 0.6, b = 0.4, t = 0.02, density = 2.7;
  const Vector3 e1 = Vector3(1, 2, 2).normalized();
  const Vector3 e2 = Vector3(2, 1, -2).normalized();
  const Vector3 n = e1.cross(e2);
  auto at = [&](double u, double v) { return Vector3(kOrigin + u * a * e1 + v * b * e2); };
  Props want;
  want.mass = density * t * a * b;
  want.centre = at(0.5, 0.5);
  const double m12 = want.mass / 12;
  want.inertia =
      m12 * ((b * b + t * t) * e1 * e1.transpose() + (a * a + t * t) * e2 * e2.transpose() +
             (a * a + b * b) * n * n.transpose());
  const std::vector<Vector3> quad{at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
  const std::vector<std::array<int, 2>> quad_edges{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  expect_props(combine({of(ElementShape::Quad4, quad, density, t)}), want, "S4");
  std::vector<Vector3> quad8 = with_midsides(quad, quad_edges);
  expect_props(combine({of(ElementShape::Quad8, quad8, density, t)}), want, "S8R");
  quad8.push_back(at(0.5, 0.5));
  expect_props(combine({of(ElementShape::Quad9, quad8, density, t)}), want, "S9R5");
  const std::vector<std::array<int, 2>> tri_edges{{0, 1}, {1, 2}, {2, 0}};
  const std::vector<Vector3> lower{at(0, 0), at(1, 0), at(1, 1)},
      upper{at(0, 0), at(1, 1), at(0, 1)};
  expect_props(combine({of(ElementShape::Tri3, lower, density, t),
                        of(ElementShape::Tri3, upper, density, t)}),
               want, "S3");
  expect_props(combine({of(ElementShape::Tri6, with_midsides(lower, tri_edges), density, t),
                        of(ElementShape::Tri6, with_midsides(upper, tri_edges), density, t)}),
               want, "STRI65");
}

// OFFSET=SPOS puts the nodes on the top surface: the midsurface, and the centre, lie t/2 below
// them along the normal; DENSITY=μ on the section adds μ per unit area at the midsurface (no
// spread through the thickness).
TEST(ElementMass, ShellOffsetAndAddedMass) {
  const double a = 0.6, b = 0.4, t = 0.02, density = 2.7, added = 0.3;
  const Vector3 e1 = Vector3(1, 2, 2).normalized();
  const Vector3 e2 = Vector3(2, 1, -2).normalized();
  const Vector3 n = e1.cross(e2);
  auto at = [&](double u, double v) { return Vector3(kOrigin + u * a * e1 + v * b * e2); };
  const double material = density * t * a * b, surface = added * a * b;
  Props want;
  want.mass = material + surface;
  want.centre = at(0.5, 0.5) - 0.5 * t * n;
  want.inertia = material / 12 *
                     ((b * b + t * t) * e1 * e1.transpose() +
                      (a * a + t * t) * e2 * e2.transpose() + (a * a + b * b) * n * n.transpose()) +
                 surface / 12 *
                     (b * b * e1 * e1.transpose() + a * a * e2 * e2.transpose() +
                      (a * a + b * b) * n * n.transpose());
  ElementMassData data;
  data.density = density;
  data.section = t;
  data.offset = 0.5;
  data.added_per_area = added;
  const std::vector<Vector3> quad{at(0, 0), at(1, 0), at(1, 1), at(0, 1)};
  expect_props(combine({element_mass_properties(ElementShape::Quad4, quad, data)}), want,
               "S4, OFFSET=SPOS, DENSITY=");
}

// A thin rod of length L and area A along d: m = ρAL, I = m L²/12 (1 − d dᵀ).
TEST(ElementMass, LinesAreThinRods) {
  const double length = 1.3, area = 0.01, density = 7.8;
  const Vector3 d = Vector3(2, -1, 2).normalized();
  const Vector3 end = kOrigin + length * d;
  Props want;
  want.mass = density * area * length;
  want.centre = mid(kOrigin, end);
  want.inertia = want.mass * length * length / 12 * (Matrix3::Identity() - d * d.transpose());
  expect_props(combine({of(ElementShape::Line2, {kOrigin, end}, density, area)}), want, "T3D2");
  expect_props(combine({of(ElementShape::Line3, {kOrigin, want.centre, end}, density, area)}), want,
               "T3D3");
}

// Beams: a RECT profile a × b is a box of sides L (along d), a (along n1), b (along n2),
// I = m/12 [(a² + b²) d dᵀ + (L² + b²) n1 n1ᵀ + (L² + a²) n2 n2ᵀ]; a CIRC of radius r a cylinder,
// I = m r²/2 d dᵀ + m (3r² + L²)/12 (1 − d dᵀ); a PIPE of outside radius r and wall t a tube,
// r² above replaced by r² + rᵢ², rᵢ = r − t. The n1 the section gives, (0, 0, −1), is not
// across the axis: the beam makes it so.
TEST(ElementMass, BeamsCarryTheirProfile) {
  const double length = 1.3, density = 7.8;
  const Vector3 d = Vector3(2, -1, 2).normalized();
  const Vector3 end = kOrigin + length * d;
  const Vector3 n1 = (Vector3(0, 0, -1) - Vector3(0, 0, -1).dot(d) * d).normalized();
  const Vector3 n2 = d.cross(n1);
  const Matrix3 axial = d * d.transpose(), across = Matrix3::Identity() - axial;
  const std::vector<Vector3> line2{kOrigin, end}, line3{kOrigin, mid(kOrigin, end), end};

  const double a = 0.12, b = 0.05;
  const std::array<double, 2> rect_sizes{a, b};
  const std::optional<BeamProfile> rect = beam_profile("RECT", rect_sizes);
  ASSERT_TRUE(rect);
  Props box;
  box.mass = density * a * b * length;
  box.centre = mid(kOrigin, end);
  box.inertia = box.mass / 12 *
                ((a * a + b * b) * axial + (length * length + b * b) * n1 * n1.transpose() +
                 (length * length + a * a) * n2 * n2.transpose());
  expect_props(combine({of(ElementShape::Line2, line2, density, 1, rect)}), box, "B31 RECT");
  expect_props(combine({of(ElementShape::Line3, line3, density, 1, rect)}), box, "B32 RECT");

  const double r = 0.04, t = 0.01, ri = r - t;
  const std::array<double, 1> circ_sizes{r};
  const std::array<double, 2> pipe_sizes{r, t};
  const std::optional<BeamProfile> circ = beam_profile("CIRC", circ_sizes);
  const std::optional<BeamProfile> pipe = beam_profile("PIPE", pipe_sizes);
  ASSERT_TRUE(circ && pipe);
  for (const auto& [profile, inner, what] :
       {std::tuple{&circ, 0.0, "B31 CIRC"}, std::tuple{&pipe, ri, "B31 PIPE"}}) {
    const double r2 = r * r + inner * inner;
    Props tube;
    tube.mass = density * std::numbers::pi * (r * r - inner * inner) * length;
    tube.centre = mid(kOrigin, end);
    tube.inertia = tube.mass * (r2 / 2 * axial + (3 * r2 + length * length) / 12 * across);
    expect_props(combine({of(ElementShape::Line2, line2, density, 1, *profile)}), tube, what);
  }
  EXPECT_FALSE(beam_profile("I", rect_sizes));
}

}  // namespace
}  // namespace clinch
