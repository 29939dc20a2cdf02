#include "src/model/label_index.hpp"

namespace clinch {

std::int32_t LabelIndex::insert(std::int32_t label, std::int32_t index) {
  if (dense_mode_) {
    const std::size_t slot = static_cast<std::size_t>(label);
    if (slot >= dense_.size()) {
      if (slot > 2 * count_ + 65536) {
        to_sparse();
        return insert(label, index);
      }
      std::size_t grown = dense_.size() < 1024 ? 1024 : dense_.size();
      while (grown <= slot) grown *= 2;
      dense_.resize(grown, kMissing);
    }
    if (dense_[slot] != kMissing) return dense_[slot];
    dense_[slot] = index;
    ++count_;
    return kMissing;
  }
  auto [it, inserted] = sparse_.emplace(label, index);
  if (!inserted) return it->second;
  ++count_;
  return kMissing;
}

std::int32_t LabelIndex::find(std::int32_t label) const {
  if (dense_mode_) {
    const std::size_t slot = static_cast<std::size_t>(label);
    return slot < dense_.size() ? dense_[slot] : kMissing;
  }
  auto it = sparse_.find(label);
  return it == sparse_.end() ? kMissing : it->second;
}

void LabelIndex::to_sparse() {
  sparse_.reserve(count_);
  for (std::size_t slot = 0; slot < dense_.size(); ++slot) {
    if (dense_[slot] != kMissing) sparse_.emplace(static_cast<std::int32_t>(slot), dense_[slot]);
  }
  dense_.clear();
  dense_.shrink_to_fit();
  dense_mode_ = false;
}

}  // namespace clinch
