// Test support: rank `rank` of `ranks` of a distributed run, alone in the process. Nothing is
// exchanged: each system keeps what its own elements put in its part of the tangent, which is
// what the PETSc backend sums (test_row_assembly.cpp, test_equation_layout.cpp).
#pragma once

#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "src/parallel/communicator.hpp"

namespace clinch {

class PartCommunicator final : public Communicator {
 public:
  PartCommunicator(int rank, int ranks) : rank_(rank), ranks_(ranks) {}
  int rank() const override { return rank_; }
  int size() const override { return ranks_; }
  void sum(std::span<double>) override {}
  void max(std::span<std::uint8_t>) override {}
  void share(std::byte*, std::size_t, std::size_t) override {}
  void share_bytes(std::byte*, std::span<const std::size_t>) override {}
  // No rank's value is known here: all zero, so that every row seems the last rank's.
  std::vector<int> gather(int) override {
    return std::vector<int>(static_cast<std::size_t>(ranks_), 0);
  }
  void all_to_all(const AllToAll&, std::span<const double>, std::span<double>) override {}
  void all_to_all(const AllToAll&, std::span<const int>, std::span<int>) override {}
  int first(bool mine) override { return mine ? rank_ : ranks_; }
  std::string broadcast(const std::string& text, int) override { return text; }
  [[noreturn]] void abort(int) override { std::abort(); }

 private:
  int rank_, ranks_;
};

}  // namespace clinch
