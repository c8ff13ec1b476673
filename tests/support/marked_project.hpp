// Test support for the query API: a small in-memory project whose positions are written as a
// snippet of a file with '|' where the cursor stands ("fbMotor.|Start(").
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "checker/check.hpp"
#include "checker/query/location.hpp"

namespace rung::check::testing {

class MarkedProject {
 public:
  using Files = std::vector<std::pair<std::string, std::string>>;

  explicit MarkedProject(Files files, project::Profile profile = project::Profile::Codesys) : files_(std::move(files)) {
    project::ProjectConfig config;
    config.profile = profile;
    workspace_ = Workspace::from_texts(files_, config);
  }
  // MarkedProject({{"a.st", "..."}}) picks this one (a Files there would be ambiguous).
  MarkedProject(std::initializer_list<std::pair<std::string, std::string>> files,
                project::Profile profile = project::Profile::Codesys)
      : MarkedProject(Files(files), profile) {}

  const Workspace& workspace() const { return *workspace_; }
  const ProjectModel& model() const { return workspace_->model(); }
  SourceId id(const std::string& path) const { return *workspace_->model().find_source(path); }

  // The file offset of the '|' in `marked`, in the `nth` occurrence of the snippet in the file.
  uint32_t at(const std::string& path, const std::string& marked, size_t nth = 0) const {
    const size_t cursor = marked.find('|');
    std::string snippet = marked;
    snippet.erase(cursor, 1);
    const std::string& text = text_of(path);
    size_t found = text.find(snippet);
    for (size_t i = 0; i < nth && found != std::string::npos; ++i) found = text.find(snippet, found + 1);
    EXPECT_NE(found, std::string::npos) << snippet << " not in " << path;
    return static_cast<uint32_t>(found + cursor);
  }
  // "path@offset" of a marked position and of a query answer.
  std::string where(const std::string& path, const std::string& marked, size_t nth = 0) const {
    return path + "@" + std::to_string(at(path, marked, nth));
  }
  static std::string where(const query::Location& location) {
    return location.path + "@" + std::to_string(location.range.begin);
  }

  const std::string& text_of(const std::string& path) const {
    for (const auto& [name, text] : files_) {
      if (name == path) return text;
    }
    ADD_FAILURE() << "no file " << path;
    return files_.front().second;
  }

 private:
  Files files_;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace rung::check::testing
