#include "src/study/scaled_deck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace clinch {
namespace {

std::string static_data_line(const ScaledIncrements& s) {
  if (s.direct) return fmt::format("{}, {}", deck_real(s.initial), deck_real(s.period));
  return fmt::format("{}, {}, {}, {}", deck_real(s.initial), deck_real(s.period),
                     deck_real(s.minimum), deck_real(s.maximum));
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
  ScaledDeck deck;
  deck.lines_ = split_deck_lines(sources.text(0));
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
      inc.begin = inc.end = (comma == std::string::npos ? line_content_length(line) : comma) + 1;
    }
    deck.edits_.push_back(inc);
    // The data line: replaced whole, or added after the keyword line and its continuations.
    Edit data;
    data.kind = Edit::Kind::StaticData;
    data.step = deck.steps_.size() - 1;
    if (procedure.data_loc.valid()) {
      data.line = procedure.data_loc.line;
      data.begin = 1;
      data.end = line_content_length(deck.lines_[data.line - 1]) + 1;
    } else {
      std::size_t line = procedure.loc.line;
      while (line < deck.lines_.size()) {
        const std::string& l = deck.lines_[line - 1];
        const std::size_t last = l.find_last_not_of(" \t\r");
        if (last == std::string::npos || l[last] != ',') break;
        ++line;
      }
      data.line = line;
      data.begin = data.end = line_content_length(deck.lines_[line - 1]) + 1;
    }
    deck.edits_.push_back(data);
  }
  deck.includes_ = absolute_include_edits(sources);
  return deck;
}

std::string ScaledDeck::text(double scale) const {
  std::vector<DeckLineEdit> edits = includes_;
  for (const Edit& e : edits_) {
    const StepIncrements& s = steps_[e.step];
    const ScaledIncrements scaled = scale_increments(s.procedure, s.max_increments, scale);
    std::string replacement;
    if (e.kind == Edit::Kind::StepInc) {
      replacement = e.begin == e.end ? fmt::format(", INC={}", scaled.max_increments)
                                     : fmt::format("{}", scaled.max_increments);
    } else {
      replacement = e.begin == e.end ? fmt::format("\n{}", static_data_line(scaled))
                                     : static_data_line(scaled);
    }
    edits.push_back({e.line, e.begin, e.end, std::move(replacement)});
  }
  return apply_line_edits(lines_, std::move(edits));
}

}  // namespace clinch
