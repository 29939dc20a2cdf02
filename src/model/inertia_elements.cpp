#include "src/model/inertia_elements.hpp"

#include "src/model/element_library.hpp"
#include "src/model/model.hpp"

namespace clinch {

std::vector<std::int32_t> inertia_element_nodes(const Model& model) {
  std::vector<std::int32_t> node_of(model.elements.size(), -1);
  for (std::size_t i = 0; i < model.instances.size(); ++i) {
    const Instance& instance = model.instances[i];
    if (i == 0 && instance.part != 0) continue;
    for (const ElementBlock& block : model.parts[instance.part].element_blocks) {
      if (!is_inertia_only(static_cast<ElementFamily>(block.family))) continue;
      for (std::int32_t k = 0; k < block.count; ++k) {
        const std::int32_t local = block.element_nodes(k)[0];
        const auto e = static_cast<std::size_t>(block.first_element + k + instance.element_offset);
        if (local == kGround || e >= node_of.size()) continue;
        node_of[e] = local + instance.node_offset;
      }
    }
  }
  return node_of;
}

}  // namespace clinch
