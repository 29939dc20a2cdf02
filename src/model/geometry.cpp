// Geometry of the model: instance placement of a point or a vector, the geometric tolerance,
// element type names and the display of references. The stage that places instances and resolves
// references is src/resolve/ (geometry_placement.cpp, reference_lookup.cpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/diagnostic.hpp"
#include "base/suggest.hpp"
#include "src/model/model.hpp"

namespace clinch {

const char* element_type_name(ElementType type) {
  switch (type) {
    case ElementType::Conn3D2:
      return "CONN3D2";
    case ElementType::Conn2D2:
      return "CONN2D2";
    case ElementType::SpringA:
      return "SPRINGA";
    case ElementType::Spring1:
      return "SPRING1";
    case ElementType::Spring2:
      return "SPRING2";
    case ElementType::DashpotA:
      return "DASHPOTA";
    case ElementType::Dashpot1:
      return "DASHPOT1";
    case ElementType::Dashpot2:
      return "DASHPOT2";
  }
  return "?";
}

double length_of(const Vec3& x) { return std::hypot(x[0], x[1], x[2]); }

double geometry_tolerance(const std::vector<Node>& nodes) {
  if (nodes.empty()) return 1e-8;
  Vec3 lo = nodes.front().x, hi = lo;
  for (const Node& node : nodes) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], node.x[k]);
      hi[k] = std::max(hi[k], node.x[k]);
    }
  }
  const double diagonal = length_of({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  return 1e-8 * std::max(1.0, std::isfinite(diagonal) ? diagonal : 1.0);
}

Vec3 Instance::rotate(const Vec3& v) const {
  Vec3 out{};
  for (int i = 0; i < 3; ++i) {
    out[i] = rotation[i][0] * v[0] + rotation[i][1] * v[1] + rotation[i][2] * v[2];
  }
  return out;
}

Vec3 Instance::place(const Vec3& x) const {
  Vec3 shifted{x[0] + translation[0] - axis_point[0], x[1] + translation[1] - axis_point[1],
               x[2] + translation[2] - axis_point[2]};
  Vec3 r = rotate(shifted);
  return {axis_point[0] + r[0], axis_point[1] + r[1], axis_point[2] + r[2]};
}

Model::Model() {
  parts.emplace_back();
  instances.emplace_back();
}

std::string describe(const TargetRef& ref, bool element) {
  std::string prefix = ref.instance_key.empty() ? "" : ref.instance_display + ".";
  if (ref.is_label) {
    return fmt::format("{} {}{}", element ? "element" : "node", prefix, ref.label);
  }
  return fmt::format("{} set '{}{}'", element ? "element" : "node", prefix, ref.set_display);
}

std::string qualified_label(const Model& model, std::int32_t instance, std::int32_t label) {
  if (instance <= 0) return std::to_string(label);
  return model.instances[instance].name.display + "." + std::to_string(label);
}

}  // namespace clinch
