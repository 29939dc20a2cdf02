#include "src/study/deck_lines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace clinch {

std::vector<std::string> split_deck_lines(std::string_view text) {
  std::vector<std::string> lines;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.emplace_back(text.substr(start));
      break;
    }
    lines.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::size_t line_content_length(const std::string& line) {
  return !line.empty() && line.back() == '\r' ? line.size() - 1 : line.size();
}

std::vector<DeckLineEdit> absolute_include_edits(const SourceManager& sources) {
  std::vector<DeckLineEdit> edits;
  for (std::uint32_t f = 1; f < sources.file_count(); ++f) {
    const SourceLoc at = sources.file(f).included_from;
    if (!at.valid() || at.file != 0) continue;
    edits.push_back({at.line, at.column, at.column + at.length,
                     std::filesystem::absolute(sources.file(f).path).string()});
  }
  return edits;
}

std::string deck_real(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

std::string apply_line_edits(std::vector<std::string> lines, std::vector<DeckLineEdit> edits) {
  std::sort(edits.begin(), edits.end(), [](const DeckLineEdit& a, const DeckLineEdit& b) {
    return a.line != b.line ? a.line < b.line : a.begin < b.begin;
  });
  // Right to left within a line, so that earlier columns stay valid.
  for (auto it = edits.rbegin(); it != edits.rend(); ++it) {
    lines[it->line - 1].replace(it->begin - 1, it->end - it->begin, it->replacement);
  }
  std::string out;
  for (const std::string& line : lines) {
    out += line;
    out += '\n';
  }
  return out;
}

}  // namespace clinch
