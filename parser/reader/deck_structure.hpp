// Where the reader stands in the deck: inside a *PART, the *ASSEMBLY, an *INSTANCE, a *STEP or a
// *CONNECTOR BEHAVIOR block (input-syntax.md §7.1–§7.2), and before or after the first *STEP, which
// separates model data from history data (§8). It decides where each keyword may stand, and
// reports the block keywords that do not pair up.
#pragma once

#include <cstdint>

#include "base/diagnostic.hpp"
#include "base/source_location.hpp"
#include "parser/block_context.hpp"
#include "parser/keyword_spec.hpp"
#include "parser/lexer.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"

namespace clinch {

class DeckStructure {
 public:
  DeckStructure(Model& model, DiagnosticSink& sink, const SourceManager& sources)
      : model_(model), sink_(sink), sources_(sources) {}

  const ReaderPosition& position() const { return position_; }

  // Any keyword that is not a behaviour sub-option closes the behaviour block.
  void leave_behavior() { position_.in_behavior = false; }
  // Any keyword that is not a material sub-option closes the material block.
  void leave_material() { position_.in_material = false; }
  // Any keyword closes the *COUPLING block: *KINEMATIC or *DISTRIBUTING follows it at once.
  void leave_coupling() { position_.in_coupling = false; }

  // Checks where a keyword stands (input-syntax.md §7.1, §8); false when the block is skipped.
  bool check_level(const KeywordSpec& spec, const KeywordLine& line);

  // Opens and closes parts, the assembly, instances, steps and behaviour blocks, even when the
  // block's parameters are bad; `params` are the block's validated parameters (the part's NAME).
  // False when the block is skipped.
  bool enter(const KeywordSpec& spec, const KeywordLine& line, const ParamSet& params);

  // At the end of the deck: blocks left open, and a deck without any *STEP.
  void finish(std::uint32_t main_file);

 private:
  SourceLoc part_loc() const { return model_.parts[position_.part].name.loc; }
  SourceLoc assembly_loc() const { return assembly_loc_; }

  Model& model_;
  DiagnosticSink& sink_;
  const SourceManager& sources_;
  ReaderPosition position_;
  SourceLoc open_step_loc_;
  SourceLoc assembly_loc_;
  bool assembly_seen_ = false;
};

}  // namespace clinch
