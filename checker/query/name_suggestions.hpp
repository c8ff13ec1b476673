// "Did you mean": the name rung check suggests for a name it does not know, as data the language
// server turns into a replacement (the checker writes the same candidate into its help text).
// The candidates are the checker's: for a bare name (E001, E002) every name visible in the scope,
// for a member after '.' (E005) the members of the object's type and its bases, for a formal
// parameter (E301) the callee's inputs, outputs and in-outs; the closest one by
// check::closest_name, and only when it is close enough to be a likely typo.
#pragma once

#include <optional>
#include <string>

#include "checker/check.hpp"

namespace rung::check::query {

struct NameSuggestion {
  TextRange range;          // the unknown name, FILE coordinates
  std::string replacement;  // the name meant, spelled as declared
};

// For the unknown name at `file_offset` (FILE coordinates of `source`); nullopt when the name is
// known, or nothing is close to it.
std::optional<NameSuggestion> suggest_name(const Workspace& workspace, SourceId source, uint32_t file_offset);

}  // namespace rung::check::query
