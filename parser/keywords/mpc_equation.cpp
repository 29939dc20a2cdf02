// *MPC and *EQUATION (docs/constraints.md "MPCs", "Equations"). The definitions are kept as
// written; resolve_mpc_equations follows their references and builds the constraints.
#include <fmt/format.h>

#include <array>
#include <cctype>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/keyword_families.hpp"

namespace clinch {
namespace {

// A trailing comma leaves an empty last field; it carries nothing.
void drop_trailing_empty(std::vector<Field>& fields) {
  while (!fields.empty() && fields.back().empty()) fields.pop_back();
}

// ---------------------------------------------------------------------------------------------
// *EQUATION: per equation a line `N`, then N terms `node or node set, DOF, coefficient`, at most
// four a line, over as many lines as needed (the manual's *EQUATION data lines).

constexpr std::size_t kTermsPerLine = 4;

class EquationHandler : public KeywordHandler {
 public:
  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (broken_ || line.blank) return;
    drop_trailing_empty(fields);
    if (fields.empty()) return;
    if (expected_ == 0) {
      read_count(ctx, line, fields);
      return;
    }
    if (!ctx.check_field_count(line, fields, 3 * kTermsPerLine,
                               "node, DOF, coefficient: up to four terms a line")) {
      broken_ = true;
      return;
    }
    for (std::size_t i = 0; i < fields.size(); i += 3) {
      if (current_.terms.size() == expected_) {
        ctx.report(DiagCode::too_many_fields, fields[i],
                   fmt::format("the equation declares {} term{}; this line gives more (each "
                               "equation starts with a line holding its number of terms)",
                               expected_, expected_ == 1 ? "" : "s"));
        broken_ = true;
        return;
      }
      if (!read_term(ctx, line, fields, i)) {
        broken_ = true;
        return;
      }
    }
    if (current_.terms.size() == expected_) finish(ctx);
  }

  void end(BlockContext& ctx) override {
    if (broken_ || expected_ == 0) return;
    ctx.report(DiagCode::missing_data_line, current_.count_loc,
               fmt::format("the equation declares {} terms but only {} follow{}", expected_,
                           current_.terms.size(), current_.terms.size() == 1 ? "s" : ""));
  }

 private:
  void read_count(BlockContext& ctx, const DataLine& line, const std::vector<Field>& fields) {
    if (!ctx.check_field_count(line, fields, 1, "the number of terms N of the equation")) {
      broken_ = true;
      return;
    }
    auto n = ctx.integer(fields[0], "number of terms");
    if (!n) {
      broken_ = true;
      return;
    }
    if (*n < 1) {
      ctx.report(DiagCode::value_out_of_range, fields[0],
                 fmt::format("the number of terms of an equation must be at least 1, got {}", *n));
      broken_ = true;
      return;
    }
    current_ = EquationDefinition{};
    current_.count_loc = fields[0].loc;
    expected_ = static_cast<std::size_t>(*n);
  }

  bool read_term(BlockContext& ctx, const DataLine& line, const std::vector<Field>& fields,
                 std::size_t at) {
    static constexpr std::array<std::string_view, 3> kWhat{"node or node set", "DOF",
                                                           "coefficient"};
    for (std::size_t k = 0; k < 3; ++k) {
      if (at + k >= fields.size() || fields[at + k].empty()) {
        ctx.missing(at + k >= fields.size() ? BlockContext::end_of_line(line) : fields[at + k].loc,
                    kWhat[k]);
        return false;
      }
    }
    auto target = ctx.target(fields[at], "node");
    auto dof = ctx.integer(fields[at + 1], "DOF");
    auto coefficient = ctx.real(fields[at + 2], "coefficient");
    if (!target || !dof || !coefficient) return false;
    if (*dof < 1 || *dof > 6) {
      ctx.report(DiagCode::invalid_dof, fields[at + 1],
                 fmt::format("DOF {} is not valid (DOFs are 1-6)", *dof));
      return false;
    }
    // The first nodal variable is the one eliminated: its coefficient divides the others (the
    // manual's "Linear constraint equations": it "should not be set to zero").
    if (current_.terms.empty() && *coefficient == 0.0) {
      ctx.report(DiagCode::value_out_of_range, fields[at + 2],
                 "the coefficient of the first term must not be zero: its DOF is the one the "
                 "equation eliminates");
      return false;
    }
    EquationTermDefinition term;
    term.target = *target;
    term.dof = static_cast<int>(*dof);
    term.coefficient = *coefficient;
    term.dof_loc = fields[at + 1].loc;
    term.coefficient_loc = fields[at + 2].loc;
    current_.terms.push_back(std::move(term));
    return true;
  }

  void finish(BlockContext& ctx) {
    ctx.model().constraints.equation_definitions.push_back(std::move(current_));
    current_ = EquationDefinition{};
    expected_ = 0;
  }

  EquationDefinition current_;
  std::size_t expected_ = 0;  // terms of the open equation; 0: the next line is an `N` line
  bool broken_ = false;       // after an error the rest of the block cannot be paired up
};

// ---------------------------------------------------------------------------------------------
// *MPC: data lines `type, a, b`.

struct MpcTypeName {
  std::string_view name;
  MpcDefinition::Type type;
};
constexpr std::array<MpcTypeName, 4> kMpcTypes{{{"BEAM", MpcDefinition::Type::Beam},
                                                {"LINK", MpcDefinition::Type::Link},
                                                {"PIN", MpcDefinition::Type::Pin},
                                                {"TIE", MpcDefinition::Type::Tie}}};

std::string upper(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c != ' ') out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

class MpcHandler : public KeywordHandler {
 public:
  void begin(BlockContext& ctx) override {
    const ParamSet& params = ctx.params();
    if (params.has("USER")) {
      ctx.report(DiagCode::unsupported_option, params.loc("USER"),
                 "*MPC, USER is not supported by clinch: it has no user subroutines; write the "
                 "constraint as MPC BEAM, LINK, PIN or TIE, an *EQUATION or a connector element");
      refused_ = true;
      return;
    }
    if (params.has("MODE")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("MODE"),
                 "MODE applies to user subroutine MPC only (with USER) and has no effect here");
    }
    if (params.has("ALPHA")) {
      ctx.report(DiagCode::parameter_ignored, params.loc("ALPHA"),
                 "ALPHA (thermal expansion of the constraint) has no effect: clinch applies no "
                 "temperatures");
    }
  }

  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>& fields) override {
    if (refused_ || line.blank) return;
    drop_trailing_empty(fields);
    if (fields.empty()) return;
    if (fields[0].empty()) {
      ctx.missing(fields[0].loc, "MPC type");
      return;
    }
    const std::string written = upper(fields[0].text);
    const MpcTypeName* type = nullptr;
    for (const MpcTypeName& t : kMpcTypes) {
      if (t.name == written) type = &t;
    }
    if (!type) {
      ctx.report(DiagCode::unsupported_option, fields[0],
                 fmt::format("MPC type {} is not supported by clinch: BEAM, LINK, PIN and TIE "
                             "are (a connector element, CONN3D2 or CONN2D2, models the other "
                             "joints)",
                             fields[0].text));
      return;
    }
    if (!ctx.check_field_count(line, fields, 3,
                               "MPC type, node or node set a, node or node set b")) {
      return;
    }
    for (std::size_t k = 1; k <= 2; ++k) {
      if (k >= fields.size() || fields[k].empty()) {
        ctx.missing(k >= fields.size() ? BlockContext::end_of_line(line) : fields[k].loc,
                    k == 1 ? "node or node set a" : "node or node set b");
        return;
      }
    }
    auto first = ctx.target(fields[1], "node");
    auto second = ctx.target(fields[2], "node");
    if (!first || !second) return;
    // The manual's "General multi-point constraints": "If the first entry is a node,
    // subsequent entries must be nodes."
    if (first->is_label && !second->is_label) {
      ctx.report(DiagCode::invalid_value, fields[2],
                 fmt::format("the first entry of this MPC is a node, so the second must be a node "
                             "too, got node set '{}'; give a node set first to constrain a set",
                             second->set_display));
      return;
    }
    MpcDefinition mpc;
    mpc.type = type->type;
    mpc.loc = line.loc;
    mpc.type_loc = fields[0].loc;
    mpc.first = std::move(*first);
    mpc.second = std::move(*second);
    ctx.model().constraints.mpcs.push_back(std::move(mpc));
  }

 private:
  bool refused_ = false;
};

}  // namespace

std::vector<KeywordSpec> mpc_equation_keyword_specs() {
  KeywordSpec equation;
  equation.name = "EQUATION";
  equation.level = KeywordLevel::ModelGeometry;
  equation.make_handler = [] { return std::unique_ptr<KeywordHandler>(new EquationHandler); };

  KeywordSpec mpc;
  mpc.name = "MPC";
  mpc.level = KeywordLevel::ModelGeometry;
  mpc.params = {{"USER", ParamKind::Flag},
                {"MODE", ParamKind::Enum, false, {"DOF", "NODE"}},
                {"ALPHA", ParamKind::Value}};
  mpc.make_handler = [] { return std::unique_ptr<KeywordHandler>(new MpcHandler); };

  std::vector<KeywordSpec> specs;
  specs.push_back(std::move(equation));
  specs.push_back(std::move(mpc));
  return specs;
}

}  // namespace clinch
