// f(i) for each set bit i of a mask, lowest first: the grouped returns walk groups and
// components this way.
#pragma once

#include <bit>

namespace clinch {

template <typename F>
[[gnu::always_inline]] inline void for_each_bit(unsigned mask, F&& f) {
  while (mask) {
    f(std::countr_zero(mask));
    mask &= mask - 1;
  }
}

}  // namespace clinch
