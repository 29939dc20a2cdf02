#include "src/fit/parameter_deck.hpp"

#include <fmt/format.h>

#include "base/diagnostic.hpp"
#include "parser/parameters.hpp"
#include "parser/reader/deck_files.hpp"
#include "parser/reader/prepass.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

std::optional<ParameterDeck> ParameterDeck::prepare(const std::string& path,
                                                    const std::vector<std::string>& names,
                                                    std::string* error) {
  SourceManager sources;
  std::optional<std::uint32_t> main = sources.load_deck(path, error);
  if (!main) {
    *error = fmt::format("cannot read '{}': {}", path, *error);
    return std::nullopt;
  }
  // The reader's own pre-pass, run again: the deck has already been checked, so what it reports
  // here is known and dropped.
  DiagnosticSink quiet;
  DeckFiles files(sources, quiet);
  files.add_main(*main);
  ParameterTable parameters;
  Model model;
  run_prepass(*main, sources, files, parameters, model, quiet);
  parameters.evaluate(quiet);

  ParameterDeck deck;
  deck.names_ = names;
  deck.lines_ = split_deck_lines(sources.text(*main));
  for (const std::string& name : names) {
    const ParameterTable::Entry* entry = parameters.use(name);
    if (entry == nullptr) {
      const std::optional<std::string> meant = parameters.suggest(name);
      *error = fmt::format("--vary {}: {} defines no *PARAMETER '{}'{}", name,
                           sources.file(*main).display_name, name,
                           meant ? fmt::format(" (did you mean '{}'?)", *meant) : std::string());
      return std::nullopt;
    }
    if (!entry->ok || !entry->value.is_number()) {
      *error = fmt::format("{}: error: --vary {}: the parameter is not a number",
                           sources.format(entry->loc), name);
      return std::nullopt;
    }
    if (entry->loc.file != *main) {
      *error = fmt::format(
          "{}: error: --vary {}: the parameter is defined in an included file, which the deck "
          "copies of a fit do not change (define it in the deck file itself)",
          sources.format(entry->loc), name);
      return std::nullopt;
    }
    deck.values_.push_back(entry->value.as_double());
    deck.positions_.push_back(sources.format(entry->loc));
    // The definition `name = expression  # comment` is replaced from the name to the line end.
    const std::string& line = deck.lines_[entry->loc.line - 1];
    deck.definitions_.push_back(
        {entry->loc.line, entry->loc.column, line_content_length(line) + 1, std::string()});
  }
  deck.includes_ = absolute_include_edits(sources);
  return deck;
}

std::string ParameterDeck::text(const std::vector<double>& values) const {
  std::vector<DeckLineEdit> edits = includes_;
  for (std::size_t i = 0; i < definitions_.size(); ++i) {
    DeckLineEdit edit = definitions_[i];
    edit.replacement = fmt::format("{} = {}", names_[i], deck_real(values[i]));
    edits.push_back(std::move(edit));
  }
  return apply_line_edits(lines_, std::move(edits));
}

}  // namespace clinch
