#include "base/diagnostic.hpp"

#include <algorithm>
#include <array>

namespace clinch {
namespace {

struct CodeInfo {
  std::string_view id;
  std::string_view name;
};

constexpr std::array kCodes = {
#define CLINCH_DIAG(code, ident, name) CodeInfo{#code, name},
#include "base/diagnostic_codes.def"
#undef CLINCH_DIAG
};

}  // namespace

std::string_view diag_code_id(DiagCode code) { return kCodes[static_cast<std::size_t>(code)].id; }
std::string_view diag_code_name(DiagCode code) {
  return kCodes[static_cast<std::size_t>(code)].name;
}
Severity diag_code_severity(DiagCode code) {
  return diag_code_id(code)[0] == 'W' ? Severity::Warning : Severity::Error;
}

Diagnostic& DiagnosticSink::report(DiagCode code, SourceLoc loc, std::string message) {
  return report(code, diag_code_severity(code), loc, std::move(message));
}

Diagnostic& DiagnosticSink::report(DiagCode code, Severity severity, SourceLoc loc,
                                   std::string message) {
  if (severity == Severity::Error) {
    ++errors_;
  } else {
    ++warnings_;
  }
  if (diagnostics_.size() >= kMaxStored) {
    ++dropped_;
    overflow_ = Diagnostic{code, severity, loc, {}, {}};
    return overflow_;
  }
  diagnostics_.push_back(Diagnostic{code, severity, loc, std::move(message), {}});
  return diagnostics_.back();
}

void DiagnosticSink::add_note(std::size_t index, DiagNote note) {
  if (index < diagnostics_.size()) diagnostics_[index].notes.push_back(std::move(note));
}

void DiagnosticSink::sort_by_location() {
  std::stable_sort(diagnostics_.begin(), diagnostics_.end(),
                   [](const Diagnostic& a, const Diagnostic& b) {
                     if (a.loc.valid() != b.loc.valid()) return a.loc.valid();
                     if (a.loc.file != b.loc.file) return a.loc.file < b.loc.file;
                     if (a.loc.line != b.loc.line) return a.loc.line < b.loc.line;
                     return a.loc.column < b.loc.column;
                   });
}

}  // namespace clinch
