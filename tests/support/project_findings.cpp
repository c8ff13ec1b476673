#include "tests/support/project_findings.hpp"

#include <algorithm>

namespace rung::check::testing {

std::vector<Finding> project_findings(const Files& files, const project::ProjectConfig& config, Warnings warnings) {
  auto workspace = Workspace::from_texts(files, config);
  std::vector<Finding> result;
  for (const auto& file : workspace->check_all(1)) {
    // Lines are counted in the file's own text (paths may come back normalised: match the end).
    const std::string* text = nullptr;
    for (const auto& [path, content] : files) {
      if (file.path.ends_with(path)) text = &content;
    }
    for (const auto& diagnostic : file.diagnostics) {
      const auto line = text ? 1 + std::count(text->begin(), text->begin() + diagnostic.range.begin, '\n') : 0;
      const bool mark = warnings == Warnings::Marked && diagnostic.severity == Severity::Warning;
      result.push_back(
          {diagnostic.code + "@" + std::to_string(line) + (mark ? "?" : ""), diagnostic.message, diagnostic.help});
    }
  }
  return result;
}

std::vector<std::string> codes_at_lines(const Files& files, const project::ProjectConfig& config, Warnings warnings) {
  std::vector<std::string> result;
  for (Finding& finding : project_findings(files, config, warnings)) result.push_back(std::move(finding.at));
  return result;
}

std::vector<std::string> messages_with_code(const Files& files, const project::ProjectConfig& config,
                                            std::string_view code) {
  std::vector<std::string> result;
  const std::string prefix = std::string(code) + "@";
  for (Finding& finding : project_findings(files, config)) {
    if (finding.at.starts_with(prefix)) result.push_back(std::move(finding.message));
  }
  return result;
}

project::ProjectConfig config_for(project::Profile profile) {
  project::ProjectConfig config;
  config.profile = profile;
  return config;
}

}  // namespace rung::check::testing
