// textDocument/prepareRename and textDocument/rename: the LSP side of checker/query/rename.
#pragma once

#include "lsp/session.hpp"

namespace rung::lsp {

// {range, placeholder} of the name under the cursor; RpcError(RequestFailed) with the reason
// when it cannot be renamed (a keyword, a library name, a comment ...).
Json prepare_rename(Session& session, const Json& params);

// The WorkspaceEdit that renames the symbol under the cursor to params.newName in every file of
// its project: `documentChanges` (with the open buffers' versions) when the client supports
// them, `changes` otherwise. RpcError(RequestFailed) with the reason when it is refused.
Json rename(Session& session, const Json& params);

}  // namespace rung::lsp
