// The history keyword family (keywords.md §8–§18): the concatenated specs and the helpers shared
// by step_static.cpp, boundary_load.cpp, amplitude.cpp and output.cpp.
#include <fmt/format.h>

#include "parser/keywords/history_keywords.hpp"
#include "parser/keywords/keyword_families.hpp"

namespace clinch {

std::vector<KeywordSpec> history_keyword_specs() {
  std::vector<KeywordSpec> specs;
  for (auto* family : {&step_keyword_specs, &frequency_keyword_specs, &condition_keyword_specs,
                       &amplitude_keyword_specs, &initial_condition_keyword_specs,
                       &output_keyword_specs}) {
    for (KeywordSpec& spec : family()) specs.push_back(std::move(spec));
  }
  return specs;
}

Step& current_step(BlockContext& ctx) {
  std::vector<Step>& steps = ctx.model().history.steps;
  const std::int32_t index = ctx.position().step < 0 ? 0 : ctx.position().step;
  while (static_cast<std::int32_t>(steps.size()) <= index) {
    Step step;
    const std::string name = fmt::format("Step-{}", steps.size() + 1);
    step.name = Name{name_key(name, false), name, ctx.keyword().loc};
    step.loc = ctx.keyword().loc;
    step.placeholder = true;
    if (!steps.empty()) {
      step.nlgeom = steps.back().nlgeom;
      step.controls = steps.back().controls;
    }
    steps.push_back(std::move(step));
  }
  return steps[static_cast<std::size_t>(index)];
}

bool report_second_procedure(BlockContext& ctx, const Step& step) {
  if (!step.procedure && !step.frequency) return false;
  ctx.report(DiagCode::step_procedure, ctx.keyword().loc,
             fmt::format("step '{}' has more than one procedure", step.name.display))
      .notes.push_back({step.procedure ? step.procedure->loc : step.frequency->loc,
                        "first procedure is here"});
  return true;
}

bool report_unsupported_params(BlockContext& ctx, std::initializer_list<std::string_view> names) {
  bool any = false;
  for (const ParamSet::Entry& entry : ctx.params().entries()) {
    for (std::string_view name : names) {
      if (entry.spec->name != name) continue;
      ctx.report(DiagCode::unsupported_option, entry.param->loc,
                 fmt::format("parameter '{}' of {} is not supported by clinch", name,
                             ctx.keyword_display()));
      any = true;
    }
  }
  return any;
}

}  // namespace clinch
