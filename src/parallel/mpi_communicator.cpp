// The MPI world behind Communicator (communicator.hpp). It needs MPI running: the PETSc plugin
// starts it through PETSc before it asks for the world, so that the linear solver and the
// exchanges here share one world.
#include <mpi.h>

#include <cstdlib>
#include <limits>
#include <vector>

#include "src/parallel/communicator.hpp"

namespace clinch {
namespace {

// MPI counts are int: larger arrays go in pieces of at most this many bytes (or items).
constexpr std::size_t kLargestCount = std::numeric_limits<int>::max() / 2;

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void sum(std::span<double> values) override {
    for (std::size_t at = 0; at < values.size(); at += kLargestCount) {
      const std::size_t n = std::min(kLargestCount, values.size() - at);
      MPI_Allreduce(MPI_IN_PLACE, values.data() + at, static_cast<int>(n), MPI_DOUBLE, MPI_SUM,
                    MPI_COMM_WORLD);
    }
  }
  void max(std::span<std::uint8_t> values) override {
    for (std::size_t at = 0; at < values.size(); at += kLargestCount) {
      const std::size_t n = std::min(kLargestCount, values.size() - at);
      MPI_Allreduce(MPI_IN_PLACE, values.data() + at, static_cast<int>(n), MPI_UINT8_T, MPI_MAX,
                    MPI_COMM_WORLD);
    }
  }
  void share(std::byte* all, std::size_t count, std::size_t item_bytes) override {
    std::vector<std::size_t> bytes(static_cast<std::size_t>(size_));
    for (int r = 0; r < size_; ++r) {
      const ItemRange range = share_of(count, r, size_);
      bytes[static_cast<std::size_t>(r)] = (range.end - range.begin) * item_bytes;
    }
    share_bytes(all, bytes);
  }
  // Each rank broadcasts its share in turn: one collective per rank keeps counts within int by
  // splitting, which MPI_Allgatherv's displacements could not.
  void share_bytes(std::byte* all, std::span<const std::size_t> bytes) override {
    std::size_t offset = 0;
    for (int r = 0; r < size_; ++r) {
      const std::size_t total = bytes[static_cast<std::size_t>(r)];
      for (std::size_t at = 0; at < total; at += kLargestCount) {
        const std::size_t n = std::min(kLargestCount, total - at);
        MPI_Bcast(all + offset + at, static_cast<int>(n), MPI_BYTE, r, MPI_COMM_WORLD);
      }
      offset += total;
    }
  }
  std::vector<int> gather(int mine) override {
    std::vector<int> all(static_cast<std::size_t>(size_));
    MPI_Allgather(&mine, 1, MPI_INT, all.data(), 1, MPI_INT, MPI_COMM_WORLD);
    return all;
  }
  void all_to_all(const AllToAll& plan, std::span<const double> send,
                  std::span<double> receive) override {
    MPI_Alltoallv(send.data(), plan.send_count.data(), plan.send_offset.data(), MPI_DOUBLE,
                  receive.data(), plan.receive_count.data(), plan.receive_offset.data(), MPI_DOUBLE,
                  MPI_COMM_WORLD);
  }
  void all_to_all(const AllToAll& plan, std::span<const int> send,
                  std::span<int> receive) override {
    MPI_Alltoallv(send.data(), plan.send_count.data(), plan.send_offset.data(), MPI_INT,
                  receive.data(), plan.receive_count.data(), plan.receive_offset.data(), MPI_INT,
                  MPI_COMM_WORLD);
  }
  int first(bool mine) override {
    int candidate = mine ? rank_ : size_;
    MPI_Allreduce(MPI_IN_PLACE, &candidate, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return candidate;
  }
  std::string broadcast(const std::string& text, int root) override {
    unsigned long long length = text.size();
    MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, root, MPI_COMM_WORLD);
    std::string result = rank_ == root ? text : std::string(length, '\0');
    if (length > 0) {
      MPI_Bcast(result.data(), static_cast<int>(length), MPI_CHAR, root, MPI_COMM_WORLD);
    }
    return result;
  }
  [[noreturn]] void abort(int code) override {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::exit(code);  // MPI_Abort does not return; this keeps the promise if it did
  }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<Communicator> make_mpi_world_communicator(std::string* error) {
  int running = 0;
  MPI_Initialized(&running);
  if (!running) {
    if (error != nullptr) *error = "MPI is not running";
    return nullptr;
  }
  return std::make_unique<MpiCommunicator>();
}

}  // namespace clinch
