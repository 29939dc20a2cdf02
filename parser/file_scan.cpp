#include "parser/file_scan.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace clinch {

LineScanner scan_file(const SourceManager& sources, std::uint32_t index, DiagnosticSink& sink,
                      bool checks) {
  const SourceFile& file = sources.file(index);
  if (!file.on_disk) return LineScanner(file.text, index, sink, checks);
  return LineScanner(std::make_unique<FileWindow>(file.path), index, sink, checks);
}

void check_read_whole(SourceManager& sources, const LineScanner& scanner, std::uint32_t index,
                      DiagnosticSink& sink) {
  const SourceFile& file = sources.file(index);
  if (!file.on_disk || (!scanner.read_failed() && scanner.bytes_read() == file.size)) return;
  if (scanner.read_failed()) {
    sources.note_read_error(fmt::format(
        "cannot read '{}' after {} bytes: {}{}", file.display_name, scanner.bytes_read(),
        scanner.read_error(),
        file.included_from.valid() ? ", included at " + sources.format(file.included_from) : ""));
    return;
  }
  const SourceLoc at = file.included_from.valid()
                           ? file.included_from
                           : SourceLoc{index, std::max<std::uint32_t>(scanner.line_number(), 1), 1};
  sink.report(DiagCode::file_not_found, at,
              !scanner.open_error().empty()
                  ? fmt::format("cannot open '{}': {}", file.display_name, scanner.open_error())
                  : fmt::format("cannot read '{}' whole: it changed while it was read ({} bytes "
                                "when opened, {} read)",
                                file.display_name, file.size, scanner.bytes_read()));
}

}  // namespace clinch
