#include "src/parallel/communicator.hpp"

#include <algorithm>
#include <cstdlib>

namespace clinch {
namespace {

class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void sum(std::span<double>) override {}
  void max(std::span<std::uint8_t>) override {}
  void share(std::byte*, std::size_t, std::size_t) override {}
  void share_bytes(std::byte*, std::span<const std::size_t>) override {}
  int first(bool mine) override { return mine ? 0 : 1; }
  std::string broadcast(const std::string& text, int) override { return text; }
  [[noreturn]] void abort(int code) override { std::exit(code); }
};

}  // namespace

ItemRange share_of(std::size_t count, int rank, int size) {
  const auto r = static_cast<std::size_t>(rank), p = static_cast<std::size_t>(size);
  const std::size_t base = count / p, extra = count % p;
  const std::size_t begin = r * base + std::min(r, extra);
  return {begin, begin + base + (r < extra ? 1 : 0)};
}

std::unique_ptr<Communicator> make_serial_communicator() {
  return std::make_unique<SerialCommunicator>();
}

bool launched_on_several_ranks() {
  // Open MPI's launcher sets these for every process it starts (MPICH's: PMI_SIZE).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name); value && std::atoi(value) > 1) return true;
  }
  return false;
}

}  // namespace clinch
