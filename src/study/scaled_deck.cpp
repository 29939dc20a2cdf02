#include "src/study/scaled_deck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace clinch {
namespace {

// A real as the deck reader takes it ("0.25", "1.0", "1e-05").
std::string real_text(double value) {
  std::string text = fmt::format("{}", value);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

std::string static_data_line(const ScaledIncrements& s) {
  if (s.direct) return fmt::format("{}, {}", real_text(s.initial), real_text(s.period));
  return fmt::format("{}, {}, {}, {}", real_text(s.initial), real_text(s.period),
                     real_text(s.minimum), real_text(s.maximum));
}

// Length of a line without its carriage return.
std::size_t content_length(const std::string& line) {
  return !line.empty() && line.back() == '\r' ? line.size() - 1 : line.size();
}

}  // namespace

ScaledIncrements scale_increments(const StaticProcedure& procedure, int max_increments,
                                  double scale) {
  ScaledIncrements s;
  s.direct = procedure.direct;
  s.period = procedure.period;
  s.initial = std::min(procedure.initial_increment, procedure.period) * scale;
  s.maximum = std::max(procedure.max_increment * scale, s.initial);
  s.minimum = std::min(procedure.min_increment, s.initial);
  const double needed = std::ceil(s.period / s.initial * (1.0 - 1e-9));
  const double scaled_limit = std::ceil(max_increments / scale);
  s.max_increments = static_cast<int>(std::min(2147483647.0, std::max(needed, scaled_limit)));
  return s;
}

std::optional<ScaledDeck> ScaledDeck::prepare(const Model& model, const SourceManager& sources,
                                              std::string* error) {
  namespace fs = std::filesystem;
  ScaledDeck deck;
  const std::string_view text = sources.text(0);
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) deck.lines_.emplace_back(text.substr(start));
      break;
    }
    deck.lines_.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  const auto outside_deck = [&](SourceLoc loc, std::string_view what) {
    *error = fmt::format(
        "{}: error: {} lies in an included file: `clinch study` scales the "
        "*STATIC lines of the deck file itself (move the step into it)",
        sources.format(loc), what);
  };
  for (std::size_t i = 0; i < model.history.steps.size(); ++i) {
    const Step& step = model.history.steps[i];
    if (!step.procedure) continue;
    const StaticProcedure& procedure = *step.procedure;
    if (step.loc.file != 0) {
      outside_deck(step.loc, "this *STEP");
      return std::nullopt;
    }
    if (procedure.loc.file != 0) {
      outside_deck(procedure.loc, "this *STATIC");
      return std::nullopt;
    }
    deck.steps_.push_back({procedure, step.max_increments});
    // INC: its value is replaced, or it is added right after the keyword name.
    Edit inc;
    inc.kind = Edit::Kind::StepInc;
    inc.step = deck.steps_.size() - 1;
    if (step.inc_loc.valid()) {
      inc.line = step.inc_loc.line;
      inc.begin = step.inc_loc.column;
      inc.end = step.inc_loc.column + step.inc_loc.length;
    } else {
      const std::string& line = deck.lines_[step.loc.line - 1];
      const std::size_t comma = line.find(',', step.loc.column - 1);
      inc.line = step.loc.line;
      inc.begin = inc.end = (comma == std::string::npos ? content_length(line) : comma) + 1;
    }
    deck.edits_.push_back(inc);
    // The data line: replaced whole, or added after the keyword line and its continuations.
    Edit data;
    data.kind = Edit::Kind::StaticData;
    data.step = deck.steps_.size() - 1;
    if (procedure.data_loc.valid()) {
      data.line = procedure.data_loc.line;
      data.begin = 1;
      data.end = content_length(deck.lines_[data.line - 1]) + 1;
    } else {
      std::size_t line = procedure.loc.line;
      while (line < deck.lines_.size()) {
        const std::string& l = deck.lines_[line - 1];
        const std::size_t last = l.find_last_not_of(" \t\r");
        if (last == std::string::npos || l[last] != ',') break;
        ++line;
      }
      data.line = line;
      data.begin = data.end = content_length(deck.lines_[line - 1]) + 1;
    }
    deck.edits_.push_back(data);
  }
  for (std::uint32_t f = 1; f < sources.file_count(); ++f) {
    const SourceLoc at = sources.file(f).included_from;
    if (!at.valid() || at.file != 0) continue;
    deck.edits_.push_back(Edit{.line = at.line,
                               .begin = at.column,
                               .end = at.column + at.length,
                               .replacement = fs::absolute(sources.file(f).path).string()});
  }
  std::sort(deck.edits_.begin(), deck.edits_.end(), [](const Edit& a, const Edit& b) {
    return a.line != b.line ? a.line < b.line : a.begin < b.begin;
  });
  return deck;
}

std::string ScaledDeck::text(double scale) const {
  std::vector<std::string> lines = lines_;
  // Right to left within a line, so that earlier columns stay valid.
  for (auto it = edits_.rbegin(); it != edits_.rend(); ++it) {
    std::string replacement = it->replacement;
    if (it->kind != Edit::Kind::Fixed) {
      const StepIncrements& s = steps_[it->step];
      const ScaledIncrements scaled = scale_increments(s.procedure, s.max_increments, scale);
      if (it->kind == Edit::Kind::StepInc) {
        replacement = it->begin == it->end ? fmt::format(", INC={}", scaled.max_increments)
                                           : fmt::format("{}", scaled.max_increments);
      } else {
        replacement = it->begin == it->end ? fmt::format("\n{}", static_data_line(scaled))
                                           : static_data_line(scaled);
      }
    }
    std::string& line = lines[it->line - 1];
    line.replace(it->begin - 1, it->end - it->begin, replacement);
  }
  std::string out;
  for (const std::string& line : lines) {
    out += line;
    out += '\n';
  }
  return out;
}

}  // namespace clinch
