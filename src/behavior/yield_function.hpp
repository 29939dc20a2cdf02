// The size of an admissible force set as a function of its accumulated measure: the yield size
// F_y(ū) of a plasticity (behaviors.md §6.1) or the friction capacity F_lim(γ) of a friction
// definition (friction.md §4.1). The return mappings evaluate it at every local iteration and
// take it by reference, so plasticity and friction share one set of returns.
#pragma once

#include <concepts>

namespace clinch {

struct YieldSample {
  double value = 0;  // F_y(ū)
  double slope = 0;  // h = dF_y/dū (the right-hand segment at a table breakpoint)
};

// A non-owning reference to any object with `YieldSample at(double) const`. The object must
// outlive the reference (the returns use it only during the call).
class YieldFunction {
 public:
  YieldFunction() = default;
  template <typename Law>
    requires(!std::same_as<Law, YieldFunction>)
  YieldFunction(const Law& law)  // NOLINT(google-explicit-constructor): a view, like std::span
      : object_(&law), at_([](const void* object, double x) {
          return static_cast<const Law*>(object)->at(x);
        }) {}

  YieldSample at(double x) const { return at_(object_, x); }

 private:
  const void* object_ = nullptr;
  YieldSample (*at_)(const void*, double) = nullptr;
};

}  // namespace clinch
