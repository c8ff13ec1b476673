// Where a query answer points: a file and a byte range in FILE coordinates (what the editor shows;
// for a TwinCAT or .EXP container the offsets are the XML file's, not the parsed virtual text's).
#pragma once

#include <string>

#include "checker/project_model.hpp"

namespace rung::check::query {

struct Location {
  SourceId source = kNoSource;
  std::string path;
  TextRange range;  // FILE coordinates
};

// A range of the parsed (tree) text of `source`, in file coordinates: the same mapping
// Workspace::check_source applies to diagnostics (Document::file_offset_of / file_end_offset_of).
Location location_in_file(const ProjectModel& model, SourceId source, TextRange tree_range);

// Where `symbol` is declared: its name, or the start of its declaration when it has no name token
// of its own (a plain file's GVL is named after the file).
Location declaration_location(const ProjectModel& model, const Symbol& symbol);

}  // namespace rung::check::query
