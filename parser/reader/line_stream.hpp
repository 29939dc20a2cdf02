// The physical lines of a deck, with the files that *INCLUDE splices in (input-syntax.md §5.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "base/diagnostic.hpp"
#include "parser/file_scan.hpp"
#include "parser/lexer.hpp"
#include "parser/source_manager.hpp"

namespace clinch {

// Physical lines of the deck with *INCLUDE splicing: a stack of files being read. The stream
// that first reads a file records where its keyword lines are (SourceManager::begin_layout).
class LineStream {
 public:
  LineStream(SourceManager& sources, DiagnosticSink& sink, bool checks = true)
      : sources_(sources), sink_(sink), checks_(checks) {}

  void push(std::uint32_t file) {
    frames_.push_back(std::make_unique<Frame>(
        Frame{file, scan_file(sources_, file, sink_, checks_), sources_.begin_layout(file)}));
  }
  bool empty() const { return frames_.empty(); }
  std::size_t depth() const { return frames_.size(); }
  std::uint32_t file_at(std::size_t level) const { return frames_[level]->file; }

  // Next line of the innermost open file; pops finished files. End only when all are done.
  LineScanner::Kind next() {
    while (!frames_.empty()) {
      LineScanner::Kind kind = advance(*frames_.back());
      if (kind != LineScanner::Kind::End) return kind;
      frames_.pop_back();
    }
    return LineScanner::Kind::End;
  }
  // Next line of the current file only (continuations must end in the same file, §5.1).
  LineScanner::Kind next_in_file() {
    if (frames_.empty()) return LineScanner::Kind::End;
    return advance(*frames_.back());
  }
  const LineScanner& scanner() const { return frames_.back()->scanner; }

 private:
  struct Frame {
    std::uint32_t file;
    LineScanner scanner;
    bool records_layout;
    bool finished = false;
  };
  LineScanner::Kind advance(Frame& frame) {
    const LineScanner::Kind kind = frame.scanner.next();
    if (kind == LineScanner::Kind::Keyword && frame.records_layout) {
      sources_.record_keyword_line(frame.file, frame.scanner.line_number());
    }
    if (kind == LineScanner::Kind::End && !frame.finished) {
      frame.finished = true;
      if (frame.records_layout) sources_.end_layout(frame.file, frame.scanner.line_number());
      check_read_whole(sources_, frame.scanner, frame.file, sink_);
    }
    return kind;
  }
  SourceManager& sources_;
  DiagnosticSink& sink_;
  bool checks_;
  std::vector<std::unique_ptr<Frame>> frames_;
};

}  // namespace clinch
