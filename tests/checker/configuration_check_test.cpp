// CONFIGURATION / RESOURCE / TASK / PROGRAM ... WITH and VAR_CONFIG end to end: E506 unknown
// task or program type, E507 a task without trigger, E508 VAR_CONFIG paths and the incomplete
// addresses they complete, and the globals of a configuration as seen by VAR_EXTERNAL.
// Lnnn point into the seed manuals in ../shared/seeds (002 = MP300, 000 = CODESYS textbook).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "checker/check.hpp"

namespace rung::check {
namespace {

using Files = std::vector<std::pair<std::string, std::string>>;
using Codes = std::vector<std::string>;

std::vector<Diagnostic> check(const Files& files, project::Profile profile = project::Profile::Iec) {
  project::ProjectConfig config;
  config.profile = profile;
  auto workspace = Workspace::from_texts(files, config);
  std::vector<Diagnostic> found;
  for (const auto& file : workspace->check_all(1)) {
    found.insert(found.end(), file.diagnostics.begin(), file.diagnostics.end());
  }
  return found;
}

std::vector<Diagnostic> check(const std::string& text, project::Profile profile = project::Profile::Iec) {
  return check({{"P.st", text}}, profile);
}

Codes codes(const std::vector<Diagnostic>& found) {
  Codes out;
  for (const Diagnostic& d : found) out.push_back(d.code);
  return out;
}

const std::string kMain = "PROGRAM Main\nVAR fbSensor : FB_Sensor; END_VAR\nfbSensor();\nEND_PROGRAM\n";
const std::string kSensor =
    "FUNCTION_BLOCK FB_Sensor\nVAR bInput AT %I* : BOOL; bOutput AT %Q* : BOOL; nPlain : INT; END_VAR\n"
    "END_FUNCTION_BLOCK\n";

// A configuration with one resource running Main in task Fast, and `entries` in its VAR_CONFIG.
std::string configuration(const std::string& entries,
                          const std::string& tasks = "TASK Fast (INTERVAL := T#10MS, PRIORITY := 1);\n",
                          const std::string& programs = "PROGRAM Inst1 WITH Fast : Main;\n") {
  std::string text = "CONFIGURATION Plant\n  RESOURCE Cpu ON PLC\n" + tasks + programs + "  END_RESOURCE\n";
  if (!entries.empty()) text += "  VAR_CONFIG\n" + entries + "  END_VAR\n";
  return text + "END_CONFIGURATION\n";
}

const std::string kBothEntries =
    "Cpu.Inst1.fbSensor.bInput AT %IX0.0 : BOOL;\nCpu.Inst1.fbSensor.bOutput AT %QX0.0 : BOOL;\n";

// --- A valid configuration ---------------------------------------------------------------------

TEST(ConfigurationCheck, PlcopenConfigurationWithGlobalsIsClean) {
  // The configuration's and the resource's VAR_GLOBAL are the globals VAR_EXTERNAL refers to.
  const std::string text =
      "PROGRAM Main\nVAR_EXTERNAL gCounter : INT; gEnable : BOOL; END_VAR\n"
      "IF gEnable THEN gCounter := gCounter + 1; END_IF\nEND_PROGRAM\n"
      "CONFIGURATION Plant\n  VAR_GLOBAL gCounter : INT; END_VAR\n"
      "  RESOURCE Cpu ON PLC\n    VAR_GLOBAL gEnable : BOOL; END_VAR\n"
      "    TASK Fast (INTERVAL := T#10MS, PRIORITY := 1);\n    TASK OnEdge (SINGLE := gEnable, PRIORITY := 2);\n"
      "    PROGRAM Inst1 WITH Fast : Main;\n    PROGRAM Inst2 WITH OnEdge : Main;\n"
      "  END_RESOURCE\nEND_CONFIGURATION\n";
  EXPECT_EQ(codes(check(text)), Codes{});
  EXPECT_EQ(codes(check(text, project::Profile::Codesys)), Codes{});
  // The same with the configuration in a file of its own.
  EXPECT_EQ(codes(check({{"Main.st", text.substr(0, text.find("CONFIGURATION"))},
                         {"Plant.st", text.substr(text.find("CONFIGURATION"))}})),
            Codes{});
}

// --- E506 -------------------------------------------------------------------------------------

TEST(ConfigurationCheck, UnknownTaskSuggestsTheDeclaredOne) {
  auto found = check(kSensor + kMain +
                     configuration("", "TASK Fast (INTERVAL := T#10MS);\n", "PROGRAM Inst1 WITH Fats : Main;\n"));
  ASSERT_EQ(codes(found), Codes{"E506"});
  EXPECT_EQ(found[0].message, "task 'Fats' is not declared in resource 'Cpu'");
  EXPECT_EQ(found[0].help, "did you mean 'Fast'?");
}

TEST(ConfigurationCheck, TasksOfAnotherResourceAreNotVisible) {
  const std::string text = kSensor + kMain +
                           "CONFIGURATION Plant\n  RESOURCE A ON PLC\n    TASK Fast (INTERVAL := T#10MS);\n"
                           "  END_RESOURCE\n  RESOURCE B ON PLC\n    PROGRAM Inst1 WITH Fast : Main;\n"
                           "  END_RESOURCE\nEND_CONFIGURATION\n";
  EXPECT_EQ(codes(check(text)), Codes{"E506"});
}

TEST(ConfigurationCheck, ProgramTypeMustBeAProgram) {
  auto unknown = check(kSensor + kMain +
                       configuration("", "TASK Fast (INTERVAL := T#10MS);\n", "PROGRAM Inst1 WITH Fast : Mian;\n"));
  ASSERT_EQ(codes(unknown), Codes{"E506"});
  EXPECT_EQ(unknown[0].message, "there is no PROGRAM 'Mian' in the project");
  EXPECT_EQ(unknown[0].help, "did you mean 'Main'?");
  auto block = check(kSensor + kMain +
                     configuration("", "TASK Fast (INTERVAL := T#10MS);\n", "PROGRAM Inst1 WITH Fast : FB_Sensor;\n"));
  ASSERT_EQ(codes(block), Codes{"E506"});
  EXPECT_EQ(block[0].message, "'FB_Sensor' is a function block, not a PROGRAM: a resource runs programs");
}

TEST(ConfigurationCheck, FunctionBlockTaskAssociationNeedsADeclaredTask) {
  // IEC 61131-3: PROGRAM P1 WITH T1 : Main (FB1 WITH SLOW_1);
  const std::string tasks = "TASK Fast (INTERVAL := T#10MS);\nTASK Slow (INTERVAL := T#1S);\n";
  EXPECT_EQ(codes(check(kSensor + kMain +
                        configuration("", tasks, "PROGRAM Inst1 WITH Fast : Main (fbSensor WITH Slow);\n"))),
            Codes{});
  EXPECT_EQ(codes(check(kSensor + kMain +
                        configuration("", tasks, "PROGRAM Inst1 WITH Fast : Main (fbSensor WITH Slwo);\n"))),
            Codes{"E506"});
}

// --- E507 and the other task parameters --------------------------------------------------------

TEST(ConfigurationCheck, TaskWithoutIntervalOrSingleNeverRunsInIec) {
  const std::string text = kSensor + kMain + configuration("", "TASK Fast (PRIORITY := 1);\n");
  auto found = check(text);
  ASSERT_EQ(codes(found), Codes{"E507"});
  EXPECT_EQ(found[0].message, "TASK 'Fast' has neither INTERVAL nor SINGLE, so it never runs");
  EXPECT_EQ(codes(check(kSensor + kMain + configuration("", "TASK Fast;\n"))), Codes{"E507"});
  // CODESYS runs such a task freewheeling (000 L1446-1501).
  EXPECT_EQ(codes(check(text, project::Profile::Codesys)), Codes{});
}

TEST(ConfigurationCheck, CodesysPrioritiesAreZeroToThirtyOne) {
  // 000 L1568-1574, 001 L2980-2984: priority 0..31, 0 is the highest.
  auto high = check(kSensor + kMain + configuration("", "TASK Fast (INTERVAL := T#10MS, PRIORITY := 32);\n"),
                    project::Profile::Codesys);
  ASSERT_EQ(codes(high), Codes{"E102"});
  EXPECT_EQ(high[0].message, "PRIORITY 32 is out of range: task priorities are 0 (highest) to 31");
  EXPECT_EQ(codes(check(kSensor + kMain + configuration("", "TASK Fast (INTERVAL := T#10MS, PRIORITY := 31);\n"),
                        project::Profile::Codesys)),
            Codes{});
  // The IEC standard gives no range.
  EXPECT_EQ(codes(check(kSensor + kMain + configuration("", "TASK Fast (INTERVAL := T#10MS, PRIORITY := 99);\n"))),
            Codes{});
}

TEST(ConfigurationCheck, MisspelledTaskParameter) {
  auto found = check(kSensor + kMain + configuration("", "TASK Fast (INTERVALL := T#10MS, PRIORITY := 1);\n"));
  EXPECT_EQ(codes(found), (Codes{"E507", "E301"}));
  EXPECT_EQ(found[1].help, "did you mean 'INTERVAL'?");
}

// --- E508: VAR_CONFIG ------------------------------------------------------------------------

TEST(ConfigurationCheck, VarConfigCompletingEveryIncompleteAddressIsClean) {
  EXPECT_EQ(codes(check(kSensor + kMain + configuration(kBothEntries))), Codes{});
  // The configuration in another file than the blocks it configures.
  EXPECT_EQ(codes(check({{"Sensor.st", kSensor}, {"Main.st", kMain}, {"Plant.st", configuration(kBothEntries)}})),
            Codes{});
}

TEST(ConfigurationCheck, PathThatNamesNoVariable) {
  auto found = check(kSensor + kMain +
                     configuration("Cpu.Inst1.fbSensr.bInput AT %IX0.0 : BOOL;\n"
                                   "Cpu.Inst1.fbSensor.bOutput AT %QX0.0 : BOOL;\n"));
  // The misspelt path, and so the input that stays incomplete.
  ASSERT_EQ(codes(found), (Codes{"E508", "E508"}));
  EXPECT_EQ(found[0].message,
            "the incomplete address of 'bInput' is completed by no VAR_CONFIG entry for 'Cpu.Inst1.fbSensor.bInput'");
  EXPECT_EQ(found[1].message, "VAR_CONFIG path 'Cpu.Inst1.fbSensr.bInput': 'Main' has no variable 'fbSensr'");
  EXPECT_EQ(found[1].help, "did you mean 'fbSensor'?");
  EXPECT_EQ(
      codes(check(kSensor + kMain + configuration(kBothEntries + "Cpu.Inst7.fbSensor.bInput AT %IX0.1 : BOOL;\n"))),
      Codes{"E508"});
  EXPECT_EQ(
      codes(check(kSensor + kMain + configuration(kBothEntries + "Cpux.Inst1.fbSensor.bInput AT %IX0.1 : BOOL;\n"))),
      Codes{"E508"});
}

TEST(ConfigurationCheck, AddressForAVariableWithoutIncompleteAddress) {
  auto found = check(kSensor + kMain + configuration(kBothEntries + "Cpu.Inst1.fbSensor.nPlain AT %QW2 : INT;\n"));
  ASSERT_EQ(codes(found), Codes{"E508"});
  EXPECT_EQ(found[0].message,
            "'Cpu.Inst1.fbSensor.nPlain' in 'FB_Sensor' has no incomplete address (AT %I* or %Q*) for VAR_CONFIG to "
            "complete");
  // An entry without address may still give an initial value (IEC 61131-3).
  EXPECT_EQ(codes(check(kSensor + kMain + configuration(kBothEntries + "Cpu.Inst1.fbSensor.nPlain : INT := 5;\n"))),
            Codes{});
}

TEST(ConfigurationCheck, KindAndTypeMustMatchTheIncompleteAddress) {
  // 002 L11640-11650: the kind (input/output) and the data type must match the FB declaration.
  auto kind = check(kSensor + kMain +
                    configuration("Cpu.Inst1.fbSensor.bInput AT %QX0.1 : BOOL;\n"
                                  "Cpu.Inst1.fbSensor.bOutput AT %QX0.0 : BOOL;\n"));
  ASSERT_EQ(codes(kind), Codes{"E508"});
  EXPECT_EQ(kind[0].message,
            "'Cpu.Inst1.fbSensor.bInput' is declared AT %I* (an input address) but gets %QX0.1, an output address");
  auto type = check(kSensor + kMain +
                    configuration("Cpu.Inst1.fbSensor.bInput AT %IW2 : INT;\n"
                                  "Cpu.Inst1.fbSensor.bOutput AT %QX0.0 : BOOL;\n"));
  EXPECT_EQ(codes(type), Codes{"E508"});
}

TEST(ConfigurationCheck, CompleteAddressesAreNotReconfigured) {
  const std::string block = "FUNCTION_BLOCK FB_Sensor\nVAR bInput AT %IX3.0 : BOOL; END_VAR\nEND_FUNCTION_BLOCK\n";
  auto found = check(block + kMain + configuration("Cpu.Inst1.fbSensor.bInput AT %IX0.0 : BOOL;\n"));
  // E201 too: the IEC grammar gives a function block only incomplete addresses (AT %I*).
  ASSERT_EQ(codes(found), (Codes{"E201", "E508"}));
  EXPECT_NE(found[1].message.find("already has the address %IX3.0"), std::string::npos);
}

TEST(ConfigurationCheck, EveryInstanceNeedsItsEntry) {
  // 002 L11652-11654: an incomplete address without configuration is an error too.
  const std::string main = "PROGRAM Main\nVAR fbSensor : FB_Sensor; fbSpare : FB_Sensor; END_VAR\nEND_PROGRAM\n";
  auto found = check(kSensor + main + configuration(kBothEntries));
  ASSERT_EQ(codes(found), (Codes{"E508", "E508"}));
  EXPECT_EQ(found[0].message,
            "the incomplete address of 'bInput' is completed by no VAR_CONFIG entry for 'Cpu.Inst1.fbSpare.bInput'");
  EXPECT_EQ(found[0].help, "add 'Cpu.Inst1.fbSpare.bInput AT %IX… : BOOL;' to a VAR_CONFIG");
  // A project without any VAR_CONFIG maps them elsewhere (the I/O mapping dialog).
  EXPECT_EQ(codes(check(kSensor + main)), Codes{});
}

TEST(ConfigurationCheck, CodesysVarConfigInAGlobalListNamesProgramsDirectly) {
  // 002 L11614-11690: VAR_CONFIG in a GVL, paths from the PROGRAM's name.
  const std::string fb =
      "FUNCTION_BLOCK locio\nVAR\nxLocIn AT %I*: BOOL := TRUE;\nxLocOut AT %Q*: BOOL;\nEND_VAR\n"
      "END_FUNCTION_BLOCK\n";
  const std::string prg = "PROGRAM PLC_PRG\nVAR\nlocioVar1: locio;\nlocioVar2: locio;\nEND_VAR\nEND_PROGRAM\n";
  const std::string gvl =
      "VAR_CONFIG\nPLC_PRG.locioVar1.xLocIn AT %IX1.0 : BOOL;\nPLC_PRG.locioVar1.xLocOut AT %QX0.0 : BOOL;\n"
      "PLC_PRG.locioVar2.xLocIn AT %IX1.0 : BOOL;\nPLC_PRG.locioVar2.xLocOut AT %QX0.3 : BOOL;\nEND_VAR\n";
  EXPECT_EQ(codes(check({{"locio.st", fb}, {"PLC_PRG.st", prg}, {"GVL.st", gvl}}, project::Profile::Codesys)), Codes{});
  // The manual prints the three objects one after another without END_ keywords: the VAR_CONFIG
  // after the program is the next object, not a section of the program.
  const std::string concatenated =
      "FUNCTION_BLOCK locio\nVAR\nxLocIn AT %I*: BOOL := TRUE;\nxLocOut AT %Q*: BOOL;\nEND_VAR\n"
      "PROGRAM PLC_PRG\nVAR\nlocioVar1: locio;\nlocioVar2: locio;\nEND_VAR\n" +
      gvl;
  EXPECT_EQ(codes(check(concatenated, project::Profile::Codesys)), Codes{});
  // Closed by END_PROGRAM, the VAR_CONFIG is the program's, which no POU may declare.
  EXPECT_EQ(codes(check(fb + "PROGRAM PLC_PRG\nVAR\nlocioVar1: locio;\nEND_VAR\n"
                             "VAR_CONFIG\nPLC_PRG.locioVar1.xLocIn AT %IX1.0 : BOOL;\nEND_VAR\nEND_PROGRAM\n",
                        project::Profile::Codesys)),
            Codes{"E201"});
  // A missing entry in the same layout.
  const std::string partial = "VAR_CONFIG\nPLC_PRG.locioVar1.xLocIn AT %IX1.0 : BOOL;\nEND_VAR\n";
  EXPECT_EQ(codes(check({{"locio.st", fb}, {"PLC_PRG.st", prg}, {"GVL.st", partial}}, project::Profile::Codesys)),
            (Codes{"E508", "E508"}));
}

TEST(ConfigurationCheck, VarConfigMustGiveACompleteAddress) {
  EXPECT_EQ(codes(check(kSensor + kMain +
                        configuration("Cpu.Inst1.fbSensor.bInput AT %I* : BOOL;\n"
                                      "Cpu.Inst1.fbSensor.bOutput AT %QX0.0 : BOOL;\n"))),
            Codes{"E505"});
}

TEST(ConfigurationCheck, InheritedIncompleteAddressesCountToo) {
  const std::string derived = "FUNCTION_BLOCK FB_Derived EXTENDS FB_Sensor\nEND_FUNCTION_BLOCK\n";
  const std::string main = "PROGRAM Main\nVAR fbSensor : FB_Derived; END_VAR\nEND_PROGRAM\n";
  EXPECT_EQ(codes(check(kSensor + derived + main + configuration(kBothEntries), project::Profile::Codesys)), Codes{});
  EXPECT_EQ(codes(check(kSensor + derived + main + configuration("Cpu.Inst1.fbSensor.bInput AT %IX0.0 : BOOL;\n"),
                        project::Profile::Codesys)),
            Codes{"E508"});
}

}  // namespace
}  // namespace rung::check
