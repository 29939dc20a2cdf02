// Test support for the derived-component and potential evaluation tests: a complete one-element
// BUSHING deck (six available components) around a behaviour body, read and validated by the
// deck reader, and central-difference derivatives of a scalar or vector function of the six
// components checked with base/jacobian_check.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <type_traits>

#include "base/jacobian_check.hpp"
#include "base/small_types.hpp"
#include "parser/deck_reader.hpp"
#include "src/behavior/potential/connector_potential.hpp"
#include "src/behavior/potential/derived_component.hpp"
#include "tests/unit/checked_deck.hpp"

namespace clinch::potential_test {

// `parameters` are *PARAMETER lines (without the keyword); `body` follows
// *CONNECTOR BEHAVIOR, NAME=B.
inline std::unique_ptr<CheckedDeck> read_bushing_deck(const std::string& body,
                                                      const std::string& parameters = "") {
  std::string text;
  if (!parameters.empty()) text += "*PARAMETER\n" + parameters;
  text +=
      "*NODE\n1, 0., 0., 0.\n2, 0., 0., 0.\n"
      "*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*ORIENTATION, NAME=GLOBAL\n1.0, 0.0, 0.0, 0.0, 1.0, 0.0\n"
      "*CONNECTOR SECTION, ELSET=C, BEHAVIOR=B\nBUSHING,\nGLOBAL\n"
      "*CONNECTOR BEHAVIOR, NAME=B\n"
      "*CONNECTOR ELASTICITY\n"
      "1.0e5, 0.0, 1.0e5, 0.0, 0.0, 1.0e5, 0.0, 0.0\n"
      "0.0, 1.0e6, 0.0, 0.0, 0.0, 0.0, 1.0e6, 0.0\n"
      "0.0, 0.0, 0.0, 0.0, 1.0e6\n" +
      body + "*BOUNDARY\n1, 1, 6\n*STEP\n*STATIC\n0.1, 1.0\n*END STEP\n";
  auto deck = std::make_unique<CheckedDeck>();
  read_deck_text("t.inp", text, deck->sources, deck->model, deck->sink);
  return deck;
}

inline int error_count(const CheckedDeck& deck) {
  int n = 0;
  for (const Diagnostic& d : deck.sink.diagnostics()) n += d.severity == Severity::Error;
  return n;
}

inline const ConnectorBehavior& behavior_of(const CheckedDeck& deck) {
  return deck.model.behaviors.behaviors.at(0);
}

// The (only) potential of the deck's behaviour, compiled.
inline ConnectorPotential compile_potential(const CheckedDeck& deck, std::size_t i = 0) {
  const ConnectorBehavior& b = behavior_of(deck);
  return ConnectorPotential::compile(b, b.potentials.at(i));
}

// Step of the central differences: 1e-5·max(1, |c_j|), inside the 1e-4·max(1, |c|) bound of §3.
// Truncation error h²|f'''|/6 and round-off ε|f|/h are both about 1e-10 of the scale of the
// compared quantity for states whose kinks are further than ~1% of |c| away.
inline double step(double c) { return 1e-5 * std::max(1.0, std::fabs(c)); }

// The derivatives `analytic` of `f` (a scalar or a 6-vector function of the six components:
// its gradient as a row, or its Jacobian) against central differences at `c` with the steps
// above, entry-wise within rtol·max(max|numeric|, floor) (`floor` for quantities that are zero).
// Only the components in `columns` are differenced; of a Jacobian, only those rows are compared.
template <typename F>
void expect_fd_derivatives(const Eigen::Ref<const Eigen::MatrixXd>& analytic, F&& f,
                           const Vector6& c, double rtol, double floor, const std::string& what,
                           ComponentMask columns = 0b111111) {
  Vector6 steps = Vector6::Zero();
  for (int j = 0; j < 6; ++j) {
    if ((columns >> j) & 1u) steps[j] = step(c[j]);
  }
  const auto vector_f = [&f](const Eigen::VectorXd& x, Eigen::VectorXd& value) {
    if constexpr (std::is_arithmetic_v<decltype(f(Vector6(x)))>) {
      value = Eigen::VectorXd::Constant(1, f(Vector6(x)));
    } else {
      value = f(Vector6(x));
    }
    return true;
  };
  JacobianCheckOptions options;
  if (analytic.rows() == 6) options.compare_row = [columns](int i) { return (columns >> i) & 1u; };
  const JacobianReport report =
      check_jacobian(perturb_additively(vector_f, c), steps, analytic, options);
  EXPECT_LE(report.max_error, rtol * std::max(report.largest_numeric, floor)) << what << "\n"
                                                                              << report;
}

// Entry-wise comparison with a tolerance relative to the largest entry of `expected` (an
// absolute floor `floor` for quantities that are zero).
template <typename A, typename B>
void expect_close(const A& actual, const B& expected, double rtol, double floor,
                  const std::string& what) {
  const double scale = std::max(expected.cwiseAbs().maxCoeff(), floor);
  for (int i = 0; i < actual.rows(); ++i) {
    for (int j = 0; j < actual.cols(); ++j) {
      EXPECT_NEAR(actual(i, j), expected(i, j), rtol * scale)
          << what << " entry (" << i << ", " << j << ")";
    }
  }
}

// A random state with components uniform in [−scale, scale] (fixed seed: reproducible).
inline Vector6 random_state(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Vector6 c;
  for (int j = 0; j < 6; ++j) c[j] = u(rng);
  return c;
}

}  // namespace clinch::potential_test
