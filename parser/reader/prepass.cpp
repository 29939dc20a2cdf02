#include "parser/reader/prepass.hpp"

#include <string>
#include <vector>

#include "parser/file_scan.hpp"
#include "parser/lexer.hpp"
#include "parser/reader/line_stream.hpp"

namespace clinch {

void run_prepass(std::uint32_t main_file, SourceManager& sources, DeckFiles& files,
                 ParameterTable& parameters, Model& model, DiagnosticSink& sink) {
  DiagnosticSink quiet;
  LineStream stream(sources, quiet, /*checks=*/false);
  stream.push(main_file);
  bool in_parameter = false;
  std::vector<KeywordSegment> segments;
  while (true) {
    LineScanner::Kind kind = stream.next();
    if (kind == LineScanner::Kind::End) break;
    if (kind == LineScanner::Kind::Comment) continue;
    if (kind == LineScanner::Kind::Keyword) {
      KeywordLine line;
      segments.assign(1, {stream.scanner().text(), stream.scanner().loc()});
      if (!parse_keyword_line(segments, line, quiet)) {
        in_parameter = false;
        continue;
      }
      if (line.name == "INCLUDE") {
        in_parameter = false;
        for (const KeywordParam& p : line.params) {
          if (p.name != "INPUT" || !p.has_value || stream.depth() > kMaxIncludeDepth) continue;
          std::string path = files.resolve(stream.scanner().loc().file, p.value.text);
          auto idx = files.try_load(path, p.value.loc);
          if (idx) stream.push(*idx);
        }
        continue;
      }
      if (line.name == "PART" || line.name == "ASSEMBLY") model.part_assembly = true;
      in_parameter = line.name == "PARAMETER";
      if (in_parameter) {
        for (const KeywordParam& p : line.params) {
          if (p.name != "INPUT" || !p.has_value) continue;
          std::string path = files.resolve(stream.scanner().loc().file, p.value.text);
          auto idx = files.try_load(path, p.value.loc);
          if (!idx) continue;
          LineScanner scanner = scan_file(sources, *idx, quiet);
          for (auto k = scanner.next(); k != LineScanner::Kind::End; k = scanner.next()) {
            if (k == LineScanner::Kind::Data) {
              parameters.add_line({std::string(scanner.text()), scanner.loc()});
            }
          }
          check_read_whole(sources, scanner, *idx, sink);
        }
      }
      continue;
    }
    if (in_parameter && kind == LineScanner::Kind::Data) {
      parameters.add_line({std::string(stream.scanner().text()), stream.scanner().loc()});
    }
  }
}

}  // namespace clinch
