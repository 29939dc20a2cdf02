// *HEADING, the keywords that have no effect in clinch (input-syntax.md §9) and the keywords
// clinch knows but does not support (E0202).
#include <fmt/format.h>

#include "parser/block_context.hpp"
#include "parser/keyword_handler.hpp"
#include "parser/keywords/keyword_families.hpp"

namespace clinch {
namespace {

// *HEADING: the first data line is the title (copied to the .log header).
class HeadingHandler : public KeywordHandler {
 public:
  void data_line(BlockContext& ctx, const DataLine& line, std::vector<Field>&) override {
    if (ctx.model().heading.empty() && !line.blank) ctx.model().heading = std::string(line.text);
  }
};

KeywordSpec no_effect(std::string_view name, KeywordLevel level) {
  KeywordSpec spec;
  spec.name = name;
  spec.keyword_class = KeywordClass::NoEffect;
  spec.level = level;
  spec.data = DataMode::Skip;
  spec.loose_params = true;
  return spec;
}

KeywordSpec not_supported(std::string_view name) {
  KeywordSpec spec;
  spec.name = name;
  spec.keyword_class = KeywordClass::NotSupported;
  spec.level = KeywordLevel::Anywhere;
  spec.data = DataMode::Skip;
  spec.loose_params = true;
  return spec;
}

}  // namespace

std::vector<KeywordSpec> general_keyword_specs() {
  std::vector<KeywordSpec> specs;
  KeywordSpec heading;
  heading.name = "HEADING";
  heading.level = KeywordLevel::Model;
  heading.data = DataMode::Raw;
  heading.make_handler = [] { return std::unique_ptr<KeywordHandler>(new HeadingHandler); };
  specs.push_back(std::move(heading));

  // *PARAMETER is evaluated in the reader's pre-pass (input-syntax.md §6.4); its block only has
  // to be recognised here. *INCLUDE is handled by the reader itself.
  KeywordSpec parameter;
  parameter.name = "PARAMETER";
  parameter.level = KeywordLevel::Anywhere;
  parameter.data = DataMode::Raw;
  specs.push_back(std::move(parameter));

  specs.push_back(no_effect("PREPRINT", KeywordLevel::Model));
  // Abaqus/CAE writes *Restart, write, frequency=0 into every step; only READ matters.
  KeywordSpec restart = no_effect("RESTART", KeywordLevel::ModelOrHistory);
  restart.refused_params = {"READ"};
  restart.refused_reason = "clinch cannot start from a restart of an earlier analysis";
  specs.push_back(std::move(restart));
  specs.push_back(no_effect("FILE FORMAT", KeywordLevel::ModelOrHistory));
  specs.push_back(no_effect("MONITOR", KeywordLevel::History));
  specs.push_back(no_effect("PRINT", KeywordLevel::History));
  specs.push_back(no_effect("DIAGNOSTICS", KeywordLevel::History));
  specs.push_back(no_effect("NODE FILE", KeywordLevel::History));
  specs.push_back(no_effect("EL FILE", KeywordLevel::History));
  specs.push_back(no_effect("ENERGY PRINT", KeywordLevel::History));
  specs.push_back(no_effect("ENERGY FILE", KeywordLevel::History));
  specs.push_back(no_effect("CONTACT FILE", KeywordLevel::History));

  // Known Abaqus/CalculiX keywords that change results and that clinch v1 does not implement
  // (input-syntax.md §9, keywords.md §1).
  for (std::string_view name :
       {"BEAM GENERAL SECTION",
        "TRANSFORM", "SYSTEM", "GAP", "DSLOAD",
        "TEMPERATURE", "TIME POINTS", "NO ANALYSIS", "PARAMETER DEPENDENCE",
        "PARAMETER TABLE", "PARAMETER TABLE TYPE", "PARAMETER SHAPE VARIATION",
        "CONNECTOR UNIAXIAL BEHAVIOR", "CHANGE FRICTION", "SURFACE INTERACTION",
        "CONTACT PAIR", "CONTACT", "TIE", "SURFACE BEHAVIOR", "GRAVITY",
        "USER MATERIAL", "DEPVAR", "USER ELEMENT", "MODEL CHANGE",
        "NODAL THICKNESS", "NORMAL", "ELEMENT MATRIX OUTPUT", "SUBMODEL", "DSFLUX", "CFLUX",
        "FILM", "RADIATE", "CONNECTOR ELEMENT PROPERTY", "DISTRIBUTING COUPLING",
        "SHELL GENERAL SECTION", "COHESIVE SECTION", "GASKET SECTION",
        "HYPERELASTIC", "VISCOELASTIC", "CREEP", "DAMAGE INITIATION", "DAMAGE EVOLUTION",
        "EMBEDDED ELEMENT", "PRE-TENSION SECTION", "FASTENER", "FASTENER PROPERTY",
        "CONTACT PROPERTY ASSIGNMENT", "CONTACT INCLUSIONS", "CONTACT CONTROLS", "CLEARANCE",
        "INERTIA RELIEF", "PHYSICAL CONSTANTS",
        "BASE MOTION", "ELEMENT PROPERTIES", "NODAL ENERGY RATE", "ADAPTIVE MESH",
        "DSECURRENT", "RELEASE", "MOTION", "INITIAL STATE", "IMPORT", "MAP SOLUTION"}) {
    specs.push_back(not_supported(name));
  }
  // Step procedures that clinch does not run (keywords.md §15: *STATIC, *DYNAMIC and *FREQUENCY
  // are run).
  for (std::string_view name :
       {"MODAL DYNAMIC", "STEADY STATE DYNAMICS", "BUCKLE",
        "HEAT TRANSFER", "COUPLED TEMPERATURE-DISPLACEMENT", "VISCO", "GEOSTATIC", "SOILS",
        "RANDOM RESPONSE", "RESPONSE SPECTRUM", "SUBSTRUCTURE GENERATE", "MATRIX GENERATE"}) {
    KeywordSpec spec = not_supported(name);
    spec.refused_procedure = true;
    specs.push_back(std::move(spec));
  }
  return specs;
}

}  // namespace clinch
