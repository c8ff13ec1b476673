// Session: diagnostics. Files whose findings may have changed are "due"; the worker publishes
// open files first, then the rest of the project one file per step, so a keystroke's own
// diagnostics never wait behind a whole-project re-check and requests interleave with the work.
#include <algorithm>

#include "checker/lint/lint.hpp"
#include "lsp/json_util.hpp"
#include "lsp/session.hpp"
#include "lsp/uri.hpp"
#include "parser/diagnostic_codes.hpp"

namespace rung::lsp {

namespace {

int lsp_severity(Severity severity) {
  switch (severity) {
    case Severity::Error:
      return 1;
    case Severity::Warning:
      return 2;
    case Severity::Info:
      return 3;
    case Severity::Hint:
      return 4;
  }
  return 1;
}

// Unused-variable style findings are shown faded by editors that know the tag.
bool is_unnecessary(std::string_view code) { return code == "L071" || code == "L072" || code == "L073"; }

}  // namespace

Json Session::diagnostics_of(const DocumentRef& document) const {
  const Project& project = *document.project;
  std::vector<Diagnostic> all = project.workspace->check_source(document.source).diagnostics;
  lint::FileFindings lint = project.lint(document.source);
  for (lint::Finding& finding : lint.findings) all.push_back(std::move(finding.diagnostic));
  sort_diagnostics(all);
  Json out = Json::array();
  for (const Diagnostic& diagnostic : all) {
    std::string message = diagnostic.message;
    if (!diagnostic.help.empty()) message += "\nhelp: " + diagnostic.help;
    Json item{{"range", range_of(document, diagnostic.range)},
              {"severity", lsp_severity(diagnostic.severity)},
              {"code", diagnostic.code},
              {"source", "rung"},
              {"message", message}};
    if (find_diagnostic_code(diagnostic.code)) item["codeDescription"] = Json{{"href", diagnostic_docs_url(diagnostic.code)}};
    if (is_unnecessary(diagnostic.code)) item["tags"] = Json::array({1});
    if (!diagnostic.labels.empty()) {
      Json related = Json::array();
      for (const DiagnosticLabel& label : diagnostic.labels) {
        related.push_back(Json{{"location", Json{{"uri", document.uri}, {"range", range_of(document, label.range)}}},
                               {"message", label.message}});
      }
      item["relatedInformation"] = std::move(related);
    }
    out.push_back(std::move(item));
  }
  return out;
}

void Session::mark_dirty(const std::vector<Affected>& affected) {
  for (const Affected& entry : affected) {
    for (const check::SourceId id : entry.sources) {
      const DocumentRef document{entry.project, id, uri_of(*entry.project, id)};
      if (open_.contains(document.uri)) {
        dirty_open_.insert({entry.project, id});
      } else {
        dirty_background_.insert({entry.project, id});
      }
    }
  }
}

void Session::publish(const DocumentRef& document) {
  Json diagnostics = diagnostics_of(document);
  if (diagnostics.empty() && !published_.contains(document.uri)) return;  // nothing to show or clear
  if (diagnostics.empty()) {
    published_.erase(document.uri);
  } else {
    published_.insert(document.uri);
  }
  Json params{{"uri", document.uri}, {"diagnostics", std::move(diagnostics)}};
  if (const OpenDocument* open = open_document(document.uri)) params["version"] = open->version;
  notify("textDocument/publishDiagnostics", std::move(params));
}

bool Session::background_step() {
  if (!push_diagnostics_) {
    // A pulling client asks itself; tell it once that what it has may be stale.
    const bool due = !dirty_open_.empty() || !dirty_background_.empty();
    dirty_open_.clear();
    dirty_background_.clear();
    if (due && json_at(client_capabilities_, {"workspace", "diagnostics", "refreshSupport"}) == true) sink_(make_request("rung-refresh", "workspace/diagnostic/refresh", nullptr));
    return false;
  }
  auto& queue = dirty_open_.empty() ? dirty_background_ : dirty_open_;
  if (queue.empty()) return false;
  const auto [project, source] = *queue.begin();
  queue.erase(queue.begin());
  if (!project->removed.contains(source)) publish(DocumentRef{project, source, uri_of(*project, source)});
  return true;
}

void Session::drop_project(const Project* project) {
  std::erase_if(dirty_open_, [&](const auto& entry) { return entry.first == project; });
  std::erase_if(dirty_background_, [&](const auto& entry) { return entry.first == project; });
}

void Session::clear_published(const Project& project) {
  for (const auto& [key, id] : project.by_path) {
    const std::string uri = uri_of(project, id);
    if (published_.erase(uri)) notify("textDocument/publishDiagnostics", Json{{"uri", uri}, {"diagnostics", Json::array()}});
  }
}

void Session::publish_config_text(const std::string& uri, const std::filesystem::path& folder, const std::string& text) {
  const project::LoadedConfig loaded = project::parse_project_config(text, folder);
  const source::LineIndex lines(text);
  Json diagnostics = Json::array();
  for (const Diagnostic& diagnostic : loaded.diagnostics) {
    const auto position = [&](uint32_t offset) {
      const source::Position p = lines.position_of(offset);
      return Json{{"line", p.line}, {"character", p.utf16_column}};
    };
    diagnostics.push_back(Json{{"range", Json{{"start", position(diagnostic.range.begin)}, {"end", position(diagnostic.range.end)}}},
                               {"severity", lsp_severity(diagnostic.severity)},
                               {"code", diagnostic.code},
                               {"codeDescription", Json{{"href", diagnostic_docs_url(diagnostic.code)}}},
                               {"source", "rung"},
                               {"message", diagnostic.message}});
  }
  if (diagnostics.empty() && !published_.contains(uri)) return;
  if (diagnostics.empty()) {
    published_.erase(uri);
  } else {
    published_.insert(uri);
  }
  notify("textDocument/publishDiagnostics", Json{{"uri", uri}, {"diagnostics", std::move(diagnostics)}});
}

void Session::publish_config_diagnostics(const Project& project) {
  if (!project.config.config.config_file) return;
  publish_config_text(uri_of_path(*project.config.config.config_file), project.root, project.config.text);
}

}  // namespace rung::lsp
