// *OUTPUT, *ELEMENT OUTPUT, *NODE OUTPUT (keywords.md §17) and the CalculiX print requests
// *NODE PRINT, *EL PRINT (§18). Identifiers are classified here (unknown E0901, unsupported
// E0904, velocity-type W0904: output-variables.md §1.2, §5); everything that depends on the
// elements of a set (E0902, W0901, W0903, derived components) is checked in resolve_history.
#include <fmt/format.h>

#include "parser/keywords/history_keywords.hpp"
#include "src/model/output_variables.hpp"

namespace clinch {
namespace {

// Reads the identifiers of one data line into `out` (history requests only).
void read_identifiers(BlockContext& ctx, const std::vector<Field>& fields, OutputContext context,
                      std::vector<OutputIdentifier>& out) {
  for (const Field& field : fields) {
    if (field.empty()) continue;
    IdentifierParse parsed = parse_output_identifier(field.text, context);
    switch (parsed.status) {
      case IdentifierStatus::Ok:
        // In a *DYNAMIC step V and A have values (CV and CA are refused there, check.hpp).
        if (parsed.info->producer == OutputProducer::StaticZero &&
            !(ctx.position().in_step && current_step(ctx).dynamic)) {
          ctx.report(DiagCode::output_static_zero, field,
                     fmt::format("{} is always 0 in a static step", field.text));
        }
        parsed.id.loc = field.loc;
        out.push_back(std::move(parsed.id));
        break;
      case IdentifierStatus::Unsupported:
        ctx.report(DiagCode::output_unsupported_variable, field,
                   fmt::format("output variable '{}' is not supported by clinch", field.text));
        break;
      case IdentifierStatus::WrongKind:
        ctx.report(DiagCode::output_unknown_variable, field,
                   fmt::format("unknown output variable '{}' for {}", field.text,
                               ctx.keyword_display()))
            .notes.push_back({field.loc, fmt::format("'{}' is {} output variable; request it "
                                                     "with {}",
                                                     field.text, parsed.kind_hint,
                                                     parsed.request_with)});
        break;
      case IdentifierStatus::Unknown: {
        Diagnostic& d = ctx.report(DiagCode::output_unknown_variable, field,
                                   fmt::format("unknown output variable '{}'", field.text));
        if (!parsed.suggestion.empty()) {
          d.notes.push_back({field.loc, fmt::format("did you mean '{}'?", parsed.suggestion)});
        }
        break;
      }
    }
  }
}

// W0202 for each given parameter of `names` that does not apply to a static connector run.
void warn_ignored_params(BlockContext& ctx, std::initializer_list<std::string_view> names,
                         std::string_view why) {
  for (std::string_view p : names) {
    if (ctx.params().has(p)) {
      ctx.report(DiagCode::parameter_ignored, ctx.params().loc(p),
                 fmt::format("{} has no effect {}", p, why));
    }
  }
}

// A set parameter (ELSET=, NSET=) as a reference.
std::optional<TargetRef> set_param(BlockContext& ctx, std::string_view param, bool element) {
  const Field* value = ctx.params().value(param);
  if (!value) return std::nullopt;
  return ctx.target(*value, element ? "element set" : "node set");
}

// ---- *OUTPUT ----------------------------------------------------------------------------------

class OutputHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    HistoryModel& history = ctx.model().history;
    Step& step = current_step(ctx);
    OutputRequest request;
    request.loc = ctx.keyword().loc;
    if (report_unsupported_params(ctx, {"TIME POINTS"})) {
      // Kept as an ignored request so that the blocks under it are not E0610.
      request.field = true;
      step.outputs.push_back(std::move(request));
      return;
    }
    const bool has_history = params.has("HISTORY");
    const bool has_field = params.has("FIELD");
    warn_ignored_params(ctx, {"FILTER", "MODE LIST", "SENSITIVITY", "DIAGNOSTICS"},
                        "in a static connector analysis");
    if (params.enum_value("TIME MARKS") == "NO") {
      ctx.report(DiagCode::parameter_ignored, params.loc("TIME MARKS"),
                 "TIME MARKS=NO has no effect: clinch ends increments at the output times");
    }
    if (!has_history && !has_field && params.has("DIAGNOSTICS")) {
      // *OUTPUT, DIAGNOSTICS=YES|NO alone is a request about the Abaqus output database.
      request.field = true;
      step.outputs.push_back(std::move(request));
      return;
    }
    if (has_history == has_field) {
      ctx.report(DiagCode::output_kind_missing, ctx.keyword().loc,
                 has_history ? "*OUTPUT takes HISTORY or FIELD, not both"
                             : "*OUTPUT needs HISTORY or FIELD");
      // The blocks under it are then only checked for their sets, like field output.
      request.field = true;
      step.outputs.push_back(std::move(request));
      return;
    }
    request.field = has_field;
    if (has_field) {
      // input-syntax.md §9: one W0902 per deck.
      if (!history.field_output_warned) {
        history.field_output_warned = true;
        ctx.report(DiagCode::field_output_ignored, ctx.keyword().loc,
                   "field output requests are ignored; clinch writes history output only");
      }
      step.outputs.push_back(std::move(request));
      return;
    }

    int given = 0;
    const ParamSet::Entry* second = nullptr;
    const ParamSet::Entry* first = nullptr;
    for (const ParamSet::Entry& entry : params.entries()) {
      const std::string_view n = entry.spec->name;
      if (n == "FREQUENCY" || n == "NUMBER INTERVAL" || n == "TIME INTERVAL") {
        (++given == 1 ? first : second) = &entry;
        if (given == 2) {
          ctx.report(DiagCode::conflicting_parameters, entry.param->loc,
                     fmt::format("{} cannot be combined with {}", n, first->spec->name))
              .notes.push_back(
                  {first->param->loc, fmt::format("{} given here", first->spec->name)});
        }
      }
    }
    if (auto frequency = ctx.integer_param("FREQUENCY")) {
      if (*frequency < 0 || *frequency > 2147483647) {
        ctx.report(DiagCode::value_out_of_range, *params.value("FREQUENCY"),
                   fmt::format("FREQUENCY must be 0 or a positive integer, got {}", *frequency));
      } else {
        request.frequency = static_cast<int>(*frequency);
      }
    }
    if (auto number = ctx.integer_param("NUMBER INTERVAL")) {
      if (*number < 1 || *number > 2147483647) {
        ctx.report(DiagCode::value_out_of_range, *params.value("NUMBER INTERVAL"),
                   fmt::format("NUMBER INTERVAL must be a positive integer, got {}", *number));
      } else {
        request.number_interval = static_cast<int>(*number);
      }
    }
    if (auto interval = ctx.real_param("TIME INTERVAL")) {
      if (!(*interval > 0)) {
        ctx.report(DiagCode::value_out_of_range, *params.value("TIME INTERVAL"),
                   fmt::format("TIME INTERVAL must be positive, got {}",
                               params.value("TIME INTERVAL")->text));
      } else {
        request.time_interval = *interval;
      }
    }
    const std::string_view op = params.enum_value("OP");
    request.op = op == "NEW"       ? OutputRequest::Op::New
                 : op == "REPLACE" ? OutputRequest::Op::Replace
                                   : OutputRequest::Op::Add;
    const std::string_view variable = params.enum_value("VARIABLE");
    request.variables = variable == "PRESELECT" ? OutputRequest::Variables::Preselect
                        : variable == "ALL"     ? OutputRequest::Variables::All
                                                : OutputRequest::Variables::Listed;
    ++history.output_requests;
    if (auto name = ctx.name_param("NAME")) {
      request.name = *name;
    } else {
      const std::string generated = fmt::format("H-Output-{}", history.output_requests);
      request.name = Name{name_key(generated, false), generated, request.loc};
    }
    step.outputs.push_back(std::move(request));
  }
};

// The *OUTPUT request a block (*ELEMENT OUTPUT, *NODE OUTPUT, *ENERGY OUTPUT) belongs to: the
// step's last one; none is an error at the block's keyword.
OutputRequest* open_request(BlockContext& ctx) {
  Step& step = current_step(ctx);
  if (!step.outputs.empty()) return &step.outputs.back();
  ctx.report(DiagCode::output_without_output_keyword, ctx.keyword().loc,
             fmt::format("{} must follow an *OUTPUT keyword in the same step",
                         ctx.keyword_display()));
  return nullptr;
}

// ---- *ELEMENT OUTPUT / *NODE OUTPUT -----------------------------------------------------------

class OutputBlockHandler : public KeywordHandler {
 public:
  explicit OutputBlockHandler(bool element) : element_(element) {}

  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    OutputRequest* open = open_request(ctx);
    if (open == nullptr) {
      skip_ = true;
      return;
    }
    OutputRequest& request = *open;
    field_ = request.field;
    const char* set_name = element_ ? "ELSET" : "NSET";
    if (element_) {
      warn_ignored_params(ctx, {"DIRECTIONS", "POSITION", "REBAR"},
                          "on connector and spring output");
    }
    warn_ignored_params(ctx, {"EXTERIOR"}, "on connector models (no three-dimensional elements)");
    warn_ignored_params(ctx, {"TRACER SET"}, "in a static analysis (Abaqus/Explicit only)");
    std::optional<TargetRef> set = set_param(ctx, set_name, element_);
    if (!params.has(set_name) && !field_) {
      ctx.report(DiagCode::missing_parameter, ctx.keyword().loc,
                 fmt::format("{} requires parameter '{}' in a history request",
                             ctx.keyword_display(), set_name));
      skip_ = true;
      return;
    }
    if (params.has(set_name) && !set) {
      skip_ = true;
      return;
    }
    const bool preselect = params.has("VARIABLE");  // PRESELECT or ALL
    if (element_) {
      ElementOutputRequest block;
      block.loc = ctx.keyword().loc;
      block.has_elset = set.has_value();
      block.preselect = preselect;
      if (set) block.elset = std::move(*set);
      request.elements.push_back(std::move(block));
    } else {
      NodeOutputRequest block;
      block.loc = ctx.keyword().loc;
      block.has_nset = set.has_value();
      if (set) block.nset = std::move(*set);
      // The preselected nodal variables of a static step: U and RF.
      if (preselect) {
        for (std::string_view v : {"U", "RF"}) {
          IdentifierParse parsed = parse_output_identifier(v, OutputContext::NodeOutput);
          parsed.id.loc = params.loc("VARIABLE", true);
          block.identifiers.push_back(std::move(parsed.id));
        }
      }
      request.nodes.push_back(std::move(block));
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    // Field output identifiers are not checked: clinch ignores field output (§17).
    if (skip_ || field_ || line.blank) return;
    OutputRequest& request = current_step(ctx).outputs.back();
    if (element_) {
      read_identifiers(ctx, fields, OutputContext::ElementOutput,
                       request.elements.back().identifiers);
    } else {
      read_identifiers(ctx, fields, OutputContext::NodeOutput, request.nodes.back().identifiers);
    }
  }

 private:
  bool element_;
  bool skip_ = false;
  bool field_ = false;
};

// ---- *ENERGY OUTPUT ---------------------------------------------------------------------------

// Whole-model energies (docs/dynamics.md "Energies"): the listed ones, or with VARIABLE= or no
// data line every energy clinch writes.
class EnergyOutputHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const OutputRequest* open = open_request(ctx);
    if (open == nullptr) {
      skip_ = true;
      return;
    }
    field_ = open->field;
    listed_ = !ctx.params().has("VARIABLE");
    // Energies of an element set (ELSET=) are not written: E0210 at the parameter.
    skip_ = report_unsupported_params(ctx, {"ELSET"});
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || field_ || line.blank) return;
    if (!listed_) {
      ctx.report(DiagCode::unexpected_data_line, line.loc,
                 "*ENERGY OUTPUT with VARIABLE= takes no data lines");
      skip_ = true;
      return;
    }
    read_identifiers(ctx, fields, OutputContext::EnergyOutput,
                     current_step(ctx).outputs.back().energies);
    read_any_ = true;
  }

  void end(BlockContext& ctx) override {
    if (skip_ || field_ || read_any_) return;
    Step& step = current_step(ctx);
    std::vector<OutputIdentifier>& energies = step.outputs.back().energies;
    // ALLSD joins the default set in a step with STABILIZE (docs/stabilization.md).
    const bool stabilized = step.procedure && step.procedure->stabilize;
    for (std::string_view v : {"ALLKE", "ALLIE", "ALLFD", "ALLVD", "ALLSD", "ALLWK", "ETOTAL"}) {
      if (v == "ALLSD" && !stabilized) continue;
      IdentifierParse parsed = parse_output_identifier(v, OutputContext::EnergyOutput);
      parsed.id.loc = ctx.keyword().loc;
      energies.push_back(std::move(parsed.id));
    }
  }

 private:
  bool skip_ = false;
  bool field_ = false;
  bool listed_ = true;
  bool read_any_ = false;
};

// ---- *NODE PRINT / *EL PRINT ------------------------------------------------------------------

class PrintHandler : public KeywordHandler {
 public:
  explicit PrintHandler(bool node) : node_(node) {}

  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    if (report_unsupported_params(ctx, {"TIME POINTS"})) {
      skip_ = true;
      return;
    }
    if (params.has("FREQUENCYF")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("FREQUENCYF"),
                 "FREQUENCYF has no effect in clinch (it controls CalculiX file output)");
    }
    warn_ignored_params(ctx, {"SUMMARY"}, "in clinch (it controls the Abaqus .dat file)");
    warn_ignored_params(ctx, {"POSITION", "DIRECTIONS", "REBAR"},
                        "on connector and spring output");
    PrintRequest request;
    request.node = node_;
    request.loc = ctx.keyword().loc;
    const char* set_name = node_ ? "NSET" : "ELSET";
    if (params.has(set_name)) {
      std::optional<TargetRef> set = set_param(ctx, set_name, !node_);
      if (!set) {
        skip_ = true;
        return;
      }
      request.set = std::move(*set);
      request.has_set = true;
    } else {
      // Without NSET (ELSET) Abaqus prints every node (element) of the model.
      request.all = true;
      request.set.set_display = node_ ? "ALL-NODES" : "ALL-ELEMENTS";
    }
    if (params.has("FREQUENCY")) {
      request.frequency_loc = params.loc("FREQUENCY", true);
      if (auto frequency = ctx.integer_param("FREQUENCY")) {
        if (*frequency < 0 || *frequency > 2147483647) {
          ctx.report(DiagCode::value_out_of_range, *params.value("FREQUENCY"),
                     fmt::format("FREQUENCY must be 0 or a positive integer, got {}", *frequency));
        } else {
          request.frequency = static_cast<int>(*frequency);
        }
      }
    }
    const std::string_view totals = params.enum_value("TOTALS");
    request.totals = totals == "YES"    ? PrintRequest::Totals::Yes
                     : totals == "ONLY" ? PrintRequest::Totals::Only
                                        : PrintRequest::Totals::No;
    Step& step = current_step(ctx);
    // W0906 (§18): each request keeps its own FREQUENCY; warn once per step when they differ.
    bool all_agree = true;
    for (const PrintRequest& other : step.prints) {
      if (other.frequency != step.prints.front().frequency) all_agree = false;
    }
    if (all_agree && !step.prints.empty() && request.frequency != step.prints.front().frequency) {
      const PrintRequest& first = step.prints.front();
      ctx.report(DiagCode::print_frequency_differs,
                 request.frequency_loc.valid() ? request.frequency_loc : request.loc,
                 "FREQUENCY differs between print requests; each request uses its own")
          .notes.push_back({first.frequency_loc.valid() ? first.frequency_loc : first.loc,
                            fmt::format("FREQUENCY={} here", first.frequency)});
    }
    step.prints.push_back(std::move(request));
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (skip_ || line.blank) return;
    read_identifiers(ctx, fields, node_ ? OutputContext::NodePrint : OutputContext::ElPrint,
                     current_step(ctx).prints.back().identifiers);
  }

 private:
  bool node_;
  bool skip_ = false;
};

}  // namespace

std::vector<KeywordSpec> output_keyword_specs() {
  std::vector<KeywordSpec> specs;

  KeywordSpec output;
  output.name = "OUTPUT";
  output.level = KeywordLevel::History;
  output.data = DataMode::None;
  output.params = {
      {"HISTORY", ParamKind::Flag},
      {"FIELD", ParamKind::Flag},
      {"FREQUENCY"},
      {"NUMBER INTERVAL"},
      {"TIME INTERVAL"},
      unsupported_param("TIME POINTS"),
      {"OP", ParamKind::Enum, false, {"ADD", "NEW", "REPLACE"}},
      {"NAME"},
      {"VARIABLE", ParamKind::Enum, false, {"PRESELECT", "ALL"}},
      {"TIME MARKS", ParamKind::FlagOrYesNo},
      {"FILTER"},
      {"MODE LIST"},
      {"SENSITIVITY", ParamKind::FlagOrYesNo},
      {"DIAGNOSTICS", ParamKind::FlagOrYesNo},
  };
  output.make_handler = &make<OutputHandler>;
  specs.push_back(std::move(output));

  KeywordSpec element_output;
  element_output.name = "ELEMENT OUTPUT";
  element_output.level = KeywordLevel::History;
  element_output.params = {
      {"ELSET"},
      {"DIRECTIONS", ParamKind::FlagOrYesNo},
      {"POSITION"},
      {"EXTERIOR", ParamKind::Flag},
      {"REBAR", ParamKind::OptionalValue},
      {"TRACER SET"},
      {"VARIABLE", ParamKind::Enum, false, {"PRESELECT", "ALL"}},
  };
  element_output.make_handler = [] {
    return std::unique_ptr<KeywordHandler>(new OutputBlockHandler(true));
  };
  specs.push_back(std::move(element_output));

  KeywordSpec node_output;
  node_output.name = "NODE OUTPUT";
  node_output.level = KeywordLevel::History;
  node_output.params = {
      {"NSET"},
      {"GLOBAL", ParamKind::FlagOrYesNo},
      {"EXTERIOR", ParamKind::Flag},
      {"TRACER SET"},
      {"VARIABLE", ParamKind::Enum, false, {"PRESELECT", "ALL"}},
  };
  node_output.make_handler = [] {
    return std::unique_ptr<KeywordHandler>(new OutputBlockHandler(false));
  };
  specs.push_back(std::move(node_output));

  KeywordSpec node_print;
  node_print.name = "NODE PRINT";
  node_print.level = KeywordLevel::History;
  node_print.params = {
      {"NSET"},
      {"FREQUENCY"},
      {"TOTALS", ParamKind::Enum, false, {"NO", "YES", "ONLY"}},
      {"GLOBAL", ParamKind::FlagOrYesNo},
      unsupported_param("TIME POINTS"),
      {"FREQUENCYF"},
      {"SUMMARY", ParamKind::FlagOrYesNo},
  };
  node_print.make_handler = [] { return std::unique_ptr<KeywordHandler>(new PrintHandler(true)); };
  specs.push_back(std::move(node_print));

  KeywordSpec el_print;
  el_print.name = "EL PRINT";
  el_print.level = KeywordLevel::History;
  el_print.params = {
      {"ELSET"},
      {"FREQUENCY"},
      {"TOTALS", ParamKind::Enum, false, {"NO", "YES", "ONLY"}},
      {"GLOBAL", ParamKind::FlagOrYesNo},
      unsupported_param("TIME POINTS"),
      {"SUMMARY", ParamKind::FlagOrYesNo},
      {"POSITION", ParamKind::Enum, false,
       {"INTEGRATION POINTS", "CENTROIDAL", "NODES", "AVERAGED AT NODES"}},
      {"DIRECTIONS", ParamKind::FlagOrYesNo},
      {"REBAR", ParamKind::OptionalValue},
  };
  el_print.make_handler = [] { return std::unique_ptr<KeywordHandler>(new PrintHandler(false)); };
  specs.push_back(std::move(el_print));

  KeywordSpec energy_output;
  energy_output.name = "ENERGY OUTPUT";
  energy_output.level = KeywordLevel::History;
  energy_output.params = {
      unsupported_param("ELSET"),
      {"VARIABLE", ParamKind::Enum, false, {"PRESELECT", "ALL"}},
  };
  energy_output.make_handler = [] {
    return std::unique_ptr<KeywordHandler>(new EnergyOutputHandler());
  };
  specs.push_back(std::move(energy_output));
  return specs;
}

}  // namespace clinch
