#include "bench/generated_project.hpp"

#include <fstream>
#include <functional>
#include <random>

#include "bench/generated_source.hpp"

namespace rung::bench {
namespace {

// Each file gets between kMinLines and kMinLines + kLineSpread - 1 lines (filler decides).
constexpr size_t kMinLines = 88;
constexpr size_t kLineSpread = 31;

// Names of one cell's declarations; the cell before it (if any) is referenced too, so the
// project is one connected graph rather than independent islands.
struct Cell {
  explicit Cell(size_t index) : k(std::to_string(index)), previous(index > 0 ? std::to_string(index - 1) : "") {}
  std::string k;
  std::string previous;  // empty for the first cell
  bool has_previous() const { return !previous.empty(); }
  std::string mode() const { return "E_Mode" + k; }
  std::string recipe() const { return "ST_Recipe" + k; }
  std::string diag() const { return "ST_Diag" + k; }
  std::string gvl() const { return "GVL_Cell" + k; }
  std::string fb() const { return "FB_Axis" + k; }
  std::string scale() const { return "F_Scale" + k; }
  std::string describe() const { return "F_Describe" + k; }
  std::string average() const { return "F_Average" + k; }
  std::string program() const { return "PRG_Cell" + k; }
};

std::string real_literal(std::mt19937& rng) {
  return std::to_string(rng() % 200) + "." + std::to_string(rng() % 10);
}

void write_types(LineWriter& out, const Cell& c, std::mt19937& rng, size_t target) {
  out.line("// Data types of cell " + c.k + ": operating mode, recipe and diagnostics.");
  out.line("{attribute 'qualified_only'}");
  out.line("{attribute 'strict'}");
  out.line("TYPE " + c.mode() + " :");
  out.line("(");
  out.line("    Idle := 0,");
  out.line("    Starting,");
  out.line("    Running,");
  out.line("    Stopping,");
  out.line("    Fault := 99");
  out.line(");");
  out.line("END_TYPE");
  out.line("");
  out.line("TYPE " + c.recipe() + " :");
  out.line("STRUCT");
  out.line("    sName : STRING(32) := 'recipe " + c.k + "';");
  out.line("    nCount : INT := " + std::to_string(3 + rng() % 7) + ";      // parts per batch");
  out.line("    rMin : REAL := 0.0;");
  out.line("    rMax : REAL := " + real_literal(rng) + ";");
  out.line("    tTimeout : TIME := T#" + std::to_string(1 + rng() % 9) + "S;");
  out.line("    eStartMode : " + c.mode() + " := " + c.mode() + ".Idle;");
  out.line("    aLimits : ARRAY[0..9] OF REAL;");
  if (c.has_previous()) out.line("    stUpstream : ST_Recipe" + c.previous + ";   (* the cell that feeds this one *)");
  out.line("END_STRUCT");
  out.line("END_TYPE");
  out.line("");
  out.line("TYPE " + c.diag() + " :");
  out.line("STRUCT");
  out.line("    bHealthy : BOOL := TRUE;");
  // Filler fields up to the file's size, of the kinds diagnostics structures hold.
  for (size_t field = 0; out.lines() + 2 < target; ++field) {
    const std::string name = std::to_string(field);
    switch (rng() % 5) {
      case 0: out.line("    bFlag" + name + " : BOOL;"); break;
      case 1: out.line("    nCounter" + name + " : UDINT;   // events since power-on"); break;
      case 2: out.line("    rValue" + name + " : REAL := " + real_literal(rng) + ";"); break;
      case 3: out.line("    tLast" + name + " : TIME;"); break;
      default: out.line("    sText" + name + " : STRING(20) := 'diag';"); break;
    }
  }
  out.line("END_STRUCT");
  out.line("END_TYPE");
}

void write_global_list(LineWriter& out, const Cell& c, std::mt19937& rng, size_t target) {
  out.line("// Global variables of cell " + c.k + " (read with the list's name: " + c.gvl() + ".bStart).");
  out.line("{attribute 'qualified_only'}");
  out.line("VAR_GLOBAL CONSTANT");
  out.line("    cMaxCount : INT := 100;");
  out.line("    cTolerance : REAL := 0.01;");
  out.line("END_VAR");
  out.line("VAR_GLOBAL");
  out.line("    bStart : BOOL;                 // start request from the HMI");
  out.line("    bLamp : BOOL;");
  out.line("    eMode : " + c.mode() + " := " + c.mode() + ".Idle;");
  out.line("    aSetpoints : ARRAY[0..9] OF REAL;");
  out.line("    stRecipe : " + c.recipe() + ";");
  out.line("    stDiag : " + c.diag() + ";");
  out.line("    sOperator : STRING(40) := 'operator';");
  out.line("    nCycles : UDINT;");
  for (size_t item = 0; out.lines() + 1 < target; ++item) {
    const std::string name = std::to_string(item);
    switch (rng() % 4) {
      case 0: out.line("    bSignal" + name + " : BOOL;"); break;
      case 1: out.line("    iLevel" + name + " : INT := " + std::to_string(rng() % 1000) + ";"); break;
      case 2: out.line("    rAnalog" + name + " : REAL;   (* scaled sensor value *)"); break;
      default: out.line("    aHistory" + name + " : ARRAY[1..8] OF DINT;"); break;
    }
  }
  out.line("END_VAR");
}

void write_functions(LineWriter& out, const Cell& c, std::mt19937& rng, size_t target) {
  out.line("// Helper functions of cell " + c.k + ".");
  out.line("FUNCTION " + c.scale() + " : REAL");
  out.line("VAR_INPUT");
  out.line("    rIn : REAL;");
  out.line("    rInMin : REAL;");
  out.line("    rInMax : REAL;");
  out.line("    rOutMin : REAL;");
  out.line("    rOutMax : REAL;");
  out.line("END_VAR");
  out.line("IF ABS(rInMax - rInMin) < 1.0E-6 THEN");
  out.line("    " + c.scale() + " := rOutMin;");
  out.line("ELSE");
  out.line("    " + c.scale() + " := rOutMin + (rIn - rInMin) * (rOutMax - rOutMin) / (rInMax - rInMin);");
  out.line("END_IF");
  out.line("END_FUNCTION");
  out.line("");
  out.line("FUNCTION " + c.describe() + " : STRING(80)");
  out.line("VAR_INPUT");
  out.line("    eMode : " + c.mode() + ";");
  out.line("    iCode : INT;");
  out.line("END_VAR");
  out.line("VAR");
  out.line("    sName : STRING(20);");
  out.line("END_VAR");
  out.line("CASE eMode OF");
  out.line("    " + c.mode() + ".Idle: sName := 'idle';");
  out.line("    " + c.mode() + ".Starting, " + c.mode() + ".Running: sName := 'active';");
  out.line("    " + c.mode() + ".Fault: sName := 'fault';");
  out.line("ELSE");
  out.line("    sName := 'stopping';");
  out.line("END_CASE");
  out.line(c.describe() + " := CONCAT(CONCAT(sName, ': '), INT_TO_STRING(iCode));");
  out.line("IF LEN(" + c.describe() + ") > 60 THEN");
  out.line("    " + c.describe() + " := LEFT(" + c.describe() + ", 60);");
  out.line("END_IF");
  out.line("END_FUNCTION");
  out.line("");
  out.line("FUNCTION " + c.average() + " : REAL");
  out.line("VAR_INPUT");
  out.line("    aValues : ARRAY[0..9] OF REAL;");
  out.line("END_VAR");
  out.line("VAR");
  out.line("    i : INT;");
  out.line("    rSum : REAL;");
  out.line("END_VAR");
  out.line("FOR i := 0 TO 9 DO");
  out.line("    rSum := rSum + aValues[i];");
  out.line("END_FOR");
  if (c.has_previous()) {
    // Formal call of the previous cell's function.
    out.line(c.average() + " := F_Scale" + c.previous +
             "(rIn := rSum / 10.0, rInMin := 0.0, rInMax := 100.0, rOutMin := 0.0, rOutMax := 1.0);");
  } else {
    out.line(c.average() + " := rSum / 10.0;");
  }
  out.line("END_FUNCTION");
  // First-order filters up to the file's size.
  for (size_t filter = 0; out.lines() + 14 < target; ++filter) {
    const std::string name = "F_Filter" + c.k + "_" + std::to_string(filter);
    out.line("");
    out.line("(* first-order lag, factor " + std::to_string(filter) + " *)");
    out.line("FUNCTION " + name + " : REAL");
    out.line("VAR_INPUT");
    out.line("    rIn : REAL;");
    out.line("    rOld : REAL;");
    out.line("    rFactor : REAL := " + real_literal(rng) + ";");
    out.line("END_VAR");
    out.line("IF rFactor <= 0.0 THEN");
    out.line("    " + name + " := rIn;");
    out.line("ELSE");
    out.line("    " + name + " := rOld + (rIn - rOld) / MAX(1.0, rFactor);");
    out.line("END_IF");
    out.line("END_FUNCTION");
  }
}

// Lines the methods after the FB's body take (write_function_block reserves room for them).
constexpr size_t kMethodLines = 34;

void write_function_block(LineWriter& out, const Cell& c, std::mt19937& rng, size_t target) {
  out.line("// One axis of cell " + c.k + ": follows the recipe, counts parts, drives the axis before it.");
  out.line("{attribute 'reflection'}");
  out.line("FUNCTION_BLOCK " + c.fb());
  write_mixed_statement_variables(out);
  out.line("VAR_INPUT");
  out.line("    eMode : " + c.mode() + ";");
  out.line("    stRecipe : " + c.recipe() + ";");
  out.line("END_VAR");
  out.line("VAR_OUTPUT");
  out.line("    rPosition : REAL;");
  out.line("    sStatus : STRING(80);");
  out.line("END_VAR");
  out.line("VAR");
  if (c.has_previous()) out.line("    fbInner : FB_Axis" + c.previous + ";");
  out.line("    rtStart : R_TRIG;");
  out.line("    ctuParts : CTU;");
  out.line("    nLoops : INT;");
  out.line("END_VAR");
  out.line("");
  out.line("rtStart(CLK := bEnable);");
  out.line("IF rtStart.Q THEN");
  out.line("    ctuParts(CU := TRUE, RESET := FALSE, PV := 10);");
  out.line("END_IF");
  if (c.has_previous()) {
    out.line("fbInner(bEnable := bEnable AND eMode = " + c.mode() + ".Running, rSetpoint := rSetpoint * 0.5,");
    out.line("        tDelay := stRecipe.tTimeout, eMode := E_Mode" + c.previous + ".Running,");
    out.line("        stRecipe := stRecipe.stUpstream);");
    out.line("rPosition := fbInner.rPosition + " + c.scale() + "(rSum, 0.0, 100.0, 0.0, 10.0);");
  } else {
    out.line("rPosition := " + c.scale() + "(rSum, 0.0, 100.0, 0.0, 10.0);");
  }
  out.line("nLoops := 0;");
  out.line("WHILE nLoops < stRecipe.nCount AND nLoops < 10 DO");
  out.line("    nLoops := nLoops + 1;");
  out.line("END_WHILE");
  out.line("CASE eMode OF");
  out.line("    " + c.mode() + ".Idle:");
  out.line("        iState := 0;");
  out.line("    " + c.mode() + ".Running:");
  out.line("        rSum := LIMIT(stRecipe.rMin, rSum + rSetpoint, stRecipe.rMax);");
  out.line("ELSE");
  out.line("    bDone := ctuParts.Q;");
  out.line("END_CASE");
  while (out.lines() + kMethodLines + 3 < target) write_mixed_statement(out, rng);
  out.line("sStatus := " + c.describe() + "(eMode, iState);");
  out.line("END_FUNCTION_BLOCK");
  out.line("");
  out.line("METHOD Reset : BOOL");
  out.line("VAR_INPUT");
  out.line("    bClearCount : BOOL;");
  out.line("END_VAR");
  out.line("iState := 0;");
  out.line("rSum := 0.0;");
  out.line("IF bClearCount THEN");
  out.line("    ctuParts(CU := FALSE, RESET := TRUE);");
  out.line("END_IF");
  out.line("Reset := TRUE;");
  out.line("END_METHOD");
  out.line("");
  out.line("METHOD Step : REAL");
  out.line("VAR_INPUT");
  out.line("    rDelta : REAL;");
  out.line("END_VAR");
  out.line("VAR");
  out.line("    rNext : REAL;");
  out.line("END_VAR");
  out.line("rNext := rPosition + rDelta;");
  out.line("Step := LIMIT(stRecipe.rMin, rNext, stRecipe.rMax);");
  out.line("END_METHOD");
  out.line("");
  out.line("METHOD PUBLIC Fill : INT");
  out.line("VAR_INPUT");
  out.line("    iValue : INT;");
  out.line("END_VAR");
  out.line("FOR i := 0 TO 15 DO");
  out.line("    aBuffer[i] := iValue;");
  out.line("END_FOR");
  out.line("Fill := iValue * 16;");
  out.line("END_METHOD");
}

void write_program(LineWriter& out, const Cell& c, std::mt19937& rng, size_t target) {
  const std::string gvl = c.gvl();
  out.line("// Cell " + c.k + " sequence: start delay, axis, scaling and operator messages.");
  out.line("PROGRAM " + c.program());
  out.line("VAR");
  out.line("    fbAxis : " + c.fb() + ";");
  out.line("    tonStart : TON;");
  out.line("    tpPulse : TP;");
  out.line("    ftStop : F_TRIG;");
  out.line("    aValues : ARRAY[0..9] OF REAL;");
  out.line("    i : INT;");
  out.line("    rAverage : REAL;");
  out.line("    sMessage : STRING(80);");
  out.line("    nPos : INT;");
  out.line("    bOk : BOOL;");
  out.line("END_VAR");
  out.line("");
  out.line("tonStart(IN := " + gvl + ".bStart, PT := T#500MS);");
  out.line("IF tonStart.Q AND " + gvl + ".eMode = " + c.mode() + ".Idle THEN");
  out.line("    " + gvl + ".eMode := " + c.mode() + ".Starting;");
  out.line("ELSIF " + gvl + ".eMode = " + c.mode() + ".Starting THEN");
  out.line("    " + gvl + ".eMode := " + c.mode() + ".Running;");
  out.line("END_IF");
  out.line("fbAxis(bEnable := tonStart.Q, rSetpoint := " + gvl + ".aSetpoints[0], tDelay := T#1S,");
  out.line("       eMode := " + gvl + ".eMode, stRecipe := " + gvl + ".stRecipe, bDone => bOk);");
  out.line("FOR i := 0 TO 9 DO");
  out.line("    aValues[i] := " + c.scale() + "(" + gvl + ".aSetpoints[i], 0.0, 100.0, 0.0, 1.0);");
  out.line("END_FOR");
  out.line("rAverage := " + c.average() + "(aValues);");
  out.line("sMessage := " + c.describe() + "(eMode := " + gvl + ".eMode, iCode := fbAxis.iState);");
  out.line("nPos := FIND(sMessage, ':');");
  out.line("IF nPos > 1 THEN");
  out.line("    sMessage := MID(sMessage, 5, nPos);");
  out.line("END_IF");
  out.line("IF fbAxis.Reset(bClearCount := NOT " + gvl + ".bStart) THEN");
  out.line("    rAverage := fbAxis.Step(0.5);");
  out.line("END_IF");
  out.line("ftStop(CLK := " + gvl + ".bStart);");
  out.line("CASE " + gvl + ".eMode OF");
  out.line("    " + c.mode() + ".Running:");
  out.line("        IF ftStop.Q THEN");
  out.line("            " + gvl + ".eMode := " + c.mode() + ".Stopping;");
  out.line("        END_IF");
  out.line("    " + c.mode() + ".Stopping:");
  out.line("        IF fbAxis.bDone THEN");
  out.line("            " + gvl + ".eMode := " + c.mode() + ".Idle;");
  out.line("        END_IF");
  out.line("END_CASE");
  // Statements up to the file's size, each touching the globals, the FB or the library.
  while (out.lines() + 1 < target) {
    const std::string n = std::to_string(rng() % 10);
    switch (rng() % 6) {
      case 0:
        out.line(gvl + ".aSetpoints[" + n + "] := " + c.scale() + "(rIn := INT_TO_REAL(i), rInMin := 0.0,");
        out.line("    rInMax := 10.0, rOutMin := 0.0, rOutMax := " + real_literal(rng) + ");");
        break;
      case 1:
        out.line("IF " + gvl + ".bStart AND NOT fbAxis.bDone THEN");
        out.line("    " + gvl + ".nCycles := " + gvl + ".nCycles + 1;");
        out.line("END_IF");
        break;
      case 2:
        out.line("sMessage := CONCAT(" + gvl + ".sOperator, ' ok');");
        out.line("IF LEN(sMessage) > 30 THEN");
        out.line("    sMessage := LEFT(sMessage, 30);");
        out.line("END_IF");
        break;
      case 3:
        out.line("tpPulse(IN := fbAxis.bDone, PT := T#" + std::to_string(50 + rng() % 200) + "MS);");
        out.line(gvl + ".bLamp := tpPulse.Q OR " + gvl + ".stDiag.bHealthy;");
        break;
      case 4:
        out.line("i := 0;");
        out.line("WHILE i < 9 AND aValues[i] < rAverage DO");
        out.line("    i := i + 1;");
        out.line("END_WHILE");
        break;
      default:
        if (c.has_previous()) {
          out.line("GVL_Cell" + c.previous + ".bStart := " + gvl + ".eMode = " + c.mode() + ".Running;");
        } else {
          out.line("rAverage := MAX(rAverage, fbAxis.rPosition);");
        }
        break;
    }
  }
  out.line("END_PROGRAM");
}

using FileWriter = std::function<void(LineWriter&, const Cell&, std::mt19937&, size_t)>;

struct FileKind {
  const char* prefix;
  FileWriter write;
};

}  // namespace

GeneratedProject generate_project(size_t files, unsigned seed) {
  // Dependency order inside a cell, so any prefix of the project refers only to what it holds.
  static const FileKind kinds[] = {
      {"DUT_Cell", write_types},         {"GVL_Cell", write_global_list}, {"FUN_Cell", write_functions},
      {"FB_Axis", write_function_block}, {"PRG_Cell", write_program},
  };
  std::mt19937 rng(seed);
  GeneratedProject project;
  for (size_t i = 0; i < files; ++i) {
    const size_t cell_index = i / std::size(kinds);
    const FileKind& kind = kinds[i % std::size(kinds)];
    const Cell cell(cell_index);
    const size_t target = kMinLines + rng() % kLineSpread;
    LineWriter out;
    kind.write(out, cell, rng, target);
    GeneratedFile file;
    file.name = kind.prefix + cell.k + ".st";
    file.lines = out.lines();
    file.text = out.take();
    project.lines += file.lines;
    project.bytes += file.text.size();
    project.files.push_back(std::move(file));
  }
  return project;
}

std::vector<std::pair<std::string, std::string>> project_texts(const GeneratedProject& project) {
  std::vector<std::pair<std::string, std::string>> texts;
  texts.reserve(project.files.size());
  for (const GeneratedFile& file : project.files) texts.emplace_back(file.name, file.text);
  return texts;
}

bool write_project(const GeneratedProject& project, const std::filesystem::path& folder, std::string& error) {
  std::error_code code;
  std::filesystem::create_directories(folder, code);
  if (code) {
    error = folder.string() + ": " + code.message();
    return false;
  }
  for (const GeneratedFile& file : project.files) {
    std::ofstream out(folder / file.name, std::ios::binary | std::ios::trunc);
    out << file.text;
    if (!out) {
      error = (folder / file.name).string() + ": cannot write";
      return false;
    }
  }
  return true;
}

}  // namespace rung::bench
