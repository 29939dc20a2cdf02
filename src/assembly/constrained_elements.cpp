#include "src/assembly/constrained_elements.hpp"

#include <algorithm>
#include <optional>

namespace clinch {
namespace {

// The expansion of an element over `l` whose first `nodal` rows are nodal equations, or nullopt
// when none of them is dependent.
std::optional<ElementExpansion> expansion_of(const DependentDofs& dofs, const LocalEquations& l,
                                             int nodal) {
  const auto rows = static_cast<std::size_t>(l.count);
  const bool any = std::any_of(l.equation.begin(), l.equation.begin() + nodal,
                               [&](int eq) { return dofs.is_dependent(eq); });
  if (!any) return std::nullopt;
  ElementExpansion e;
  auto place_of = [&e](int eq) {
    const auto found = std::find(e.equations.begin(), e.equations.end(), eq);
    if (found != e.equations.end()) return static_cast<std::int16_t>(found - e.equations.begin());
    e.equations.push_back(eq);
    return static_cast<std::int16_t>(e.equations.size() - 1);
  };
  e.place.assign(rows, -1);
  for (int a = 0; a < nodal; ++a) {
    const int eq = l.equation[static_cast<std::size_t>(a)];
    if (!dofs.is_dependent(eq)) e.place[static_cast<std::size_t>(a)] = place_of(eq);
  }
  for (int a = 0; a < nodal; ++a) {
    const int eq = l.equation[static_cast<std::size_t>(a)];
    if (!dofs.is_dependent(eq)) continue;
    const DependentDof& d =
        dofs.dofs[static_cast<std::size_t>(dofs.of_equation[static_cast<std::size_t>(eq)])];
    for (std::uint32_t t = d.first_resolved; t < d.first_resolved + d.resolved_count; ++t) {
      e.term_place.push_back(place_of(dofs.resolved_equation[t]));
    }
  }
  for (std::size_t a = static_cast<std::size_t>(nodal); a < rows; ++a) {
    e.place[a] = place_of(l.equation[a]);
  }
  return e;
}

}  // namespace

void expand_constrained_elements(AnalysisPlan& plan) {
  if (plan.dependents.empty()) return;
  auto expand = [&plan](const LocalEquations& l, int nodal, std::int32_t& expansion) {
    std::optional<ElementExpansion> e = expansion_of(plan.dependents, l, nodal);
    if (!e) return;
    expansion = static_cast<std::int32_t>(plan.expansions.size());
    plan.expansions.push_back(std::move(*e));
  };
  for (ConnectorRecord& r : plan.connectors) expand(r.local, r.column_count, r.expansion);
  for (SpringRecord& r : plan.springs) expand(r.local, r.local.count, r.expansion);
}

std::span<const int> scatter_equations(const AnalysisPlan& plan, const LocalEquations& local,
                                       std::int32_t expansion) {
  if (expansion < 0) return {local.equation.data(), static_cast<std::size_t>(local.count)};
  return plan.expansions[static_cast<std::size_t>(expansion)].equations;
}

void condense(const ElementExpansion& e, const LocalEquations& l, const DependentDofs& dofs,
              const DependentMotion& motion, const LocalSystem& local, bool want_tangent,
              CondensedLocal& out, Eigen::VectorXd& internal) {
  const int n = l.count;
  const auto m = static_cast<Eigen::Index>(e.equations.size());
  out.transform.clear();
  std::size_t term = 0;
  for (int a = 0; a < n; ++a) {
    const std::int16_t place = e.place[static_cast<std::size_t>(a)];
    if (place >= 0) {
      out.transform.push_back({a, place, 1.0});
      continue;
    }
    const int eq = l.equation[static_cast<std::size_t>(a)];
    internal[eq] += local.r[a];
    const DependentDof& d =
        dofs.dofs[static_cast<std::size_t>(dofs.of_equation[static_cast<std::size_t>(eq)])];
    for (const double coefficient : motion.gradient(d)) {
      out.transform.push_back({a, e.term_place[term++], coefficient});
    }
  }
  out.r.setZero(m);
  for (const auto& t : out.transform) out.r[t.place] += t.coefficient * local.r[t.row];
  if (!want_tangent) return;
  // K' = Tᵀ(K T), over T's non-zeros: a few per row.
  out.kt.setZero(n, m);
  for (const auto& t : out.transform) {
    out.kt.col(t.place) += t.coefficient * local.k.col(t.row).head(n);
  }
  out.k.setZero(m, m);
  for (const auto& t : out.transform) out.k.row(t.place) += t.coefficient * out.kt.row(t.row);
}

}  // namespace clinch
