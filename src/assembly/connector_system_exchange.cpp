// The exchange after a distributed evaluation and the decisions taken together (docs/parallel.md):
// each rank evaluated its share of the elements into zeroed arrays, so sums give the whole
// residual and tangent. With a whole plan each rank's share of the results and of the laws'
// trial history is sent to the others, and every rank then holds the state a serial evaluation
// gives, up to the order of the sums' additions; a plan with a share of the elements keeps its
// results, and what is decided from them is joined over the ranks.
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "src/assembly/connector_system.hpp"

namespace clinch {
namespace {

static_assert(std::is_trivially_copyable_v<SpringResult>);

// One rank's StepRequest as text: ratio, flag, message, then the warnings.
std::string encode(const StepRequest& request) {
  std::string text = fmt::format("{:a}\n{}\n{}\n{}", request.dt_ratio, request.unreliable ? 1 : 0,
                                 request.message.size(), request.message);
  for (const StepRequest::Warning& w : request.warnings) {
    text += fmt::format("{}\n{}\n{}", w.element, w.message.size(), w.message);
  }
  return text;
}

void merge_encoded(const std::string& text, StepRequest& into) {
  std::size_t at = 0;
  const auto line = [&] {
    const std::size_t end = text.find('\n', at);
    std::string value = text.substr(at, end - at);
    at = end + 1;
    return value;
  };
  const auto sized = [&] {
    const std::size_t length = std::stoull(line());
    std::string value = text.substr(at, length);
    at += length;
    return value;
  };
  const double ratio = std::strtod(line().c_str(), nullptr);
  const bool unreliable = line() == "1";
  const std::string message = sized();
  if (ratio < into.dt_ratio) {
    into.dt_ratio = ratio;
    into.message = message;
  }
  into.unreliable = into.unreliable || unreliable;
  while (at < text.size()) {
    StepRequest::Warning w;
    w.element = std::stoull(line());
    w.message = sized();
    into.warnings.push_back(std::move(w));
  }
}

}  // namespace

void ConnectorSystem::distribute(Communicator& communicator, bool by_rows) {
  if (pattern_) throw std::logic_error("ConnectorSystem::distribute after the first assembly");
  communicator_ = &communicator;
  by_rows_ = by_rows;
  // A plan with a share of the elements (build_analysis_plan) holds only this rank's: it
  // evaluates all of them and keeps their results.
  if (plan_.shared) {
    const EquationLayout& layout = plan_.layout;
    if (layout.local) {
      halo_.emplace(communicator, layout.first_owned, layout.owned, layout.ghost_global);
      // The kinetic energy and the nodal work of the rank's own nodes, summed over the ranks.
      if (plan_.dynamic) initial_kinetic_ = kinetic(state_.v_n, state_.rotation_n);
      if (energy_) energy_->set_kinetic(initial_kinetic_);
      stabilization_.share_rows(communicator, layout.owned);
    }
    if (energy_) energy_->share_elements(communicator, layout.local ? owned_node_equations() : -1);
    return;
  }
  const int size = communicator.size();
  owned_connectors_ = share_of(plan_.connectors.size(), communicator.rank(), size);
  owned_springs_ = share_of(plan_.spring_total, communicator.rank(), size);
  // The laws' history is laid out connector by connector (AnalysisPlan::add_law): a rank's share
  // of it runs from its first connector's first slot to the next rank's.
  const auto history_start = [&](std::size_t c) {
    for (; c < plan_.connectors.size(); ++c) {
      if (!plan_.connectors[c].laws.empty()) return plan_.connectors[c].laws.slots[0].history;
    }
    return plan_.history_size;
  };
  history_bytes_.assign(static_cast<std::size_t>(size), 0);
  for (int r = 0; r < size; ++r) {
    const ItemRange range = share_of(plan_.connectors.size(), r, size);
    history_bytes_[static_cast<std::size_t>(r)] =
        (history_start(range.end) - history_start(range.begin)) * sizeof(double);
  }
}

void ConnectorSystem::exchange(SparseMatrix* tangent, EvalStatus& status) {
  Communicator& comm = *communicator_;
  if (const int failing = comm.first(!status.ok); failing < comm.size()) {
    status = {false, comm.broadcast(status.message, failing)};
    return;
  }
  if (halo_) {
    // Vectors by rows: each owner adds what the other ranks' elements put on its rows.
    halo_->add_to_owners({internal_.data(), static_cast<std::size_t>(internal_.size())});
    if (predicting_) {
      halo_->add_to_owners({predictor_.data(), static_cast<std::size_t>(predictor_.size())});
    }
  } else {
    comm.sum({internal_.data(), static_cast<std::size_t>(internal_.size())});
    if (predicting_) comm.sum({predictor_.data(), static_cast<std::size_t>(predictor_.size())});
  }
  // Assembled by rows, the solver sums the ranks' parts of the tangent.
  if (tangent && !by_rows_) comm.sum(tangent->values);
  double entries[4] = {element_forces_.sum[0], element_forces_.sum[1],
                       static_cast<double>(element_forces_.count[0]),
                       static_cast<double>(element_forces_.count[1])};
  comm.sum(entries);
  element_forces_.sum[0] = entries[0];
  element_forces_.sum[1] = entries[1];
  element_forces_.count[0] = static_cast<int>(entries[2]);
  element_forces_.count[1] = static_cast<int>(entries[3]);
  // Only the owner of a multiplier's connector sets its flag; the others hold 0 there. Under
  // vectors by rows a multiplier is a row of its connector's rank only.
  if (plan_.has_multipliers && !halo_) comm.max(multiplier_active_);
  // A plan with a share of the elements keeps its own results: the decisions that read them are
  // taken together (update_active_set, release_failed_components, failure_note) and the history
  // columns sum the parts of the ranks. A whole plan gets every rank's share.
  if (!plan_.shared) {
    comm.share(reinterpret_cast<std::byte*>(state_.results.data()), state_.results.size(),
               sizeof(ConnectorResult));
    comm.share_bytes(reinterpret_cast<std::byte*>(state_.history.data()), history_bytes_);
    comm.share(reinterpret_cast<std::byte*>(springs_.data()), springs_.size(),
               sizeof(SpringResult));
  }
  exchange_step_requests();
}

void ConnectorSystem::join_largest(double& value, std::string& text) const {
  if (!halo_) return;
  std::vector<double> all(static_cast<std::size_t>(communicator_->size()), 0.0);
  all[static_cast<std::size_t>(communicator_->rank())] = value;
  communicator_->sum(all);
  const auto largest = std::max_element(all.begin(), all.end());
  value = *largest;
  text = communicator_->broadcast(text, static_cast<int>(largest - all.begin()));
}

std::vector<std::string> ConnectorSystem::lines_of_every_rank(std::vector<std::string> mine) const {
  if (!communicator_ || !plan_.shared) return mine;
  std::string text;
  for (const std::string& line : mine) text += fmt::format("{}\n{}", line.size(), line);
  std::vector<std::string> all;
  for (int r = 0; r < communicator_->size(); ++r) {
    const std::string theirs = communicator_->broadcast(text, r);
    for (std::size_t at = 0; at < theirs.size();) {
      const std::size_t end = theirs.find('\n', at);
      const std::size_t length = std::stoull(theirs.substr(at, end - at));
      all.push_back(theirs.substr(end + 1, length));
      at = end + 1 + length;
    }
  }
  return all;
}

bool ConnectorSystem::any_rank(bool mine) const {
  if (!communicator_ || !plan_.shared) return mine;
  return communicator_->first(mine) < communicator_->size();
}

std::vector<double> ConnectorSystem::component_values(
    std::span<const ComponentQuery> queries) const {
  std::vector<double> values(queries.size(), 0.0);
  for (std::size_t q = 0; q < queries.size(); ++q) {
    const ComponentQuery& query = queries[q];
    if (!plan_.holds_connector(query.connector)) continue;
    const int i = query.component - 1;
    if (query.quantity == ComponentQuery::Reaction) {
      values[q] = state_.results[query.connector - plan_.first_connector].multiplier[i];
    } else {
      values[q] =
          converged_component(query.connector, query.component, static_cast<int>(query.quantity));
    }
  }
  // Each connector's rank gives its values, the others zero.
  if (communicator_ && plan_.shared) communicator_->sum(values);
  return values;
}

// The laws' requests (behaviors.md §7.4: a smaller increment) and warnings of every rank, merged
// in rank order, which is element order.
void ConnectorSystem::exchange_step_requests() {
  Communicator& comm = *communicator_;
  const std::string mine = encode(state_.request);
  StepRequest merged;
  for (int r = 0; r < comm.size(); ++r) merge_encoded(comm.broadcast(mine, r), merged);
  state_.request = std::move(merged);
}

double ConnectorSystem::sum_over_ranks(double mine) const {
  if (halo_) communicator_->sum({&mine, 1});
  return mine;
}

double ConnectorSystem::max_over_ranks(double mine) const {
  if (!halo_) return mine;
  // The ranks' values side by side, summed: a NaN stays a NaN wherever it is.
  std::vector<double> all(static_cast<std::size_t>(communicator_->size()), 0.0);
  all[static_cast<std::size_t>(communicator_->rank())] = mine;
  communicator_->sum(all);
  double largest = all[0];
  for (const double v : all) largest = std::isnan(v) || v > largest ? v : largest;
  return largest;
}

void ConnectorSystem::join_norms(IterationNorms& norms, ForceEntries& loads,
                                 ScaledNorm& residual_norm, ScaledNorm& correction_norm) const {
  // Each rank's values in its own slot, summed: one reduction of a few numbers per rank.
  constexpr std::size_t kSlot = 19;
  const auto ranks = static_cast<std::size_t>(communicator_->size());
  std::vector<double> all(kSlot * ranks, 0.0);
  double* mine = all.data() + kSlot * static_cast<std::size_t>(communicator_->rank());
  for (int f = 0; f < 2; ++f) {
    mine[f] = norms.largest_residual[f];
    mine[2 + f] = norms.largest_increment[f];
    mine[4 + f] = norms.largest_correction[f];
    mine[6 + f] = loads.sum[f];
    mine[8 + f] = loads.count[f];
  }
  const std::array<double, 4> r = residual_norm.parts(), c = correction_norm.parts();
  std::copy(r.begin(), r.end(), mine + 10);
  std::copy(c.begin(), c.end(), mine + 14);
  mine[18] = norms.constraint_violation;
  communicator_->sum(all);
  norms = {};
  loads = {};
  residual_norm = {};
  correction_norm = {};
  const auto largest = [](double a, double b) { return std::isnan(b) || b > a ? b : a; };
  for (std::size_t rank = 0; rank < ranks; ++rank) {
    const double* theirs = all.data() + kSlot * rank;
    for (int f = 0; f < 2; ++f) {
      norms.largest_residual[f] = largest(norms.largest_residual[f], theirs[f]);
      norms.largest_increment[f] = largest(norms.largest_increment[f], theirs[2 + f]);
      norms.largest_correction[f] = largest(norms.largest_correction[f], theirs[4 + f]);
      loads.sum[f] += theirs[6 + f];
      loads.count[f] += static_cast<int>(theirs[8 + f]);
    }
    norms.constraint_violation = largest(norms.constraint_violation, theirs[18]);
    residual_norm.merge(ScaledNorm::of_parts(theirs + 10));
    correction_norm.merge(ScaledNorm::of_parts(theirs + 14));
  }
}

}  // namespace clinch
