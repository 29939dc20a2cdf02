#include "src/solver/procedure.hpp"

#include "src/solver/riks_procedure.hpp"
#include "src/solver/static_step_procedure.hpp"

namespace clinch {

std::unique_ptr<Procedure> procedure_for(const Step& step) {
  if (step.procedure && step.procedure->riks) return std::make_unique<RiksProcedure>(step);
  return std::make_unique<StaticStepProcedure>(step);
}

}  // namespace clinch
