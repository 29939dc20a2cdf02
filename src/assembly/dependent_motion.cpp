#include "src/assembly/dependent_motion.hpp"

#include <fmt/format.h>

#include <cmath>

#include "src/kinematics/rotation_math.hpp"

namespace clinch {
namespace {

using Map = DependentDof::Map;

// First-level term layouts (dependent_dofs.cpp): a rigid arm reads [u_ref,k, ω_ref,0…2] (the
// spin about its own axis k left out), a link [u_other,k, u_node,0…2, u_other,0…2] (axis k left
// out).
constexpr std::uint32_t kSpins = 1, kLinkNode = 1, kLinkOther = 4;

}  // namespace

DependentMotion::DependentMotion(const DependentDofs& dofs, const DofMap& map)
    : dofs_(dofs),
      map_(map),
      first_(dofs.term_coefficient),
      resolved_(dofs.resolved_equation.size(), 0.0) {}

Vector3 DependentMotion::current_arm(const DependentDof& d, const std::vector<Matrix3>& rotation,
                                     bool nlgeom) const {
  if (!nlgeom || rotation.empty()) return d.arm;
  return rotation[static_cast<std::size_t>(d.reference)] * d.arm;
}

bool DependentMotion::link_state(const DependentDof& d, const Eigen::VectorXd& x, Vector3& gap,
                                 double& h) const {
  double across = 0;
  for (int j = 0; j < 3; ++j) {
    if (j == d.axis) continue;
    gap[j] = d.arm[j] + value_at(x, d.first_term + kLinkNode + static_cast<std::uint32_t>(j)) -
             value_at(x, d.first_term + kLinkOther + static_cast<std::uint32_t>(j));
    across += gap[j] * gap[j];
  }
  gap[d.axis] = 0;
  const double along = d.arm.squaredNorm() - across;
  if (!(along > 0)) return false;
  h = std::copysign(std::sqrt(along), d.arm[d.axis]);
  return true;
}

bool DependentMotion::update_values(Eigen::VectorXd& x, std::vector<Matrix3>& rotation,
                                    bool nlgeom, std::string* why) const {
  const bool finite = nlgeom && !rotation.empty();
  for (const DependentDof& d : dofs_.dofs) {
    double value = value_at(x, d.first_term);
    switch (d.map) {
      case Map::RigidTranslation: {
        if (d.term_count == 1) break;
        if (finite) {
          value += ((rotation[static_cast<std::size_t>(d.reference)] - Matrix3::Identity()) *
                    d.arm)[d.axis];
        } else {
          Vector3 theta;
          for (int i = 0; i < 3; ++i) {
            theta[i] = value_at(x, d.first_term + kSpins + static_cast<std::uint32_t>(i));
          }
          value += theta.cross(d.arm)[d.axis];
        }
        break;
      }
      case Map::Rotation: break;
      case Map::Linear:
        value = 0;
        for (std::uint32_t t = d.first_term; t < d.first_term + d.term_count; ++t) {
          value += first_[t] * value_at(x, t);
        }
        break;
      case Map::LinkTranslation: {
        if (!nlgeom) {
          for (int j = 0; j < 3; ++j) {
            if (j == d.axis) continue;
            const auto t = static_cast<std::uint32_t>(j);
            value -= d.arm[j] / d.arm[d.axis] *
                     (value_at(x, d.first_term + kLinkNode + t) -
                      value_at(x, d.first_term + kLinkOther + t));
          }
          break;
        }
        Vector3 gap;
        double h = 0;
        if (!link_state(d, x, gap, h)) {
          *why = fmt::format("an MPC LINK can no longer keep its length {:.6g}: its ends moved "
                             "apart across it by more than that",
                             d.arm.norm());
          return false;
        }
        value += h - d.arm[d.axis];
        break;
      }
    }
    x[d.equation] = value;
  }
  if (finite) {
    for (const auto& [node, reference] : dofs_.rotation_followers) {
      rotation[static_cast<std::size_t>(node)] = rotation[static_cast<std::size_t>(reference)];
    }
  }
  return true;
}

void DependentMotion::update_gradients(const Eigen::VectorXd& x,
                                       const std::vector<Matrix3>& rotation, bool nlgeom) {
  for (const DependentDof& d : dofs_.dofs) {
    double* c = first_.data() + d.first_term;
    switch (d.map) {
      case Map::RigidTranslation: {
        c[0] = 1.0;
        if (d.term_count == 1) break;
        // δu_k = δu_ref,k + (δω × a)_k = δu_ref,k + δω·(a × e_k).
        const Vector3 lever = current_arm(d, rotation, nlgeom).cross(Vector3::Unit(d.axis));
        for (int i = 0; i < 3; ++i) c[kSpins + static_cast<std::uint32_t>(i)] = lever[i];
        break;
      }
      case Map::Rotation: c[0] = 1.0; break;
      case Map::Linear: break;
      case Map::LinkTranslation: {
        c[0] = 1.0;
        Vector3 slope;  // ∂x_k/∂x_node,j = −d_j/h
        Vector3 gap;
        double h = 0;
        if (nlgeom && link_state(d, x, gap, h)) {
          slope = -gap / h;
        } else {
          slope = -d.arm / d.arm[d.axis];
        }
        for (int j = 0; j < 3; ++j) {
          const auto t = static_cast<std::uint32_t>(j);
          c[kLinkNode + t] = j == d.axis ? 0.0 : slope[j];
          c[kLinkOther + t] = j == d.axis ? 0.0 : -slope[j];
        }
        break;
      }
    }
    // Chains: ∂u_d/∂q = Σ_t c_t ∂u_t/∂q, the dependent terms already substituted.
    for (std::uint32_t e = d.first_resolved; e < d.first_resolved + d.resolved_count; ++e) {
      const std::int32_t via = dofs_.resolved_via_entry[e];
      resolved_[e] = first_[dofs_.resolved_via_term[e]] *
                     (via >= 0 ? resolved_[static_cast<std::size_t>(via)] : 1.0);
    }
  }
}

void DependentMotion::add_curvature(const DependentDof& d, double f, const Eigen::VectorXd& x,
                                    const std::vector<Matrix3>& rotation,
                                    std::vector<CurvatureEntry>& out) const {
  if (f == 0.0 || !d.curved()) return;
  if (d.map == Map::RigidTranslation) {
    // ∂/∂ω_j of δω·(a × e_k) with δa = δω × a: (e_j × a) × e_k, i.e. a_i δ_jk − a_k δ_ij.
    const Vector3 a = current_arm(d, rotation, true);
    for (int i = 0; i < 3; ++i) {
      const int row = map_.equation(d.reference, 4 + i);
      if (row < 0) continue;
      for (int j = 0; j < 3; ++j) {
        const int column = map_.equation(d.reference, 4 + j);
        const double value = (j == d.axis ? a[i] : 0.0) - (i == j ? a[d.axis] : 0.0);
        if (column >= 0 && value != 0.0) out.push_back({row, column, f * value});
      }
    }
    return;
  }
  // A link: h(d) = s·√(L² − Σ d_j²) has ∂²h/∂d_i∂d_j = −δ_ij/h − d_i d_j/h³ (i, j ≠ k), and
  // d_j = x_node,j − x_other,j.
  Vector3 gap;
  double h = 0;
  if (!link_state(d, x, gap, h)) return;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (i == d.axis || j == d.axis) continue;
      const double hessian = -(i == j ? 1.0 / h : 0.0) - gap[i] * gap[j] / (h * h * h);
      for (const std::uint32_t side_i : {kLinkNode, kLinkOther}) {
        for (const std::uint32_t side_j : {kLinkNode, kLinkOther}) {
          const int row = dofs_.term_equation[d.first_term + side_i + static_cast<std::uint32_t>(i)];
          const int column =
              dofs_.term_equation[d.first_term + side_j + static_cast<std::uint32_t>(j)];
          if (row < 0 || column < 0) continue;
          const double sign = side_i == side_j ? 1.0 : -1.0;
          out.push_back({row, column, f * sign * hessian});
        }
      }
    }
  }
}

}  // namespace clinch
