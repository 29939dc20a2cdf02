#include "parser/diagnostic_render.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "parser/source_manager.hpp"

namespace clinch {
namespace {

std::string_view severity_word(Severity severity) {
  switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

// The include chain of a location, innermost first: one "included from" note per level.
std::vector<SourceLoc> include_chain(SourceLoc loc, const SourceManager& sources) {
  std::vector<SourceLoc> chain;
  while (loc.valid() && loc.file < sources.file_count()) {
    SourceLoc parent = sources.file(loc.file).included_from;
    if (!parent.valid()) break;
    chain.push_back(parent);
    if (chain.size() > 64) break;
    loc = parent;
  }
  return chain;
}

void append_located(std::string& out, SourceLoc loc, std::string_view severity,
                    std::string_view message, const SourceManager& sources, bool with_caret) {
  if (loc.valid()) {
    out += sources.format(loc);
    out += ": ";
  } else {
    out += "clinch: ";
  }
  out += severity;
  out += ": ";
  out += message;
  out += '\n';
  if (!with_caret || !loc.valid()) return;
  std::string_view line = sources.line_text(loc);
  if (line.empty() || line.size() > 400) return;
  out += ' ';
  // Control and non-ASCII bytes are shown as '?' so that binary input cannot garble a terminal.
  for (char c : line) {
    const auto u = static_cast<unsigned char>(c);
    out += c == '\t' ? c : ((u < 0x20 || u >= 0x7f) ? '?' : c);
  }
  out += "\n ";
  for (std::uint32_t i = 1; i < loc.column && i <= line.size(); ++i) {
    out += line[i - 1] == '\t' ? '\t' : ' ';
  }
  out += '^';
  // The rest of the span underlined, as clang does (^~~~~); a TAB stays a TAB so that the
  // underline keeps its alignment with the line above.
  for (std::uint32_t i = loc.column + 1; i <= loc.end_column() && i <= line.size(); ++i) {
    out += line[i - 1] == '\t' ? '\t' : '~';
  }
  out += '\n';
}

}  // namespace

std::string render_text(const Diagnostic& diagnostic, const SourceManager& sources) {
  std::string out;
  append_located(out, diagnostic.loc, severity_word(diagnostic.severity),
                 fmt::format("{} [{}]", diagnostic.message, diag_code_name(diagnostic.code)),
                 sources, true);
  for (const DiagNote& note : diagnostic.notes) {
    append_located(out, note.loc, "note", note.message, sources, false);
  }
  for (SourceLoc parent : include_chain(diagnostic.loc, sources)) {
    append_located(out, parent, "note",
                   fmt::format("included from {}", sources.format(parent)), sources, false);
  }
  return out;
}

std::string render_json(const std::vector<Diagnostic>& diagnostics,
                        const SourceManager& sources) {
  auto location_fields = [&](nlohmann::json& object, SourceLoc loc) {
    if (loc.valid()) {
      object["file"] = sources.file(loc.file).display_name;
      object["line"] = loc.line;
      object["column"] = loc.column;
      object["end_column"] = loc.end_column();
    } else {
      object["file"] = nullptr;
      object["line"] = nullptr;
      object["column"] = nullptr;
      object["end_column"] = nullptr;
    }
  };
  nlohmann::json array = nlohmann::json::array();
  for (const Diagnostic& diagnostic : diagnostics) {
    nlohmann::json object;
    location_fields(object, diagnostic.loc);
    object["severity"] = severity_word(diagnostic.severity);
    object["code"] = diag_code_id(diagnostic.code);
    object["name"] = diag_code_name(diagnostic.code);
    object["message"] = diagnostic.message;
    nlohmann::json notes = nlohmann::json::array();
    auto add_note = [&](SourceLoc loc, const std::string& message) {
      nlohmann::json note;
      location_fields(note, loc);
      note["message"] = message;
      notes.push_back(std::move(note));
    };
    for (const DiagNote& note : diagnostic.notes) add_note(note.loc, note.message);
    for (SourceLoc parent : include_chain(diagnostic.loc, sources)) {
      add_note(parent, fmt::format("included from {}", sources.format(parent)));
    }
    object["notes"] = std::move(notes);
    array.push_back(std::move(object));
  }
  return array.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace clinch
