#include "src/parallel/halo_exchange.hpp"

#include <algorithm>
#include <numeric>

namespace clinch {
namespace {

std::vector<int> offsets_of(const std::vector<int>& counts) {
  std::vector<int> offsets(counts.size(), 0);
  if (!counts.empty()) std::exclusive_scan(counts.begin(), counts.end(), offsets.begin(), 0);
  return offsets;
}

}  // namespace

HaloExchange::HaloExchange(Communicator& communicator, int first_owned, int owned,
                           std::vector<int> ghosts)
    : communicator_(communicator), owned_(owned), ghosts_(ghosts.size()) {
  const int ranks = communicator.size();
  // The ranks' first rows ascend: a row's owner is the last rank starting at or before it.
  const std::vector<int> starts = communicator.gather(first_owned);
  std::vector<int> asked(static_cast<std::size_t>(ranks), 0);
  for (const int g : ghosts) {
    const auto owner = std::upper_bound(starts.begin(), starts.end(), g) - starts.begin() - 1;
    ++asked[static_cast<std::size_t>(owner)];
  }
  // How many each rank asks of each: one count per pair.
  AllToAll counts;
  counts.send_count.assign(static_cast<std::size_t>(ranks), 1);
  counts.receive_count = counts.send_count;
  counts.send_offset = offsets_of(counts.send_count);
  counts.receive_offset = counts.send_offset;
  std::vector<int> exported_counts(static_cast<std::size_t>(ranks), 0);
  communicator.all_to_all(counts, std::span<const int>(asked), std::span<int>(exported_counts));
  // Ghosts ascend and so do their owners: each owner's requests are one range of `ghosts`.
  to_owners_.send_count = asked;
  to_owners_.send_offset = offsets_of(asked);
  to_owners_.receive_count = exported_counts;
  to_owners_.receive_offset = offsets_of(exported_counts);
  exported_.assign(
      static_cast<std::size_t>(std::accumulate(exported_counts.begin(), exported_counts.end(), 0)),
      0);
  communicator.all_to_all(to_owners_, std::span<const int>(ghosts), std::span<int>(exported_));
  for (int& e : exported_) e -= first_owned;  // owned entries
  received_.resize(exported_.size());
  to_ghosts_ = {to_owners_.receive_count, to_owners_.receive_offset, to_owners_.send_count,
                to_owners_.send_offset};
}

void HaloExchange::add_to_owners(std::span<double> values) {
  communicator_.all_to_all(to_owners_, values.subspan(static_cast<std::size_t>(owned_), ghosts_),
                           std::span<double>(received_));
  for (std::size_t k = 0; k < exported_.size(); ++k) {
    values[static_cast<std::size_t>(exported_[k])] += received_[k];
  }
}

void HaloExchange::copy_to_ghosts(std::span<double> values) {
  for (std::size_t k = 0; k < exported_.size(); ++k) {
    received_[k] = values[static_cast<std::size_t>(exported_[k])];
  }
  communicator_.all_to_all(to_ghosts_, std::span<const double>(received_),
                           values.subspan(static_cast<std::size_t>(owned_), ghosts_));
}

}  // namespace clinch
