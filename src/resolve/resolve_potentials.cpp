// Resolve of derived components, potentials and connector friction
// (derived-components-and-potentials.md §1.5–§2.7, friction.md §2, §8): name resolution inside
// each behaviour block, classification of derived components (g_S/g_M/g_N/mixed) and of
// potential contributions (P_N/P_S), the plasticity/friction rules, component availability
// against every section that uses the behaviour, placement (potential-missing), predefined
// friction per connection type, and unused derived components. Runs after resolve_sections,
// which fills ConnectorSection::behavior_index, available and constrained.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "base/diagnostic.hpp"
#include "base/suggest.hpp"
#include "src/model/default_stick_stiffness.hpp"
#include "src/model/model.hpp"
#include "src/model/potential_queries.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

std::string component_list(ComponentMask mask) {
  std::string out;
  for (int i = 1; i <= 6; ++i) {
    if (!has_component(mask, i)) continue;
    if (!out.empty()) out += ", ";
    out += std::to_string(i);
  }
  return out.empty() ? "none" : out;
}

std::string join_types(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) {
    if (!out.empty()) out += ", ";
    out += n;
  }
  return out;
}

// Type names compared without regard to case and to the interchangeable ' ', '_', '-'
// (keywords.md §4).
std::string type_key(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (c == ' ' || c == '_' || c == '-') continue;
    out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  }
  return out;
}

std::string format_number(double v) { return fmt::format("{}", v); }

// A section that uses the behaviour being checked.
struct SectionUse {
  const ConnectorSection* section = nullptr;
  bool two_d = false;  // CONN2D2 elements: components 3, 4, 5 do not exist
  std::string type;    // "SLOT", "CARTESIAN, CARDAN"
};

enum class PredefinedSupport { Supported, Unsupported, Unavailable };

// friction.md §2.3, connection-types.md §2.4: PREDEFINED runs for SLOT and SLIDE-PLANE alone or
// with a rotational type that does not make them an assembled type. The assembled types with
// predefined friction (and their basic-pair equivalents) are refused: friction.md marks their
// contact-force formulas and data-line layouts not confirmed, and the stored manual pages cut off
// before them (docs/decisions.md, "Friction"). The others have none.
PredefinedSupport predefined_support(const ConnectorSection& section, ComponentMask* j) {
  std::vector<std::string> keys;
  for (const std::string& n : section.type_names) keys.push_back(type_key(n));
  auto has = [&](std::string_view k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
  };
  for (std::string_view assembled :
       {"CYLINDRICAL", "TRANSLATOR", "HINGE", "PLANAR", "UJOINT", "SLIPRING"}) {
    if (has(assembled)) return PredefinedSupport::Unsupported;
  }
  if (has("JOIN") && (has("REVOLUTE") || has("UNIVERSAL"))) return PredefinedSupport::Unsupported;
  if (has("SLOT")) {
    if (has("REVOLUTE") || has("ALIGN")) return PredefinedSupport::Unsupported;
    *j = component_bit(1);
    return PredefinedSupport::Supported;
  }
  if (has("SLIDEPLANE")) {
    if (has("REVOLUTE")) return PredefinedSupport::Unsupported;
    *j = static_cast<ComponentMask>(component_bit(2) | component_bit(3));
    return PredefinedSupport::Supported;
  }
  return PredefinedSupport::Unavailable;
}

class BehaviorChecker {
 public:
  BehaviorChecker(Model& model, DiagnosticSink& sink, std::size_t index)
      : sink_(sink), b_(model.behaviors.behaviors[index]) {
    for (const ConnectorSection& s : model.sections.connector_sections) {
      if (s.behavior_index != static_cast<std::int32_t>(index) || !s.valid) continue;
      SectionUse use;
      use.section = &s;
      use.type = join_types(s.type_names);
      for (std::int32_t e : s.elements) {
        if (e >= 0 && static_cast<std::size_t>(e) < model.elements.size() &&
            model.elements[static_cast<std::size_t>(e)].type == ElementType::Conn2D2) {
          use.two_d = true;
        }
      }
      sections_.push_back(std::move(use));
    }
  }

  void run() {
    group_terms();
    check_two_d_components();
    for (std::size_t p = 0; p < b_.potentials.size(); ++p) check_potential(p);
    for (std::size_t f = 0; f < b_.frictions.size(); ++f) check_friction(f);
    check_missing_potentials();
    warn_unused();
  }

 private:
  // --- derived components -------------------------------------------------------------------

  void group_terms() {
    for (std::size_t i = 0; i < b_.derived_terms.size(); ++i) {
      const std::string& key = b_.derived_terms[i].name.key;
      auto [it, inserted] = terms_.try_emplace(key);
      if (inserted) first_terms_.push_back(static_cast<std::int32_t>(i));
      it->second.push_back(static_cast<std::int32_t>(i));
    }
    for (auto& [key, indices] : terms_) {
      std::vector<const DerivedComponentTerm*> list;
      for (std::int32_t i : indices) list.push_back(&term(i));
      const DerivedType type = classify_terms(list);
      for (std::int32_t i : indices)
        b_.derived_terms[static_cast<std::size_t>(i)].component_type = type;
    }
  }

  DerivedComponentTerm& term(std::int32_t i) {
    return b_.derived_terms[static_cast<std::size_t>(i)];
  }

  const std::vector<std::int32_t>* terms_of(const std::string& key) const {
    auto it = terms_.find(key);
    return it == terms_.end() ? nullptr : &it->second;
  }

  bool all_complete(const std::vector<std::int32_t>& indices) {
    for (std::int32_t i : indices) {
      if (!term(i).complete) return false;
    }
    return true;
  }

  // DCP §1.6: on CONN2D2 only components 1, 2 and 6 exist.
  void check_two_d_components() {
    const SectionUse* two_d = nullptr;
    for (const SectionUse& s : sections_) {
      if (s.two_d) {
        two_d = &s;
        break;
      }
    }
    if (!two_d) return;
    for (std::size_t t = 0; t < b_.derived_terms.size(); ++t) {
      const DerivedComponentTerm& dc = b_.derived_terms[t];
      for (std::size_t j = 0; j < dc.components.size() && j < dc.component_locs.size(); ++j) {
        const int k = dc.components[j];
        if (k < 3 || k > 5) continue;
        reported_fields_.insert({static_cast<std::int32_t>(t), static_cast<std::int32_t>(j)});
        Diagnostic& d = sink_.report(
            DiagCode::dc_bad_component, dc.component_locs[j],
            fmt::format("derived component '{}' lists component {}, which does not exist on "
                        "CONN2D2 elements (components 1, 2, 6)",
                        dc.name.display, k));
        d.notes.push_back({two_d->section->behavior.loc,
                           "the behavior is used by this *CONNECTOR SECTION of CONN2D2 elements"});
      }
    }
  }

  // DCP §1.5 rules 1–2 for one use of a derived component by plasticity or friction.
  void check_derived_rules(const std::vector<std::int32_t>& indices, const char* user,
                           SourceLoc use_loc, const std::string& use_note) {
    if (indices.empty() || !all_complete(indices)) return;  // its own errors come first
    const DerivedComponentTerm& first = term(indices.front());
    const DerivedType type = first.component_type;
    if (type == DerivedType::Mixed) {
      const bool first_is_sum = first.op == DerivedOperator::Sum;
      for (std::int32_t i : indices) {
        const DerivedComponentTerm& t = term(i);
        if ((t.op == DerivedOperator::Sum) == first_is_sum) continue;
        Diagnostic& d = sink_.report(
            DiagCode::dc_mixed_type, t.operator_loc.valid() ? t.operator_loc : t.loc,
            fmt::format("derived component '{}' mixes a {} term with {} terms and cannot be used "
                        "by {}",
                        first.name.display, derived_operator_name(t.op),
                        derived_operator_name(first.op), user));
        d.notes.push_back(
            {first.loc, fmt::format("first term ({}) is here", derived_operator_name(first.op))});
        d.notes.push_back({use_loc, use_note});
        return;
      }
      return;
    }
    if (type == DerivedType::Sum) return;  // g_S: any sign
    for (std::int32_t i : indices) {
      const DerivedComponentTerm& t = term(i);
      if (t.sign > 0) continue;
      Diagnostic& d = sink_.report(
          DiagCode::dc_negative_norm_term, t.sign_loc.valid() ? t.sign_loc : t.loc,
          fmt::format("derived component '{}' has a {} term with SIGN=NEGATIVE; terms of a {} "
                      "derived component used by {} must be positive",
                      first.name.display, derived_operator_name(t.op),
                      type == DerivedType::Macauley ? "Macaulay-type" : "norm-type", user));
      d.notes.push_back({use_loc, use_note});
    }
  }

  // Components a derived component lists must be available in every section that uses the
  // behaviour (DCP §1.5 rule 3); a CONTACT FORCE may also list constrained components.
  void check_derived_availability(const std::vector<std::int32_t>& indices, bool allow_constrained,
                                  SourceLoc use_loc, const std::string& use_note) {
    for (const SectionUse& s : sections_) {
      const ComponentMask allowed = static_cast<ComponentMask>(
          s.section->available | (allow_constrained ? s.section->constrained : 0));
      for (std::int32_t i : indices) {
        const DerivedComponentTerm& t = term(i);
        for (std::size_t j = 0; j < t.components.size() && j < t.component_locs.size(); ++j) {
          const int k = t.components[j];
          if (has_component(allowed, k)) continue;
          if (!reported_fields_.insert({i, static_cast<std::int32_t>(j)}).second) continue;
          Diagnostic& d = sink_.report(
              DiagCode::dc_unavailable_component, t.component_locs[j],
              allow_constrained
                  ? fmt::format("derived component '{}' lists component {}, which connection "
                                "type {} neither makes available nor constrains (available: {}; "
                                "constrained: {})",
                                t.name.display, k, s.type, component_list(s.section->available),
                                component_list(s.section->constrained))
                  : fmt::format("derived component '{}' lists component {}, which is not "
                                "available for connection type {} (available: {}); a derived "
                                "component used in a potential may list only available "
                                "components",
                                t.name.display, k, s.type, component_list(s.section->available)));
          d.notes.push_back({use_loc, use_note});
          d.notes.push_back(
              {s.section->behavior.loc,
               fmt::format("connection type {} comes from this *CONNECTOR SECTION", s.type)});
        }
      }
    }
  }

  // E0506 with a did-you-mean note (edit distance ≤ 2, case-insensitive) and the names the
  // block defines (DCP §1.6).
  void report_undefined(SourceLoc loc, std::string message, bool suggestion_at_definition,
                        const std::string& name) {
    Diagnostic& d = sink_.report(DiagCode::undefined_derived_component, loc, std::move(message));
    std::int32_t best = -1;
    std::size_t best_distance = 3;
    for (std::int32_t i : first_terms_) {
      const std::size_t distance = folded_edit_distance(name, term(i).name.display);
      if (distance <= 2 && distance < best_distance) {
        best = i;
        best_distance = distance;
      }
    }
    if (best >= 0) {
      d.notes.push_back({suggestion_at_definition ? term(best).loc : loc,
                         fmt::format("did you mean '{}'?", term(best).name.display)});
    }
    if (first_terms_.empty()) {
      d.notes.push_back({SourceLoc{}, fmt::format("behavior '{}' defines no *CONNECTOR DERIVED "
                                                  "COMPONENT",
                                                  b_.name.display)});
    } else {
      std::string names;
      for (std::int32_t i : first_terms_) {
        if (!names.empty()) names += ", ";
        names += term(i).name.display;
      }
      d.notes.push_back({SourceLoc{}, fmt::format("derived components defined in behavior '{}': {}",
                                                  b_.name.display, names)});
    }
  }

  // --- potentials ---------------------------------------------------------------------------

  const PotentialOwner* owner_of(const Potential& p) const {
    if (p.owner < 0 || static_cast<std::size_t>(p.owner) >= b_.potential_owners.size()) {
      return nullptr;
    }
    return &b_.potential_owners[static_cast<std::size_t>(p.owner)];
  }

  // DCP §2.6: P_N if H is ABS or MACAULEY or E_i is a g_N/g_M derived component; P_S if H = NONE
  // on an intrinsic component or a g_S derived component. Unknown for a mixed derived component.
  void classify(PotentialContribution& c) {
    c.type_known = false;
    if (c.function != PotentialFunction::None) {
      c.type = ContributionType::Norm;
      c.type_known = true;
      return;
    }
    if (!c.derived) {
      c.type = ContributionType::Sum;
      c.type_known = true;
      return;
    }
    if (c.first_term < 0) return;
    switch (term(c.first_term).component_type) {
      case DerivedType::Sum:
        c.type = ContributionType::Sum;
        c.type_known = true;
        break;
      case DerivedType::Macauley:
      case DerivedType::Norm:
        c.type = ContributionType::Norm;
        c.type_known = true;
        break;
      case DerivedType::Mixed:
        break;
    }
  }

  std::string describe_contribution(const PotentialContribution& c) {
    const std::string source = c.derived
                                   ? fmt::format("derived component '{}'", c.derived_name.display)
                                   : fmt::format("component {}", c.component);
    if (c.function != PotentialFunction::None) {
      return fmt::format("H={} on {}", potential_function_name(c.function), source);
    }
    if (c.derived && c.first_term >= 0) {
      return fmt::format("H=NONE on {} of type {}", source,
                         derived_type_name(term(c.first_term).component_type));
    }
    return fmt::format("H=NONE on {}", source);
  }

  static const char* type_word(ContributionType t) {
    return t == ContributionType::Norm ? "norm-type" : "sum-type";
  }

  void check_potential(std::size_t index) {
    Potential& p = b_.potentials[index];
    const PotentialOwner* owner = owner_of(p);
    const bool strict = owner && (owner->kind == PotentialOwner::Kind::Plasticity ||
                                  owner->kind == PotentialOwner::Kind::Friction);
    const char* user = owner ? owner_keyword(owner->kind) : "*CONNECTOR POTENTIAL";

    // Resolve names; classify.
    for (PotentialContribution& c : p.contributions) {
      if (!c.derived || c.derived_name.empty()) {
        classify(c);
        continue;
      }
      const auto* indices = terms_of(c.derived_name.key);
      if (!indices) {
        report_undefined(c.source_loc,
                         fmt::format("unknown derived component '{}'", c.derived_name.display),
                         false, c.derived_name.display);
        continue;
      }
      c.first_term = indices->front();
      for (std::int32_t i : *indices) term(i).referenced = true;
      classify(c);
    }

    // Availability (DCP §2.2, §1.5 rule 3), in every owner context.
    for (PotentialContribution& c : p.contributions) {
      if (!c.derived && c.component >= 1) {
        for (const SectionUse& s : sections_) {
          if (has_component(s.section->available, c.component)) continue;
          Diagnostic& d = sink_.report(
              DiagCode::potential_unavailable_component, c.source_loc,
              fmt::format("component {} is not available for connection type {} (available: {})",
                          c.component, s.type, component_list(s.section->available)));
          d.notes.push_back(
              {s.section->behavior.loc,
               fmt::format("connection type {} comes from this *CONNECTOR SECTION", s.type)});
          break;
        }
      } else if (c.derived && c.first_term >= 0) {
        check_derived_availability(*terms_of(c.derived_name.key), false, c.loc,
                                   "used by the potential contribution here");
      }
    }

    // Common type, stored for the return mappings (DCP §5).
    std::int32_t first_known = -1;
    p.mixed = false;
    for (std::size_t i = 0; i < p.contributions.size(); ++i) {
      const PotentialContribution& c = p.contributions[i];
      if (!c.valid || !c.type_known) continue;
      if (first_known < 0) {
        first_known = static_cast<std::int32_t>(i);
        p.type = c.type;
      } else if (c.type != p.type) {
        p.mixed = true;
      }
    }
    if (!strict) return;

    // Rule 1: one contribution type.
    if (p.mixed) {
      const PotentialContribution& ref = p.contributions[static_cast<std::size_t>(first_known)];
      for (std::size_t i = 0; i < p.contributions.size(); ++i) {
        const PotentialContribution& c = p.contributions[i];
        if (!c.valid || !c.type_known || c.type == ref.type) continue;
        Diagnostic& d = sink_.report(
            DiagCode::potential_mixed_type, c.loc,
            fmt::format("contribution {} of the potential of {} is {} ({}), but contribution {} "
                        "is {}; a plasticity or friction potential cannot mix them",
                        i + 1, user, type_word(c.type), describe_contribution(c), first_known + 1,
                        type_word(ref.type)));
        d.notes.push_back({ref.loc, fmt::format("contribution {} ({}) is here", first_known + 1,
                                                type_word(ref.type))});
      }
    }
    // Rule 2: norm-type contributions have s = +1.
    for (std::size_t i = 0; i < p.contributions.size(); ++i) {
      const PotentialContribution& c = p.contributions[i];
      if (!c.valid || !c.type_known || c.type != ContributionType::Norm || c.sign > 0) continue;
      sink_.report(DiagCode::potential_negative_norm_sign, c.sign_loc.valid() ? c.sign_loc : c.loc,
                   fmt::format("contribution {} is norm-type ({}) and has sign s=-1; in the "
                               "potential of {} norm-type contributions must have s=+1",
                               i + 1, describe_contribution(c), user));
    }
    // Rule 3: SUM needs β ≥ 1 and every α = β.
    if (p.op == PotentialOperator::Sum) {
      const std::string beta = p.exponent_given ? p.exponent_text : format_number(p.exponent);
      if (p.exponent < 1.0 && p.exponent_given) {
        sink_.report(DiagCode::potential_exponent_rule, p.exponent_loc,
                     fmt::format("EXPONENT={} is less than 1; in a plasticity or friction "
                                 "potential beta must be at least 1",
                                 beta));
      }
      for (const PotentialContribution& c : p.contributions) {
        if (!c.valid || !c.alpha_given || c.alpha == p.exponent) continue;
        sink_.report(DiagCode::potential_exponent_rule, c.alpha_loc,
                     fmt::format("exponent alpha={} differs from {}EXPONENT={}; in a plasticity "
                                 "or friction potential every alpha must equal beta",
                                 c.alpha_text, p.exponent_given ? "" : "the default ", beta));
      }
    }
    // Rule 4: the derived components used obey DCP §1.5.
    for (const PotentialContribution& c : p.contributions) {
      if (!c.derived || c.first_term < 0) continue;
      check_derived_rules(*terms_of(c.derived_name.key), user, c.loc,
                          "used by the potential contribution here");
    }
  }

  // Components a potential involves (DCP §2.8): named intrinsic components and every component
  // of the derived components it uses.
  ComponentMask potential_components(const Potential& p) {
    ComponentMask mask = 0;
    for (const PotentialContribution& c : p.contributions) {
      if (!c.derived && c.component >= 1 && c.component <= 6) mask |= component_bit(c.component);
      if (c.derived && c.first_term >= 0) {
        for (std::int32_t i : *terms_of(c.derived_name.key)) {
          for (int k : term(i).components) {
            if (k >= 1 && k <= 6) mask |= component_bit(k);
          }
        }
      }
    }
    return mask;
  }

  void check_missing_potentials() {
    for (const PotentialOwner& owner : b_.potential_owners) {
      if (!owner.requires_potential) continue;
      if (owner.potential >= 0 &&
          static_cast<std::size_t>(owner.potential) < b_.potentials.size()) {
        continue;
      }
      std::string why;
      switch (owner.kind) {
        case PotentialOwner::Kind::Plasticity:
          why =
              "*CONNECTOR PLASTICITY without COMPONENT= (coupled plasticity) needs a "
              "*CONNECTOR POTENTIAL after it";
          break;
        case PotentialOwner::Kind::Friction:
          why =
              "*CONNECTOR FRICTION without COMPONENT= or PREDEFINED (coupled friction) needs a "
              "*CONNECTOR POTENTIAL after it";
          break;
        case PotentialOwner::Kind::DamageInitiation:
          why =
              "*CONNECTOR DAMAGE INITIATION without COMPONENT= needs a *CONNECTOR POTENTIAL "
              "after it";
          break;
        case PotentialOwner::Kind::DamageEvolution:
          why = "*CONNECTOR DAMAGE EVOLUTION needs a *CONNECTOR POTENTIAL after it";
          break;
      }
      sink_.report(DiagCode::potential_missing, owner.loc, why);
    }
  }

  // --- friction -----------------------------------------------------------------------------

  void check_friction(std::size_t index) {
    FrictionDefinition& f = b_.frictions[index];
    ComponentMask j = 0;        // friction components J (friction.md §2.1)
    ComponentMask contact = 0;  // components of the contact measure N

    if (f.predefined) {
      check_predefined(f, j);
    } else if (f.component >= 1) {
      j = component_bit(f.component);
      for (const SectionUse& s : sections_) {
        if (has_component(s.section->available, f.component)) continue;
        // behaviors.md §1.1: at the BEHAVIOR= value of the section, note at the option.
        Diagnostic& d =
            sink_.report(DiagCode::component_not_available, s.section->behavior.loc,
                         fmt::format("component {} of connector behavior '{}' is not available for "
                                     "connection type {} (available: {})",
                                     f.component, b_.name.display, s.type,
                                     component_list(s.section->available)));
        d.notes.push_back(
            {f.component_loc, fmt::format("*CONNECTOR FRICTION, COMPONENT={} of behavior '{}' is "
                                          "here",
                                          f.component, b_.name.display)});
      }
    } else if (f.owner >= 0 && static_cast<std::size_t>(f.owner) < b_.potential_owners.size()) {
      const PotentialOwner& owner = b_.potential_owners[static_cast<std::size_t>(f.owner)];
      if (owner.potential >= 0 &&
          static_cast<std::size_t>(owner.potential) < b_.potentials.size()) {
        j = potential_components(b_.potentials[static_cast<std::size_t>(owner.potential)]);
      }
    }

    if (f.contact == FrictionDefinition::Contact::Component) {
      contact = component_bit(f.contact_component);
      for (const SectionUse& s : sections_) {
        const ComponentMask allowed =
            static_cast<ComponentMask>(s.section->available | s.section->constrained);
        if (has_component(allowed, f.contact_component)) continue;
        Diagnostic& d = sink_.report(
            DiagCode::component_not_available, s.section->behavior.loc,
            fmt::format("contact force component {} of connector behavior '{}' is neither "
                        "available nor constrained for connection type {} (available: {}; "
                        "constrained: {})",
                        f.contact_component, b_.name.display, s.type,
                        component_list(s.section->available),
                        component_list(s.section->constrained)));
        d.notes.push_back(
            {f.contact_loc, fmt::format("*CONNECTOR FRICTION, CONTACT FORCE={} of behavior '{}' is "
                                        "here",
                                        f.contact_component, b_.name.display)});
      }
    } else if (f.contact == FrictionDefinition::Contact::Derived) {
      const auto* indices = terms_of(f.contact_name.key);
      if (!indices) {
        report_undefined(f.contact_name.loc,
                         fmt::format("CONTACT FORCE={}: no *CONNECTOR DERIVED COMPONENT of that "
                                     "name in behavior {}",
                                     f.contact_name.display, b_.name.display),
                         true, f.contact_name.display);
      } else {
        for (std::int32_t i : *indices) {
          term(i).referenced = true;
          for (int k : term(i).components) {
            if (k >= 1 && k <= 6) contact |= component_bit(k);
          }
        }
        const std::string note = "used as CONTACT FORCE of the *CONNECTOR FRICTION here";
        check_derived_rules(*indices, "*CONNECTOR FRICTION", f.loc, note);
        check_derived_availability(*indices, true, f.loc, note);
      }
    }

    f.friction_components = j;
    if ((contact & j) != 0) {
      int shared = 0;
      for (int k = 1; k <= 6 && !shared; ++k) {
        if (has_component(static_cast<ComponentMask>(contact & j), k)) shared = k;
      }
      sink_.report(DiagCode::friction_contact_self, f.contact_loc,
                   fmt::format("the contact force measure involves component {}, which is also a "
                               "friction component of this definition; clinch leaves this "
                               "definition's own friction force out of it",
                               shared));
    }
    if (!f.has_law) {
      sink_.report(DiagCode::friction_missing_law, f.loc,
                   "*CONNECTOR FRICTION has no *FRICTION law; add *FRICTION with the friction "
                   "coefficient");
    }
    if (!f.stick_stiffness && !f.stick_stiffness_loc.valid()) report_default_stick_stiffness(f, j);
    // A connector's law stack holds the elastic-plastic law and at most kMaxFrictions friction
    // laws (src/assembly/analysis_plan.hpp).
    if (index == kMaxFrictions) {
      sink_.report(DiagCode::unsupported_option, f.loc,
                   fmt::format("behavior '{}' has more than {} *CONNECTOR FRICTION definitions, "
                               "which this version does not support; combine them",
                               b_.name.display, kMaxFrictions));
    }
  }

  static constexpr std::size_t kMaxFrictions = 5;

  void check_predefined(const FrictionDefinition& f, ComponentMask& j) {
    std::set<std::string> reported;
    for (const SectionUse& s : sections_) {
      ComponentMask section_j = 0;
      const PredefinedSupport support = predefined_support(*s.section, &section_j);
      if (support == PredefinedSupport::Supported) {
        if (j == 0) j = section_j;
        continue;
      }
      if (!reported.insert(s.type).second) continue;
      Diagnostic& d =
          support == PredefinedSupport::Unsupported
              ? sink_.report(DiagCode::unsupported_option, f.loc,
                             fmt::format("predefined friction for connection type {} is not "
                                         "supported: the manual text that gives its contact "
                                         "force and the layout of its geometric data line (pin "
                                         "radius, lengths) could not be found, and clinch does "
                                         "not guess them; define it with COMPONENT= or "
                                         "*CONNECTOR POTENTIAL and CONTACT FORCE= a *CONNECTOR "
                                         "DERIVED COMPONENT that scales the constraint forces",
                                         s.type))
              : sink_.report(DiagCode::friction_predefined_unavailable, f.loc,
                             fmt::format("connection type {} has no predefined friction; use "
                                         "COMPONENT= or a *CONNECTOR POTENTIAL",
                                         s.type));
      d.notes.push_back(
          {s.section->behavior.loc,
           fmt::format("connection type {} comes from this *CONNECTOR SECTION", s.type)});
    }
  }

  // friction.md §5: the run log states the default stick stiffness once per run
  // (default_stick_stiffness_summary); only a value with no elastic stiffness to scale from is
  // worth a warning, since 1e6 in the model's units may be far off (docs/decisions.md).
  void report_default_stick_stiffness(const FrictionDefinition& f, ComponentMask j) {
    const DefaultStickStiffness stiffness = default_stick_stiffness(b_);
    if ((stiffness.fallback & j) == 0) return;
    const std::string values = describe_stick_stiffness(stiffness, j);
    sink_.report(DiagCode::friction_default_stick_stiffness, f.loc,
                 fmt::format("STICK STIFFNESS omitted; using {} (no connector elasticity to "
                             "scale from)",
                             values.empty() ? "1e+06" : values));
  }

  // --- unused -------------------------------------------------------------------------------

  void warn_unused() {
    for (std::int32_t i : first_terms_) {
      bool referenced = false;
      for (std::int32_t t : terms_[term(i).name.key]) referenced = referenced || term(t).referenced;
      if (referenced) continue;
      sink_.report(
          DiagCode::defined_but_unused, term(i).loc,
          fmt::format("derived component '{}' is defined but never used", term(i).name.display));
    }
  }

  DiagnosticSink& sink_;
  ConnectorBehavior& b_;
  std::vector<SectionUse> sections_;
  std::unordered_map<std::string, std::vector<std::int32_t>> terms_;  // name key → terms
  std::vector<std::int32_t> first_terms_;                             // deck order
  std::set<std::pair<std::int32_t, std::int32_t>> reported_fields_;   // (term, field)
};

}  // namespace

void resolve_potentials_and_friction(Model& model, DiagnosticSink& sink) {
  for (std::size_t i = 0; i < model.behaviors.behaviors.size(); ++i) {
    BehaviorChecker(model, sink, i).run();
  }
}

}  // namespace clinch
