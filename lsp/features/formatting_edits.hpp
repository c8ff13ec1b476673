// The two halves of every formatting request around the formatter: which settings apply (the
// project's rung.toml, with the editor's indentation where rung.toml says nothing about it),
// and the TextEdits that turn the document into the formatted text, line by line.
#pragma once

#include <string_view>

#include "checker/project/project_config.hpp"
#include "lsp/session.hpp"

namespace rung::lsp {

// The project's [format] settings. The request's FormattingOptions count only where rung.toml
// does not decide: tabSize becomes indent_width unless rung.toml's [format] sets indent_width or
// a preset; insertSpaces becomes use_tabs = false unless it sets use_tabs or a preset.
project::FormatSettings formatting_settings(const project::LoadedConfig& config, const Json& options);

// TextEdit[] that turn the document's text into `after`: one edit per run of changed lines (a
// line diff), so the editor keeps cursor, marks and folds on the lines that stay.
Json line_edits(const Session& session, const DocumentRef& document, std::string_view after);

}  // namespace rung::lsp
