// Diagnostics: what the reader and the validators report. A Diagnostic has a code from the one
// catalogue (diagnostic_codes.def), a severity, a message, a location and notes. The sink collects
// every diagnostic (input-syntax.md §10: all problems are reported, not only the first); renderers
// turn them into the gcc-style text or the JSON array of cli-contract.md.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/source_location.hpp"

namespace clinch {

enum class DiagCode : unsigned short {
#define CLINCH_DIAG(code, ident, name) ident,
#include "base/diagnostic_codes.def"
#undef CLINCH_DIAG
};

enum class Severity { Error, Warning, Note };

// "E0702", "component-not-available", and whether the code is an error (E) or a warning (W).
std::string_view diag_code_id(DiagCode code);
std::string_view diag_code_name(DiagCode code);
Severity diag_code_severity(DiagCode code);

struct DiagNote {
  SourceLoc loc;  // may be invalid: a note without a location
  std::string message;
};

struct Diagnostic {
  DiagCode code;
  Severity severity;
  SourceLoc loc;
  std::string message;
  std::vector<DiagNote> notes;
};

// Collects diagnostics. Reporting returns the stored diagnostic so that a caller can add notes.
class DiagnosticSink {
 public:
  Diagnostic& report(DiagCode code, SourceLoc loc, std::string message);
  // Same, with an explicit severity (for the few names used both ways, e.g. a warning
  // upgraded to an error when the condition is worse).
  Diagnostic& report(DiagCode code, Severity severity, SourceLoc loc, std::string message);

  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  // Appends a note to the stored diagnostic at `index` in diagnostics(), for a note that is known
  // only later in the reading; nothing when that diagnostic was dropped past the cap.
  void add_note(std::size_t index, DiagNote note);
  std::size_t error_count() const { return errors_; }
  std::size_t warning_count() const { return warnings_; }
  bool has_errors() const { return errors_ > 0; }
  // Diagnostics past the cap are counted but not stored (binary junk can produce one per line).
  std::size_t dropped_count() const { return dropped_; }
  static constexpr std::size_t kMaxStored = 1000;
  // Orders diagnostics by (file order of first appearance, line, column), keeping report order
  // for ties, so output reads top to bottom.
  void sort_by_location();

 private:
  std::vector<Diagnostic> diagnostics_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
  std::size_t dropped_ = 0;
  Diagnostic overflow_;  // receives notes for dropped diagnostics
};

}  // namespace clinch
