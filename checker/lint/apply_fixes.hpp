// `rung lint --fix` for one file: the fixes of its findings applied to its text, the result in
// the file's own encoding, and the checks that make writing it safe.
#pragma once

#include <string>
#include <vector>

#include "checker/lint/lint_rule.hpp"
#include "parser/document.hpp"

namespace rung::lint {

struct FixedFile {
  enum class Outcome { Unchanged, Changed, NotFixed };
  Outcome outcome = Outcome::Unchanged;
  std::string bytes;    // Changed: the new file content (encoding, BOM and line ends as before)
  size_t applied = 0;   // fixes applied
  size_t deferred = 0;  // fixes left for another round (they overlap an applied one)
  std::string problem;  // NotFixed: why the file is left as it is
};

// Applies the fixes of `findings` (FILE coordinates of `document`), each one whole or not at all.
// A file with syntax errors or undecodable bytes is never fixed, nor one whose fixes would give it
// syntax errors (a rule's bug must not damage a program).
FixedFile fix_file(const Document& document, const std::vector<Finding>& findings);

}  // namespace rung::lint
