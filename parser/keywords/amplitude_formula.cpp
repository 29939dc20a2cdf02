// Data lines of the formula amplitudes (keywords.md §8; Abaqus "Amplitude curves"):
//   PERIODIC:  N, ω, t0, A0 on the first line, then A1, B1, A2, B2, … (2N values, 8 a line)
//   MODULATED: A0, A, t0, ω1, ω2
//   DECAY:     A0, A, t0, td
// SCALEX/SHIFTX map a time t to SCALEX·t + SHIFTX as for the points of a table, so the formula
// of the new time has t0 ← SCALEX·t0 + SHIFTX, ω ← ω/SCALEX and td ← SCALEX·td; SCALEY/SHIFTY
// map a value a to SCALEY·a + SHIFTY, so A0 ← SCALEY·A0 + SHIFTY and the other magnitudes are
// scaled.
#include "parser/keywords/amplitude_formula.hpp"

#include <fmt/format.h>

#include <cmath>

namespace clinch {
namespace {

const char* definition_name(AmplitudeDefinition definition) {
  switch (definition) {
    case AmplitudeDefinition::Periodic:
      return "PERIODIC";
    case AmplitudeDefinition::Modulated:
      return "MODULATED";
    default:
      return "DECAY";
  }
}

void report_layout(BlockContext& ctx, const Amplitude& a, SourceLoc where, std::string message) {
  ctx.report(DiagCode::invalid_amplitude, where, std::move(message))
      .notes.push_back({a.loc, fmt::format("in amplitude '{}'", a.name.display)});
}

bool read_periodic(BlockContext& ctx, Amplitude& a, const std::vector<AmplitudeNumber>& numbers) {
  std::size_t first_line = 0;
  while (first_line < numbers.size() && numbers[first_line].line == 0) ++first_line;
  if (first_line != 4) {
    report_layout(ctx, a, numbers.front().loc,
                  fmt::format("the first data line of a PERIODIC amplitude gives N, ω, t0, A0 "
                              "(4 values); got {}",
                              first_line));
    return false;
  }
  const double n = numbers[0].value;
  if (n < 1 || n != std::floor(n) || n > 1e6) {
    report_layout(ctx, a, numbers[0].loc,
                  fmt::format("N, the number of Fourier terms, must be a positive integer; got {}",
                              n));
    return false;
  }
  const auto terms = static_cast<std::size_t>(n);
  const std::size_t coefficients = numbers.size() - 4;
  if (coefficients != 2 * terms) {
    report_layout(ctx, a, coefficients == 0 ? numbers[3].loc : numbers.back().loc,
                  fmt::format("N = {} Fourier terms need {} coefficients (A1, B1, … A{}, B{}) "
                              "after the first line; got {}",
                              terms, 2 * terms, terms, terms, coefficients));
    return false;
  }
  AmplitudeFormula& f = a.formula;
  f.omega = numbers[1].value;
  f.start_time = numbers[2].value;
  f.initial = numbers[3].value;
  for (std::size_t k = 0; k < terms; ++k) {
    f.cosines.push_back(numbers[4 + 2 * k].value);
    f.sines.push_back(numbers[5 + 2 * k].value);
  }
  return true;
}

bool read_fixed(BlockContext& ctx, Amplitude& a, const std::vector<AmplitudeNumber>& numbers) {
  const bool modulated = a.definition == AmplitudeDefinition::Modulated;
  const std::size_t expected = modulated ? 5 : 4;
  if (numbers.size() != expected) {
    report_layout(ctx, a, numbers.size() > expected ? numbers[expected].loc : numbers.back().loc,
                  fmt::format("a {} amplitude gives {} ({} values); got {}",
                              definition_name(a.definition),
                              modulated ? "A0, A, t0, ω1, ω2" : "A0, A, t0, td", expected,
                              numbers.size()));
    return false;
  }
  AmplitudeFormula& f = a.formula;
  f.initial = numbers[0].value;
  f.magnitude = numbers[1].value;
  f.start_time = numbers[2].value;
  if (modulated) {
    f.omega = numbers[3].value;
    f.omega2 = numbers[4].value;
    return true;
  }
  f.decay_time = numbers[3].value;
  if (!(f.decay_time > 0)) {
    report_layout(ctx, a, numbers[3].loc,
                  fmt::format("the decay time td must be positive; got {}", f.decay_time));
    return false;
  }
  return true;
}

void scale_and_shift(Amplitude& a) {
  AmplitudeFormula& f = a.formula;
  f.start_time = a.scale_x * f.start_time + a.shift_x;
  f.omega /= a.scale_x;
  f.omega2 /= a.scale_x;
  f.decay_time *= a.scale_x;
  f.initial = a.scale_y * f.initial + a.shift_y;
  f.magnitude *= a.scale_y;
  for (double& c : f.cosines) c *= a.scale_y;
  for (double& s : f.sines) s *= a.scale_y;
}

}  // namespace

bool read_amplitude_formula(BlockContext& ctx, Amplitude& a,
                            const std::vector<AmplitudeNumber>& numbers) {
  const bool ok = a.definition == AmplitudeDefinition::Periodic ? read_periodic(ctx, a, numbers)
                                                                : read_fixed(ctx, a, numbers);
  if (ok) scale_and_shift(a);
  return ok;
}

}  // namespace clinch
