#include "src/cli/check_command.hpp"

#include <cstdio>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/check/check.hpp"
#include "src/cli/blas_threads.hpp"

namespace clinch {

int run_check(const std::string& deck_path, DiagnosticFormat format) {
  stop_idle_blas_threads();
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string io_error;
  if (read_deck_file(deck_path, sources, model, sink, &io_error) == ReadStatus::IoError) {
    if (format == DiagnosticFormat::Json) {
      // The message names the path, which may hold quotes or bytes that are not UTF-8: built as
      // JSON, not pasted into it.
      const nlohmann::json diagnostic = {
          {"file", nullptr},     {"line", nullptr},       {"column", nullptr},
          {"end_column", nullptr}, {"severity", "error"}, {"code", "E0108"},
          {"name", "file-not-found"}, {"message", io_error}, {"notes", nlohmann::json::array()}};
      std::cout << nlohmann::json::array({diagnostic}).dump(
                       2, ' ', false, nlohmann::json::error_handler_t::replace)
                << "\n";
    }
    std::cerr << "clinch: error: " << io_error << "\n";
    return 3;
  }
  report_run_refusals(model, sink);
  sink.sort_by_location();
  if (format == DiagnosticFormat::Json) {
    std::cout << render_json(sink.diagnostics(), sources) << "\n";
  } else {
    for (const Diagnostic& d : sink.diagnostics()) std::cerr << render_text(d, sources);
    if (sink.dropped_count() > 0) {
      std::cerr << fmt::format("clinch: note: {} more diagnostics were not shown\n",
                               sink.dropped_count());
    }
    // The deck is the first file registered: its name as diagnostics show it ("<stdin>" for -).
    std::cerr << fmt::format("{}: {} error{}, {} warning{}\n", sources.file(0).display_name,
                             sink.error_count(), sink.error_count() == 1 ? "" : "s",
                             sink.warning_count(), sink.warning_count() == 1 ? "" : "s");
  }
  return sink.has_errors() ? 1 : 0;
}

}  // namespace clinch
