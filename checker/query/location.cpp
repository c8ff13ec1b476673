#include "checker/query/location.hpp"

namespace rung::check::query {

Location location_in_file(const ProjectModel& model, SourceId source, TextRange tree_range) {
  const Document& document = *model.source(source).document;
  return Location{.source = source,
                  .path = document.path(),
                  .range = {document.file_offset_of(tree_range.begin), document.file_end_offset_of(tree_range.end)}};
}

Location declaration_location(const ProjectModel& model, const Symbol& symbol) {
  return location_in_file(model, symbol.source, symbol.name_range);
}

}  // namespace rung::check::query
