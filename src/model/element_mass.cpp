#include "src/model/element_mass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <initializer_list>

#include "src/model/element_library.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

// A value with its derivatives along the (up to three) natural coordinates: the shape functions
// are polynomials, so their derivatives come out exact from sums and products.
struct Dual {
  double v = 0.0;
  std::array<double, 3> d{};
};
Dual operator+(Dual a, const Dual& b) {
  a.v += b.v;
  for (int k = 0; k < 3; ++k) a.d[k] += b.d[k];
  return a;
}
Dual operator-(Dual a, const Dual& b) {
  a.v -= b.v;
  for (int k = 0; k < 3; ++k) a.d[k] -= b.d[k];
  return a;
}
Dual operator*(const Dual& a, const Dual& b) {
  Dual r{a.v * b.v, {}};
  for (int k = 0; k < 3; ++k) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return r;
}
Dual operator*(double s, Dual a) {
  a.v *= s;
  for (int k = 0; k < 3; ++k) a.d[k] *= s;
  return a;
}
Dual operator+(double s, Dual a) {
  a.v += s;
  return a;
}
Dual operator-(double s, const Dual& a) { return s + (-1.0) * a; }
Dual operator+(const Dual& a, double s) { return s + a; }
Dual operator-(const Dual& a, double s) { return (-s) + a; }
Dual coordinate(double value, int k) {
  Dual c{value, {}};
  c.d[static_cast<std::size_t>(k)] = 1.0;
  return c;
}

constexpr int kMaxNodes = 20;
using Shapes = std::array<Dual, kMaxNodes>;

// One-dimensional quadratic Lagrange functions at −1, 0, 1.
std::array<Dual, 3> quadratic(const Dual& s) {
  return {0.5 * (s * (s - 1.0)), 1.0 - s * s, 0.5 * (s * (s + 1.0))};
}

// Corners of the quadrilateral and the hexahedron (Abaqus order).
constexpr int kQuadCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr int kHexCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
// Midside nodes of the quadratic elements: the corners (0-based) each lies between.
constexpr int kTriEdge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kTetEdge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kHexEdge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// A simplex's functions from its area or volume coordinates l: l itself (linear), or the
// corners' l(2l − 1) and the midsides' 4 lᵢlⱼ on `edges` (quadratic).
template <std::size_t Corners, std::size_t Edges>
void simplex_functions(const std::array<Dual, Corners>& l, const int (&edges)[Edges][2],
                       bool quadratic, Shapes& n) {
  for (std::size_t i = 0; i < Corners; ++i) n[i] = quadratic ? l[i] * (2.0 * l[i] - 1.0) : l[i];
  if (!quadratic) return;
  for (std::size_t e = 0; e < Edges; ++e) {
    n[Corners + e] =
        4.0 * (l[static_cast<std::size_t>(edges[e][0])] * l[static_cast<std::size_t>(edges[e][1])]);
  }
}

// The shape functions at natural coordinates ξ (the reference domains: [−1, 1] per direction
// for lines, quadrilaterals and hexahedra and for the wedge's ζ; the unit simplex for
// triangles, tetrahedra and the wedge's ξ, η).
Shapes shape_functions(ElementShape shape, const std::array<Dual, 3>& xi) {
  Shapes n{};
  const Dual &a = xi[0], &b = xi[1], &c = xi[2];
  switch (shape) {
    case ElementShape::Line2:
      n[0] = 0.5 * (1.0 - a);
      n[1] = 0.5 * (1.0 + a);
      break;
    case ElementShape::Line3: {
      const auto l = quadratic(a);
      n[0] = l[0];
      n[1] = l[1];
      n[2] = l[2];
      break;
    }
    case ElementShape::Tri3:
    case ElementShape::Tri6: {
      const std::array<Dual, 3> l{1.0 - a - b, a, b};
      simplex_functions(l, kTriEdge, shape == ElementShape::Tri6, n);
      break;
    }
    case ElementShape::Quad4:
      for (int i = 0; i < 4; ++i) {
        n[i] = 0.25 * ((1.0 + kQuadCorner[i][0] * a) * (1.0 + kQuadCorner[i][1] * b));
      }
      break;
    case ElementShape::Quad8:
      for (int i = 0; i < 4; ++i) {
        const double p = kQuadCorner[i][0], q = kQuadCorner[i][1];
        n[i] = 0.25 * ((1.0 + p * a) * (1.0 + q * b) * (p * a + q * b - 1.0));
      }
      n[4] = 0.5 * ((1.0 - a * a) * (1.0 - b));
      n[5] = 0.5 * ((1.0 + a) * (1.0 - b * b));
      n[6] = 0.5 * ((1.0 - a * a) * (1.0 + b));
      n[7] = 0.5 * ((1.0 - a) * (1.0 - b * b));
      break;
    case ElementShape::Quad9: {
      const auto la = quadratic(a), lb = quadratic(b);
      // Corner k at index 0 or 2 of each direction, midsides and centre at 1.
      constexpr int at[9][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0},
                                {2, 1}, {1, 2}, {0, 1}, {1, 1}};
      for (int i = 0; i < 9; ++i) n[i] = la[at[i][0]] * lb[at[i][1]];
      break;
    }
    case ElementShape::Tet4:
    case ElementShape::Tet10: {
      const std::array<Dual, 4> l{1.0 - a - b - c, a, b, c};
      simplex_functions(l, kTetEdge, shape == ElementShape::Tet10, n);
      break;
    }
    case ElementShape::Wedge6:
    case ElementShape::Wedge15: {
      const std::array<Dual, 3> l{1.0 - a - b, a, b};
      if (shape == ElementShape::Wedge6) {
        for (int i = 0; i < 3; ++i) {
          n[i] = 0.5 * (l[i] * (1.0 - c));
          n[3 + i] = 0.5 * (l[i] * (1.0 + c));
        }
        break;
      }
      const Dual bubble = 1.0 - c * c;
      for (int i = 0; i < 6; ++i) {
        const double s = i < 3 ? -1.0 : 1.0;
        const Dual& li = l[i % 3];
        n[i] = 0.5 * (li * ((2.0 * li - 1.0) * (1.0 + s * c) - bubble));
      }
      for (int e = 0; e < 6; ++e) {
        const double s = e < 3 ? -1.0 : 1.0;
        n[6 + e] = 2.0 * (l[kTriEdge[e % 3][0]] * l[kTriEdge[e % 3][1]] * (1.0 + s * c));
      }
      for (int i = 0; i < 3; ++i) n[12 + i] = l[i] * bubble;
      break;
    }
    case ElementShape::Hex8:
    case ElementShape::Hex20:
      for (int i = 0; i < 8; ++i) {
        const double p = kHexCorner[i][0], q = kHexCorner[i][1], r = kHexCorner[i][2];
        n[i] = 0.125 * ((1.0 + p * a) * (1.0 + q * b) * (1.0 + r * c));
        if (shape == ElementShape::Hex20) {
          n[i] = n[i] * (p * a + q * b + r * c - 2.0);
        }
      }
      if (shape == ElementShape::Hex8) break;
      for (int e = 0; e < 12; ++e) {
        // The edge's middle: the coordinate along it is 0, the others those of its corners.
        const int* p = kHexCorner[kHexEdge[e][0]];
        const int* q = kHexCorner[kHexEdge[e][1]];
        Dual f{0.25, {}};
        for (int k = 0; k < 3; ++k) {
          f = f * (p[k] == q[k]
                       ? 1.0 + p[k] * xi[static_cast<std::size_t>(k)]
                       : 1.0 - xi[static_cast<std::size_t>(k)] * xi[static_cast<std::size_t>(k)]);
        }
        n[8 + e] = f;
      }
      break;
  }
  return n;
}

int node_count(ElementShape shape) {
  constexpr int counts[] = {2, 3, 3, 6, 4, 8, 9, 4, 10, 6, 15, 8, 20};
  return counts[static_cast<int>(shape)];
}

int dimension(ElementShape shape) {
  if (shape <= ElementShape::Line3) return 1;
  return shape <= ElementShape::Quad9 ? 2 : 3;
}

bool quadratic_shape(ElementShape shape) {
  switch (shape) {
    case ElementShape::Line3:
    case ElementShape::Tri6:
    case ElementShape::Quad8:
    case ElementShape::Quad9:
    case ElementShape::Tet10:
    case ElementShape::Wedge15:
    case ElementShape::Hex20:
      return true;
    default:
      return false;
  }
}

// Gauss–Legendre points and weights on [−1, 1]: 3 points are exact to degree 5, enough for the
// second moment of the linear shapes (degree 4 per direction with the simplices' collapse); 5
// points, exact to degree 9, for the quadratic ones.
struct Rule1D {
  std::vector<double> x, w;
};
const Rule1D& gauss(bool fine) {
  static const Rule1D three{{-0.7745966692414834, 0.0, 0.7745966692414834},
                            {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  static const Rule1D five{
      {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640},
      {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
       0.2369268850561891}};
  return fine ? five : three;
}

// The quadrature points of a reference domain with their weights. Simplices are collapsed
// squares and cubes (Duffy): ξ = u, η = v(1 − u), ζ = w(1 − u)(1 − v) with u, v, w ∈ [0, 1],
// whose Jacobian (1 − u) or (1 − u)²(1 − v) joins the weight.
struct QuadraturePoint {
  std::array<double, 3> xi{};
  double weight = 0.0;
};
std::vector<QuadraturePoint> quadrature(ElementShape shape) {
  const Rule1D& g = gauss(quadratic_shape(shape));
  const std::size_t m = g.x.size();
  std::vector<QuadraturePoint> points;
  auto unit = [&](std::size_t i) { return 0.5 * (g.x[i] + 1.0); };  // on [0, 1], weight w/2
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      for (std::size_t k = 0; k < m; ++k) {
        QuadraturePoint p;
        switch (shape) {
          case ElementShape::Line2:
          case ElementShape::Line3:
            if (j || k) continue;
            p = {{g.x[i], 0, 0}, g.w[i]};
            break;
          case ElementShape::Quad4:
          case ElementShape::Quad8:
          case ElementShape::Quad9:
            if (k) continue;
            p = {{g.x[i], g.x[j], 0}, g.w[i] * g.w[j]};
            break;
          case ElementShape::Hex8:
          case ElementShape::Hex20:
            p = {{g.x[i], g.x[j], g.x[k]}, g.w[i] * g.w[j] * g.w[k]};
            break;
          case ElementShape::Tri3:
          case ElementShape::Tri6: {
            if (k) continue;
            const double u = unit(i), v = unit(j);
            p = {{u, v * (1 - u), 0}, 0.25 * g.w[i] * g.w[j] * (1 - u)};
            break;
          }
          case ElementShape::Wedge6:
          case ElementShape::Wedge15: {
            const double u = unit(i), v = unit(j);
            p = {{u, v * (1 - u), g.x[k]}, 0.25 * g.w[i] * g.w[j] * (1 - u) * g.w[k]};
            break;
          }
          case ElementShape::Tet4:
          case ElementShape::Tet10: {
            const double u = unit(i), v = unit(j), w = unit(k);
            p = {{u, v * (1 - u), w * (1 - u) * (1 - v)},
                 0.125 * g.w[i] * g.w[j] * g.w[k] * (1 - u) * (1 - u) * (1 - v)};
            break;
          }
        }
        points.push_back(p);
      }
    }
  }
  return points;
}

const std::vector<QuadraturePoint>& quadrature_of(ElementShape shape) {
  static const auto all = [] {
    std::array<std::vector<QuadraturePoint>, 13> rules;
    for (int s = 0; s < 13; ++s) rules[static_cast<std::size_t>(s)] = quadrature(ElementShape(s));
    return rules;
  }();
  return all[static_cast<std::size_t>(shape)];
}

Vector3 position(const Model& model, std::int32_t node) {
  const Vec3& x = model.nodes[static_cast<std::size_t>(node)].x;
  return {x[0], x[1], x[2]};
}

}  // namespace

std::optional<ElementShape> mass_shape(const ElementBlock& block) {
  using enum ElementShape;
  const std::string_view type = block.type;
  // The shape of a family with the block's node count.
  const auto with_nodes = [&](std::initializer_list<ElementShape> shapes) {
    for (const ElementShape s : shapes) {
      if (node_count(s) == block.nodes_per_element) return std::optional(s);
    }
    return std::optional<ElementShape>();
  };
  switch (static_cast<ElementFamily>(block.family)) {
    case ElementFamily::Solid:  // not the pyramid C3D5
      if (!type.starts_with("C3D") && !type.starts_with("SC")) return std::nullopt;
      return with_nodes({Tet4, Tet10, Wedge6, Wedge15, Hex8, Hex20});
    case ElementFamily::Planar:
      if (type.starts_with("CAX")) return std::nullopt;  // axisymmetric: mass per radian
      [[fallthrough]];
    case ElementFamily::Shell:
    case ElementFamily::Membrane:
      return with_nodes({Tri3, Tri6, Quad4, Quad8, Quad9});
    case ElementFamily::Truss:
    case ElementFamily::Beam:
      return with_nodes({Line2, Line3});
    default:
      return std::nullopt;
  }
}

std::optional<BeamProfile> beam_profile(std::string_view section, std::span<const double> sizes) {
  auto size = [&](std::size_t i) { return i < sizes.size() ? sizes[i] : 0.0; };
  BeamProfile p;
  if (section == "RECT") {  // width a along n1, height b along n2
    const double a = size(0), b = size(1);
    p.area = a * b;
    p.along_n1 = b * a * a * a / 12;
    p.along_n2 = a * b * b * b / 12;
    return p;
  }
  if (section == "CIRC" || section == "PIPE" || section == "THICK PIPE") {
    // Outside radius r; a pipe's wall thickness t (the annulus's exact moments).
    const double r = size(0), inner = section == "CIRC" ? 0.0 : r - size(1);
    constexpr double pi = 3.14159265358979323846;
    p.area = pi * (r * r - inner * inner);
    p.along_n1 = p.along_n2 = pi * (std::pow(r, 4) - std::pow(inner, 4)) / 4;
    return p;
  }
  return std::nullopt;
}

ElementMassProperties element_mass_properties(ElementShape shape, std::span<const Vector3> x,
                                              const ElementMassData& data) {
  const double density = data.density, section = data.section;
  const BeamProfile* profile = data.beam ? &*data.beam : nullptr;
  // Moments about the first node, y = x − x₀: no cancellation in the inertia of an element far
  // from the origin.
  const auto count = static_cast<std::size_t>(node_count(shape));
  const int dim = dimension(shape);
  const double per_measure = dim == 3   ? density
                             : dim == 2 ? density * section + data.added_per_area
                                        : density * (profile ? profile->area : section);
  double mass = 0.0;
  Vector3 first = Vector3::Zero();
  Matrix3 second = Matrix3::Zero();
  for (const QuadraturePoint& q : quadrature_of(shape)) {
    const Shapes n = shape_functions(
        shape, {coordinate(q.xi[0], 0), coordinate(q.xi[1], 1), coordinate(q.xi[2], 2)});
    Vector3 at = Vector3::Zero();
    Matrix3 jacobian = Matrix3::Zero();  // columns ∂y/∂ξ_k
    for (std::size_t i = 0; i < count; ++i) {
      const Vector3 y = x[i] - x[0];
      at += n[i].v * y;
      for (int k = 0; k < dim; ++k) jacobian.col(k) += n[i].d[static_cast<std::size_t>(k)] * y;
    }
    double measure = 0.0;
    Vector3 normal = Vector3::Zero();
    if (dim == 3) {
      measure = std::abs(jacobian.determinant());
    } else if (dim == 2) {
      const Vector3 cross = jacobian.col(0).cross(jacobian.col(1));
      measure = cross.norm();
      if (measure > 0) normal = cross / measure;
      at -= data.offset * section * normal;  // the midsurface, from the nodes' surface
    } else {
      measure = jacobian.col(0).norm();
    }
    const double m = per_measure * measure * q.weight;
    mass += m;
    first += m * at;
    second += m * at * at.transpose();
    // Through the thickness t of a surface: ∫ζ² dζ over [−t/2, t/2] = t³/12.
    if (dim == 2) {
      second +=
          density * std::pow(section, 3) / 12 * measure * q.weight * normal * normal.transpose();
    }
    // A beam's cross-section, across its tangent t: ρ(∫x₁² dA n1 n1ᵀ + ∫x₂² dA n2 n2ᵀ).
    if (profile && measure > 0) {
      const Vector3 t = jacobian.col(0) / measure;
      Vector3 n1 = profile->n1 - profile->n1.dot(t) * t;
      if (n1.norm() < 1e-8 * profile->n1.norm()) n1 = t.unitOrthogonal();
      n1.normalize();
      const Vector3 n2 = t.cross(n1);
      second += density * measure * q.weight *
                (profile->along_n1 * n1 * n1.transpose() + profile->along_n2 * n2 * n2.transpose());
    }
  }
  ElementMassProperties out;
  out.mass = mass;
  if (mass <= 0) return out;
  const Vector3 offset = first / mass;
  out.centre = x[0] + offset;
  // About the centre: S = ∫ρ y yᵀ − m c cᵀ; the inertia tensor I = tr(S) 1 − S.
  const Matrix3 spread = second - mass * offset * offset.transpose();
  out.rotary = spread.trace() * Matrix3::Identity() - spread;
  return out;
}

namespace {

// A parameter's number, or none when it is not one.
std::optional<double> number(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return std::nullopt;
  return value;
}

std::optional<double> material_density(const Model& model, const ElementSection& section) {
  if (section.material_index < 0) return std::nullopt;
  const Material& material =
      model.structure.materials[static_cast<std::size_t>(section.material_index)];
  std::optional<double> density;
  for (const MaterialOption& option : material.options) {
    if (option.keyword == "DENSITY" && !option.rows.empty() && !option.rows[0].values.empty()) {
      density = option.rows[0].values[0];
    }
  }
  return density;
}

// The parameters of a section that change its mass (docs/dynamics.md "Element mass of a rigid
// body"): a surface's OFFSET and DENSITY=, a beam's SECTION=; COMPOSITE and NODAL THICKNESS
// (thicknesses clinch does not read) are named as unsupported.
void read_mass_parameters(const ElementSection& section, ElementMassData& d, std::string& profile) {
  const bool surface =
      section.kind == ElementSection::Kind::Shell || section.kind == ElementSection::Kind::Membrane;
  for (const KeptParameter& p : section.parameters) {
    if (p.name == "SECTION") profile = p.value;
    if (!surface) continue;
    if (p.name == "COMPOSITE" || p.name == "NODAL THICKNESS") d.unsupported = p.name;
    if (p.name == "OFFSET") {
      const std::optional<double> value = p.value == "SPOS"   ? 0.5
                                          : p.value == "SNEG" ? -0.5
                                                              : number(p.value);
      if (value)
        d.offset = *value;
      else
        d.unsupported = "OFFSET=" + p.value;
    }
    if (p.name == "DENSITY") {
      const std::optional<double> value = number(p.value);
      if (value)
        d.added_per_area = *value;
      else
        d.unsupported = "DENSITY=" + p.value;
    }
  }
}

}  // namespace

std::vector<std::optional<ElementMassData>> element_mass_data(const Model& model) {
  std::vector<std::optional<ElementMassData>> data(model.elements.size());
  for (const ElementSection& section : model.structure.sections) {
    const bool known = section.kind == ElementSection::Kind::Solid ||
                       section.kind == ElementSection::Kind::Shell ||
                       section.kind == ElementSection::Kind::Membrane ||
                       section.kind == ElementSection::Kind::Truss ||
                       section.kind == ElementSection::Kind::Beam;
    if (!known) continue;
    ElementMassData d;
    std::string profile;
    read_mass_parameters(section, d, profile);
    const std::optional<double> density = material_density(model, section);
    if (!density && d.added_per_area == 0 && d.unsupported.empty()) continue;
    d.density = density.value_or(0.0);
    // The first field of the first data line: thickness or area (default 1).
    if (!section.rows.empty() && !section.rows[0].values.empty() && section.rows[0].given[0]) {
      d.section = section.rows[0].values[0];
    }
    if (section.kind == ElementSection::Kind::Beam) {
      // *BEAM SECTION: SECTION= and the sizes on line 1, the n1 axis on line 2.
      const std::vector<double> none;
      d.beam = beam_profile(profile, section.rows.empty() ? none : section.rows[0].values);
      if (!d.beam) {
        d.unsupported = "SECTION=" + profile;
      } else if (section.rows.size() > 1 && section.rows[1].values.size() >= 3) {
        const std::vector<double>& n = section.rows[1].values;
        if (Vector3(n[0], n[1], n[2]).norm() > 0) d.beam->n1 = Vector3(n[0], n[1], n[2]);
      }
    }
    for (const std::int32_t e : section.elements) data[static_cast<std::size_t>(e)] = d;
  }
  return data;
}

std::vector<ElementMass> rigid_body_element_masses(const Model& model) {
  std::vector<ElementMass> out;
  if (model.constraints.rigid_bodies.empty()) return out;
  // Each element's block, its place in it and its instance's node offset.
  struct Where {
    const ElementBlock* block = nullptr;
    std::int32_t k = 0, node_offset = 0;
  };
  std::vector<Where> where(model.elements.size());
  for (std::size_t i = 0; i < model.instances.size(); ++i) {
    const Instance& instance = model.instances[i];
    if (i == 0 && instance.part != 0) continue;
    for (const ElementBlock& block : model.parts[instance.part].element_blocks) {
      const std::optional<ElementShape> shape = mass_shape(block);
      if (!shape || block.nodes_per_element != node_count(*shape)) continue;
      for (std::int32_t k = 0; k < block.count; ++k) {
        const auto e = static_cast<std::size_t>(block.first_element + k + instance.element_offset);
        if (e < where.size()) where[e] = {&block, k, instance.node_offset};
      }
    }
  }
  const std::vector<std::optional<ElementMassData>> data = element_mass_data(model);
  for (std::size_t b = 0; b < model.constraints.rigid_bodies.size(); ++b) {
    const RigidBodyDefinition& body = model.constraints.rigid_bodies[b];
    if (body.reference < 0) continue;
    // A body written in a part is one definition for every instance: its reference node is the
    // last instance's, and each instance's elements go to its own copy of it. A body written
    // in the assembly has one reference node for all its elements.
    const std::int32_t last_offset =
        body.part == 0 ? 0
                       : model
                             .instances[static_cast<std::size_t>(
                                 model.nodes[static_cast<std::size_t>(body.reference)].instance)]
                             .node_offset;
    for (const std::int32_t e : body.elements) {
      const Where& w = where[static_cast<std::size_t>(e)];
      const auto& d = data[static_cast<std::size_t>(e)];
      if (!w.block || !d || !d->unsupported.empty()) continue;
      const std::span<const std::int32_t> local = w.block->element_nodes(w.k);
      if (std::find(local.begin(), local.end(), kGround) != local.end()) continue;
      std::array<Vector3, kMaxNodes> x;
      for (std::size_t i = 0; i < local.size(); ++i) {
        x[i] = position(model, local[i] + w.node_offset);
      }
      ElementMass element;
      static_cast<ElementMassProperties&>(element) =
          element_mass_properties(*mass_shape(*w.block), std::span(x.data(), local.size()), *d);
      if (element.mass <= 0) continue;
      element.element = e;
      element.body = static_cast<std::int32_t>(b);
      element.reference =
          body.part == 0 ? body.reference : body.reference - last_offset + w.node_offset;
      out.push_back(element);
    }
  }
  return out;
}

}  // namespace clinch
