// The LSP SymbolKind of each kind of declaration, shared by document symbols, workspace symbols
// and the call and type hierarchies so that one declaration has one icon everywhere.
#pragma once

#include "checker/query/outline.hpp"

namespace rung::lsp {

// LSP 3.17 SymbolKind (1 File .. 26 TypeParameter).
int lsp_symbol_kind(check::query::OutlineKind kind);

}  // namespace rung::lsp
