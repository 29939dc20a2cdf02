#include "src/solver/procedure.hpp"

#include "src/model/history_model.hpp"
#include "src/solver/dynamic_step_procedure.hpp"
#include "src/solver/riks_procedure.hpp"
#include "src/solver/static_step_procedure.hpp"

namespace clinch {

std::unique_ptr<Procedure> procedure_for(const Step& step,
                                         const std::vector<double>& output_intervals) {
  if (step.dynamic) return std::make_unique<DynamicStepProcedure>(step, output_intervals);
  if (step.procedure && step.procedure->riks) return std::make_unique<RiksProcedure>(step);
  return std::make_unique<StaticStepProcedure>(step, output_intervals);
}

}  // namespace clinch
