#include "src/check/check_behavior_sections.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/diagnostic.hpp"
#include "src/model/model.hpp"

namespace clinch {
namespace {

// One place where a behaviour option names a component (behaviors.md §1.1).
struct ComponentUse {
  int component;
  SourceLoc loc;            // the option's keyword line (where the note points)
  std::string_view option;  // "*CONNECTOR ELASTICITY"
};

std::vector<ComponentUse> component_uses(const ConnectorBehavior& b) {
  std::vector<ComponentUse> uses;
  auto add = [&](int c, SourceLoc loc, std::string_view option) {
    if (c >= 1 && c <= 6) uses.push_back({c, loc, option});
  };
  auto add_mask = [&](std::uint8_t mask, SourceLoc loc, std::string_view option) {
    for (int c = 1; c <= 6; ++c) {
      if (mask & (1u << (c - 1))) add(c, loc, option);
    }
  };
  for (const ConnectorElasticity& e : b.elasticities) {
    if (e.kind == ConnectorElasticity::Kind::Rigid) {
      if (!e.rigid_all) add_mask(e.rigid_components, e.loc, "*CONNECTOR ELASTICITY");
    } else if (e.kind != ConnectorElasticity::Kind::Coupled) {
      add(e.component, e.loc, "*CONNECTOR ELASTICITY");
    }
  }
  for (const ConnectorStop& s : b.stops) add(s.component, s.loc, "*CONNECTOR STOP");
  for (const ConnectorLock& l : b.locks) {
    add(l.component, l.loc, "*CONNECTOR LOCK");
    add(l.locked, l.loc, "*CONNECTOR LOCK");
  }
  for (const ConnectorFailure& f : b.failures) {
    add(f.component, f.loc, "*CONNECTOR FAILURE");
    add(f.released, f.loc, "*CONNECTOR FAILURE");
  }
  for (const ConnectorPlasticity& p : b.plasticities) {
    add(p.component, p.loc, "*CONNECTOR PLASTICITY");
  }
  for (const DamageInitiation& d : b.damage_initiations) {
    add(d.component, d.loc, "*CONNECTOR DAMAGE INITIATION");
  }
  for (const DamageEvolution& d : b.damage_evolutions) {
    add_mask(d.affected, d.loc, "*CONNECTOR DAMAGE EVOLUTION");
  }
  for (const ConnectorDamping& d : b.dampings) add(d.component, d.loc, "*CONNECTOR DAMPING");
  return uses;
}

std::string type_display(const ConnectorSection& s) {
  std::string out;
  for (const std::string& t : s.type_names) {
    if (!out.empty()) out += ", ";
    out += t;
  }
  return out.empty() ? "?" : out;
}

std::string mask_list(std::uint8_t mask) {
  std::string out;
  for (int c = 1; c <= 6; ++c) {
    if (!(mask & (1u << (c - 1)))) continue;
    if (!out.empty()) out += ", ";
    out += std::to_string(c);
  }
  return out.empty() ? "none" : out;
}

bool has_type(const ConnectorSection& s, std::string_view name) {
  return std::find(s.type_names.begin(), s.type_names.end(), name) != s.type_names.end();
}

// The initial position p_i(0) of `component` in element `element`, when it is cheap to know
// (behaviors.md §5.1): the initial length for AXIAL, and the global offsets for CARTESIAN
// without an orientation at node a. nullopt otherwise (the check is then skipped).
std::optional<double> initial_position(const Model& model, const ConnectorSection& s,
                                       std::int32_t element, int component) {
  if (element < 0 || static_cast<std::size_t>(element) >= model.elements.size()) {
    return std::nullopt;
  }
  const Element& e = model.elements[static_cast<std::size_t>(element)];
  Vec3 xa{}, xb{};
  const std::int32_t a = e.nodes[0], b = e.nodes[1];
  auto valid_node = [&](std::int32_t n) {
    return n >= 0 && static_cast<std::size_t>(n) < model.nodes.size();
  };
  if (a != kGround && !valid_node(a)) return std::nullopt;
  if (b != kGround && !valid_node(b)) return std::nullopt;
  if (a == kGround && b == kGround) return std::nullopt;
  // keywords.md §3: the ground point sits at the initial position of the other node.
  xa = a != kGround ? model.nodes[static_cast<std::size_t>(a)].x
                    : model.nodes[static_cast<std::size_t>(b)].x;
  xb = b != kGround ? model.nodes[static_cast<std::size_t>(b)].x : xa;
  const Vec3 d{xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
  if (component == 1 && has_type(s, "AXIAL")) {
    return length_of(d);
  }
  const bool oriented_a = !s.orientations.empty() && !s.orientations[0].empty();
  if (component <= 3 && !oriented_a && (has_type(s, "CARTESIAN") || has_type(s, "ACCELEROMETER"))) {
    return d[static_cast<std::size_t>(component - 1)];
  }
  return std::nullopt;
}

std::string format_limit(const std::optional<double>& v) {
  return v ? fmt::format("{}", *v) : std::string("none");
}

}  // namespace

std::array<double, 6> symmetric_block_eigenvalues(const std::array<std::array<double, 6>, 6>& m,
                                                  std::uint8_t mask, std::size_t& count) {
  std::array<int, 6> index{};
  count = 0;
  for (int c = 0; c < 6; ++c) {
    if (mask & (1u << c)) index[count++] = c;
  }
  const std::size_t n = count;
  std::array<std::array<double, 6>, 6> a{};
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) a[i][j] = m[index[i]][index[j]];
  }
  // Cyclic Jacobi rotations: converges quadratically; 50 sweeps is far more than a 6×6 needs.
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) off += a[i][j] * a[i][j];
    }
    if (off == 0 || !std::isfinite(off)) break;
    for (std::size_t p = 0; p < n; ++p) {
      for (std::size_t q = p + 1; q < n; ++q) {
        if (a[p][q] == 0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1);
        const double s = t * c;
        for (std::size_t k = 0; k < n; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (std::size_t k = 0; k < n; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
      }
    }
  }
  std::array<double, 6> eig{};
  for (std::size_t i = 0; i < n; ++i) eig[i] = a[i][i];
  std::sort(eig.begin(), eig.begin() + static_cast<std::ptrdiff_t>(n));
  return eig;
}

void check_behavior_against_sections(const Model& model, std::size_t index, DiagnosticSink& sink) {
  const ConnectorBehavior& b = model.behaviors.behaviors[index];
  const std::vector<ComponentUse> uses = component_uses(b);
  std::set<std::pair<std::size_t, int>> reference_warned;         // (field, ·)
  std::set<std::pair<std::size_t, std::uint8_t>> coupled_warned;  // (elasticity, mask)
  std::set<std::pair<std::size_t, std::uint8_t>> definite_checked;
  std::set<std::size_t> stops_warned;

  for (const ConnectorSection& s : model.sections.connector_sections) {
    if (s.behavior_index != static_cast<std::int32_t>(index) || !s.valid) continue;
    const std::uint8_t available = s.available;

    // behaviors.md §1.1 / keywords.md §1: E0702 at the section's BEHAVIOR= value, one per
    // missing component, with a note at each option line that names it.
    for (int c = 1; c <= 6; ++c) {
      if (available & (1u << (c - 1))) continue;
      Diagnostic* d = nullptr;
      for (const ComponentUse& use : uses) {
        if (use.component != c) continue;
        if (!d) {
          d = &sink.report(
              DiagCode::component_not_available, s.behavior.loc,
              fmt::format("component {} of connector behavior '{}' is not available for "
                          "connection type {} (available: {})",
                          c, b.name.display, type_display(s), mask_list(available)));
        }
        d->notes.push_back({use.loc, fmt::format("{} names component {} here", use.option, c)});
      }
    }

    // §3: reference values of components the type does not make available are ignored.
    if (b.reference) {
      for (std::size_t k = 0; k < 6; ++k) {
        if (!b.reference->value[k] || (available & (1u << k))) continue;
        if (!reference_warned.insert({k, 0}).second) continue;
        sink.report(DiagCode::reference_ignored, b.reference->value_loc[k],
                    fmt::format("reference value of component {} is ignored: connection type {} "
                                "does not make it available",
                                k + 1, type_display(s)));
      }
    }

    for (std::size_t e = 0; e < b.elasticities.size(); ++e) {
      const ConnectorElasticity& el = b.elasticities[e];
      if (el.kind != ConnectorElasticity::Kind::Coupled || !el.valid) continue;
      // §4.3: rows and columns of unavailable components are ignored.
      std::uint8_t ignored = 0;
      for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) {
          const bool out = !(available & (1u << i)) || !(available & (1u << j));
          if (out && el.coupled[i][j] != 0) ignored |= static_cast<std::uint8_t>(1u << i);
        }
      }
      ignored &= static_cast<std::uint8_t>(~available);
      if (ignored && coupled_warned.insert({e, available}).second) {
        sink.report(DiagCode::coupled_stiffness_ignored, el.data_loc,
                    fmt::format("coupled stiffness terms of component(s) {} are ignored: "
                                "connection type {} does not make them available",
                                mask_list(ignored), type_display(s)));
      }
      if (!definite_checked.insert({e, available}).second) continue;
      bool finite = true;
      for (const auto& row : el.coupled) {
        for (double v : row) finite = finite && std::isfinite(v);
      }
      if (!finite) continue;
      std::size_t n = 0;
      const std::array<double, 6> eig = symmetric_block_eigenvalues(el.coupled, available, n);
      if (n == 0) continue;
      double scale = 0;
      for (std::size_t k = 0; k < n; ++k) scale = std::max(scale, std::fabs(eig[k]));
      const double tol = 1e-10 * scale;
      if (eig[0] < -tol) {
        sink.report(DiagCode::stiffness_not_positive_definite, Severity::Error, el.data_loc,
                    fmt::format("coupled stiffness is indefinite over the available components "
                                "{} of connection type {} (smallest eigenvalue {:.6g})",
                                mask_list(available), type_display(s), eig[0]));
      } else if (eig[0] <= tol && !b.plasticities.empty()) {
        // §6.4: the plastic returns work with the compliance K⁻¹, which a singular K lacks.
        sink.report(DiagCode::stiffness_not_positive_definite, Severity::Error, el.data_loc,
                    fmt::format("coupled stiffness is only positive semi-definite over the "
                                "available components {} of connection type {}; connector "
                                "plasticity needs a positive definite elasticity",
                                mask_list(available), type_display(s)));
      } else if (eig[0] <= tol) {
        sink.report(DiagCode::stiffness_not_positive_definite, el.data_loc,
                    fmt::format("coupled stiffness is only positive semi-definite over the "
                                "available components {} of connection type {}",
                                mask_list(available), type_display(s)));
      }
    }

    // §5.1: a stop whose limits exclude the initial position.
    for (std::size_t k = 0; k < b.stops.size(); ++k) {
      const ConnectorStop& stop = b.stops[k];
      if (!stop.valid || stop.component < 1 || stop.component > 6) continue;
      if (!(available & (1u << (stop.component - 1)))) continue;
      if (stops_warned.count(k)) continue;
      for (std::int32_t element : s.elements) {
        std::optional<double> p0 = initial_position(model, s, element, stop.component);
        if (!p0) continue;
        if ((stop.lower && *p0 < *stop.lower) || (stop.upper && *p0 > *stop.upper)) {
          stops_warned.insert(k);
          const Element& el = model.elements[static_cast<std::size_t>(element)];
          sink.report(
              DiagCode::stop_initially_violated, stop.data_loc,
              fmt::format("component {} starts at position {} in connector element {}, "
                          "outside the stop limits [{}, {}]; the first increment pushes "
                          "it back to the limit",
                          stop.component, *p0, qualified_label(model, el.instance, el.label),
                          format_limit(stop.lower), format_limit(stop.upper)));
          break;
        }
      }
    }
  }
}

}  // namespace clinch
