#include "cli/sarif_report.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "parser/diagnostic_codes.hpp"

namespace rung::cli {
namespace {

std::string sarif_level(Severity severity) {
  switch (severity) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    default: return "note";
  }
}

nlohmann::json artifact(const Document& document) {
  return {{"uri", std::filesystem::path(document.path()).generic_string()}};
}

nlohmann::json sarif_fix(const Document& document, const lint::Fix& fix) {
  nlohmann::json replacements = nlohmann::json::array();
  for (const lint::TextEdit& edit : fix.edits) {
    replacements.push_back(
        {{"deletedRegion", sarif_region(document, edit.range)}, {"insertedContent", {{"text", edit.replacement}}}});
  }
  return {{"description", {{"text", fix.description}}},
          {"artifactChanges", {{{"artifactLocation", artifact(document)}, {"replacements", replacements}}}}};
}

}  // namespace

nlohmann::json sarif_region(const Document& document, TextRange range) {
  const FilePosition start = document.position_of_file_offset(range.begin);
  const FilePosition end = document.position_of_file_offset(range.end);
  return {{"startLine", start.line}, {"startColumn", start.column}, {"endLine", end.line}, {"endColumn", end.column}};
}

nlohmann::json sarif_report(const std::vector<SarifFinding>& findings) {
  nlohmann::json rules = nlohmann::json::array();
  for (const DiagnosticCodeInfo& info : all_diagnostic_codes()) {
    rules.push_back(
        {{"id", std::string(info.code)},
         {"name", std::string(info.title)},
         {"shortDescription", {{"text", std::string(info.summary)}}},
         {"helpUri", diagnostic_docs_url(info.code)},
         {"defaultConfiguration", {{"level", sarif_level(info.default_severity)}}}});
  }
  nlohmann::json results = nlohmann::json::array();
  for (const SarifFinding& finding : findings) {
    const Diagnostic& diagnostic = *finding.diagnostic;
    std::string text = diagnostic.message;
    if (!diagnostic.help.empty()) text += " (" + diagnostic.help + ")";
    nlohmann::json result{{"ruleId", diagnostic.code},
                          {"level", sarif_level(diagnostic.severity)},
                          {"message", {{"text", text}}},
                          {"locations",
                           {{{"physicalLocation",
                              {{"artifactLocation", artifact(*finding.document)},
                               {"region", sarif_region(*finding.document, diagnostic.range)}}}}}}};
    if (finding.fix) result["fixes"] = {sarif_fix(*finding.document, *finding.fix)};
    results.push_back(std::move(result));
  }
  return {
      {"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
      {"version", "2.1.0"},
      {"runs",
       {{{"tool",
          {{"driver", {{"name", "rung"}, {"informationUri", "https://github.com/rung-plc/rung"}, {"rules", rules}}}}},
         {"results", results}}}}};
}

}  // namespace rung::cli
