# Generates a C++ source holding every docs/diagnostics/*.md page, so `rung explain CODE` works
# from any directory without the docs installed. Runs at build time (see cli/CMakeLists.txt).
#   -DDOCS_DIR=... -DOUTPUT=...
file(GLOB pages "${DOCS_DIR}/*.md")
list(SORT pages)
set(body "// Generated from docs/diagnostics by cli/embed_docs.cmake. Do not edit.\n")
string(APPEND body "#include \"cli/explain_pages.hpp\"\n\nnamespace rung::cli {\n\n")
string(APPEND body "std::span<const ExplainPage> explain_pages() {\n  static const ExplainPage kPages[] = {\n")
foreach(page IN LISTS pages)
  get_filename_component(code "${page}" NAME_WE)
  if(code STREQUAL "README")
    continue()
  endif()
  file(READ "${page}" text)
  string(APPEND body "      {\"${code}\", R\"rung_page(${text})rung_page\"},\n")
endforeach()
string(APPEND body "  };\n  return kPages;\n}\n\n}  // namespace rung::cli\n")
file(WRITE "${OUTPUT}.tmp" "${body}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
