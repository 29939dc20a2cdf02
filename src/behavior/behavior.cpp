#include "src/behavior/behavior.hpp"

namespace clinch {

int history_slot(std::span<const HistoryVariable> layout, std::string_view output, int component) {
  for (std::size_t s = 0; s < layout.size(); ++s) {
    if (layout[s].component == component && layout[s].output == output) return static_cast<int>(s);
  }
  return -1;
}

}  // namespace clinch
