// The registration function of each feature group: each adds its request handlers to the Router
// and its part of the ServerCapabilities. register.cpp calls them all.
#pragma once

#include "lsp/router.hpp"

namespace rung::lsp {

void register_diagnostics(Router& router);      // textDocument/diagnostic (pull)
void register_navigation(Router& router);       // definition, declaration, typeDefinition, implementation,
                                                // references, documentHighlight, rename, prepareRename
void register_symbols(Router& router);          // documentSymbol, workspace/symbol
void register_hierarchy(Router& router);        // call hierarchy, type hierarchy, code lens
void register_completion(Router& router);       // completion, completionItem/resolve
void register_hover(Router& router);            // hover, signatureHelp, inlayHint
void register_presentation(Router& router);     // semanticTokens, foldingRange, selectionRange
void register_formatting(Router& router);       // formatting, rangeFormatting, onTypeFormatting
void register_code_actions(Router& router);     // codeAction (quick fixes, refactorings)

}  // namespace rung::lsp
