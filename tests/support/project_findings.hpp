// Test support: checks a small in-memory project and lists what rung reports, in a form that
// reads well in an EXPECT_EQ ("E302@16" = code E302 on line 16).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "checker/check.hpp"

namespace rung::check::testing {

using Files = std::vector<std::pair<std::string, std::string>>;  // (path, text)

struct Finding {
  std::string at;  // "CODE@LINE", 1-based line in its own file; warnings end in "?" if marked
  std::string message;
  std::string help;
};

enum class Warnings { Marked, Unmarked };

// Every diagnostic of every file of the project, in the order `rung check` sorts them.
std::vector<Finding> project_findings(const Files& files, const project::ProjectConfig& config,
                                      Warnings warnings = Warnings::Marked);

// Only the "CODE@LINE" of each finding.
std::vector<std::string> codes_at_lines(const Files& files, const project::ProjectConfig& config,
                                        Warnings warnings = Warnings::Marked);

// The messages of the findings with this code, in order.
std::vector<std::string> messages_with_code(const Files& files, const project::ProjectConfig& config,
                                            std::string_view code);

// A configuration with just the profile set.
project::ProjectConfig config_for(project::Profile profile);

}  // namespace rung::check::testing
