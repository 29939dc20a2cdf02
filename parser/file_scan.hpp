// Scanning one file of the source table: a file on disk is streamed through a FileWindow (it is
// never held whole), an in-memory buffer is scanned in place; at its end, a file on disk must
// have been read whole, as it was when it was opened.
#pragma once

#include <cstdint>

#include "base/diagnostic.hpp"
#include "parser/lexer.hpp"
#include "parser/source_manager.hpp"

namespace clinch {

LineScanner scan_file(const SourceManager& sources, std::uint32_t index, DiagnosticSink& sink,
                      bool checks = true);

// Called once the scanner is at End: E0108 if the file could not be read whole as it was when it
// was opened (removed, truncated or grown in between), at the *INCLUDE or INPUT= value that
// opened it, or at the last line of the deck itself. A read error (EIO, a sysfs attribute that
// fails) is no fault of the deck but an I/O error: it goes to sources.note_read_error, naming
// the file, and the command exits with 3 (read_deck_file).
void check_read_whole(SourceManager& sources, const LineScanner& scanner, std::uint32_t index,
                      DiagnosticSink& sink);

}  // namespace clinch
