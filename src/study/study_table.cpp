#include "src/study/study_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

#include "src/output/csv_table.hpp"

namespace clinch {
namespace {

std::string state_text(const StudySetting& s) {
  switch (s.outcome.state) {
    case SettingState::Completed:
      return "COMPLETED";
    case SettingState::Failed:
      if (s.status && !s.status->ending.empty()) return s.status->ending;
      if (!s.outcome.note.empty()) return "FAILED: " + s.outcome.note;
      return fmt::format("FAILED: clinch run exited with {} (see {})", s.outcome.exit_code,
                         s.history.substr(0, s.history.rfind('/')) + "/run.out");
    case SettingState::Running:
    case SettingState::NotRun:
      break;
  }
  return s.outcome.note.empty() ? "not run" : s.outcome.note;
}

const char* order_text(OrderStatus status) {
  switch (status) {
    case OrderStatus::Observed:
      return "observed";
    case OrderStatus::Agree:
      return "agree";
    case OrderStatus::NotObserved:
      return "not-observed";
    case OrderStatus::TooFewRuns:
      return "too-few-runs";
    case OrderStatus::ZeroColumn:
      return "zero-column";
    case OrderStatus::Negligible:
      return "negligible";
  }
  return "";
}

bool write_file(const std::string& path, const std::string& text, std::string* error) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) {
    *error = fmt::format("cannot write '{}'", path);
    return false;
  }
  return true;
}

}  // namespace

std::string render_study_table(const StudyResult& result) {
  std::string out =
      fmt::format("{:>7} {:>7} {:>6} {:>7} {:>8} {:>6} {:>9} {:>11} {:>11}  {:<16} {}\n", "setting",
                  "scale", "incs", "iters", "cutbacks", "work", "wall s", "vs finest", "est. error",
                  "worst column", "status");
  // One completed setting has nothing to be compared with.
  const StudyEstimate* e = result.estimate && result.estimate->worst_difference.size() >= 2
                               ? &*result.estimate
                               : nullptr;
  for (std::size_t i = 0; i < result.settings.size(); ++i) {
    const StudySetting& s = result.settings[i];
    std::string incs = "-", iters = "-", cuts = "-", work = "-", wall = "-", diff = "-", est = "-",
                worst = "";
    if (s.status) {
      incs = fmt::format("{}", s.status->converged_increments());
      iters = fmt::format("{}", s.status->total_iterations());
      cuts = fmt::format("{}", s.status->cutbacks());
      work = fmt::format("{}", setting_work(*s.status));
    }
    if (s.outcome.state == SettingState::Completed || s.outcome.state == SettingState::Failed) {
      wall = fmt::format("{:.3f}", s.outcome.wall_seconds);
    }
    if (e != nullptr && s.run >= 0) {
      const auto r = static_cast<std::size_t>(s.run);
      diff = fmt::format("{:.2e}", e->worst_difference[r]);
      est = fmt::format("{}{:.2e}", e->estimate_is_bound[r] ? ">" : "", e->worst_estimated[r]);
      worst = e->worst_column[r];
    }
    out += fmt::format("{:>7} {:>7} {:>6} {:>7} {:>8} {:>6} {:>9} {:>11} {:>11}  {:<16} {}{}\n",
                       i + 1, scale_text(s.scale), incs, iters, cuts, work, wall, diff, est, worst,
                       state_text(s), result.chosen == i ? "  <- --rtol" : "");
  }
  if (e == nullptr) return out;
  std::size_t counts[6] = {};
  std::vector<std::string> negligible;
  const ColumnEstimate* least_converged = nullptr;
  for (const ColumnEstimate& c : e->columns) {
    ++counts[static_cast<int>(c.status)];
    if (c.status == OrderStatus::Negligible) negligible.push_back(c.name);
    if (c.status == OrderStatus::Observed &&
        (least_converged == nullptr || c.estimated.back() > least_converged->estimated.back())) {
      least_converged = &c;
    }
  }
  out += "work: increment attempts + Newton iterations (residual assemblies)\n";
  out += fmt::format(
      "errors: largest over the history columns and the coarsest setting's {} times, relative "
      "to the model's scale of each column's kind\n        (forces and moments: the largest "
      "|force or moment|; motions: the largest |motion|; damage and criteria: 1);\n        "
      "'vs finest' against the finest completed setting, 'est. error' against the Richardson "
      "limit\n",
      e->times.size());
  out += fmt::format(
      "columns: {} with an observed order, {} agreeing to round-off, {} without an observed "
      "order ('>': their estimate is only the difference from the finest), {} too few settings, "
      "{} zero\n",
      counts[static_cast<int>(OrderStatus::Observed)], counts[static_cast<int>(OrderStatus::Agree)],
      counts[static_cast<int>(OrderStatus::NotObserved)],
      counts[static_cast<int>(OrderStatus::TooFewRuns)],
      counts[static_cast<int>(OrderStatus::ZeroColumn)]);
  if (!negligible.empty()) {
    // Said, so that a reader knows what the verdict does not cover.
    constexpr std::size_t kListed = 8;
    std::string names;
    for (std::size_t i = 0; i < std::min(kListed, negligible.size()); ++i) {
      names += (i > 0 ? ", " : "") + negligible[i];
    }
    if (negligible.size() > kListed) names += fmt::format(", ... ({} more)", negligible.size() - kListed);
    out += fmt::format(
        "left out: {} column{} zero to round-off (largest |value| at most {:g} of the scale of "
        "its kind: totals balanced by a motion's reaction, constraint residuals): {}; --columns "
        "estimates them\n",
        negligible.size(), negligible.size() == 1 ? "" : "s", kNegligibleColumn, names);
  }
  const std::size_t estimated = e->columns.size() - counts[static_cast<int>(OrderStatus::ZeroColumn)] -
                                counts[static_cast<int>(OrderStatus::Negligible)];
  if (estimated > 0 && counts[static_cast<int>(OrderStatus::Agree)] == estimated) {
    out += "every estimated column agrees to round-off in every setting: the deck's own "
           "increments (setting 1) are exact\n";
  }
  if (least_converged != nullptr) {
    out += fmt::format(
        "least converged column: {}, observed order {:.2f}, estimated error of the "
        "finest setting {:.2e}\n",
        least_converged->name, least_converged->order, least_converged->estimated.back());
  }
  if (result.rtol) {
    if (result.chosen) {
      const StudySetting& s = result.settings[*result.chosen];
      out += fmt::format(
          "--rtol {:g}: setting {} (scale {}, {} increments, {} iterations, work {}), estimated "
          "error {:.2e}{}\n",
          *result.rtol, *result.chosen + 1, scale_text(s.scale), s.status->converged_increments(),
          s.status->total_iterations(), setting_work(*s.status),
          e->worst_estimated[static_cast<std::size_t>(s.run)],
          e->estimate_is_bound[static_cast<std::size_t>(s.run)]
              ? " (a lower bound: some columns show no convergence order)"
              : "");
    } else {
      out += fmt::format("--rtol {:g}: no setting has an estimated error below it\n", *result.rtol);
    }
  }
  return out;
}

bool write_settings_csv(const StudyResult& result, const std::string& path, std::string* error) {
  std::string text =
      "setting,scale,state,exit_code,wall_seconds,increments,iterations,cutbacks,work,"
      "difference_to_finest,estimated_error,estimate_is_bound,worst_column,chosen,rtol,deck,"
      "status\n";
  const StudyEstimate* e = result.estimate ? &*result.estimate : nullptr;
  for (std::size_t i = 0; i < result.settings.size(); ++i) {
    const StudySetting& s = result.settings[i];
    const bool ran =
        s.outcome.state == SettingState::Completed || s.outcome.state == SettingState::Failed;
    const bool estimated = e != nullptr && s.run >= 0;
    const auto r = static_cast<std::size_t>(std::max(0, s.run));
    text +=
        fmt::format("{},{:.17g},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", i + 1, s.scale,
                    s.outcome.state == SettingState::Completed ? "completed"
                    : s.outcome.state == SettingState::Failed  ? "failed"
                                                               : "not-run",
                    ran ? fmt::format("{}", s.outcome.exit_code) : "",
                    ran ? fmt::format("{:.6g}", s.outcome.wall_seconds) : "",
                    s.status ? fmt::format("{}", s.status->converged_increments()) : "",
                    s.status ? fmt::format("{}", s.status->total_iterations()) : "",
                    s.status ? fmt::format("{}", s.status->cutbacks()) : "",
                    s.status ? fmt::format("{}", setting_work(*s.status)) : "",
                    estimated ? fmt::format("{:.17g}", e->worst_difference[r]) : "",
                    estimated ? fmt::format("{:.17g}", e->worst_estimated[r]) : "",
                    estimated ? (e->estimate_is_bound[r] ? "1" : "0") : "",
                    estimated ? csv_field(e->worst_column[r]) : "", result.chosen == i ? "1" : "0",
                    result.rtol ? fmt::format("{:g}", *result.rtol) : "", csv_field(s.deck),
                    csv_field(state_text(s)));
  }
  return write_file(path, text, error);
}

bool write_columns_csv(const StudyResult& result, const std::string& path, std::string* error) {
  std::string text =
      "setting,scale,column,column_scale,order_status,order,difference_to_finest,"
      "estimated_error\n";
  if (result.estimate) {
    for (const ColumnEstimate& c : result.estimate->columns) {
      for (std::size_t i = 0; i < result.settings.size(); ++i) {
        const StudySetting& s = result.settings[i];
        if (s.run < 0) continue;
        const auto r = static_cast<std::size_t>(s.run);
        text += fmt::format("{},{:.17g},{},{:.17g},{},{},{:.17g},{:.17g}\n", i + 1, s.scale,
                            csv_field(c.name), c.scale, order_text(c.status),
                            c.status == OrderStatus::Observed ? fmt::format("{:.6g}", c.order) : "",
                            c.difference[r], c.estimated[r]);
      }
    }
  }
  return write_file(path, text, error);
}

}  // namespace clinch
