#include "src/assembly/spring_element.hpp"

namespace clinch {
namespace {

// Δ of a spring or dashpot at the nodal values x (keywords.md §7), with ∂Δ/∂(node values) on
// its 6 columns and, under NLGEOM for SPRINGA, the geometric part ∂²Δ/∂(node values)².
struct Elongation {
  double delta = 0;
  Eigen::Matrix<double, 6, 1> gradient = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 6> curvature = Eigen::Matrix<double, 6, 6>::Zero();
};

// The three values of `x` from DOF `first_dof` of `node` (0 where inactive or grounded).
Vector3 node_vector(const AnalysisPlan& plan, const Eigen::VectorXd& x, std::int32_t node,
                    int first_dof) {
  Vector3 v = Vector3::Zero();
  if (node < 0) return v;
  for (int k = 0; k < 3; ++k) {
    const int eq = plan.dofs.equation(node, first_dof + k);
    if (eq >= 0) v[k] = x[eq];
  }
  return v;
}

// The element's nodal vectors [node 1, node 2] on the DOFs its Δ reads.
Eigen::Matrix<double, 6, 1> element_values(const AnalysisPlan& plan, const SpringRecord& s,
                                           const Eigen::VectorXd& x) {
  const int first = s.type != ElementType::SpringA && s.rotational ? 4 : 1;
  Eigen::Matrix<double, 6, 1> values;
  values << node_vector(plan, x, s.nodes[0], first), node_vector(plan, x, s.nodes[1], first);
  return values;
}

Elongation elongation(const AnalysisPlan& plan, const SpringRecord& s, const Eigen::VectorXd& x,
                      bool nlgeom) {
  auto node_vector = [&](std::int32_t node, int first_dof) {
    return clinch::node_vector(plan, x, node, first_dof);
  };
  Elongation e;
  if (s.type == ElementType::SpringA) {
    // keywords.md §7: exact axial kinematics under NLGEOM, initial direction otherwise.
    const Vector3 du = node_vector(s.nodes[1], 1) - node_vector(s.nodes[0], 1);
    const double l0 = s.d0.stableNorm();
    Vector3 n = s.d0 / l0;
    if (nlgeom) {
      const Vector3 d = s.d0 + du;
      const double l = d.stableNorm();
      n = d / l;
      e.delta = l - l0;
      const Matrix3 lateral = (Matrix3::Identity() - n * n.transpose()) / l;
      e.curvature.topLeftCorner<3, 3>() = lateral;
      e.curvature.bottomRightCorner<3, 3>() = lateral;
      e.curvature.topRightCorner<3, 3>() = -lateral;
      e.curvature.bottomLeftCorner<3, 3>() = -lateral;
    } else {
      e.delta = n.dot(du);
    }
    e.gradient << -n, n;
  } else {
    const int first = s.rotational ? 4 : 1;
    e.gradient.head<3>() = s.direction[0];
    if (s.type == ElementType::Spring2) e.gradient.tail<3>() = -s.direction[1];
    e.delta = s.direction[0].dot(node_vector(s.nodes[0], first));
    if (s.type == ElementType::Spring2) {
      e.delta -= s.direction[1].dot(node_vector(s.nodes[1], first));
    }
  }
  return e;
}

}  // namespace

void evaluate_spring(const AnalysisPlan& plan, const SpringRecord& s, const SpringMotion& motion,
                     bool want_tangent, LocalSystem& local, SpringResult& result) {
  const SpringLaw& law = *plan.spring_laws[s.law];
  const Elongation e = elongation(plan, s, motion.x, motion.nlgeom);
  SpringResponse response;
  // ∂(rate)/∂(node values) of a dashpot in a dynamic step: the rate is ∇Δ·V with V the nodal
  // velocities, so it moves with V (∂V/∂u = dv_du) and, under NLGEOM, with the direction of Δ.
  Eigen::Matrix<double, 6, 1> rate_gradient = Eigen::Matrix<double, 6, 1>::Zero();
  if (!s.dashpot) {
    response = law.evaluate(e.delta);
  } else if (motion.velocity) {
    // docs/dynamics.md: in a dynamic step the dashpot sees the true rate of Δ.
    const Eigen::Matrix<double, 6, 1> velocity = element_values(plan, s, *motion.velocity);
    response = law.evaluate(e.gradient.dot(velocity));
    rate_gradient = motion.dv_du * e.gradient + e.curvature * velocity;
  } else if (motion.dt > 0) {
    // behaviors.md §8: in a static step the dashpot's velocity is Δ's increment over Δt.
    const double delta_n = elongation(plan, s, motion.x_n, motion.nlgeom).delta;
    response = law.evaluate((e.delta - delta_n) / motion.dt);
    response.stiffness /= motion.dt;
  }
  result = {response.force, e.delta};
  for (int a = 0; a < s.column_count; ++a) {
    local.r[a] = response.force * e.gradient[s.columns[static_cast<std::size_t>(a)]];
  }
  if (!want_tangent) return;
  for (int b = 0; b < s.column_count; ++b) {
    const int cb = s.columns[static_cast<std::size_t>(b)];
    for (int a = 0; a < s.column_count; ++a) {
      const int ca = s.columns[static_cast<std::size_t>(a)];
      const double rate_by_value = motion.velocity && s.dashpot ? rate_gradient[cb]
                                                                 : e.gradient[cb];
      local.k(a, b) = response.stiffness * e.gradient[ca] * rate_by_value +
                      response.force * e.curvature(ca, cb);
    }
  }
}

}  // namespace clinch
