// A *CONNECTOR MOTION on a component that has a *CONNECTOR STOP suspends the stop while it is
// prescribed: clinch enforces the motion, the stronger constraint, and the stop applies again
// once the motion is removed (docs/decisions.md, "Steps"). The motion's data line says so
// (motion-suspends-stop), once per line, with a note at the stop.
#include <fmt/format.h>

#include <optional>
#include <string>

#include "base/diagnostic.hpp"
#include "src/check/check.hpp"
#include "src/model/model.hpp"
#include "src/model/references.hpp"

namespace clinch {
namespace {

const ConnectorStop* stop_of(const Model& model, std::int32_t element, int component) {
  const SectionModel& sections = model.sections;
  const auto e = static_cast<std::size_t>(element);
  if (e >= sections.section_of_element.size()) return nullptr;
  const std::int32_t s = sections.section_of_element[e];
  if (s < 0 || static_cast<std::size_t>(s) >= sections.connector_sections.size()) return nullptr;
  const std::int32_t b = sections.connector_sections[static_cast<std::size_t>(s)].behavior_index;
  if (b < 0 || static_cast<std::size_t>(b) >= model.behaviors.behaviors.size()) return nullptr;
  for (const ConnectorStop& stop : model.behaviors.behaviors[static_cast<std::size_t>(b)].stops) {
    if (stop.valid && stop.component == component) return &stop;
  }
  return nullptr;
}

void check_motion(const Model& model, const ConnectorCondition& motion, DiagnosticSink& sink) {
  for (std::int32_t e : motion.resolved) {
    const ConnectorStop* stop = stop_of(model, e, motion.component);
    if (!stop) continue;
    const auto limit = [](const std::optional<double>& v) {
      return v ? fmt::format("{}", *v) : std::string("none");
    };
    const Element& element = model.elements[static_cast<std::size_t>(e)];
    sink.report(DiagCode::motion_suspends_stop, motion.loc,
                fmt::format("*CONNECTOR MOTION drives component {} of element {}, which has a "
                            "*CONNECTOR STOP (lower {}, upper {}); the stop is not enforced "
                            "while the motion is prescribed",
                            motion.component,
                            qualified_label(model, element.instance, element.label),
                            limit(stop->lower), limit(stop->upper)))
        .notes.push_back({stop->loc, "the stop is defined here"});
    return;
  }
}

}  // namespace

void check_motion_stops(const Model& model, DiagnosticSink& sink) {
  for (const ConnectorCondition& motion : model.history.model_motions) {
    check_motion(model, motion, sink);
  }
  for (const Step& step : model.history.steps) {
    for (const ConnectorCondition& motion : step.motions) check_motion(model, motion, sink);
  }
}

}  // namespace clinch
