#include "src/cli/keywords_command.hpp"

#include <iostream>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "base/fold_name.hpp"
#include "base/suggest.hpp"
#include "parser/keyword_registry.hpp"
#include "src/model/connection_types.hpp"
#include "src/cli/keyword_notes.hpp"

namespace clinch {
namespace {

std::string_view class_phrase(KeywordClass keyword_class) {
  switch (keyword_class) {
    case KeywordClass::Supported:
      return "supported";
    case KeywordClass::NoEffect:
      return "read and skipped: no effect on the results (warning keyword-ignored, W0201)";
    case KeywordClass::NotSupported:
      return "refused: known, but not implemented (error unsupported-keyword, E0202)";
  }
  return "";
}

std::string_view level_phrase(KeywordLevel level) {
  switch (level) {
    case KeywordLevel::Anywhere:
      return "anywhere in the deck";
    case KeywordLevel::Model:
      return "model data (before the first *STEP, outside *PART and *ASSEMBLY)";
    case KeywordLevel::ModelGeometry:
      return "model data inside a *PART or the *ASSEMBLY (anywhere before the first *STEP in a "
             "deck without parts)";
    case KeywordLevel::ModelOrHistory:
      return "model data or inside a step";
    case KeywordLevel::History:
      return "inside a step (*STEP ... *END STEP)";
    case KeywordLevel::Block:
      return "opens or closes a block (*PART, *ASSEMBLY, *INSTANCE, *STEP)";
  }
  return "";
}

std::string_view data_mode_phrase(DataMode data) {
  switch (data) {
    case DataMode::None:
      return "none (a data line is an error)";
    case DataMode::Fields:
      return "comma-separated fields";
    case DataMode::Raw:
      return "lines of text, read as written";
    case DataMode::Skip:
      return "skipped";
  }
  return "";
}

// The value a parameter takes, e.g. "=TABULAR | SMOOTH STEP" or "(flag)".
std::string value_phrase(const ParamSpec& param, std::string_view quote) {
  auto quoted = [&](std::string_view text) { return fmt::format("{0}{1}{0}", quote, text); };
  switch (param.kind) {
    case ParamKind::Flag:
      return "flag (no value)";
    case ParamKind::FlagOrYesNo:
      return fmt::format("flag, or ={} or ={}", quoted("YES"), quoted("NO"));
    case ParamKind::Value:
      return "=value";
    case ParamKind::OptionalValue:
      return "flag, or =value";
    case ParamKind::Enum: {
      std::string text = "one of ";
      for (std::size_t i = 0; i < param.values.size(); ++i) {
        if (i > 0) text += ", ";
        text += quoted(param.values[i]);
      }
      return text;
    }
  }
  return "";
}

std::string placement_phrase(const KeywordSpec& spec) {
  if (spec.behavior_suboption) {
    std::string text = "inside a *CONNECTOR BEHAVIOR block (any other keyword closes the block)";
    if (spec.unsupported_outside_behavior) text += "; outside one it is refused";
    return text;
  }
  return std::string(level_phrase(spec.level));
}

std::string component_list(ComponentMask mask) {
  std::string text;
  for (int c = 1; c <= 6; ++c) {
    if ((mask & (1u << (c - 1))) == 0) continue;
    if (!text.empty()) text += " ";
    text += std::to_string(c);
  }
  return text.empty() ? "none" : text;
}

// The connection types of *CONNECTOR SECTION, from the table the kinematics are built from
// (src/model/connection_types.cpp): what runs, with its available and constrained components,
// and what is refused.
void print_connection_types(std::ostream& out, std::string_view bullet, std::string_view quote) {
  for (const ConnectionTypeInfo& type : connection_types()) {
    if (type.support == V1Support::Unsupported) continue;
    out << fmt::format("{}{}{}{}: available components {}; constrained {}{}{}\n", bullet, quote,
                       type.name, quote, component_list(type.available),
                       component_list(type.constrained),
                       type.allowed_2d ? "; also on CONN2D2" : "",
                       type.support == V1Support::Converted ? " (run as CARTESIAN)" : "");
  }
  std::string refused;
  for (const ConnectionTypeInfo& type : connection_types()) {
    if (type.support != V1Support::Unsupported) continue;
    if (!refused.empty()) refused += ", ";
    refused += fmt::format("{0}{1}{0}", quote, type.name);
  }
  out << fmt::format("{}refused, their kinematics not implemented (error unsupported-connection-type, "
                     "E0704): {}\n", bullet, refused);
}

void print_text_details(std::ostream& out, const KeywordSpec& spec) {
  out << fmt::format("*{}: {}\n", spec.name, class_phrase(spec.keyword_class));
  const KeywordNotes* notes = find_keyword_notes(spec.name);
  if (notes != nullptr && !notes->summary.empty()) out << fmt::format("  {}\n", notes->summary);
  if (spec.keyword_class == KeywordClass::NotSupported) return;
  out << fmt::format("Where: {}\n", placement_phrase(spec));
  if (spec.keyword_class == KeywordClass::NoEffect) {
    out << "Parameters and data lines: not checked\n";
    for (std::string_view refused : spec.refused_params) {
      out << fmt::format("Refused: {} ({}; error unsupported-option, E0210)\n", refused,
                         spec.refused_reason);
    }
    return;
  }
  if (spec.params.empty()) {
    out << "Parameters: none\n";
  } else {
    out << "Parameters:\n";
    for (const ParamSpec& param : spec.params) {
      out << fmt::format("  {:<24} {}{}\n", param.name, value_phrase(param, ""),
                         param.required ? " (required)" : "");
    }
  }
  out << fmt::format("Data lines: {}\n", data_mode_phrase(spec.data));
  if (notes != nullptr && !notes->data_lines.empty()) {
    out << fmt::format("  {}\n", notes->data_lines);
  }
  if (spec.name == "CONNECTOR SECTION") {
    out << "Connection types:\n";
    print_connection_types(out, "  ", "");
  }
  if (notes != nullptr && !notes->ignored.empty()) {
    out << "Read and ignored (warning):\n";
    for (const KeywordRefusal& ignored : notes->ignored) {
      out << fmt::format("  {}: {}\n", ignored.what, ignored.why);
    }
  }
  if (notes != nullptr && !notes->refused.empty()) {
    out << "Refused (error unsupported-option, E0210):\n";
    for (const KeywordRefusal& refusal : notes->refused) {
      out << fmt::format("  {}: {}\n", refusal.what, refusal.why);
    }
  }
}

std::vector<const KeywordSpec*> specs_of_class(KeywordClass keyword_class) {
  std::vector<const KeywordSpec*> selected;
  for (const KeywordSpec* spec : KeywordRegistry::instance().specs()) {
    if (spec->keyword_class == keyword_class) selected.push_back(spec);
  }
  return selected;
}

void print_text_list(std::ostream& out) {
  const std::vector<const KeywordSpec*> supported = specs_of_class(KeywordClass::Supported);
  out << fmt::format("Supported keywords ({}; `clinch keywords NAME` for the details):\n",
                     supported.size());
  for (const KeywordSpec* spec : supported) {
    const KeywordNotes* notes = find_keyword_notes(spec->name);
    out << fmt::format("  *{:<34} {}\n", spec->name, notes != nullptr ? notes->summary : "");
  }
  out << "\nRead and skipped, no effect on the results (warning keyword-ignored, W0201):\n";
  for (const KeywordSpec* spec : specs_of_class(KeywordClass::NoEffect)) {
    out << fmt::format("  *{}", spec->name);
    for (std::string_view refused : spec->refused_params) {
      out << fmt::format(" (but {} is refused: {})", refused, spec->refused_reason);
    }
    out << "\n";
  }
  out << "\nRefused: known, but not implemented (error unsupported-keyword, E0202):\n";
  std::string line = " ";
  for (const KeywordSpec* spec : specs_of_class(KeywordClass::NotSupported)) {
    std::string item = fmt::format(" *{}", spec->name);
    if (line.size() + item.size() > 96) {
      out << line << "\n";
      line = " ";
    }
    line += item;
  }
  out << line << "\n";
}

// Prose for markdown: '*' (keyword names), '<', '>' and '_' outside code spans are escaped, so
// that "*CONNECTOR PLASTICITY ... *CONNECTOR POTENTIAL" is not read as emphasis.
std::string markdown_prose(std::string_view text) {
  std::string out;
  bool in_code = false;
  for (char c : text) {
    if (c == '`') in_code = !in_code;
    if (!in_code && (c == '*' || c == '<' || c == '>' || c == '_')) out += '\\';
    out += c;
  }
  return out;
}

// Markdown: `docs/keywords.md`. Table cells never hold a '|' (no parameter value has one).
void print_markdown_details(std::ostream& out, const KeywordSpec& spec) {
  out << fmt::format("### \\*{}\n\n", spec.name);
  const KeywordNotes* notes = find_keyword_notes(spec.name);
  if (notes != nullptr && !notes->summary.empty()) {
    out << markdown_prose(notes->summary) << "\n\n";
  }
  out << fmt::format("Where: {}.\n\n", markdown_prose(placement_phrase(spec)));
  if (spec.params.empty()) {
    out << "Parameters: none.\n\n";
  } else {
    out << "| parameter | value | required |\n|---|---|---|\n";
    for (const ParamSpec& param : spec.params) {
      out << fmt::format("| `{}` | {} | {} |\n", param.name, value_phrase(param, "`"),
                         param.required ? "yes" : "no");
    }
    out << "\n";
  }
  out << fmt::format("Data lines: {}.", data_mode_phrase(spec.data));
  if (notes != nullptr && !notes->data_lines.empty()) {
    out << " " << markdown_prose(notes->data_lines);
  }
  out << "\n\n";
  if (spec.name == "CONNECTOR SECTION") {
    out << "Connection types:\n\n";
    print_connection_types(out, "- ", "`");
    out << "\n";
  }
  if (notes != nullptr && !notes->ignored.empty()) {
    out << "Read and ignored (warning):\n\n";
    for (const KeywordRefusal& ignored : notes->ignored) {
      out << fmt::format("- {}: {}\n", markdown_prose(ignored.what), markdown_prose(ignored.why));
    }
    out << "\n";
  }
  if (notes != nullptr && !notes->refused.empty()) {
    out << "Refused (error `unsupported-option`, E0210):\n\n";
    for (const KeywordRefusal& refusal : notes->refused) {
      out << fmt::format("- {}: {}\n", markdown_prose(refusal.what),
                         markdown_prose(refusal.why));
    }
    out << "\n";
  }
}

void print_markdown(std::ostream& out) {
  out << "# Keywords\n\n"
         "<!-- Generated by `clinch keywords --format markdown` (scripts/update_keywords_doc.sh); "
         "do not edit: the test docs_keywords_current fails when this file differs from the "
         "command's output. -->\n\n"
         "What clinch reads in a deck, from its keyword registry: every keyword it supports, "
         "with its parameters and their allowed values, where it may stand, its data lines and "
         "the options it reads but refuses; then the keywords it reads and skips, and those it "
         "refuses. Names are case-insensitive and blanks in them do not count (`*Connector "
         "Section` is `*CONNECTOR SECTION`); a parameter value may be shortened to a unique "
         "prefix. `*INCLUDE, INPUT=file` inserts a file (anywhere). A refused keyword or option is an error of `clinch check` and `clinch run` "
         "alike, never skipped in silence. `clinch keywords NAME` prints one keyword.\n\n";
  const std::vector<const KeywordSpec*> supported = specs_of_class(KeywordClass::Supported);
  out << fmt::format("## Supported keywords ({})\n\n| keyword | what it does |\n|---|---|\n",
                     supported.size());
  for (const KeywordSpec* spec : supported) {
    const KeywordNotes* notes = find_keyword_notes(spec->name);
    out << fmt::format("| `*{}` | {} |\n", spec->name,
                       notes != nullptr ? markdown_prose(notes->summary) : "");
  }
  out << "\n## Read and skipped (warning `keyword-ignored`, W0201)\n\n"
         "These keywords have no effect on the results; clinch warns and skips their data "
         "lines, whatever their parameters.\n\n";
  for (const KeywordSpec* spec : specs_of_class(KeywordClass::NoEffect)) {
    out << fmt::format("- `*{}`", spec->name);
    for (std::string_view refused : spec->refused_params) {
      out << fmt::format(": `{}` is refused (error `unsupported-option`): {}", refused,
                         spec->refused_reason);
    }
    out << "\n";
  }
  out << "\n## Refused keywords (error `unsupported-keyword`, E0202)\n\n"
         "Keywords of Abaqus or CalculiX that change results and that clinch does not "
         "implement. A deck that holds one is refused with an error that names it.\n\n";
  std::string list;
  for (const KeywordSpec* spec : specs_of_class(KeywordClass::NotSupported)) {
    if (!list.empty()) list += ", ";
    list += fmt::format("`*{}`", spec->name);
  }
  out << list << ".\n\n## Supported keywords in detail\n\n";
  for (const KeywordSpec* spec : supported) print_markdown_details(out, *spec);
}

}  // namespace

int run_keywords(const KeywordsOptions& options) {
  if (!options.name) {
    if (options.format == KeywordsFormat::Markdown) {
      print_markdown(std::cout);
    } else {
      print_text_list(std::cout);
    }
    return 0;
  }
  std::string_view name = *options.name;
  if (!name.empty() && name.front() == '*') name.remove_prefix(1);
  const KeywordRegistry& registry = KeywordRegistry::instance();
  const KeywordSpec* spec = registry.find(fold_name(name));
  if (spec == nullptr) {
    std::cerr << fmt::format("clinch: error: '*{}' is not a keyword clinch knows", name);
    if (auto match = closest_match(fmt::format("*{}", name), registry.display_names())) {
      std::cerr << fmt::format("; did you mean '{}'?", *match);
    }
    std::cerr << "\n";
    return 1;
  }
  if (options.format == KeywordsFormat::Markdown) {
    print_markdown_details(std::cout, *spec);
  } else {
    print_text_details(std::cout, *spec);
  }
  return 0;
}

}  // namespace clinch
