// History data (keywords.md §8–§18): the CalculiX spring decks check clean and fill the step
// model as expected; *STATIC defaults, carried-over NLGEOM and controls, amplitudes, boundary
// conditions across steps, connector motions, and the output-identifier catalogue.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/support/external_decks.hpp"
#include "parser/deck_reader.hpp"
#include "parser/diagnostic_render.hpp"
#include "src/model/output_variables.hpp"

namespace clinch {
namespace {

struct Read {
  SourceManager sources;
  DiagnosticSink sink;
  Model model;
  std::string listing() const {
    std::string out;
    for (const Diagnostic& d : sink.diagnostics()) out += render_text(d, sources);
    return out;
  }
  std::size_t count(DiagCode code) const {
    return static_cast<std::size_t>(
        std::count_if(sink.diagnostics().begin(), sink.diagnostics().end(),
                      [&](const Diagnostic& d) { return d.code == code; }));
  }
  const Diagnostic* find(DiagCode code, std::uint32_t line = 0) const {
    for (const Diagnostic& d : sink.diagnostics()) {
      if (d.code == code && (line == 0 || d.loc.line == line)) return &d;
    }
    return nullptr;
  }
};

std::unique_ptr<Read> read_text(const std::string& text) {
  auto r = std::make_unique<Read>();
  read_deck_text("deck.inp", text, r->sources, r->model, r->sink);
  return r;
}

std::unique_ptr<Read> read_external(const std::string& name) {
  const std::string path = std::string(CLINCH_SHARED_DIR) + "/external-decks/" + name;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::stringstream buffer;
  buffer << in.rdbuf();
  auto r = std::make_unique<Read>();
  read_deck_text(name, buffer.str(), r->sources, r->model, r->sink);
  return r;
}

// A two-node SPRINGA model (DOFs 1–3 active at both nodes) before the steps.
const std::string kSpringModel =
    "*NODE, NSET=ALL\n"
    "1, 0., 0., 0.\n"
    "2, 1., 0., 0.\n"
    "*ELEMENT, TYPE=SPRINGA, ELSET=S\n"
    "1, 1, 2\n"
    "*SPRING, ELSET=S\n"
    "\n"
    "10.\n"
    "*BOUNDARY\n"
    "1, 1, 3\n";

TEST(History, CalculixSpringDecksCheckWithoutErrors) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  for (const char* name :
       {"ccx-spring1.inp", "ccx-spring2.inp", "ccx-spring6.inp", "ccx-spring7.inp"}) {
    auto r = read_external(name);
    EXPECT_EQ(r->sink.error_count(), 0u) << name << "\n" << r->listing();
    ASSERT_EQ(r->model.history.steps.size(), 1u) << name;
    const Step& step = r->model.history.steps[0];
    EXPECT_TRUE(step.nlgeom) << name;
    EXPECT_TRUE(step.closed);
    ASSERT_TRUE(step.procedure.has_value());
    // *STATIC without a data line: Δt₀ = T = 1, Δt_min = 1e-5·T, Δt_max = T (§15).
    EXPECT_DOUBLE_EQ(step.procedure->period, 1.0);
    EXPECT_DOUBLE_EQ(step.procedure->initial_increment, 1.0);
    EXPECT_DOUBLE_EQ(step.procedure->min_increment, 1e-5);
    EXPECT_DOUBLE_EQ(step.procedure->max_increment, 1.0);
    EXPECT_EQ(r->model.history.model_boundaries.size(), 2u);
    ASSERT_EQ(step.prints.size(), 1u);
    EXPECT_TRUE(step.prints[0].node);
    ASSERT_EQ(step.prints[0].identifiers.size(), 1u);
    // *NODE PRINT U / RF: translations only, as CalculiX prints them (§18).
    EXPECT_EQ(step.prints[0].identifiers[0].components, 0b000111);
  }
}

TEST(History, CalculixSpringDecksGiveOnlyTheWarningsTheSpecDemands) {
  CLINCH_SKIP_WITHOUT_EXTERNAL_DECKS();
  // spring1/spring2: SPRINGA uses DOFs 1–3 of both nodes; nothing to warn about.
  EXPECT_EQ(read_external("ccx-spring1.inp")->sink.diagnostics().size(), 0u);
  EXPECT_EQ(read_external("ccx-spring2.inp")->sink.diagnostics().size(), 0u);
  // spring6: node 1 belongs to no element (W0502), SPRING1 uses only DOF 1 of node 2 (W0803).
  auto six = read_external("ccx-spring6.inp");
  EXPECT_NE(six->find(DiagCode::node_without_element, 14), nullptr) << six->listing();
  EXPECT_NE(six->find(DiagCode::inactive_dof, 15), nullptr) << six->listing();
  EXPECT_EQ(six->sink.warning_count(), 2u) << six->listing();
  // spring7: SPRING2 on DOF 1 of both nodes; the step's loads and BCs are stored.
  auto seven = read_external("ccx-spring7.inp");
  const Step& step = seven->model.history.steps.at(0);
  ASSERT_EQ(step.boundaries.size(), 2u);
  EXPECT_EQ(step.boundaries[0].dofs, 0b1);
  EXPECT_DOUBLE_EQ(step.boundaries[0].magnitude, 2.0);
  EXPECT_EQ(seven->count(DiagCode::inactive_dof), 3u) << seven->listing();
  auto one = read_external("ccx-spring1.inp");
  ASSERT_EQ(one->model.history.steps[0].loads.size(), 1u);
  EXPECT_EQ(one->model.history.steps[0].loads[0].dof, 1);
  EXPECT_DOUBLE_EQ(one->model.history.steps[0].loads[0].magnitude, 1.0);
}

TEST(History, StaticDefaultsAreResolved) {
  auto r = read_text(kSpringModel +
                     "*STEP\n*STATIC\n0.1, 2.\n*END STEP\n"
                     "*STEP, INC=5\n*STATIC, DIRECT=NO STOP\n0.5, 2.\n*END STEP\n");
  EXPECT_FALSE(r->sink.has_errors()) << r->listing();
  ASSERT_EQ(r->model.history.steps.size(), 2u);
  const StaticProcedure& p = *r->model.history.steps[0].procedure;
  EXPECT_DOUBLE_EQ(p.initial_increment, 0.1);
  EXPECT_DOUBLE_EQ(p.period, 2.0);
  EXPECT_DOUBLE_EQ(p.min_increment, 2e-5);
  EXPECT_DOUBLE_EQ(p.max_increment, 2.0);
  const StaticProcedure& q = *r->model.history.steps[1].procedure;
  EXPECT_TRUE(q.direct);
  EXPECT_TRUE(q.no_stop);
  EXPECT_EQ(r->model.history.steps[1].max_increments, 5);
  EXPECT_EQ(r->model.history.steps[1].name.display, "Step-2");
}

TEST(History, DirectIncrementCountToleratesRoundOff) {
  // 1/0.1 is 10 up to round-off: exactly INC=10 increments, no E0806.
  auto ok = read_text(kSpringModel + "*STEP, INC=10\n*STATIC, DIRECT\n0.1, 1.\n*END STEP\n");
  EXPECT_EQ(ok->count(DiagCode::too_many_direct_increments), 0u) << ok->listing();
  auto bad = read_text(kSpringModel + "*STEP, INC=10\n*STATIC, DIRECT\n0.09, 1.\n*END STEP\n");
  const Diagnostic* d = bad->find(DiagCode::too_many_direct_increments);
  ASSERT_NE(d, nullptr) << bad->listing();
  EXPECT_NE(d->message.find("needs 12 increments but INC=10"), std::string::npos) << d->message;
}

TEST(History, NlgeomAndControlsCarryOver) {
  auto r = read_text(kSpringModel +
                     "*STEP, NLGEOM\n*STATIC\n"
                     "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n6, 9, , 20\n, 0.4, , , , , 2.\n"
                     "*CONTROLS, PARAMETERS=FIELD, FIELD=ROTATION\n0.001\n"
                     "*END STEP\n"
                     "*STEP\n*STATIC\n*END STEP\n"
                     "*STEP, NLGEOM=NO\n*STATIC\n*CONTROLS, RESET\n*END STEP\n");
  EXPECT_EQ(r->sink.error_count(), 0u) << r->listing();
  EXPECT_EQ(r->count(DiagCode::nlgeom_stays_on), 1u);
  const auto& steps = r->model.history.steps;
  ASSERT_EQ(steps.size(), 3u);
  for (const Step& s : steps) EXPECT_TRUE(s.nlgeom);
  EXPECT_EQ(steps[0].controls.time.i0, 6);
  EXPECT_EQ(steps[0].controls.time.ir, 9);
  EXPECT_EQ(steps[0].controls.time.ip, 9);  // blank keeps the current value
  EXPECT_EQ(steps[0].controls.time.ic, 20);
  EXPECT_DOUBLE_EQ(steps[0].controls.time.dc, 0.4);
  EXPECT_DOUBLE_EQ(steps[0].controls.time.dd, 2.0);
  EXPECT_DOUBLE_EQ(steps[0].controls.rotation.residual, 0.001);
  EXPECT_DOUBLE_EQ(steps[0].controls.translation.residual, 0.005);
  // Step 2 inherits, step 3 resets.
  EXPECT_EQ(steps[1].controls.time.ic, 20);
  EXPECT_DOUBLE_EQ(steps[1].controls.rotation.residual, 0.001);
  EXPECT_EQ(steps[2].controls.time.ic, 16);
  EXPECT_DOUBLE_EQ(steps[2].controls.rotation.residual, 0.005);
}

TEST(History, AmplitudesAreScaledAndGenerated) {
  auto r = read_text(kSpringModel +
                     "*AMPLITUDE, NAME=A, SCALEX=2., SHIFTY=1., TIME=TOTAL TIME\n"
                     "0., 0., 1., 1.\n"
                     "*AMPLITUDE, NAME=EQ, DEFINITION=EQUALLY SPACED, FIXED INTERVAL=0.5, "
                     "BEGIN=1.\n0., 2., 4.\n"
                     "*STEP\n*STATIC\n*CLOAD, AMPLITUDE=a\n2, 1, 1.\n"
                     "*CLOAD, AMPLITUDE=EQ, OP=NEW\n2, 2, 1.\n*END STEP\n");
  EXPECT_EQ(r->sink.diagnostics().size(), 1u) << r->listing();  // W0805 (mixed OP) only
  EXPECT_EQ(r->count(DiagCode::mixed_op), 1u);
  const auto& amplitudes = r->model.history.amplitudes;
  ASSERT_EQ(amplitudes.size(), 2u);
  EXPECT_TRUE(amplitudes[0].total_time);
  EXPECT_EQ(amplitudes[0].times, (std::vector<double>{0., 2.}));
  EXPECT_EQ(amplitudes[0].values, (std::vector<double>{1., 2.}));
  EXPECT_EQ(amplitudes[1].times, (std::vector<double>{1., 1.5, 2.}));
  EXPECT_EQ(amplitudes[1].values, (std::vector<double>{0., 2., 4.}));
  const Step& step = r->model.history.steps[0];
  ASSERT_EQ(step.blocks.size(), 2u);
  EXPECT_EQ(step.blocks[0].amplitude_index, 0);
  EXPECT_EQ(step.blocks[1].amplitude_index, 1);
  EXPECT_TRUE(step.replaces(ConditionKind::Load));
  EXPECT_FALSE(step.replaces(ConditionKind::Boundary));
}

TEST(History, OpNewRemovesEarlierBoundaryConditions) {
  // After OP=NEW in step 2, node 2 DOF 1 is no longer prescribed: the load there is not W0801.
  auto r = read_text(kSpringModel +
                     "*STEP\n*STATIC\n*BOUNDARY\n2, 1, 1, 0.5\n*CLOAD\n2, 1, 1.\n*END STEP\n"
                     "*STEP\n*STATIC\n*BOUNDARY, OP=NEW\n1, PINNED\n*CLOAD\n2, 1, 1.\n"
                     "*END STEP\n");
  EXPECT_EQ(r->sink.error_count(), 0u) << r->listing();
  ASSERT_EQ(r->count(DiagCode::load_on_prescribed_dof), 1u) << r->listing();
  EXPECT_EQ(r->find(DiagCode::load_on_prescribed_dof)->loc.line, 16u);
  const BoundaryCondition& pinned = r->model.history.steps[1].boundaries.at(0);
  EXPECT_EQ(pinned.named_type, "PINNED");
  EXPECT_EQ(pinned.dofs, 0b000111);
}

TEST(History, NamedTypesIn2DApplyOnlyDofs126) {
  auto r = read_text(
      "*NODE\n1, 0., 0.\n2, 1., 0.\n*ELEMENT, TYPE=CONN2D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C\nROTATION\n*BOUNDARY\n1, ENCASTRE\n2, XSYMM\n"
      "*STEP\n*STATIC\n*CONNECTOR MOTION\nC, 6, 0.1\n*END STEP\n");
  EXPECT_EQ(r->sink.diagnostics().size(), 0u) << r->listing();
  ASSERT_EQ(r->model.history.steps[0].motions.size(), 1u);
  EXPECT_EQ(r->model.history.steps[0].motions[0].component, 6);
}

TEST(History, ModelDataMotionAndBlocks) {
  auto r = read_text(
      "*NODE\n1, 0., 0., 0.\n2, 1., 0., 0.\n*ELEMENT, TYPE=CONN3D2, ELSET=C\n1, 1, 2\n"
      "*CONNECTOR SECTION, ELSET=C\nAXIAL\n*BOUNDARY\n1, 1, 3\n2, 2, 3\n"
      "*CONNECTOR MOTION\nC, 1\n"
      "*STEP\n*STATIC\n*CONNECTOR MOTION, OP=NEW\nC, 1, 0.2\n*END STEP\n");
  EXPECT_EQ(r->sink.diagnostics().size(), 0u) << r->listing();
  const HistoryModel& h = r->model.history;
  ASSERT_EQ(h.model_motions.size(), 1u);
  EXPECT_DOUBLE_EQ(h.model_motions[0].magnitude, 0.0);
  ASSERT_EQ(h.model_blocks.size(), 2u);
  EXPECT_EQ(h.model_blocks[1].kind, ConditionKind::Motion);
  EXPECT_TRUE(h.steps[0].replaces(ConditionKind::Motion));
  EXPECT_DOUBLE_EQ(h.steps[0].motions.at(0).magnitude, 0.2);
}

TEST(History, StepWithBadParametersStillCollectsItsData) {
  // The *STEP line fails (unknown parameter), so its handler never runs; the history data of
  // that step still goes into a placeholder step, and the step after it is the second one.
  auto r = read_text(kSpringModel +
                     "*STEP, NAMEE=X\n*STATIC\n*CLOAD\n2, 1, 1.\n*END STEP\n"
                     "*STEP, NAME=Two\n*STATIC\n*END STEP\n");
  EXPECT_EQ(r->count(DiagCode::unknown_parameter), 1u) << r->listing();
  EXPECT_EQ(r->count(DiagCode::step_procedure), 0u) << r->listing();
  const auto& steps = r->model.history.steps;
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_TRUE(steps[0].placeholder);
  EXPECT_EQ(steps[0].loads.size(), 1u);
  EXPECT_TRUE(steps[0].procedure.has_value());
  EXPECT_EQ(steps[1].name.display, "Two");
}

TEST(History, UnclosedStepWithoutProcedure) {
  auto r = read_text(kSpringModel + "*STEP, NAME=Open\n*CLOAD\n2, 1, 1.\n");
  EXPECT_EQ(r->count(DiagCode::missing_end_step), 1u) << r->listing();
  const Diagnostic* d = r->find(DiagCode::step_procedure);
  ASSERT_NE(d, nullptr) << r->listing();
  EXPECT_EQ(d->loc.line, 11u);
}

TEST(History, OutputRequestsAreStored) {
  auto r = read_text(kSpringModel +
                     "*STEP\n*STATIC\n*OUTPUT, HISTORY, NUMBER INTERVAL=4\n"
                     "*NODE OUTPUT, NSET=ALL\nRF\n*ELEMENT OUTPUT, ELSET=S\nS, E\n"
                     "*OUTPUT, HISTORY, NAME=Mine, OP=NEW\n*NODE OUTPUT, NSET=ALL\nUT\n"
                     "*END STEP\n");
  EXPECT_EQ(r->sink.diagnostics().size(), 0u) << r->listing();
  const auto& outputs = r->model.history.steps.at(0).outputs;
  ASSERT_EQ(outputs.size(), 2u);
  EXPECT_EQ(outputs[0].name.display, "H-Output-1");
  EXPECT_EQ(outputs[0].number_interval, 4);
  ASSERT_EQ(outputs[0].nodes.size(), 1u);
  EXPECT_EQ(outputs[0].nodes[0].identifiers.at(0).components, 0b111111);
  EXPECT_EQ(outputs[0].elements.at(0).identifiers.size(), 2u);
  EXPECT_EQ(outputs[1].name.display, "Mine");
  EXPECT_EQ(outputs[1].op, OutputRequest::Op::New);
}

TEST(OutputVariables, AliasesComponentsAndScalars) {
  auto ctm1 = parse_output_identifier("ctm1", OutputContext::ElementOutput);
  ASSERT_EQ(ctm1.status, IdentifierStatus::Ok);
  EXPECT_EQ(ctm1.id.variable, "CTF");
  EXPECT_EQ(ctm1.id.components, 1u << 3);
  EXPECT_TRUE(ctm1.id.explicit_component);

  auto ctm = parse_output_identifier("CTM", OutputContext::ElementOutput);
  EXPECT_EQ(ctm.id.components, 0b111000);
  EXPECT_FALSE(ctm.id.explicit_component);

  auto cur3 = parse_output_identifier("CUR3", OutputContext::ElPrint);
  EXPECT_EQ(cur3.id.variable, "CU");
  EXPECT_EQ(cur3.id.components, 1u << 5);

  auto cdmg = parse_output_identifier("CDMG", OutputContext::ElementOutput);
  EXPECT_EQ(cdmg.id.components, 0u);
  auto cdmgr2 = parse_output_identifier("CDMGR2", OutputContext::ElementOutput);
  EXPECT_EQ(cdmgr2.id.variable, "CDMG");
  EXPECT_EQ(cdmgr2.id.components, 1u << 4);
  auto coupled = parse_output_identifier("CUPEQC", OutputContext::ElementOutput);
  EXPECT_EQ(coupled.id.variable, "CUPEQC");
  EXPECT_EQ(coupled.id.components, 0u);

  auto derived = parse_output_identifier("CDERF-normal", OutputContext::ElementOutput);
  ASSERT_EQ(derived.status, IdentifierStatus::Ok);
  EXPECT_EQ(derived.id.variable, "CDERF");
  EXPECT_EQ(derived.id.derived_name, "normal");

  EXPECT_EQ(parse_output_identifier("CTF7", OutputContext::ElementOutput).status,
            IdentifierStatus::Unknown);
  EXPECT_EQ(parse_output_identifier("CTM4", OutputContext::ElementOutput).status,
            IdentifierStatus::Unknown);
  auto cft = parse_output_identifier("CFT", OutputContext::ElementOutput);
  EXPECT_EQ(cft.status, IdentifierStatus::Unknown);
  EXPECT_EQ(cft.suggestion, "CTF");
  EXPECT_EQ(parse_output_identifier("ALLSE", OutputContext::ElementOutput).status,
            IdentifierStatus::Unsupported);
  EXPECT_EQ(parse_output_identifier("CTF", OutputContext::NodeOutput).status,
            IdentifierStatus::WrongKind);
  EXPECT_EQ(parse_output_identifier("U", OutputContext::ElPrint).status,
            IdentifierStatus::WrongKind);
}

TEST(OutputVariables, NodalNames) {
  auto u = parse_output_identifier("U", OutputContext::NodeOutput);
  EXPECT_EQ(u.id.components, 0b111111);
  EXPECT_EQ(parse_output_identifier("U", OutputContext::NodePrint).id.components, 0b000111);
  auto ur2 = parse_output_identifier("UR2", OutputContext::NodeOutput);
  EXPECT_EQ(ur2.id.variable, "U");
  EXPECT_EQ(ur2.id.components, 1u << 4);
  auto rm = parse_output_identifier("RM", OutputContext::NodeOutput);
  EXPECT_EQ(rm.id.variable, "RF");
  EXPECT_EQ(rm.id.components, 0b111000);
  EXPECT_EQ(parse_output_identifier("U4", OutputContext::NodeOutput).status,
            IdentifierStatus::Unknown);
  // Identifiers Abaqus and CalculiX define and clinch does not are known, not supported (E0904).
  EXPECT_EQ(parse_output_identifier("NT", OutputContext::NodePrint).status,
            IdentifierStatus::Unsupported);
  EXPECT_EQ(parse_output_identifier("COORD", OutputContext::NodeOutput).status,
            IdentifierStatus::Unsupported);
  auto vr = parse_output_identifier("VR3", OutputContext::NodeOutput);
  EXPECT_EQ(vr.id.variable, "V");
  EXPECT_EQ(vr.id.components, 1u << 5);
  EXPECT_EQ(parse_output_identifier("XYZ", OutputContext::NodeOutput).status,
            IdentifierStatus::Unknown);
}

TEST(OutputVariables, ColumnLabels) {
  EXPECT_EQ(output_column_label("CTF", 4), "CTF4");
  EXPECT_EQ(output_column_label("U", 5), "UR2");
  EXPECT_EQ(output_column_label("RF", 4), "RM1");
  EXPECT_EQ(output_column_label("CF", 6), "CM3");
  EXPECT_EQ(output_column_label("S", 1), "S11");
  EXPECT_EQ(output_column_label("CDMG", 0), "CDMG");
  EXPECT_EQ(output_column_label("CDERF", 0, "normal"), "CDERF-normal");
}

TEST(History, GarbageDoesNotCrash) {
  const char* bodies[] = {
      "*STEP\n*STATIC\n,,,,\n1e400, -0, x\n*END STEP\n",
      "*STEP\n*BOUNDARY\n,\n\"q\", 1\nALL, 2, 1, 1, 1, 1\n*END STEP\n*END STEP\n",
      "*AMPLITUDE, NAME=A\n,\n*AMPLITUDE, NAME=A, DEFINITION=SMOOTH STEP\n1\n*STEP\n*STATIC\n"
      "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n,,,,,,,,,,,,\nx\n1,2,3\n4\n*END STEP\n",
      "*STEP\n*STATIC\n*NODE OUTPUT\n*ELEMENT OUTPUT, ELSET=S\nCDERF-, CDERF, ,\n"
      "*NODE PRINT, NSET=ALL, TOTALS=ONLY\nU, RF, CF\n*EL PRINT, ELSET=S, TOTALS=YES\nS, E\n"
      "*CONNECTOR LOAD\nS, 1, 1.\n*CONNECTOR MOTION\n1\n*END STEP\n",
  };
  for (const char* body : bodies) {
    auto r = read_text(kSpringModel + body);
    for (const Diagnostic& d : r->sink.diagnostics()) EXPECT_TRUE(d.loc.valid()) << d.message;
  }
}

}  // namespace
}  // namespace clinch
