// Lookup of the nodes, elements, sets and instances a reference names (input-syntax.md §3.2, §7.3),
// with the errors of a name that is not there. Used by every stage of resolve that follows a
// reference once the model data is complete.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/source_location.hpp"
#include "src/model/references.hpp"

namespace clinch {

class DiagnosticSink;
struct Model;
struct Part;

// Global node/element indices a reference denotes. A reference written inside part p (> 0)
// denotes the copies of every instance of p. Reports undefined labels, sets and instances
// (E0501, E0502, E0503, E0508, with did-you-mean notes) and returns false then; an empty set is
// not an error here (callers that need members report E0515).
bool resolve_nodes(const Model& model, const TargetRef& ref, std::vector<std::int32_t>& out,
                   DiagnosticSink& sink);
bool resolve_elements(const Model& model, const TargetRef& ref, std::vector<std::int32_t>& out,
                      DiagnosticSink& sink);

// The instance a qualifier names, or −1 with E0508 reported.
std::int32_t find_instance(const Model& model, const std::string& key, const std::string& display,
                           SourceLoc loc, DiagnosticSink& sink);

// E0502/E0503 for a set `part` does not define, with a did-you-mean note.
void report_undefined_set(const Part& part, bool element_set, const std::string& display,
                          SourceLoc loc, const std::string& where, DiagnosticSink& sink);

}  // namespace clinch
