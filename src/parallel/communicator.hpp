// The ranks of a run (docs/parallel.md). Under `mpirun -n P` every rank reads the deck and holds
// the whole model; each evaluates its own share of the elements, the ranks sum the forces after
// every evaluation, and they take the same decisions (convergence, cutbacks, active sets) from
// what they sum, exchange or join. A run on one process uses no communicator.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace clinch {

// The half-open range [begin, end) of `count` items that rank `rank` of `size` owns: contiguous
// shares whose sizes differ by at most one.
struct ItemRange {
  std::size_t begin = 0, end = 0;
};
ItemRange share_of(std::size_t count, int rank, int size);

// The rows of an n-equation system that rank `rank` of `size` owns in the distributed solver:
// contiguous shares of whole node blocks of `node_block` equations, so that no node is split
// (SparseMatrix::node_block).
ItemRange owned_rows(int n, int node_block, int rank, int size);

// The items an exchange between every pair of ranks moves (MPI_Alltoallv): to rank r,
// send_count[r] items from send_offset[r]; from rank r, receive_count[r] items to
// receive_offset[r].
struct AllToAll {
  std::vector<int> send_count, send_offset, receive_count, receive_offset;
};

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Element-wise over the ranks, in place: every rank ends with the result.
  virtual void sum(std::span<double> values) = 0;
  virtual void max(std::span<std::uint8_t> values) = 0;
  // `all` holds an array of `count` items of `item_bytes` each, rank r's share (share_of) filled
  // on rank r; afterwards every rank holds every share.
  virtual void share(std::byte* all, std::size_t count, std::size_t item_bytes) = 0;
  // The same for an array whose shares have the byte sizes `bytes[r]` (r = 0…size−1), in rank
  // order.
  virtual void share_bytes(std::byte* all, std::span<const std::size_t> bytes) = 0;
  // Every rank's `mine`, in rank order.
  virtual std::vector<int> gather(int mine) = 0;
  // The exchange `plan` describes (halo_exchange.hpp).
  virtual void all_to_all(const AllToAll& plan, std::span<const double> send,
                          std::span<double> receive) = 0;
  virtual void all_to_all(const AllToAll& plan, std::span<const int> send,
                          std::span<int> receive) = 0;
  // The lowest rank for which `mine` is true, size() when none is.
  virtual int first(bool mine) = 0;
  // Rank `root`'s text, on every rank.
  virtual std::string broadcast(const std::string& text, int root) = 0;
  // Ends every rank's process with exit status `code`: for a failure one rank meets alone (an
  // output rank 0 cannot write) while the others wait for it.
  [[noreturn]] virtual void abort(int code) = 0;
};

// The world of `mpirun` (MPI started through PETSc), from the plugin libclinch_petsc.so
// (petsc_plugin_loader.hpp); a one-rank world when clinch runs without mpirun. Null, with `error`,
// when the plugin could not be loaded or MPI could not start.
std::unique_ptr<Communicator> make_world_communicator(std::string* error);

// True when the process was started by mpirun with more than one rank (read from the
// environment, before MPI starts).
bool launched_on_several_ranks();
// True when an MPI launcher (mpirun, srun) started the process, with any number of ranks.
bool launched_by_mpi();

}  // namespace clinch
