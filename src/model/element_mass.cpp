#include "src/model/element_mass.hpp"

#include <array>
#include <cmath>
#include <algorithm>
#include <span>

#include "src/model/element_library.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

// One quadrature point of an element: its shape functions and their natural derivatives.
struct ShapePoint {
  std::array<double, 8> n{};
  std::array<std::array<double, 2>, 8> dn2{};  // shells: d/dξ, d/dη
  std::array<std::array<double, 3>, 8> dn3{};  // solids: d/dξ, d/dη, d/dζ
  double weight = 0.0;
};

constexpr double kGauss3[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};  // √(3/5)
constexpr double kGaussWeight3[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

// The trilinear hexahedron (C3D8 node order), 3×3×3 Gauss points: exact for ∫ρ x xᵀ dV, whose
// integrand is of degree 4 in each natural coordinate.
std::vector<ShapePoint> hexahedron_points() {
  constexpr int corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::vector<ShapePoint> points;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      for (int c = 0; c < 3; ++c) {
        ShapePoint p;
        const double xi[3] = {kGauss3[a], kGauss3[b], kGauss3[c]};
        p.weight = kGaussWeight3[a] * kGaussWeight3[b] * kGaussWeight3[c];
        for (int i = 0; i < 8; ++i) {
          const double f[3] = {1 + corner[i][0] * xi[0], 1 + corner[i][1] * xi[1],
                               1 + corner[i][2] * xi[2]};
          p.n[i] = f[0] * f[1] * f[2] / 8;
          p.dn3[i] = {corner[i][0] * f[1] * f[2] / 8, corner[i][1] * f[0] * f[2] / 8,
                      corner[i][2] * f[0] * f[1] / 8};
        }
        points.push_back(p);
      }
    }
  }
  return points;
}

// The linear tetrahedron (C3D4), the 4-point rule exact to degree 2.
std::vector<ShapePoint> tetrahedron_points() {
  constexpr double a = 0.5854101966249685, b = 0.1381966011250105;
  std::vector<ShapePoint> points;
  for (int q = 0; q < 4; ++q) {
    double xi[3] = {b, b, b};
    if (q > 0) xi[q - 1] = a;
    ShapePoint p;
    p.weight = 1.0 / 24.0;
    p.n[0] = 1 - xi[0] - xi[1] - xi[2];
    p.dn3[0] = {-1, -1, -1};
    for (int i = 1; i < 4; ++i) {
      p.n[i] = xi[i - 1];
      p.dn3[i] = {0, 0, 0};
      p.dn3[i][static_cast<std::size_t>(i - 1)] = 1;
    }
    points.push_back(p);
  }
  return points;
}

// The bilinear quadrilateral (S4 node order), 3×3 Gauss points.
std::vector<ShapePoint> quadrilateral_points() {
  constexpr int corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  std::vector<ShapePoint> points;
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      ShapePoint p;
      p.weight = kGaussWeight3[a] * kGaussWeight3[b];
      for (int i = 0; i < 4; ++i) {
        const double f[2] = {1 + corner[i][0] * kGauss3[a], 1 + corner[i][1] * kGauss3[b]};
        p.n[i] = f[0] * f[1] / 4;
        p.dn2[i] = {corner[i][0] * f[1] / 4, corner[i][1] * f[0] / 4};
      }
      points.push_back(p);
    }
  }
  return points;
}

// The linear triangle (S3), the 3-point rule exact to degree 2.
std::vector<ShapePoint> triangle_points() {
  constexpr double at[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  std::vector<ShapePoint> points;
  for (const auto& xi : at) {
    ShapePoint p;
    p.weight = 1.0 / 6.0;
    p.n[0] = 1 - xi[0] - xi[1];
    p.n[1] = xi[0];
    p.n[2] = xi[1];
    p.dn2[0] = {-1, -1};
    p.dn2[1] = {1, 0};
    p.dn2[2] = {0, 1};
    points.push_back(p);
  }
  return points;
}

const std::vector<ShapePoint>* points_of(const ElementBlock& block) {
  static const std::vector<ShapePoint> hexahedron = hexahedron_points();
  static const std::vector<ShapePoint> tetrahedron = tetrahedron_points();
  static const std::vector<ShapePoint> quadrilateral = quadrilateral_points();
  static const std::vector<ShapePoint> triangle = triangle_points();
  const auto family = static_cast<ElementFamily>(block.family);
  if (family == ElementFamily::Solid && block.nodes_per_element == 8) return &hexahedron;
  if (family == ElementFamily::Solid && block.nodes_per_element == 4) return &tetrahedron;
  if (family == ElementFamily::Shell && block.nodes_per_element == 4) return &quadrilateral;
  if (family == ElementFamily::Shell && block.nodes_per_element == 3) return &triangle;
  return nullptr;
}

// The mass of one element, and its first and second moments ∫ρ y dV and ∫ρ y yᵀ dV, y = x − x₀
// measured from its first node (no cancellation in the inertia of an element far from the
// origin).
struct Moments {
  double mass = 0.0;
  Vector3 first = Vector3::Zero();
  Matrix3 second = Matrix3::Zero();
};

Moments integrate_element(const std::vector<ShapePoint>& points, bool shell,
                          std::span<const Vector3> y, const ElementMassData& data) {
  Moments out;
  for (const ShapePoint& p : points) {
    Vector3 at = Vector3::Zero();
    for (std::size_t i = 0; i < y.size(); ++i) at += p.n[i] * y[i];
    double measure = 0.0, density = data.density;
    Vector3 normal = Vector3::Zero();
    if (shell) {
      Vector3 d_xi = Vector3::Zero(), d_eta = Vector3::Zero();
      for (std::size_t i = 0; i < y.size(); ++i) {
        d_xi += p.dn2[i][0] * y[i];
        d_eta += p.dn2[i][1] * y[i];
      }
      const Vector3 cross = d_xi.cross(d_eta);
      measure = cross.norm() * p.weight;
      if (cross.norm() > 0) normal = cross.normalized();
      density *= data.thickness;  // per unit area
    } else {
      Matrix3 jacobian = Matrix3::Zero();
      for (std::size_t i = 0; i < y.size(); ++i) {
        jacobian += y[i] * Vector3(p.dn3[i][0], p.dn3[i][1], p.dn3[i][2]).transpose();
      }
      measure = std::abs(jacobian.determinant()) * p.weight;
    }
    const double mass = density * measure;
    out.mass += mass;
    out.first += mass * at;
    out.second += mass * at * at.transpose();
    // Through the thickness t of a shell: ∫ζ² dζ over [−t/2, t/2] = t³/12.
    if (shell) {
      out.second += data.density * std::pow(data.thickness, 3) / 12 * measure * normal *
                    normal.transpose();
    }
  }
  return out;
}

Vector3 position(const Model& model, std::int32_t node) {
  const Vec3& x = model.nodes[static_cast<std::size_t>(node)].x;
  return {x[0], x[1], x[2]};
}

}  // namespace

bool element_mass_computed(const ElementBlock& block) { return points_of(block) != nullptr; }

std::vector<std::optional<ElementMassData>> element_mass_data(const Model& model) {
  std::vector<std::optional<ElementMassData>> data(model.elements.size());
  for (const ElementSection& section : model.structure.sections) {
    const bool shell = section.kind == ElementSection::Kind::Shell;
    if ((!shell && section.kind != ElementSection::Kind::Solid) || section.material_index < 0) {
      continue;
    }
    const Material& material =
        model.structure.materials[static_cast<std::size_t>(section.material_index)];
    std::optional<double> density;
    for (const MaterialOption& option : material.options) {
      if (option.keyword == "DENSITY" && !option.rows.empty() && !option.rows[0].values.empty()) {
        density = option.rows[0].values[0];
      }
    }
    if (!density) continue;
    ElementMassData d;
    d.density = *density;
    // *SHELL SECTION: the thickness is the first field of its first data line (default 1).
    d.thickness = 1.0;
    if (shell && !section.rows.empty() && !section.rows[0].values.empty()) {
      d.thickness = section.rows[0].values[0];
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
      if (!element_mass_computed(block)) continue;
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
                       : model.instances[static_cast<std::size_t>(
                                             model.nodes[static_cast<std::size_t>(body.reference)]
                                                 .instance)]
                             .node_offset;
    for (const std::int32_t e : body.elements) {
      const Where& w = where[static_cast<std::size_t>(e)];
      const auto& d = data[static_cast<std::size_t>(e)];
      if (!w.block || !d || d->density == 0) continue;
      const std::span<const std::int32_t> local = w.block->element_nodes(w.k);
      if (std::find(local.begin(), local.end(), kGround) != local.end()) continue;
      const Vector3 origin = position(model, local[0] + w.node_offset);
      std::array<Vector3, 8> y;
      for (std::size_t i = 0; i < local.size(); ++i) {
        y[i] = position(model, local[i] + w.node_offset) - origin;
      }
      const bool shell = static_cast<ElementFamily>(w.block->family) == ElementFamily::Shell;
      const Moments m =
          integrate_element(*points_of(*w.block), shell, std::span(y.data(), local.size()), *d);
      if (m.mass <= 0) continue;
      ElementMass element;
      element.element = e;
      element.body = static_cast<std::int32_t>(b);
      element.reference =
          body.part == 0 ? body.reference : body.reference - last_offset + w.node_offset;
      element.mass = m.mass;
      const Vector3 offset = m.first / m.mass;
      element.centre = origin + offset;
      // About the centre: S = ∫ρ y yᵀ dV − m c cᵀ (c the centre from the first node); the
      // inertia tensor I = tr(S) 1 − S.
      const Matrix3 spread = m.second - m.mass * offset * offset.transpose();
      element.rotary = spread.trace() * Matrix3::Identity() - spread;
      out.push_back(element);
    }
  }
  return out;
}

}  // namespace clinch
