// The handler of one keyword block. The deck reader's block dispatcher
// (parser/reader/block_dispatcher.hpp) validates the keyword line against the KeywordSpec, then
// calls begin(), data_line() for each data line (split into fields, with <name> substitution
// done), and end(). One handler object per block; state between lines lives in the handler.
// Handlers write plain data into the model (ctx.model()) and report through ctx.
#pragma once

#include <vector>

#include "parser/lexer.hpp"

namespace clinch {

class BlockContext;

class KeywordHandler {
 public:
  virtual ~KeywordHandler() = default;
  virtual void begin(BlockContext& /*ctx*/) {}
  // `fields` are the fields of the line (empty for a blank line); `line` gives its location.
  virtual void data_line(BlockContext& /*ctx*/, const DataLine& /*line*/,
                         std::vector<Field>& /*fields*/) {}
  virtual void end(BlockContext& /*ctx*/) {}
};

}  // namespace clinch
