// The deck reader is two passes over the deck's lines (parser/reader/line_stream.hpp), with the
// deck's files loaded once (deck_files.hpp). The first pass (prepass.hpp) collects the *PARAMETER
// definitions, which are then evaluated; the second joins continued keyword lines and hands each
// block to the dispatcher (block_dispatcher.hpp), which checks the keyword line
// (keyword_checks.hpp) and where it stands (deck_structure.hpp), substitutes parameter references
// (parameter_substitution.hpp) and calls the keyword's handler.
#include "parser/deck_reader.hpp"

#include <fmt/format.h>

#include <deque>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "parser/lexer.hpp"
#include "parser/parameters.hpp"
#include "parser/reader/block_dispatcher.hpp"
#include "parser/reader/deck_files.hpp"
#include "parser/reader/deck_structure.hpp"
#include "parser/reader/line_stream.hpp"
#include "parser/reader/parameter_substitution.hpp"
#include "parser/reader/prepass.hpp"
#include "src/check/check.hpp"
#include "src/resolve/resolve.hpp"

namespace clinch {
namespace {

class Reader {
 public:
  Reader(SourceManager& sources, Model& model, DiagnosticSink& sink)
      : sources_(sources),
        model_(model),
        sink_(sink),
        files_(sources, sink),
        substitution_(parameters_, sink),
        structure_(model, sink, sources),
        blocks_(sources, model, sink, files_, substitution_, structure_) {}

  void run(std::uint32_t main_file) {
    files_.add_main(main_file);
    run_prepass(main_file, sources_, files_, parameters_, model_, sink_);
    parameters_.evaluate(sink_);
    LineStream stream(sources_, sink_);
    stream.push(main_file);
    read_lines(stream);
    blocks_.finish();
    structure_.finish(main_file);
    parameters_.report_unused(sink_);
  }

 private:
  void read_lines(LineStream& stream) {
    while (true) {
      LineScanner::Kind kind = stream.next();
      if (kind == LineScanner::Kind::End) break;
      if (stream.scanner().line_rejected() && kind != LineScanner::Kind::Comment) continue;
      switch (kind) {
        case LineScanner::Kind::Comment:
          break;
        case LineScanner::Kind::Keyword:
          keyword_line(stream);
          break;
        case LineScanner::Kind::Blank:
        case LineScanner::Kind::Data:
          blocks_.data_line(stream.scanner().text(), stream.scanner().loc(),
                            kind == LineScanner::Kind::Blank);
          break;
        case LineScanner::Kind::End:
          break;
      }
    }
  }

  // Joins a keyword line with its continuation lines (input-syntax.md §2.1).
  void keyword_line(LineStream& stream) {
    std::vector<KeywordSegment> segments;
    segments.push_back({stream.scanner().text(), stream.scanner().loc()});
    auto ends_with_comma = [](std::string_view t) {
      std::size_t e = t.size();
      while (e > 0 && (t[e - 1] == ' ' || t[e - 1] == '\t')) --e;
      return e > 0 && t[e - 1] == ',';
    };
    // A line's text lasts only until the scanner moves on: a continued keyword line keeps copies.
    std::deque<std::string> held;
    while (ends_with_comma(segments.back().text)) {
      if (held.size() < segments.size()) {
        segments.back().text = held.emplace_back(segments.back().text);
      }
      SourceLoc last =
          segments.back().loc.shifted(static_cast<std::uint32_t>(segments.back().text.size()));
      LineScanner::Kind k;
      do {
        k = stream.next_in_file();
      } while (k == LineScanner::Kind::Comment);
      if (k == LineScanner::Kind::End) {
        sink_.report(DiagCode::dangling_continuation, last.shifted(static_cast<std::uint32_t>(-1)),
                     "keyword line ends with ',' but no continuation line follows");
        break;
      }
      if (k == LineScanner::Kind::Keyword) {
        sink_.report(DiagCode::dangling_continuation, last.shifted(static_cast<std::uint32_t>(-1)),
                     "keyword line ends with ',' but the next line is a keyword line");
        // That next line is a keyword line of its own: process the current one, then it.
        process_keyword(segments);
        keyword_line(stream);
        return;
      }
      if (k == LineScanner::Kind::Blank) continue;
      segments.push_back({stream.scanner().text(), stream.scanner().loc()});
    }
    process_keyword(segments, &stream);
  }

  void process_keyword(const std::vector<KeywordSegment>& segments, LineStream* stream = nullptr) {
    KeywordLine line;
    if (!parse_keyword_line(segments, line, sink_)) {
      blocks_.close_unreadable();
      return;
    }
    if (line.name == "INCLUDE") {
      if (stream) files_.include(line, *stream);
      return;
    }
    blocks_.close();
    blocks_.open(std::move(line));
  }

  SourceManager& sources_;
  Model& model_;
  DiagnosticSink& sink_;
  ParameterTable parameters_;
  DeckFiles files_;
  ParameterSubstitution substitution_;
  DeckStructure structure_;
  BlockDispatcher blocks_;
};

// Once the deck is read: fill the model (src/resolve/), then check the rules that read it.
void resolve_and_check(Model& model, DiagnosticSink& sink) {
  resolve_model(model, sink);
  check_model(model, sink);
}

}  // namespace

ReadStatus read_deck_file(const std::string& path, SourceManager& sources, Model& model,
                          DiagnosticSink& sink, std::string* io_error) {
  std::string error;
  auto idx = sources.load_deck(path, &error);
  if (!idx) {
    if (io_error) *io_error = fmt::format("cannot read '{}': {}", path, error);
    return ReadStatus::IoError;
  }
  Reader(sources, model, sink).run(*idx);
  if (!sources.read_error().empty()) {
    // The deck read is not the deck on disk: its diagnostics would describe a truncated deck.
    if (io_error) *io_error = sources.read_error();
    return ReadStatus::IoError;
  }
  resolve_and_check(model, sink);
  return ReadStatus::Ok;
}

void read_deck_text(const std::string& display_name, std::string text, SourceManager& sources,
                    Model& model, DiagnosticSink& sink) {
  std::uint32_t idx = sources.add_buffer(display_name, std::move(text));
  Reader(sources, model, sink).run(idx);
  resolve_and_check(model, sink);
}

}  // namespace clinch
