// The contact-force measure N(f) of a friction definition (friction.md §2.2): the force of one
// component (CONTACT FORCE=k), a derived component (CONTACT FORCE=name), the Euclidean norm of
// the constraint forces of a predefined type (SLOT: f2 and f3; SLIDE-PLANE: f1, §2.3), or none.
// The friction law takes g = |N| with gradient sgn(N)·∇N, 0 where N = 0 (§4.2).
#pragma once

#include <optional>

#include "base/small_types.hpp"
#include "src/behavior/behavior.hpp"
#include "src/behavior/potential/derived_component.hpp"

namespace clinch {

class ContactForceMeasure {
 public:
  static ContactForceMeasure none() { return {}; }
  static ContactForceMeasure component(int k);
  static ContactForceMeasure derived(DerivedComponent g);
  static ContactForceMeasure norm(ComponentMask components);

  bool present() const { return kind_ != Kind::None; }
  // N(f) and, when `gradient` is not null, ∂N/∂f.
  double evaluate(const Vector6& f, Vector6* gradient) const;

 private:
  enum class Kind { None, Component, Derived, Norm };
  Kind kind_ = Kind::None;
  int slot_ = 0;
  ComponentMask components_ = 0;
  std::optional<DerivedComponent> derived_;
};

}  // namespace clinch
