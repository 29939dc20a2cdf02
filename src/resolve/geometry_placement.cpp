// The first stage of resolve (input-syntax.md §7): set operations replayed, element node labels
// resolved, instances placed and the global node and element arrays built.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "base/diagnostic.hpp"
#include "src/model/model.hpp"
#include "src/resolve/reference_lookup.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

void replay_set_operations(Model& model, std::int32_t part_index, DiagnosticSink& sink) {
  Part& part = model.parts[part_index];
  for (const SetOperation& op : part.set_operations) {
    auto& sets = op.element_set ? part.element_sets : part.node_sets;
    Set& target = sets[op.target_key];
    // Members of a root-part set are global indices; an INSTANCE= qualifier selects the
    // labels of that instance.
    const Part* source_part = &part;
    std::int32_t offset = 0;
    if (!op.instance_key.empty()) {
      std::int32_t inst = find_instance(model, op.instance_key, op.instance_display, op.loc, sink);
      if (inst < 0) continue;
      source_part = &model.parts[model.instances[inst].part];
      offset =
          op.element_set ? model.instances[inst].element_offset : model.instances[inst].node_offset;
    }
    const LabelIndex& index = op.element_set ? source_part->element_index : source_part->node_index;
    switch (op.kind) {
      case SetOperation::Kind::Labels: {
        target.members.reserve(target.members.size() + op.labels.size());
        for (const SetOperation::LabelItem& item : op.labels) {
          std::int32_t found = index.find(item.label);
          if (found == LabelIndex::kMissing) {
            sink.report(op.element_set ? DiagCode::undefined_element : DiagCode::undefined_node,
                        item.loc,
                        fmt::format("{} {} is not defined{}", op.element_set ? "element" : "node",
                                    item.label,
                                    op.instance_key.empty()
                                        ? std::string()
                                        : fmt::format(" in instance '{}'", op.instance_display)));
            target.defined_ok = false;
            continue;
          }
          target.members.push_back(found + offset);
        }
        break;
      }
      case SetOperation::Kind::Range: {
        std::int32_t skipped = 0;
        for (std::int64_t label = op.first; label <= op.last; label += op.increment) {
          std::int32_t found = index.find(static_cast<std::int32_t>(label));
          if (found == LabelIndex::kMissing) {
            ++skipped;
          } else {
            target.members.push_back(found + offset);
          }
        }
        if (skipped) {
          sink.report(DiagCode::generate_undefined_labels, op.loc,
                      fmt::format("{} labels in range {}-{} are not defined and were skipped",
                                  skipped, op.first, op.last));
        }
        break;
      }
      case SetOperation::Kind::SetName: {
        const auto& source_sets =
            op.element_set ? source_part->element_sets : source_part->node_sets;
        auto it = source_sets.find(op.source_key);
        if (it == source_sets.end()) {
          report_undefined_set(*source_part, op.element_set, op.source_display, op.loc, "", sink);
          target.defined_ok = false;
          continue;
        }
        if (!it->second.defined_ok) target.defined_ok = false;  // its failure is reported
        std::vector<std::int32_t> copy = it->second.members;
        for (std::int32_t m : copy) target.members.push_back(m + offset);
        break;
      }
      case SetOperation::Kind::ElementNodes: {
        auto it = source_part->element_sets.find(op.source_key);
        if (it == source_part->element_sets.end()) {
          report_undefined_set(*source_part, true, op.source_display, op.loc, "", sink);
          target.defined_ok = false;
          continue;
        }
        for (std::int32_t e : it->second.members) {
          // Root-part element sets may hold instance elements (global indices): their nodes
          // are global already once the arrays are built, so use the local element.
          // Root-part sets are replayed once the global arrays exist; the others use the part.
          const Element& element = part_index == 0 ? model.elements[e] : part.elements[e];
          for (std::int32_t n : element.nodes) {
            if (n != kGround) target.members.push_back(n + offset);
          }
        }
        break;
      }
    }
  }
  part.set_operations.clear();
  part.set_operations.shrink_to_fit();
  // Duplicates within a set are dropped (input-syntax.md §7.4); members in ascending order.
  for (auto* sets : {&part.node_sets, &part.element_sets}) {
    for (auto& [key, set] : *sets) {
      // Members usually arrive in order (GENERATE, label lists): sorting is then skipped.
      if (!std::is_sorted(set.members.begin(), set.members.end())) {
        std::sort(set.members.begin(), set.members.end());
      }
      set.members.erase(std::unique(set.members.begin(), set.members.end()), set.members.end());
    }
  }
}

// Element node labels → part-local node indices (root part: global indices).
void resolve_element_nodes(Model& model, std::int32_t part_index, DiagnosticSink& sink) {
  Part& part = model.parts[part_index];
  std::vector<bool> qualified(part.elements.size() * 2, false);
  for (const Part::QualifiedNode& q : part.qualified_nodes) {
    qualified[static_cast<std::size_t>(q.element) * 2 + q.slot] = true;
  }
  for (std::size_t e = 0; e < part.elements.size(); ++e) {
    Element& element = part.elements[e];
    for (int slot = 0; slot < 2; ++slot) {
      if (element.nodes[slot] == kGround || qualified[e * 2 + slot]) continue;
      std::int32_t found = part.node_index.find(element.nodes[slot]);
      if (found == LabelIndex::kMissing) {
        sink.report(DiagCode::undefined_node,
                    {element.file, element.line, element.node_columns[slot]},
                    fmt::format("node {} is not defined{}", element.nodes[slot],
                                part_index ? fmt::format(" in part '{}'", part.name.display)
                                           : std::string()));
        element.nodes[slot] = kGround;
        continue;
      }
      element.nodes[slot] = found;
    }
  }
  for (const Part::QualifiedNode& q : part.qualified_nodes) {
    Element& element = part.elements[q.element];
    std::int32_t inst = find_instance(model, q.instance_key, q.instance_display, q.loc, sink);
    if (inst < 0) {
      element.nodes[q.slot] = kGround;
      continue;
    }
    const Instance& instance = model.instances[inst];
    std::int32_t found = model.parts[instance.part].node_index.find(q.label);
    if (found == LabelIndex::kMissing) {
      sink.report(
          DiagCode::undefined_node, q.loc,
          fmt::format("node {} is not defined in instance '{}'", q.label, q.instance_display));
      element.nodes[q.slot] = kGround;
      continue;
    }
    element.nodes[q.slot] = instance.node_offset + found;
  }
  part.qualified_nodes.clear();
}

// The global node and element arrays of an assembly: each instance's copy of its part, placed,
// with element connectivity shifted to global node indices.
void gather_instances(Model& model, std::int32_t nodes, std::int32_t elements) {
  model.nodes.clear();
  model.elements.clear();
  model.nodes.reserve(static_cast<std::size_t>(nodes));
  model.elements.reserve(static_cast<std::size_t>(elements));
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(model.instances.size()); ++i) {
    const Instance& instance = model.instances[i];
    const Part& part = model.parts[instance.part];
    const bool placed = i != 0;
    for (Node node : part.nodes) {
      node.instance = i;
      if (placed) node.x = instance.place(node.x);
      model.nodes.push_back(node);
    }
    for (Element element : part.elements) {
      element.instance = i;
      if (placed) {
        for (std::int32_t& n : element.nodes) {
          if (n != kGround) n += instance.node_offset;
        }
      }
      model.elements.push_back(element);
    }
  }
}

}  // namespace

void resolve_geometry(Model& model, DiagnosticSink& sink) {
  // Offsets of every instance in the global arrays: the root first, then instances 1…
  std::int32_t nodes = 0, elements = 0;
  for (Instance& instance : model.instances) {
    instance.node_offset = nodes;
    instance.element_offset = elements;
    nodes += static_cast<std::int32_t>(model.parts[instance.part].nodes.size());
    elements += static_cast<std::int32_t>(model.parts[instance.part].elements.size());
  }
  for (std::int32_t p = 1; p < static_cast<std::int32_t>(model.parts.size()); ++p) {
    resolve_element_nodes(model, p, sink);
    replay_set_operations(model, p, sink);
  }
  resolve_element_nodes(model, 0, sink);

  if (model.instances.size() == 1) {
    // A flat deck: the root part's arrays are the global arrays (no copy, and no second buffer
    // of the size of the model at the peak).
    model.nodes = std::move(model.parts[0].nodes);
    model.elements = std::move(model.parts[0].elements);
  } else {
    gather_instances(model, nodes, elements);
  }
  // Root-part sets may name instance members, so they are replayed last.
  replay_set_operations(model, 0, sink);
  for (const Element& element : model.elements) {
    if (element.type == ElementType::Conn2D2) model.dimension = 2;
  }
  // The root part's node and element data are now in the global arrays; keep the root part's
  // label maps (they index the same positions, since the root instance comes first).
}

}  // namespace clinch
