// Shared pieces of the history keyword family (keywords.md §8–§18): the sub-family spec lists
// that step_history.cpp concatenates, the step a history block writes into, and the small
// parameter helpers every history keyword uses.
#pragma once

#include <initializer_list>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keyword_spec.hpp"
#include "src/model/history_model.hpp"

namespace clinch {

// *STEP, *END STEP, *STATIC, *CONTROLS (step_static.cpp).
std::vector<KeywordSpec> step_keyword_specs();
// *FREQUENCY (step_frequency.cpp).
std::vector<KeywordSpec> frequency_keyword_specs();
// *BOUNDARY, *CLOAD, *CONNECTOR MOTION, *CONNECTOR LOAD (boundary_load.cpp).
std::vector<KeywordSpec> condition_keyword_specs();
// *AMPLITUDE (amplitude.cpp).
std::vector<KeywordSpec> amplitude_keyword_specs();
// *INITIAL CONDITIONS, TYPE=VELOCITY (initial_conditions.cpp).
std::vector<KeywordSpec> initial_condition_keyword_specs();
// *OUTPUT, *ELEMENT OUTPUT, *NODE OUTPUT, *NODE PRINT, *EL PRINT (output.cpp).
std::vector<KeywordSpec> output_keyword_specs();

// The step the reader is in (position().step). A *STEP whose keyword line had errors creates no
// Step (its handler never runs), so missing steps are created here as placeholders: the
// history data inside such a step is still read and checked.
Step& current_step(BlockContext& ctx);

// STABILIZE and its parameters on a *STATIC line (step_stabilization.cpp): nullopt without
// STABILIZE; FACTOR, ALLSDTOL or CONTINUE without it, and STABILIZE with RIKS, are errors.
std::optional<StaticStabilization> read_stabilization(BlockContext& ctx, bool riks);

// E0605 at the keyword when `step` already has a procedure (*STATIC, *DYNAMIC or *FREQUENCY;
// input-syntax.md §8: exactly one per step), with a note at the first; true if so.
bool report_second_procedure(BlockContext& ctx, const Step& step);

// E0210 for every given parameter among `names` ("→ E0210" rows of keywords.md); true if any.
bool report_unsupported_params(BlockContext& ctx, std::initializer_list<std::string_view> names);

// Spec for a parameter that Abaqus knows and v1 rejects: any form is accepted by the generic
// checks, then report_unsupported_params gives E0210.
inline ParamSpec unsupported_param(std::string_view name) {
  return ParamSpec{name, ParamKind::OptionalValue};
}

template <typename Handler>
std::unique_ptr<KeywordHandler> make() {
  return std::make_unique<Handler>();
}

}  // namespace clinch
