// Hands each keyword block to its keyword handler: refuses the unknown, unsupported and misplaced
// keywords and those whose parameters fail, substitutes parameter references, and delivers the
// block's data lines, from the deck or from an INPUT= file (input-syntax.md §2, §3, §5.2, §9).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "base/diagnostic.hpp"
#include "base/source_location.hpp"
#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keyword_registry.hpp"
#include "parser/keyword_spec.hpp"
#include "parser/lexer.hpp"
#include "parser/reader/deck_files.hpp"
#include "parser/reader/deck_structure.hpp"
#include "parser/reader/misspelt_block.hpp"
#include "parser/reader/parameter_substitution.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

class BlockDispatcher {
 public:
  BlockDispatcher(SourceManager& sources, Model& model, DiagnosticSink& sink, DeckFiles& files,
                  ParameterSubstitution& substitution, DeckStructure& structure)
      : sources_(sources),
        model_(model),
        sink_(sink),
        registry_(KeywordRegistry::instance()),
        files_(files),
        substitution_(substitution),
        structure_(structure) {}

  // A keyword line (not *INCLUDE) starts a block; the previous block must be closed first.
  void open(KeywordLine line);
  // Ends the open block (its handler's end()), also before the first keyword line.
  void close();
  // The end of the deck: the last block closes.
  void finish();
  // A keyword line that could not be read: the block before it ends, and the data lines that
  // follow it are skipped.
  void close_unreadable();
  // A data or blank line of the deck.
  void data_line(std::string_view text, SourceLoc loc, bool blank);

 private:
  bool validate_params_with_input(const KeywordSpec& spec, KeywordLine& line, ParamSet& out);
  void read_input_file();
  void deliver_data(std::string_view text, SourceLoc loc, bool blank);
  void remember_refused_name(const KeywordSpec& spec, const KeywordLine& line);

  SourceManager& sources_;
  Model& model_;
  DiagnosticSink& sink_;
  const KeywordRegistry& registry_;
  DeckFiles& files_;
  ParameterSubstitution& substitution_;
  DeckStructure& structure_;
  std::unordered_set<std::string> warned_no_effect_;
  MisspeltBlock misspelt_;

  // The open block: its keyword line, parameters, spec (null when refused), handler and context.
  KeywordLine block_line_;
  ParamSet block_params_;
  const KeywordSpec* block_spec_ = nullptr;
  std::unique_ptr<BlockContext> block_ctx_;
  std::unique_ptr<KeywordHandler> handler_;
  // INPUT=file of the open block, taken out of its parameters before they are validated.
  KeywordParam input_line_param_;
  const KeywordParam* input_param_ = nullptr;
  bool input_used_ = false;  // the data lines came from INPUT=: none may follow in the deck
  bool skip_block_ = false;  // refused: its data lines are only scanned for <name> references
  bool block_open_ = false;  // a keyword line has been read: data lines have a block
  bool data_before_keyword_reported_ = false;
  bool data_line_reported_ = false;
  std::uint32_t block_data_lines_ = 0;
  std::vector<Field> fields_;
};

}  // namespace clinch
