#include "parser/reader/deck_structure.hpp"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace clinch {

bool DeckStructure::check_level(const KeywordSpec& spec, const KeywordLine& line) {
  const std::string kw = fmt::format("*{}", spec.name);
  const ReaderPosition& p = position_;
  auto wrong_level = [&](std::string message) {
    sink_.report(DiagCode::wrong_level, line.loc, std::move(message));
    return false;
  };
  if (spec.behavior_suboption && !p.in_behavior) {
    if (spec.unsupported_outside_behavior) {
      sink_.report(DiagCode::unsupported_keyword, line.loc,
                   fmt::format("keyword '{}' outside a *CONNECTOR BEHAVIOR belongs to surface "
                               "contact, which is not supported by clinch",
                               kw));
      return false;
    }
    return wrong_level(
        fmt::format("'{}' must follow *CONNECTOR BEHAVIOR (it is one of its "
                    "sub-options)",
                    kw));
  }
  if (spec.material_suboption && !p.in_material) {
    return wrong_level(
        fmt::format("'{}' must follow *MATERIAL (it is one of its sub-options)", kw));
  }
  if (spec.coupling_suboption && !p.in_coupling) {
    return wrong_level(fmt::format("'{}' must follow *COUPLING right after its line", kw));
  }
  if (p.in_instance && spec.name != "END INSTANCE" && spec.level != KeywordLevel::Anywhere) {
    sink_.report(DiagCode::unsupported_keyword, line.loc,
                 fmt::format("'{}' inside *INSTANCE: definitions inside an instance are not "
                             "supported",
                             kw));
    return false;
  }
  switch (spec.level) {
    case KeywordLevel::Anywhere:
    case KeywordLevel::Block:
      return true;
    case KeywordLevel::History:
      if (!p.in_step) {
        sink_.report(DiagCode::history_data_outside_step, line.loc,
                     fmt::format("'{}' is history data and must be inside a *STEP", kw));
        return false;
      }
      return true;
    case KeywordLevel::Model:
    case KeywordLevel::ModelGeometry:
    case KeywordLevel::ModelOrHistory:
      break;
  }
  if (p.after_first_step && spec.level != KeywordLevel::ModelOrHistory) {
    sink_.report(DiagCode::model_data_in_step, line.loc,
                 fmt::format("'{}' is model data and cannot appear after the first *STEP", kw));
    return false;
  }
  if (p.after_first_step && !p.in_step) {
    sink_.report(DiagCode::history_data_outside_step, line.loc,
                 fmt::format("'{}' after the first *STEP must be inside a *STEP", kw));
    return false;
  }
  if (p.in_step) return true;
  if (spec.level == KeywordLevel::ModelGeometry) {
    if (model_.part_assembly && p.part == 0 && !p.in_assembly) {
      return wrong_level(
          fmt::format("'{}' must be inside a *PART or the *ASSEMBLY in a deck "
                      "that uses parts",
                      kw));
    }
    return true;
  }
  if (p.part != 0) {
    return wrong_level(
        fmt::format("'{}' cannot appear inside *PART '{}'", kw, model_.parts[p.part].name.display));
  }
  if (p.in_assembly) {
    return wrong_level(fmt::format("'{}' cannot appear inside *ASSEMBLY", kw));
  }
  return true;
}

// Structure bookkeeping that must happen even when the block's parameters are bad, so that
// later keywords are judged at the right level (input-syntax.md §7.2, §8).
bool DeckStructure::enter(const KeywordSpec& spec, const KeywordLine& line,
                          const ParamSet& params) {
  ReaderPosition& p = position_;
  const std::string_view n = spec.name;
  if (n == "CONNECTOR BEHAVIOR") {
    p.in_behavior = true;
    p.behavior_loc = line.loc;
  } else if (n == "MATERIAL") {
    p.in_material = true;
  } else if (n == "COUPLING") {
    p.in_coupling = true;
  } else if (n == "STEP") {
    if (p.in_step) {
      sink_.report(DiagCode::missing_end_step, open_step_loc_,
                   "step has no *END STEP before the next *STEP");
    }
    p.in_step = true;
    p.after_first_step = true;
    ++p.step;
    open_step_loc_ = line.loc;
    if (p.part != 0 || p.in_assembly) {
      sink_.report(DiagCode::unbalanced_block, line.loc,
                   p.part != 0 ? "*STEP inside a *PART (missing *END PART)"
                               : "*STEP inside the *ASSEMBLY (missing *END ASSEMBLY)");
      p.part = 0;
      p.in_assembly = false;
      p.in_instance = false;
    }
  } else if (n == "PART") {
    if (p.part != 0) {
      sink_.report(DiagCode::unbalanced_block, line.loc,
                   "*PART inside another *PART (parts cannot nest; missing *END PART?)");
    } else if (p.in_assembly || assembly_seen_) {
      sink_.report(DiagCode::part_after_assembly, line.loc,
                   "*PART appears after *ASSEMBLY; parts must be defined before the assembly");
    }
    p.part = 0;
    const Field* name_field = params.value("NAME");
    BlockContext ctx(line, spec, params, model_, position_, sink_, sources_);
    std::optional<Name> name = name_field ? ctx.name(*name_field, "NAME") : std::nullopt;
    if (!name)
      name = Name{"__UNNAMED" + std::to_string(model_.parts.size()), "(unnamed)", line.loc};
    auto [it, inserted] =
        model_.part_by_key.try_emplace(name->key, static_cast<std::int32_t>(model_.parts.size()));
    if (!inserted) {
      sink_
          .report(DiagCode::duplicate_name, name->loc,
                  fmt::format("part '{}' is already defined", name->display))
          .notes.push_back({model_.parts[it->second].loc, "previous definition is here"});
    }
    Part part;
    part.name = *name;
    part.loc = line.loc;
    model_.parts.push_back(std::move(part));
    p.part = static_cast<std::int32_t>(model_.parts.size() - 1);
  } else if (n == "END PART") {
    if (p.part == 0) {
      sink_.report(DiagCode::unbalanced_block, line.loc, "*END PART without *PART");
    }
    p.part = 0;
  } else if (n == "ASSEMBLY") {
    if (assembly_seen_) {
      sink_.report(DiagCode::unbalanced_block, line.loc, "a deck has at most one *ASSEMBLY");
    } else if (p.part != 0) {
      sink_.report(DiagCode::unbalanced_block, line.loc, "*ASSEMBLY inside *PART");
      p.part = 0;
    }
    assembly_seen_ = true;
    p.in_assembly = true;
    assembly_loc_ = line.loc;
  } else if (n == "END ASSEMBLY") {
    if (!p.in_assembly) {
      sink_.report(DiagCode::unbalanced_block, line.loc, "*END ASSEMBLY without *ASSEMBLY");
    }
    p.in_assembly = false;
    p.in_instance = false;
  } else if (n == "INSTANCE") {
    if (!p.in_assembly) {
      sink_.report(DiagCode::wrong_level, line.loc, "*INSTANCE must be inside the *ASSEMBLY");
      return false;
    }
    p.in_instance = true;
  } else if (n == "END INSTANCE") {
    if (!p.in_instance) {
      sink_.report(DiagCode::unbalanced_block, line.loc, "*END INSTANCE without *INSTANCE");
    }
    p.in_instance = false;
  } else if (n == "END STEP") {
    if (!p.in_step) {
      sink_.report(DiagCode::end_step_without_step, line.loc, "*END STEP without a matching *STEP");
    }
    p.in_step = false;
  }
  return true;
}

void DeckStructure::finish(std::uint32_t main_file) {
  if (position_.in_step) {
    sink_.report(DiagCode::missing_end_step, open_step_loc_, "step has no *END STEP");
  }
  if (position_.part != 0) {
    sink_.report(DiagCode::unbalanced_block, part_loc(), "*PART has no *END PART");
  }
  if (position_.in_assembly) {
    sink_.report(DiagCode::unbalanced_block, assembly_loc(), "*ASSEMBLY has no *END ASSEMBLY");
  }
  if (!position_.after_first_step) {
    sink_.report(DiagCode::no_step, {main_file, 1, 1},
                 "the deck defines no *STEP; nothing to analyse");
  }
}

}  // namespace clinch
