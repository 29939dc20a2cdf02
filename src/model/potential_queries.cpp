#include "src/model/potential_queries.hpp"

#include <unordered_set>

namespace clinch {

const char* derived_operator_name(DerivedOperator op) {
  switch (op) {
    case DerivedOperator::Norm: return "NORM";
    case DerivedOperator::MacauleySum: return "MACAULEY SUM";
    case DerivedOperator::Sum: return "SUM";
  }
  return "NORM";
}

const char* derived_type_name(DerivedType type) {
  switch (type) {
    case DerivedType::Sum: return "SUM";
    case DerivedType::Macauley: return "MACAULEY";
    case DerivedType::Norm: return "NORM";
    case DerivedType::Mixed: return "MIXED";
  }
  return "NORM";
}

// §1.5: only T_S → g_S; only T_M → g_M; T_N alone or with T_M → g_N; T_S with T_N/T_M → mixed.
DerivedType classify_terms(const std::vector<const DerivedComponentTerm*>& terms) {
  bool sum = false, macauley = false, norm = false;
  for (const DerivedComponentTerm* t : terms) {
    switch (t->op) {
      case DerivedOperator::Sum: sum = true; break;
      case DerivedOperator::MacauleySum: macauley = true; break;
      case DerivedOperator::Norm: norm = true; break;
    }
  }
  if (sum && (norm || macauley)) return DerivedType::Mixed;
  if (sum) return DerivedType::Sum;
  if (norm) return DerivedType::Norm;
  return DerivedType::Macauley;
}

const char* potential_function_name(PotentialFunction h) {
  switch (h) {
    case PotentialFunction::Abs: return "ABS";
    case PotentialFunction::Macauley: return "MACAULEY";
    case PotentialFunction::None: return "NONE";
  }
  return "ABS";
}

const char* owner_keyword(PotentialOwner::Kind kind) {
  switch (kind) {
    case PotentialOwner::Kind::Plasticity: return "*CONNECTOR PLASTICITY";
    case PotentialOwner::Kind::Friction: return "*CONNECTOR FRICTION";
    case PotentialOwner::Kind::DamageInitiation: return "*CONNECTOR DAMAGE INITIATION";
    case PotentialOwner::Kind::DamageEvolution: return "*CONNECTOR DAMAGE EVOLUTION";
  }
  return "*CONNECTOR PLASTICITY";
}

std::int32_t find_derived_component(const ConnectorBehavior& behavior, std::string_view key) {
  for (std::size_t i = 0; i < behavior.derived_terms.size(); ++i) {
    if (behavior.derived_terms[i].name.key == key) return static_cast<std::int32_t>(i);
  }
  return -1;
}

std::vector<std::int32_t> derived_component_first_terms(const ConnectorBehavior& behavior) {
  std::vector<std::int32_t> first;
  std::unordered_set<std::string> seen;
  for (std::size_t i = 0; i < behavior.derived_terms.size(); ++i) {
    if (seen.insert(behavior.derived_terms[i].name.key).second) {
      first.push_back(static_cast<std::int32_t>(i));
    }
  }
  return first;
}

std::vector<std::int32_t> derived_component_terms(const ConnectorBehavior& behavior,
                                                  std::string_view key) {
  std::vector<std::int32_t> terms;
  for (std::size_t i = 0; i < behavior.derived_terms.size(); ++i) {
    if (behavior.derived_terms[i].name.key == key) terms.push_back(static_cast<std::int32_t>(i));
  }
  return terms;
}

bool is_force_context(DerivedContextKind kind) {
  return kind != DerivedContextKind::DamageMotionPotential;
}

namespace {

DerivedContextKind potential_context(const ConnectorBehavior& behavior,
                                     const PotentialOwner& owner) {
  switch (owner.kind) {
    case PotentialOwner::Kind::Plasticity: return DerivedContextKind::PlasticityPotential;
    case PotentialOwner::Kind::Friction: return DerivedContextKind::FrictionPotential;
    case PotentialOwner::Kind::DamageInitiation:
      // CRITERION=MOTION evaluates the potential on constitutive motions (DCP §2.7 table).
      if (owner.index >= 0 &&
          static_cast<std::size_t>(owner.index) < behavior.damage_initiations.size() &&
          behavior.damage_initiations[static_cast<std::size_t>(owner.index)].criterion ==
              DamageInitiation::Criterion::Motion) {
        return DerivedContextKind::DamageMotionPotential;
      }
      return DerivedContextKind::DamageForcePotential;
    case PotentialOwner::Kind::DamageEvolution:
      // Evolution potentials act on constitutive relative motions (DCP §2.7 table).
      return DerivedContextKind::DamageMotionPotential;
  }
  return DerivedContextKind::PlasticityPotential;
}

}  // namespace

// Owners are stored in deck order, a friction's CONTACT FORCE stands on its keyword line before
// its potential, so walking the owners gives the uses in deck order.
std::vector<DerivedComponentUse> derived_component_uses(const ConnectorBehavior& behavior,
                                                        std::string_view key) {
  std::vector<DerivedComponentUse> uses;
  const auto owner_count = static_cast<std::int32_t>(behavior.potential_owners.size());
  for (std::int32_t o = 0; o < owner_count; ++o) {
    const PotentialOwner& owner = behavior.potential_owners[static_cast<std::size_t>(o)];
    std::int32_t friction = -1;
    if (owner.kind == PotentialOwner::Kind::Friction && owner.index >= 0 &&
        static_cast<std::size_t>(owner.index) < behavior.frictions.size()) {
      friction = owner.index;
      const FrictionDefinition& f = behavior.frictions[static_cast<std::size_t>(owner.index)];
      if (f.contact == FrictionDefinition::Contact::Derived && f.contact_name.key == key) {
        uses.push_back({DerivedContextKind::ContactForce, f.contact_name.loc, o, friction, -1, -1});
      }
    }
    if (owner.potential < 0 ||
        static_cast<std::size_t>(owner.potential) >= behavior.potentials.size()) {
      continue;
    }
    const Potential& p = behavior.potentials[static_cast<std::size_t>(owner.potential)];
    if (p.owner != o) continue;
    for (std::size_t c = 0; c < p.contributions.size(); ++c) {
      const PotentialContribution& pc = p.contributions[c];
      if (pc.derived && pc.derived_name.key == key) {
        uses.push_back({potential_context(behavior, owner), pc.loc, o, friction, owner.potential,
                        static_cast<std::int32_t>(c)});
      }
    }
  }
  return uses;
}

std::optional<DerivedComponentUse> first_derived_context(const ConnectorBehavior& behavior,
                                                         std::string_view key, bool force) {
  for (const DerivedComponentUse& use : derived_component_uses(behavior, key)) {
    if (is_force_context(use.kind) == force) return use;
  }
  return std::nullopt;
}

bool derived_has_force_context(const ConnectorBehavior& behavior, std::string_view key) {
  return first_derived_context(behavior, key, true).has_value();
}

bool derived_has_motion_context(const ConnectorBehavior& behavior, std::string_view key) {
  return first_derived_context(behavior, key, false).has_value();
}

std::vector<std::int32_t> derived_output_terms(const ConnectorBehavior& behavior, bool force) {
  std::vector<std::int32_t> terms;
  for (std::int32_t t : derived_component_first_terms(behavior)) {
    const std::string& key = behavior.derived_terms[static_cast<std::size_t>(t)].name.key;
    if (first_derived_context(behavior, key, force)) terms.push_back(t);
  }
  return terms;
}

std::size_t derived_context_count(const ConnectorBehavior& behavior, std::string_view key,
                                  bool force) {
  // Two contributions of one potential are one context; a friction's CONTACT FORCE and its
  // potential are two.
  std::size_t count = 0;
  std::int32_t last_owner = -1;
  bool last_contact = false;
  for (const DerivedComponentUse& use : derived_component_uses(behavior, key)) {
    if (is_force_context(use.kind) != force) continue;
    const bool contact = use.kind == DerivedContextKind::ContactForce;
    if (count > 0 && use.owner == last_owner && contact == last_contact) continue;
    ++count;
    last_owner = use.owner;
    last_contact = contact;
  }
  return count;
}

}  // namespace clinch
