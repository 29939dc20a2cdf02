// The ghost values of vectors by rows (docs/parallel.md "Vectors by rows"): a rank holds the
// entries of the rows it owns and, after them, ghost entries for the equations of other ranks
// that its elements read. After an evaluation, each rank having added its own elements' forces,
// the ghosts' contributions are added to their owners' entries: one value per ghost entry, in one
// message per pair of ranks that share a boundary. The owners' values of the solution reach the
// ghosts through the solver, which scatters it to each rank's own and ghost equations; those of
// a vector only the owners compute (a dynamic step's initial accelerations) through
// copy_to_ghosts.
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

  // Each owned entry gains the ghost entries the other ranks hold of it; the ghost entries are
  // left as they were.
  void add_to_owners(std::span<double> values);
  // Each ghost entry takes its owner's value (the same messages the other way).
  void copy_to_ghosts(std::span<double> values);
  int owned() const { return owned_; }

 private:
  Communicator& communicator_;
  int owned_;
  // Ghosts to owners: each owner receives, rank by rank, values for its owned entries exported_
  // in the order the ghost holder asked for them.
  AllToAll to_owners_, to_ghosts_;
  std::vector<int> exported_;
  std::vector<double> received_;
  std::size_t ghosts_ = 0;
};

}  // namespace clinch
