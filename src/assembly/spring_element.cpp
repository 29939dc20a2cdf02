#include "src/assembly/spring_element.hpp"

namespace clinch {

void evaluate_spring(const AnalysisPlan& plan, const SpringRecord& s, const Eigen::VectorXd& x,
                     bool nlgeom, bool want_tangent, LocalSystem& local, SpringResult& result) {
  const SpringLaw& law = *plan.spring_laws[s.law];
  auto node_vector = [&](std::int32_t node, int first_dof) {
    Vector3 v = Vector3::Zero();
    if (node < 0) return v;
    for (int k = 0; k < 3; ++k) {
      const int eq = plan.dofs.equation(node, first_dof + k);
      if (eq >= 0) v[k] = x[eq];
    }
    return v;
  };
  Eigen::Matrix<double, 6, 1> g;  // ∂Δ/∂(node values) on the 6 spring columns
  Eigen::Matrix<double, 6, 6> kg = Eigen::Matrix<double, 6, 6>::Zero();  // geometric part / F
  double delta = 0;
  if (s.type == ElementType::SpringA) {
    // keywords.md §7: exact axial kinematics under NLGEOM, initial direction otherwise.
    const Vector3 du = node_vector(s.nodes[1], 1) - node_vector(s.nodes[0], 1);
    const double l0 = s.d0.norm();
    Vector3 n = s.d0 / l0;
    if (nlgeom) {
      const Vector3 d = s.d0 + du;
      const double l = d.norm();
      n = d / l;
      delta = l - l0;
      const Matrix3 lateral = (Matrix3::Identity() - n * n.transpose()) / l;
      kg.topLeftCorner<3, 3>() = lateral;
      kg.bottomRightCorner<3, 3>() = lateral;
      kg.topRightCorner<3, 3>() = -lateral;
      kg.bottomLeftCorner<3, 3>() = -lateral;
    } else {
      delta = n.dot(du);
    }
    g << -n, n;
  } else {
    const int first = s.rotational ? 4 : 1;
    g.head<3>() = s.direction[0];
    g.tail<3>() = s.type == ElementType::Spring2 ? Vector3(-s.direction[1]) : Vector3::Zero();
    delta = s.direction[0].dot(node_vector(s.nodes[0], first));
    if (s.type == ElementType::Spring2) delta -= s.direction[1].dot(node_vector(s.nodes[1], first));
  }
  const SpringResponse response = law.evaluate(delta);
  result = {response.force, delta};
  for (int a = 0; a < s.column_count; ++a) {
    local.r[a] = response.force * g[s.columns[static_cast<std::size_t>(a)]];
  }
  if (!want_tangent) return;
  for (int b = 0; b < s.column_count; ++b) {
    const int cb = s.columns[static_cast<std::size_t>(b)];
    for (int a = 0; a < s.column_count; ++a) {
      const int ca = s.columns[static_cast<std::size_t>(a)];
      local.k(a, b) = response.stiffness * g[ca] * g[cb] + response.force * kg(ca, cb);
    }
  }
}

}  // namespace clinch
