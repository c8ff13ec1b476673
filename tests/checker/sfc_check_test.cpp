// Semantic checks of textual SFC (IEC 61131-3 2nd ed. 2.6): step references of transitions,
// duplicate names, initial steps, vendor step-name rules, action associations and the OpenPCS step
// macros. The OpenPCS manual's cases (003.md facts 101-106) are quoted where a test follows one.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"
#include "tests/support/project_findings.hpp"

namespace rung::check {
namespace {

using Found = std::vector<std::string>;

Found found(const std::string& text, project::Profile profile = project::Profile::Iec) {
  return testing::codes_at_lines({{"P.st", text}}, testing::config_for(profile), testing::Warnings::Unmarked);
}

// A PROGRAM with `go : BOOL` whose body (from line 5 on) is `chart`.
std::string chart(const std::string& body, const std::string& vars = "") {
  return "PROGRAM Chart\nVAR\ngo : BOOL;" + vars + "\nEND_VAR\n" + body + "END_PROGRAM\n";
}

// The first message of a diagnostic with this code.
std::string message_of(const std::string& text, std::string_view code,
                       project::Profile profile = project::Profile::Iec) {
  const auto messages = testing::messages_with_code({{"P.st", text}}, testing::config_for(profile), code);
  return messages.empty() ? std::string() : messages.front();
}

// --- Charts that are fine -------------------------------------------------------------------

// An action block is a member of its POU: its body is checked once, not once more with the chart.
TEST(SfcCheck, ActionBodyFindingsAreReportedOnce) {
  EXPECT_EQ(found(chart("INITIAL_STEP Init: Fill(N); END_STEP\n"
                        "TRANSITION FROM Init TO Init := go; END_TRANSITION\n"
                        "ACTION Fill:\n"
                        "  go := undefined_name;\n"
                        "END_ACTION\n")),
            Found({"E001@8"}));
}

TEST(SfcCheck, CycleWithActionsAndTransitionLists) {
  EXPECT_EQ(found(chart("INITIAL_STEP Init: Fill(N); END_STEP\n"
                        "TRANSITION FROM Init TO (Heat, Stir) := go; END_TRANSITION\n"
                        "STEP Heat: Heater(S); lamp(N); END_STEP\n"
                        "STEP Stir: END_STEP\n"
                        "TRANSITION FROM (Heat, Stir) TO Init := NOT go; END_TRANSITION\n"
                        "ACTION Fill: go := TRUE; END_ACTION\n"
                        "ACTION Heater: go := FALSE; END_ACTION\n",
                        " lamp : BOOL;")),
            Found{});
}

TEST(SfcCheck, TwoNetworksEachWithItsInitialStep) {
  // IEC: each INITIAL_STEP starts a network of its own; networks that no transition joins are
  // separate charts.
  EXPECT_EQ(found(chart("INITIAL_STEP A: END_STEP\nSTEP B: END_STEP\n"
                        "TRANSITION FROM A TO B := go;\nTRANSITION FROM B TO A := go;\n"
                        "INITIAL_STEP C: END_STEP\nTRANSITION FROM C TO C := go;\n")),
            Found{});
}

TEST(SfcCheck, ActionAssociationMayNameAnActionOfThePou) {
  // CODESYS/TwinCAT: the actions are objects below the program, not blocks inside the chart.
  EXPECT_EQ(found("PROGRAM Chart\nVAR go : BOOL; END_VAR\n"
                  "INITIAL_STEP Init: Blink(N); END_STEP\nTRANSITION FROM Init TO Init := go;\n"
                  "END_PROGRAM\nACTION Blink:\ngo := NOT go;\nEND_ACTION\n"),
            Found{});
}

// --- Step references --------------------------------------------------------------------------

TEST(SfcCheck, TransitionToUnknownStepOrToATransition) {
  // OpenPCS fact 102: "Init1 is not a valid jump target", also when the target is a transition.
  const std::string text = chart(
      "INITIAL_STEP Init: END_STEP\nSTEP Run: END_STEP\n"
      "TRANSITION ToRun FROM Init TO Run := go;\n"
      "TRANSITION FROM Run TO Init1 := go;\n"
      "TRANSITION FROM Run TO ToRun := go;\n");
  EXPECT_EQ(found(text), (Found{"E410@8", "E410@9"}));
  EXPECT_EQ(message_of(text, "E410"), "no step 'Init1' in this SFC for TRANSITION TO");
}

TEST(SfcCheck, TransitionFromAnAction) {
  EXPECT_EQ(found(chart("INITIAL_STEP Init: END_STEP\nTRANSITION FROM Init TO Init := go;\n"
                        "TRANSITION FROM (Init, Blink) TO Init := go;\n"
                        "ACTION Blink: go := TRUE; END_ACTION\n")),
            Found{"E410@7"});
}

TEST(SfcCheck, FragmentOfTransitionsOnlyIsNotResolved) {
  // A manual's excerpt may list transitions whose steps it does not show.
  EXPECT_EQ(found("VAR go : BOOL; END_VAR\nTRANSITION FROM S1 TO S2 := go;\n"), Found{});
}

// --- Duplicate names ------------------------------------------------------------------------

TEST(SfcCheck, DuplicateStepNameWithTheFirstOneLabelled) {
  // OpenPCS fact 103: two steps named Init make "jump target Init ambiguous".
  const std::string text = chart(
      "INITIAL_STEP Init: END_STEP\nSTEP Run: END_STEP\nSTEP init: END_STEP\n"
      "TRANSITION FROM Init TO Run := go;\nTRANSITION FROM Run TO Init := go;\n");
  EXPECT_EQ(found(text), Found{"E003@7"});
  project::ProjectConfig config;
  auto workspace = Workspace::from_texts({{"P.st", text}}, config);
  const auto files = workspace->check_all(1);
  ASSERT_EQ(files.size(), 1u);
  ASSERT_EQ(files[0].diagnostics.size(), 1u);
  const Diagnostic& duplicate = files[0].diagnostics[0];
  ASSERT_EQ(duplicate.labels.size(), 1u);
  EXPECT_EQ(text.substr(duplicate.labels[0].range.begin, 4), "Init");
  EXPECT_EQ(std::count(text.begin(), text.begin() + duplicate.labels[0].range.begin, '\n'), 4);
}

TEST(SfcCheck, DuplicateActionAndTransitionNames) {
  EXPECT_EQ(found(chart("INITIAL_STEP S: END_STEP\nTRANSITION T1 FROM S TO S := go;\n"
                        "TRANSITION t1 FROM S TO S := NOT go;\n"
                        "ACTION A: go := TRUE; END_ACTION\nACTION A: go := FALSE; END_ACTION\n")),
            (Found{"E003@7", "E003@9"}));
}

// --- Initial steps --------------------------------------------------------------------------

TEST(SfcCheck, NetworkWithoutInitialStep) {
  const std::string text = chart(
      "STEP A: END_STEP\nSTEP B: END_STEP\nTRANSITION FROM A TO B := go;\n"
      "TRANSITION FROM B TO A := go;\n");
  EXPECT_EQ(found(text), Found{"E219@5"});
  EXPECT_EQ(message_of(text, "E219"), "the SFC network of step 'A' has no INITIAL_STEP");
}

TEST(SfcCheck, StepThatNoTransitionReachesIsANetworkOfItsOwn) {
  EXPECT_EQ(found(chart("INITIAL_STEP A: END_STEP\nTRANSITION FROM A TO A := go;\nSTEP Lost: END_STEP\n")),
            Found{"E219@7"});
}

TEST(SfcCheck, TwoInitialStepsInOneNetwork) {
  EXPECT_EQ(found(chart("INITIAL_STEP A: END_STEP\nINITIAL_STEP B: END_STEP\nTRANSITION FROM A TO B := go;\n"
                        "TRANSITION FROM B TO A := go;\n")),
            Found{"E219@6"});
}

TEST(SfcCheck, NoInitialStepReportIsLeftOutWhenAStepReferenceIsUnknown) {
  // The unknown name may be the step that was meant to join the networks: one diagnostic only.
  EXPECT_EQ(found(chart("INITIAL_STEP A: END_STEP\nTRANSITION FROM A TO Bb := go;\nSTEP B: END_STEP\n"
                        "TRANSITION FROM B TO B := go;\n")),
            Found{"E410@6"});
}

// --- Step names (per profile) ---------------------------------------------------------------

TEST(SfcCheck, OpenpcsStepNames) {
  // OpenPCS fact 101: Step1 and S_1 are fine; _Step1 and more than 31 characters are not.
  const std::string text = chart(
      "INITIAL_STEP Step1: END_STEP\nSTEP S_1: END_STEP\nSTEP _Step1: END_STEP\n"
      "STEP A23456789012345678901234567890123: END_STEP\n"
      "TRANSITION FROM Step1 TO S_1 := go;\nTRANSITION FROM S_1 TO _Step1 := go;\n"
      "TRANSITION FROM _Step1 TO A23456789012345678901234567890123 := go;\n"
      "TRANSITION FROM A23456789012345678901234567890123 TO Step1 := go;\n");
  EXPECT_EQ(found(text, project::Profile::Openpcs), (Found{"E218@7", "E218@8"}));
  EXPECT_EQ(message_of(text, "E218", project::Profile::Openpcs),
            "step name '_Step1' is not allowed: it begins with '_', not with a letter");
  // IEC identifiers may begin with '_' and have no length limit.
  EXPECT_EQ(found(text, project::Profile::Iec), Found{});
  EXPECT_EQ(found(text, project::Profile::Codesys), Found{});
}

// --- Action associations --------------------------------------------------------------------

TEST(SfcCheck, ActionAssociationsNameActionsOrBoolVariables) {
  EXPECT_EQ(found(chart("INITIAL_STEP Init: Missing(N); n(N); Init(N); T(N); Ok(N); flag(S); END_STEP\n"
                        "TRANSITION T FROM Init TO Init := go;\n"
                        "ACTION Ok: go := TRUE; END_ACTION\n",
                        " n : INT; flag : BOOL;")),
            (Found{"E001@5", "E004@5", "E004@5", "E004@5"}));
}

// --- Step macros (OpenPCS) --------------------------------------------------------------------

TEST(SfcCheck, StepMacrosInTheChartsIlCode) {
  // OpenPCS fact 106: @ACTIVATE_STEP(S) / @DEACTIVATE_STEP(S) / @DEACTIVATE_ALL_STEPS().
  EXPECT_EQ(found(chart("INITIAL_STEP Init: Reset(N); END_STEP\nSTEP Run: END_STEP\n"
                        "TRANSITION FROM Init TO Run := go;\nTRANSITION FROM Run TO Init := NOT go;\n"
                        "ACTION Reset:\nLD go\n@DEACTIVATE_STEP(Run)\n@ACTIVATE_STEP(Init)\n@DEACTIVATE_ALL_STEPS()\n"
                        "@ACTIVATE_STEP(Nowhere)\n@ACTIVATE_STEP()\n@DEACTIVATE_ALL_STEPS(Run)\nEND_ACTION\n"),
                  project::Profile::Openpcs),
            (Found{"E410@14", "E803@15", "E803@16"}));
}

TEST(SfcCheck, StepMacrosAreNotStructuredText) {
  // The macros exist only in IL (OpenPCS L2658-2670); the POU around stays whole.
  const std::string text = "PROGRAM Macros\nVAR go : BOOL; END_VAR\ngo := TRUE;\n@ACTIVATE_STEP(Step2);\nEND_PROGRAM\n";
  EXPECT_EQ(found(text, project::Profile::Openpcs), Found{"S007@4"});
}

TEST(SfcCheck, StepMacrosWithoutAChartAreOnlyParsed) {
  // An IL excerpt from the manual: the steps are elsewhere.
  EXPECT_EQ(found("@ACTIVATE_STEP(StepName)\n@DEACTIVATE_STEP(StepName)\n@DEACTIVATE_ALL_STEPS()\n",
                  project::Profile::Openpcs),
            Found{});
}

}  // namespace
}  // namespace rung::check
