// The call and type hierarchy questions the language server asks (checker/query/call_hierarchy,
// type_hierarchy): what a POU calls, who calls it (calls of instances are calls of their block),
// what a type extends or implements and what extends or implements it.
#include <gtest/gtest.h>

#include "checker/query/call_hierarchy.hpp"
#include "checker/query/definition.hpp"
#include "checker/query/type_hierarchy.hpp"
#include "tests/support/marked_project.hpp"

namespace rung::check {
namespace {

using testing::MarkedProject;

std::string qualified(const Symbol* symbol) {
  if (!symbol) return "(null)";
  std::string name(symbol->name);
  for (const Symbol* owner = symbol->owner; owner; owner = owner->owner) name = std::string(owner->name) + "." + name;
  return name;
}

std::vector<std::string> names_of(const std::vector<const Symbol*>& symbols) {
  std::vector<std::string> names;
  for (const Symbol* symbol : symbols) names.push_back(qualified(symbol));
  return names;
}

// "Caller -> Callee @path@offset" of each call, checking that the range spells the called name.
std::vector<std::string> calls_of(const MarkedProject& project, const std::vector<query::Call>& calls) {
  std::vector<std::string> out;
  for (const query::Call& call : calls) {
    const std::string& text = project.text_of(call.where.path);
    const std::string spelled = text.substr(call.where.range.begin, call.where.range.end - call.where.range.begin);
    out.push_back(qualified(call.caller) + " -> " + qualified(call.callee) + " " + spelled + "@" + call.where.path +
                  "@" + std::to_string(call.where.range.begin));
  }
  return out;
}

const MarkedProject::Files kPlant = {
    {"Pump.st",
     "FUNCTION F_Scale : REAL\n"
     "VAR_INPUT x : REAL; END_VAR\n"
     "F_Scale := x * 2.0;\n"
     "END_FUNCTION\n"
     "FUNCTION_BLOCK FB_Pump\n"
     "VAR_INPUT bRun : BOOL; END_VAR\n"
     "VAR tDelay : TON; fFlow : REAL; END_VAR\n"
     "METHOD Start : BOOL\n"
     "Start := F_Scale(1.0) > 0.0;\n"
     "END_METHOD\n"
     "PROPERTY Flow : REAL\n"
     "GET\n"
     "Flow := F_Scale(fFlow);\n"
     "END_GET\n"
     "END_PROPERTY\n"
     "ACTION Stop:\n"
     "tDelay(IN := FALSE);\n"
     "END_ACTION\n"
     "tDelay(IN := bRun, PT := T#1S);\n"
     "fFlow := F_Scale(1.0);\n"
     "END_FUNCTION_BLOCK\n"},
    {"Globals.st", "VAR_GLOBAL gSpare : FB_Pump; END_VAR\n"},
    {"Types.st", "TYPE ST_Station : STRUCT pump : FB_Pump; END_STRUCT END_TYPE\n"},
    {"Plant.st",
     "PROGRAM PRG_Plant\n"
     "VAR\n"
     "  fbPump : FB_Pump;\n"
     "  aPumps : ARRAY[1..2] OF FB_Pump;\n"
     "  station : ST_Station;\n"
     "  F_Scale : REAL;\n"  // a local that hides the function: F_Scale below is no call
     "  n : INT;\n"
     "END_VAR\n"
     "fbPump(bRun := TRUE);\n"
     "aPumps[1]();\n"
     "station.pump();\n"
     "gSpare();\n"
     "IF fbPump.Start() THEN fbPump.Stop(); END_IF\n"
     "n := REAL_TO_INT(F_Scale);\n"
     "PRG_Other();\n"
     "END_PROGRAM\n"
     "PROGRAM PRG_Other\n"
     "VAR r : REAL; END_VAR\n"
     "r := F_Scale(F_Scale(r));\n"
     "END_PROGRAM\n"},
    {"Il.st",
     "FUNCTION_BLOCK FB_Il\n"
     "VAR p : FB_Pump; r : REAL; END_VAR\n"
     "CAL p(bRun := TRUE)\n"
     "CAL p\n"
     "LD 1.5\n"
     "F_Scale\n"
     "ADD 1.0\n"
     "ST r\n"
     "END_FUNCTION_BLOCK\n"},
    {"Sfc.st",
     "PROGRAM PRG_Sfc\n"
     "VAR n : INT; END_VAR\n"
     "INITIAL_STEP Idle:\n"
     "  Fill(N);\n"
     "END_STEP\n"
     "TRANSITION FROM Idle TO Idle := F_Scale(1.0) > 2.0;\n"
     "END_TRANSITION\n"
     "ACTION Fill:\n"
     "  n := REAL_TO_INT(F_Scale(3.0));\n"
     "END_ACTION\n"
     "END_PROGRAM\n"},
};

const Symbol* global(const MarkedProject& project, std::string_view name) {
  return project.model().find_global(name);
}

TEST(CallHierarchy, OutgoingCallsOfAProgramGoToFunctionsBlocksMethodsActionsAndPrograms) {
  const MarkedProject project(kPlant);
  const auto calls = query::outgoing_calls(project.workspace(), *global(project, "PRG_Plant"));
  const std::string at = "@Plant.st@";
  EXPECT_EQ(calls_of(project, calls),
            (std::vector<std::string>{
                "PRG_Plant -> FB_Pump fbPump" + at + std::to_string(project.at("Plant.st", "|fbPump(bRun")),
                "PRG_Plant -> FB_Pump aPumps" + at + std::to_string(project.at("Plant.st", "|aPumps[1]")),
                "PRG_Plant -> FB_Pump pump" + at + std::to_string(project.at("Plant.st", "station.|pump")),
                "PRG_Plant -> FB_Pump gSpare" + at + std::to_string(project.at("Plant.st", "|gSpare()")),
                "PRG_Plant -> FB_Pump.Start Start" + at + std::to_string(project.at("Plant.st", "fbPump.|Start()")),
                "PRG_Plant -> FB_Pump.Stop Stop" + at + std::to_string(project.at("Plant.st", "fbPump.|Stop()")),
                "PRG_Plant -> REAL_TO_INT REAL_TO_INT" + at + std::to_string(project.at("Plant.st", "|REAL_TO_INT")),
                "PRG_Plant -> PRG_Other PRG_Other" + at + std::to_string(project.at("Plant.st", "|PRG_Other()")),
            }));
}

TEST(CallHierarchy, ABlocksOwnCallsLeaveOutItsMethodsPropertiesAndActions) {
  const MarkedProject project(kPlant);
  const Symbol* pump = global(project, "FB_Pump");
  std::vector<std::string> callees;
  for (const auto& call : query::outgoing_calls(project.workspace(), *pump)) callees.push_back(qualified(call.callee));
  EXPECT_EQ(callees, (std::vector<std::string>{"TON", "F_Scale"}));
  // A property's calls are those of its GET and SET, with the property as caller.
  const auto flow = query::outgoing_calls(project.workspace(), *pump->own_member("Flow"));
  ASSERT_EQ(flow.size(), 1u);
  EXPECT_EQ(qualified(flow[0].caller), "FB_Pump.Flow");
  EXPECT_EQ(qualified(flow[0].callee), "F_Scale");
  // An action's calls are its own.
  const auto stop = query::outgoing_calls(project.workspace(), *pump->own_member("Stop"));
  ASSERT_EQ(stop.size(), 1u);
  EXPECT_EQ(qualified(stop[0].callee), "TON");
}

TEST(CallHierarchy, IlCalAndFunctionOperatorsAreCallsButStandardOperatorsAreNot) {
  const MarkedProject project(kPlant);
  const auto calls = query::outgoing_calls(project.workspace(), *global(project, "FB_Il"));
  EXPECT_EQ(calls_of(project, calls),
            (std::vector<std::string>{
                "FB_Il -> FB_Pump p@Il.st@" + std::to_string(project.at("Il.st", "CAL |p(")),
                "FB_Il -> FB_Pump p@Il.st@" + std::to_string(project.at("Il.st", "CAL |p\n")),
                "FB_Il -> F_Scale F_Scale@Il.st@" + std::to_string(project.at("Il.st", "|F_Scale\n")),
            }));
}

TEST(CallHierarchy, SfcStepAssociationsCallActionsAndActionBlocksCallForThemselves) {
  const MarkedProject project(kPlant);
  const Symbol* sfc = global(project, "PRG_Sfc");
  std::vector<std::string> callees;
  for (const auto& call : query::outgoing_calls(project.workspace(), *sfc)) callees.push_back(qualified(call.callee));
  // The association Fill(N) and the transition's condition; Fill's own calls are Fill's.
  EXPECT_EQ(callees, (std::vector<std::string>{"PRG_Sfc.Fill", "F_Scale"}));
  std::vector<std::string> fill;
  for (const auto& call : query::outgoing_calls(project.workspace(), *sfc->own_member("Fill"))) {
    fill.push_back(qualified(call.callee));
  }
  EXPECT_EQ(fill, (std::vector<std::string>{"REAL_TO_INT", "F_Scale"}));
  // Incoming: the association counts as a call of the action.
  const auto incoming = query::incoming_calls(project.workspace(), *sfc->own_member("Fill"));
  ASSERT_EQ(incoming.size(), 1u);
  EXPECT_EQ(qualified(incoming[0].caller), "PRG_Sfc");
}

TEST(CallHierarchy, IncomingCallsOfAFunctionComeFromEveryBodyButNotFromANameThatHidesIt) {
  const MarkedProject project(kPlant);
  std::vector<std::string> callers;
  for (const auto& call : query::incoming_calls(project.workspace(), *global(project, "F_Scale"))) {
    callers.push_back(qualified(call.caller));
  }
  // Sorted by path: Il.st, Plant.st (PRG_Other twice; PRG_Plant's F_Scale is its REAL), Pump.st
  // (the method, the property's GET as the property, the block), Sfc.st (transition, action).
  EXPECT_EQ(callers, (std::vector<std::string>{"FB_Il", "PRG_Other", "PRG_Other", "FB_Pump.Start", "FB_Pump.Flow",
                                               "FB_Pump", "PRG_Sfc", "PRG_Sfc.Fill"}));
}

TEST(CallHierarchy, IncomingCallsOfABlockAreTheCallsOfItsInstances) {
  const MarkedProject project(kPlant);
  const auto calls = query::incoming_calls(project.workspace(), *global(project, "FB_Pump"));
  std::vector<std::string> sites;
  for (const auto& call : calls) sites.push_back(MarkedProject::where(call.where));
  EXPECT_EQ(sites, (std::vector<std::string>{
                       project.where("Il.st", "CAL |p("),
                       project.where("Il.st", "CAL |p\n"),
                       project.where("Plant.st", "|fbPump(bRun"),
                       project.where("Plant.st", "|aPumps[1]"),
                       project.where("Plant.st", "station.|pump"),
                       project.where("Plant.st", "|gSpare()"),
                   }));
  // fbPump.Start() calls the method, not the block.
  const auto start = query::incoming_calls(project.workspace(), *global(project, "FB_Pump")->own_member("Start"));
  ASSERT_EQ(start.size(), 1u);
  EXPECT_EQ(MarkedProject::where(start[0].where), project.where("Plant.st", "fbPump.|Start()"));
}

TEST(CallHierarchy, ABlocksLocalInstanceIsCalledFromTheBlocksThatExtendIt) {
  const MarkedProject project(
      {{"Base.st",
        "FUNCTION_BLOCK FB_Timer\nEND_FUNCTION_BLOCK\n"
        "FUNCTION_BLOCK FB_Base\nVAR t : FB_Timer; END_VAR\nt();\nEND_FUNCTION_BLOCK\n"
        "FUNCTION F\nVAR t : FB_Timer; END_VAR\nt();\nEND_FUNCTION\n"},
       {"Derived.st", "FUNCTION_BLOCK FB_Derived EXTENDS FB_Base\nt();\nEND_FUNCTION_BLOCK\n"}});
  std::vector<std::string> callers;
  for (const auto& call : query::incoming_calls(project.workspace(), *project.model().find_global("FB_Timer"))) {
    callers.push_back(qualified(call.caller));
  }
  EXPECT_EQ(callers, (std::vector<std::string>{"FB_Base", "F", "FB_Derived"}));
}

TEST(CallHierarchy, IncomingCallsStopWhenCancelled) {
  const MarkedProject project(kPlant);
  EXPECT_TRUE(query::incoming_calls(project.workspace(), *global(project, "F_Scale"), [] { return true; }).empty());
}

TEST(CallHierarchy, ItemAtACursor) {
  const MarkedProject project(kPlant);
  auto item = [&](const std::string& path, const std::string& marked) {
    return qualified(query::call_hierarchy_symbol_at(project.workspace(), project.id(path), project.at(path, marked)));
  };
  EXPECT_EQ(item("Plant.st", "|fbPump(bRun"), "FB_Pump");                // an instance: its block
  EXPECT_EQ(item("Plant.st", "fbPump.St|art()"), "FB_Pump.Start");       // a method call
  EXPECT_EQ(item("Plant.st", "PROGRAM PRG_Pl|ant"), "PRG_Plant");        // a declaration
  EXPECT_EQ(item("Pump.st", "G|ET\nFlow"), "FB_Pump.Flow");              // a GET: its property
  EXPECT_EQ(item("Plant.st", "  |n : INT"), "(null)");                   // an INT
  EXPECT_EQ(item("Plant.st", "IF fbPump.Start() THEN| "), "PRG_Plant");  // no name: the POU around
  EXPECT_EQ(item("Globals.st", "VAR_GLOBAL| "), "(null)");               // no name, no POU
}

TEST(CallHierarchy, BrokenBodiesGiveWhatCanBeFound) {
  const MarkedProject project({{"Broken.st",
                                "FUNCTION F : INT\nF := 1;\nEND_FUNCTION\n"
                                "PROGRAM P\nVAR x : INT; END_VAR\n"
                                "x := F(;\n"
                                "x := F() + ;\n"
                                "Missing(1);\n"
                                "END_PROGRAM\n"}});
  const auto calls = query::outgoing_calls(project.workspace(), *project.model().find_global("P"));
  for (const auto& call : calls) EXPECT_EQ(qualified(call.callee), "F");
  EXPECT_FALSE(calls.empty());
  EXPECT_EQ(query::incoming_calls(project.workspace(), *project.model().find_global("F")).size(), calls.size());
}

const MarkedProject::Files kDevices = {
    {"Devices.st",
     "INTERFACE I_Device\nEND_INTERFACE\n"
     "INTERFACE I_Motor EXTENDS I_Device\nEND_INTERFACE\n"
     "INTERFACE I_Both EXTENDS I_Motor, I_Device\nEND_INTERFACE\n"
     "FUNCTION_BLOCK FB_Device IMPLEMENTS I_Device\nEND_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK FB_Motor EXTENDS FB_Device IMPLEMENTS I_Motor, I_Device\nEND_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK FB_Servo EXTENDS FB_Motor\nEND_FUNCTION_BLOCK\n"
     "PROGRAM P\nVAR m : FB_Servo; a : ARRAY[1..2] OF ST_B; n : INT; END_VAR\nEND_PROGRAM\n"},
    {"Types.st",
     "TYPE ST_A : STRUCT x : INT; END_STRUCT END_TYPE\n"
     "TYPE ST_B EXTENDS ST_A : STRUCT y : INT; END_STRUCT END_TYPE\n"
     "TYPE E_X : (One, Two); END_TYPE\n"},
    {"Loop.st",  // broken code: a cycle of EXTENDS must not hang anything
     "FUNCTION_BLOCK FB_L1 EXTENDS FB_L2\nEND_FUNCTION_BLOCK\n"
     "FUNCTION_BLOCK FB_L2 EXTENDS FB_L1\nEND_FUNCTION_BLOCK\n"},
};

TEST(TypeHierarchy, SupertypesAreExtendsThenImplementsOnce) {
  const MarkedProject project(kDevices);
  EXPECT_EQ(names_of(query::supertypes_of(*project.model().find_global("FB_Motor"))),
            (std::vector<std::string>{"FB_Device", "I_Motor", "I_Device"}));
  EXPECT_EQ(names_of(query::supertypes_of(*project.model().find_global("I_Both"))),
            (std::vector<std::string>{"I_Motor", "I_Device"}));
  EXPECT_EQ(names_of(query::supertypes_of(*project.model().find_global("ST_B"))), (std::vector<std::string>{"ST_A"}));
  EXPECT_TRUE(query::supertypes_of(*project.model().find_global("FB_Device")).size() == 1);
}

TEST(TypeHierarchy, SubtypesAreTheDirectOnes) {
  const MarkedProject project(kDevices);
  const ProjectModel& model = project.model();
  EXPECT_EQ(names_of(query::subtypes_of(model, *model.find_global("I_Device"))),
            (std::vector<std::string>{"I_Motor", "I_Both", "FB_Device", "FB_Motor"}));
  EXPECT_EQ(names_of(query::subtypes_of(model, *model.find_global("FB_Device"))),
            (std::vector<std::string>{"FB_Motor"}));
  EXPECT_EQ(names_of(query::subtypes_of(model, *model.find_global("ST_A"))), (std::vector<std::string>{"ST_B"}));
  EXPECT_TRUE(query::subtypes_of(model, *model.find_global("FB_Servo")).empty());
  EXPECT_EQ(names_of(query::subtypes_of(model, *model.find_global("FB_L1"))), (std::vector<std::string>{"FB_L2"}));
}

TEST(TypeHierarchy, ItemAtACursor) {
  const MarkedProject project(kDevices);
  auto item = [&](const std::string& path, const std::string& marked) {
    return qualified(query::type_hierarchy_symbol_at(project.workspace(), project.id(path), project.at(path, marked)));
  };
  EXPECT_EQ(item("Devices.st", "EXTENDS FB_Dev|ice"), "FB_Device");
  EXPECT_EQ(item("Devices.st", "IMPLEMENTS I_Motor, I_De|vice"), "I_Device");
  EXPECT_EQ(item("Devices.st", "VAR |m : FB_Servo"), "FB_Servo");  // a variable: its type
  EXPECT_EQ(item("Devices.st", "|a : ARRAY"), "ST_B");             // through ARRAY OF
  EXPECT_EQ(item("Devices.st", "|n : INT"), "(null)");
  EXPECT_EQ(item("Types.st", "TYPE E_|X"), "(null)");  // an enumeration extends nothing
  EXPECT_EQ(item("Devices.st", "PROGRAM |P"), "(null)");
}

}  // namespace
}  // namespace rung::check
