// The behaviour checks that need the connection types of the sections using a behaviour
// (behaviors.md §1.1, §3, §4.3, §5.1): component availability, ignored reference values and
// coupled stiffness terms, the positive definiteness of the available stiffness block, and stops
// violated in the initial configuration. Part of check_behaviors; internal to src/check.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace clinch {

class DiagnosticSink;
struct Model;

// Runs the section-dependent checks of behaviour `index` (sections with behavior_index == index
// and a valid type).
void check_behavior_against_sections(const Model& model, std::size_t index, DiagnosticSink& sink);

// Eigenvalues of the symmetric block of `matrix` selected by `mask` (bit i−1 for component i),
// in increasing order; `count` receives their number (Jacobi rotations; n ≤ 6).
std::array<double, 6> symmetric_block_eigenvalues(const std::array<std::array<double, 6>, 6>& m,
                                                  std::uint8_t mask, std::size_t& count);

}  // namespace clinch
