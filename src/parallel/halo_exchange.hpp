// The ghost values of vectors by rows (docs/parallel.md "Vectors by rows"): a rank holds the
// entries of the rows it owns and, after them, ghost entries for the equations of other ranks
// that its elements read. Two exchanges keep them: the owners' values into the ghosts (after a
// correction), and the ghosts' contributions added to their owners' entries (after an
// evaluation, each rank having added its own elements' forces). Each moves one value per ghost
// entry, in one message per pair of ranks that share a boundary.
#pragma once

#include <span>
#include <vector>

#include "src/parallel/communicator.hpp"

namespace clinch {

class HaloExchange {
 public:
  // `first_owned` and `owned`: the global equations of this rank's rows; `ghosts`: the global
  // equations of its ghost entries, ascending (entry owned + k is ghosts[k]). Called by every
  // rank alike.
  HaloExchange(Communicator& communicator, int first_owned, int owned, std::vector<int> ghosts);

  // values[owned + k] ← the owner's value of ghosts[k].
  void import_ghosts(std::span<double> values);
  // Each owned entry gains the ghost entries the other ranks hold of it; the ghost entries are
  // left as they were.
  void add_to_owners(std::span<double> values);
  int owned() const { return owned_; }

 private:
  Communicator& communicator_;
  int owned_;
  // Owners to ghosts: what each rank sends is its owned entries exported_[...] in the order the
  // ghost holder asked for them.
  AllToAll to_ghosts_, to_owners_;
  std::vector<int> exported_;
  std::vector<double> owned_values_, ghost_values_;
};

}  // namespace clinch
