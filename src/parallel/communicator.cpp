#include "src/parallel/communicator.hpp"

#include <algorithm>
#include <cstdlib>

namespace clinch {

ItemRange share_of(std::size_t count, int rank, int size) {
  const auto r = static_cast<std::size_t>(rank), p = static_cast<std::size_t>(size);
  const std::size_t base = count / p, extra = count % p;
  const std::size_t begin = r * base + std::min(r, extra);
  return {begin, begin + base + (r < extra ? 1 : 0)};
}

ItemRange owned_rows(int n, int node_block, int rank, int size) {
  const auto block = static_cast<std::size_t>(std::max(node_block, 1));
  const ItemRange blocks = share_of(static_cast<std::size_t>(n) / block, rank, size);
  return {blocks.begin * block, blocks.end * block};
}

bool launched_on_several_ranks() {
  // Open MPI's launcher sets these for every process it starts (MPICH's: PMI_SIZE).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name); value && std::atoi(value) > 1) return true;
  }
  return false;
}

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

}  // namespace clinch
