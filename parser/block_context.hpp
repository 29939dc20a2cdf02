// What a keyword handler sees of the reader: the keyword line and its validated parameters, the
// model being built, the structural position (part, assembly, step), and typed field readers that
// report bad fields with the diagnostics of input-syntax.md §3.2 (with the "value comes from
// parameter" note of §6.4 for substituted values).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "base/diagnostic.hpp"
#include "parser/keyword_spec.hpp"
#include "parser/lexer.hpp"
#include "parser/source_manager.hpp"
#include "src/model/model.hpp"
#include "src/model/references.hpp"

namespace clinch {

class SourceManager;

// Structural position of the reader (input-syntax.md §7–§8).
struct ReaderPosition {
  std::int32_t part = 0;        // part being defined (0: none, i.e. flat model or assembly level)
  bool in_assembly = false;
  bool in_instance = false;
  bool in_step = false;
  bool after_first_step = false;
  std::int32_t step = -1;       // index of the open (or last) step
  bool in_behavior = false;     // a *CONNECTOR BEHAVIOR block is open (its sub-options follow)
  SourceLoc behavior_loc;       // keyword line of the open (or last) *CONNECTOR BEHAVIOR block
  bool in_material = false;     // a *MATERIAL block is open (its sub-options follow)
  bool in_coupling = false;     // the last keyword was *COUPLING (*KINEMATIC, *DISTRIBUTING follow)
};

class BlockContext {
 public:
  BlockContext(const KeywordLine& keyword, const KeywordSpec& spec, const ParamSet& params,
               Model& model, const ReaderPosition& position, DiagnosticSink& sink,
               const SourceManager& sources)
      : keyword_(keyword), spec_(spec), params_(params), model_(model), position_(position),
        sink_(sink), sources_(sources) {}

  const KeywordLine& keyword() const { return keyword_; }
  const KeywordSpec& spec() const { return spec_; }
  const ParamSet& params() const { return params_; }
  Model& model() { return model_; }
  const ReaderPosition& position() const { return position_; }
  DiagnosticSink& sink() { return sink_; }
  const SourceManager& sources() const { return sources_; }
  // "*CONNECTOR SECTION" as written in messages.
  std::string keyword_display() const;
  // Number of data lines seen so far in this block (the current line included).
  std::uint32_t line_index() const { return line_index_; }
  void set_line_index(std::uint32_t index) { line_index_ = index; }
  // At most this many data lines follow the keyword line in its own file (0 when unknown), for
  // reserving storage.
  std::size_t expected_lines() const { return sources_.lines_after_keyword(keyword_.loc); }

  Diagnostic& report(DiagCode code, SourceLoc loc, std::string message);
  // Reports at a field; adds the note naming the parameter a substituted value came from.
  Diagnostic& report(DiagCode code, const Field& field, std::string message);

  // Typed field readers (input-syntax.md §3.2). `what` names the field in messages. Empty fields
  // return nullopt without a report: callers apply defaults or report E0305 via missing().
  std::optional<std::int64_t> integer(const Field& field, std::string_view what);
  std::optional<double> real(const Field& field, std::string_view what);
  std::optional<Name> name(const Field& field, std::string_view what);
  // A node or element label 1…2147483647, optionally instance-qualified (§7.3).
  std::optional<TargetRef> label_ref(const Field& field, std::string_view what);
  // A node-or-set / element-or-set field.
  std::optional<TargetRef> target(const Field& field, std::string_view what);
  // An enumerated word among `allowed` (canonical spellings; case/blank-insensitive, unique
  // prefixes with W0203); E0208 with did-you-mean otherwise.
  std::optional<std::string> word(const Field& field, std::span<const std::string_view> allowed,
                                  std::string_view what);
  // E0305 "missing value for '<what>' of *KEYWORD" at the field (or at `where` if the line is
  // shorter).
  void missing(SourceLoc where, std::string_view what);
  // E0304 at the first extra field when a line has more than `max_fields` fields.
  bool check_field_count(const DataLine& line, const std::vector<Field>& fields,
                         std::size_t max_fields, std::string_view layout);
  // Location just after the last field of a line (where a missing field would start).
  static SourceLoc end_of_line(const DataLine& line);

  // Parameter value readers: the same checks on the value of parameter `param_name`.
  std::optional<double> real_param(std::string_view param_name);
  std::optional<std::int64_t> integer_param(std::string_view param_name);
  std::optional<Name> name_param(std::string_view param_name);

 private:
  const KeywordLine& keyword_;
  const KeywordSpec& spec_;
  const ParamSet& params_;
  Model& model_;
  const ReaderPosition& position_;
  DiagnosticSink& sink_;
  const SourceManager& sources_;
  std::uint32_t line_index_ = 0;
};

// Parses a real with the rules of input-syntax.md §3.2 (Fortran D exponents, no inf/nan/hex).
// Returns false if the text is not a number; sets *overflow when it does not fit a double.
bool parse_real_text(std::string_view text, double& value, bool* overflow);
// Parses an optionally signed decimal integer; false if not one (or out of int64 range).
bool parse_integer_text(std::string_view text, std::int64_t& value);

}  // namespace clinch
