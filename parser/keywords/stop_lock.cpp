// *CONNECTOR STOP, *CONNECTOR LOCK and *CONNECTOR FAILURE (behaviors.md §5): limits and criteria
// on the position (and total force) of one component. Each takes one data line; what needs the
// connection type (availability, the initial position) is checked by check_behaviors.
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/behavior_option_common.hpp"

namespace clinch {
namespace {

class StopHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    ConnectorStop stop;
    stop.loc = ctx.keyword().loc;
    std::optional<int> component = component_param(ctx);
    stop.valid = component && *component > 0;
    stop.component = component.value_or(0);
    stop.component_loc = ctx.params().loc("COMPONENT", true);
    behavior_->stops.push_back(stop);
    index_ = behavior_->stops.size() - 1;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_) return;
    ConnectorStop& stop = behavior_->stops[index_];
    if (++rows_ > 1) {
      if (rows_ == 2) report_extra_line(ctx, line, "L, U");
      return;
    }
    stop.data_loc = line.loc;
    ctx.check_field_count(line, fields, 2, "L, U");
    bool bad_lower = false, bad_upper = false;
    stop.lower = optional_real(ctx, fields, 0, "lower limit", &bad_lower);
    stop.upper = optional_real(ctx, fields, 1, "upper limit", &bad_upper);
    if (stop.lower) stop.lower_loc = fields[0].loc;
    if (stop.upper) stop.upper_loc = fields[1].loc;
    if (bad_lower || bad_upper) {
      stop.valid = false;
      return;
    }
    if (!stop.lower && !stop.upper) {
      ctx.report(DiagCode::stop_no_limit, line.loc,
                 "*CONNECTOR STOP has no limit: L and U are both blank");
      stop.valid = false;
      return;
    }
    if (stop.lower && stop.upper && !(*stop.lower < *stop.upper)) {
      ctx.report(
          DiagCode::value_out_of_range, fields[1],
          fmt::format("stop limits need L < U (L = {}, U = {})", fields[0].text, fields[1].text));
      stop.valid = false;
    }
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || rows_ > 0) return;
    report_missing_data(ctx, "L, U");
    behavior_->stops[index_].valid = false;
  }

 private:
  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  std::size_t rows_ = 0;
};

// Reads `p_L, p_U, F_L, F_U` (§5.2, §5.3). False when a field is bad or no bound is given
// (reported).
bool read_bounds(BlockContext& ctx, const DataLine& line, const std::vector<Field>& fields,
                 ConnectorCriterionBounds& bounds) {
  ctx.check_field_count(line, fields, 4, "p_L, p_U, F_L, F_U");
  static constexpr std::array<std::string_view, 4> kWhat = {
      "lower position bound", "upper position bound", "lower force bound", "upper force bound"};
  std::array<std::optional<double>*, 4> slots = {&bounds.position_lower, &bounds.position_upper,
                                                 &bounds.force_lower, &bounds.force_upper};
  bool ok = true;
  bool any = false;
  for (std::size_t k = 0; k < 4; ++k) {
    bool bad = false;
    *slots[k] = optional_real(ctx, fields, k, kWhat[k], &bad);
    if (k < fields.size()) bounds.loc[k] = fields[k].loc;
    if (bad) ok = false;
    if (slots[k]->has_value()) any = true;
  }
  if (ok && !any) {
    ctx.report(DiagCode::lock_no_criterion, line.loc,
               fmt::format("{} needs at least one bound (p_L, p_U, F_L, F_U are all blank)",
                           ctx.keyword_display()));
    return false;
  }
  return ok;
}

class LockHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    // §5.2: these parameters belong to the Explicit form of the lock.
    warn_explicit_only(ctx, {"DEPENDENCIES", "EXTRAPOLATION", "REGULARIZE", "RTOL"});
    ConnectorLock lock;
    lock.loc = ctx.keyword().loc;
    std::optional<int> component = component_param(ctx);
    std::optional<int> locked = component_or_all_param(ctx, "LOCK");
    lock.valid = component && *component > 0 && locked;
    lock.component = component.value_or(0);
    lock.locked = locked.value_or(0);
    lock.component_loc = ctx.params().loc("COMPONENT", true);
    lock.target_loc = ctx.params().loc("LOCK", true);
    behavior_->locks.push_back(lock);
    index_ = behavior_->locks.size() - 1;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_) return;
    if (++rows_ > 1) {
      if (rows_ == 2) report_extra_line(ctx, line, "p_L, p_U, F_L, F_U");
      return;
    }
    ConnectorLock& lock = behavior_->locks[index_];
    if (!read_bounds(ctx, line, fields, lock.bounds)) lock.valid = false;
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || rows_ > 0) return;
    report_missing_data(ctx, "p_L, p_U, F_L, F_U");
    behavior_->locks[index_].valid = false;
  }

 private:
  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  std::size_t rows_ = 0;
};

class FailureHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    behavior_ = current_behavior(ctx);
    if (!behavior_) return;
    ConnectorFailure failure;
    failure.loc = ctx.keyword().loc;
    std::optional<int> component = component_param(ctx);
    std::optional<int> released = component_or_all_param(ctx, "RELEASE");
    failure.valid = component && *component > 0 && released;
    failure.component = component.value_or(0);
    failure.released = released.value_or(0);
    failure.component_loc = ctx.params().loc("COMPONENT", true);
    failure.target_loc = ctx.params().loc("RELEASE", true);
    behavior_->failures.push_back(failure);
    index_ = behavior_->failures.size() - 1;
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (!behavior_) return;
    if (++rows_ > 1) {
      if (rows_ == 2) report_extra_line(ctx, line, "p_L, p_U, F_L, F_U");
      return;
    }
    ConnectorFailure& failure = behavior_->failures[index_];
    if (!read_bounds(ctx, line, fields, failure.bounds)) failure.valid = false;
  }

  void end(BlockContext& ctx) override {
    if (!behavior_ || rows_ > 0) return;
    report_missing_data(ctx, "p_L, p_U, F_L, F_U");
    behavior_->failures[index_].valid = false;
  }

 private:
  ConnectorBehavior* behavior_ = nullptr;
  std::size_t index_ = 0;
  std::size_t rows_ = 0;
};

}  // namespace

std::vector<KeywordSpec> stop_lock_keyword_specs() {
  std::vector<KeywordSpec> specs;
  specs.push_back(behavior_suboption_spec("CONNECTOR STOP", {component_param_spec(true)}, [] {
    return std::unique_ptr<KeywordHandler>(new StopHandler());
  }));
  std::vector<ParamSpec> lock_params = {
      component_param_spec(true), ParamSpec{"LOCK", ParamKind::Value},
      ParamSpec{"DEPENDENCIES", ParamKind::Value}, extrapolation_param_spec()};
  for (ParamSpec& p : regularize_param_specs()) lock_params.push_back(std::move(p));
  specs.push_back(behavior_suboption_spec("CONNECTOR LOCK", std::move(lock_params), [] {
    return std::unique_ptr<KeywordHandler>(new LockHandler());
  }));
  specs.push_back(behavior_suboption_spec(
      "CONNECTOR FAILURE", {component_param_spec(true), ParamSpec{"RELEASE", ParamKind::Value}},
      [] { return std::unique_ptr<KeywordHandler>(new FailureHandler()); }));
  return specs;
}

}  // namespace clinch
