#include "src/fit/run_evaluator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "src/study/ladder_runner.hpp"

namespace clinch {
namespace {

namespace fs = std::filesystem;

// Why a run failed: the first diagnostic or error line it printed, else how its process ended.
std::string failure_reason(const std::string& out_dir, const SettingOutcome& outcome) {
  std::ifstream in(fs::path(out_dir) / "run.out");
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("error") != std::string::npos) return line;
  }
  if (!outcome.note.empty()) return outcome.note;
  return fmt::format("exit {}", outcome.exit_code);
}

}  // namespace

RunEvaluator::RunEvaluator(std::vector<FitRig> rigs, Options options, std::vector<double> typical,
                           std::vector<double> lower, std::vector<double> upper)
    : rigs_(std::move(rigs)),
      options_(std::move(options)),
      typical_(std::move(typical)),
      lower_(std::move(lower)),
      upper_(std::move(upper)) {}

std::size_t RunEvaluator::residual_count() const {
  std::size_t m = 0;
  for (const FitRig& rig : rigs_) {
    for (const MeasuredCurves* data : rig.data) m += data->point_count();
  }
  return m;
}

std::vector<std::optional<Eigen::VectorXd>> RunEvaluator::evaluate(
    const std::vector<std::vector<double>>& points, const std::vector<std::string>& labels,
    std::vector<std::vector<std::optional<CsvTable>>>* tables) {
  std::vector<LadderSetting> settings;
  for (std::size_t p = 0; p < points.size(); ++p) {
    for (const FitRig& rig : rigs_) {
      const fs::path dir = fs::path(options_.work_dir) / labels[p] / rig.job;
      std::error_code ec;
      fs::create_directories(dir, ec);
      const fs::path deck = dir / (rig.job + ".inp");
      std::ofstream out(deck);
      out << rig.deck.text(points[p]);
      out.close();
      fs::remove(dir / (rig.job + ".history.csv"), ec);  // a failed run leaves no stale table
      settings.push_back({1.0, deck.string(), dir.string(), rig.job});
    }
  }
  LadderOptions ladder;
  ladder.clinch = options_.clinch;
  ladder.jobs = options_.jobs;
  ladder.stop_signal = options_.stop_signal;
  const std::vector<SettingOutcome> outcomes = run_ladder(settings, ladder);
  runs_ += static_cast<int>(std::count_if(outcomes.begin(), outcomes.end(), [](const auto& o) {
    return o.state != SettingState::NotRun;
  }));
  if (options_.stop_signal && options_.stop_signal() != 0) stopped_ = true;

  std::vector<std::optional<Eigen::VectorXd>> results;
  if (tables) tables->assign(points.size(), {});
  std::size_t k = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    std::vector<double> r;
    r.reserve(residual_count());
    bool complete = true;
    for (const FitRig& rig : rigs_) {
      const SettingOutcome& outcome = outcomes[k];
      const LadderSetting& setting = settings[k++];
      std::optional<CsvTable> table;
      std::string error;
      if (outcome.state == SettingState::Completed) {
        table = read_csv_table((fs::path(setting.out_dir) / (rig.job + ".history.csv")).string(),
                               &error);
      } else {
        error = failure_reason(setting.out_dir, outcome);
      }
      if (tables) (*tables)[p].push_back(table);
      if (!table) {
        complete = false;
        if (!stopped_) failures_.push_back({points[p], rig.deck_name, error});
        continue;
      }
      for (const MeasuredCurves* data : rig.data) {
        if (!check_columns_written(*data, *table, rig.deck_name, &error)) {
          input_error_ = error;
          complete = false;
          break;
        }
        const std::optional<std::vector<double>> model = model_values(*data, *table, &error);
        if (!model) {
          complete = false;
          failures_.push_back({points[p], rig.deck_name, error});
          break;
        }
        append_residuals(*data, *model, r);
      }
    }
    if (complete && std::all_of(r.begin(), r.end(), [](double v) { return std::isfinite(v); })) {
      results.emplace_back(
          Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())));
    } else {
      results.emplace_back();
    }
  }
  return results;
}

const Eigen::VectorXd* RunEvaluator::residuals(const std::vector<double>& x) {
  auto it = residuals_.find(x);
  if (it == residuals_.end() && options_.jobs > 1) {
    // Runs at once to spare: the difference steps run with the point, ready for when Ceres
    // accepts it (most trial points of a trust-region method are accepted).
    jacobian(x);
    it = residuals_.find(x);
  }
  if (it == residuals_.end()) {
    it = residuals_.emplace(x, std::move(evaluate({x}, {"point"}).front())).first;
  }
  return it->second ? &*it->second : nullptr;
}

const Eigen::MatrixXd* RunEvaluator::jacobian(const std::vector<double>& x) {
  auto cached = jacobians_.find(x);
  if (cached != jacobians_.end()) return cached->second ? &*cached->second : nullptr;
  const std::size_t n = x.size();
  // Forward steps, backward where the forward one would leave the bounds; a step that fails is
  // tried once the other way.
  std::vector<double> steps(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double size = std::max(std::abs(x[j]), typical_[j]);
    steps[j] = kDifferenceStep * size;
    if (x[j] + steps[j] > upper_[j]) steps[j] = -steps[j];
  }
  std::vector<std::vector<double>> points;
  std::vector<std::string> labels;
  const bool have_base = residuals_.contains(x);
  if (!have_base) {
    points.push_back(x);
    labels.push_back("point");
  }
  for (std::size_t j = 0; j < n; ++j) {
    points.push_back(x);
    points.back()[j] += steps[j];
    labels.push_back(fmt::format("step-{}", j + 1));
  }
  std::vector<std::optional<Eigen::VectorXd>> results = evaluate(points, labels);
  if (!have_base) residuals_.emplace(x, results.front());
  const Eigen::VectorXd* base = residuals(x);
  std::optional<Eigen::MatrixXd> jacobian;
  if (base != nullptr && !stopped_) {
    jacobian = Eigen::MatrixXd(base->size(), static_cast<Eigen::Index>(n));
    const std::size_t offset = have_base ? 0 : 1;
    for (std::size_t j = 0; j < n && jacobian; ++j) {
      std::optional<Eigen::VectorXd>& moved = results[offset + j];
      if (!moved && x[j] - steps[j] >= lower_[j] && x[j] - steps[j] <= upper_[j]) {
        steps[j] = -steps[j];
        std::vector<double> other = x;
        other[j] += steps[j];
        moved = std::move(evaluate({other}, {fmt::format("step-{}", j + 1)}).front());
      }
      if (!moved) {
        jacobian.reset();
        break;
      }
      jacobian->col(static_cast<Eigen::Index>(j)) = (*moved - *base) / steps[j];
    }
  }
  return (jacobians_[x] = std::move(jacobian)) ? &*jacobians_[x] : nullptr;
}

std::vector<std::optional<CsvTable>> RunEvaluator::run_tables(const std::vector<double>& x,
                                                              const std::string& label) {
  std::vector<std::vector<std::optional<CsvTable>>> tables;
  evaluate({x}, {label}, &tables);
  return std::move(tables.front());
}

}  // namespace clinch
