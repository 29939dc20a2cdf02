#include "src/behavior/friction/contact_force_measure.hpp"

#include <cmath>
#include <utility>

namespace clinch {

ContactForceMeasure ContactForceMeasure::component(int k) {
  ContactForceMeasure m;
  m.kind_ = Kind::Component;
  m.slot_ = k - 1;
  return m;
}

ContactForceMeasure ContactForceMeasure::derived(DerivedComponent g) {
  ContactForceMeasure m;
  m.kind_ = Kind::Derived;
  m.derived_ = std::move(g);
  return m;
}

ContactForceMeasure ContactForceMeasure::norm(ComponentMask components) {
  ContactForceMeasure m;
  m.kind_ = Kind::Norm;
  m.components_ = components;
  return m;
}

double ContactForceMeasure::evaluate(const Vector6& f, Vector6* gradient) const {
  if (gradient) gradient->setZero();
  switch (kind_) {
    case Kind::None:
      return 0.0;
    case Kind::Component:
      if (gradient) (*gradient)[slot_] = 1.0;
      return f[slot_];
    case Kind::Derived:
      return derived_->evaluate(f, gradient, nullptr);
    case Kind::Norm: {
      const Vector6 masked = f.cwiseProduct(mask_vector(components_));
      const double n = masked.norm();
      // DCP §1.4 subgradient convention: 0 at the kink.
      if (gradient && n > 0) *gradient = masked / n;
      return n;
    }
  }
  return 0.0;
}

}  // namespace clinch
