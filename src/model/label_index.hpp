// Label → index map for node and element labels. Labels in real decks are mostly dense, so a
// plain array indexed by label is used while that stays small (at most about twice the number
// of entries); a sparse label set switches it to a hash map. This keeps `clinch check` memory
// linear in the deck with a small constant (ARCHITECTURE.md, performance by design).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace clinch {

class LabelIndex {
 public:
  static constexpr std::int32_t kMissing = -1;
  // Inserts label → index. Returns kMissing when inserted, or the existing index otherwise.
  std::int32_t insert(std::int32_t label, std::int32_t index);
  std::int32_t find(std::int32_t label) const;
  std::size_t size() const { return count_; }

 private:
  void to_sparse();
  bool dense_mode_ = true;
  std::vector<std::int32_t> dense_;
  std::unordered_map<std::int32_t, std::int32_t> sparse_;
  std::size_t count_ = 0;
};

}  // namespace clinch
