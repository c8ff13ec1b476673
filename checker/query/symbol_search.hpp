// Workspace symbol search: the POUs, types, global variables, methods, properties, actions and
// enum values of a project whose name matches what the user typed, best matches first.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checker/project_model.hpp"

namespace rung::check::query {

struct SymbolMatch {
  const Symbol* symbol = nullptr;
  std::string name;       // as shown: the plain name, or Owner.Member for methods, properties, actions, enum values
  std::string container;  // the POU, list or enumeration it belongs to; empty for a top-level name
  int score = 0;          // higher is better (match_score)
  bool library = false;   // declared in a stub library
};

// How well `query` matches `candidate`: its characters in order, case-insensitively (FBM matches
// FB_Motor); nullopt when they do not. An exact name beats a prefix, a prefix beats a part of the
// name, which beats scattered letters; letters at word starts (after '_' or '.', a capital after
// a small letter) count more. An empty query matches everything equally.
std::optional<int> match_score(std::string_view query, std::string_view candidate);

// Names that contain the query (exact, start, part) before scattered letters; within each, project
// symbols before library ones (so the library's TON still shows when a project has many names
// with a t, an o and an n); then the better score, the shorter and the alphabetically first name.
bool better_match(const SymbolMatch& a, const SymbolMatch& b);

struct SymbolSearch {
  size_t limit = 500;
  std::function<bool(SourceId)> skip;  // files to leave out (deleted ones); may be empty
  std::function<bool()> cancelled;     // polled between files; may be empty
};

// The matches of `query` in every file of `model` (stub libraries too), sorted by better_match,
// at most `options.limit`. Names hidden with {attribute 'hide'} and unnamed snippets are left out.
std::vector<SymbolMatch> search_symbols(const ProjectModel& model, std::string_view query, const SymbolSearch& options);

}  // namespace rung::check::query
