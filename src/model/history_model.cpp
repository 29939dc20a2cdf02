#include "src/model/history_model.hpp"

namespace clinch {

const char* condition_keyword(ConditionKind kind) {
  switch (kind) {
    case ConditionKind::Boundary:
      return "*BOUNDARY";
    case ConditionKind::Motion:
      return "*CONNECTOR MOTION";
    case ConditionKind::Load:
      return "*CLOAD";
    case ConditionKind::ConnectorLoad:
      return "*CONNECTOR LOAD";
    case ConditionKind::Gravity:
      return "*DLOAD";
  }
  return "";
}

bool Step::replaces(ConditionKind kind) const {
  for (const ConditionBlock& block : blocks) {
    if (block.kind == kind && block.op_new) return true;
  }
  return false;
}

}  // namespace clinch
