// Fills a NodeTable from a tree-sitter tree: all of it after a parse, or only the part an edit
// changed after an incremental re-parse.
#pragma once

#include <tree_sitter/api.h>

#include <vector>

#include "parser/syntax_tree.hpp"

namespace rung {

// Replaces table.nodes by the visible nodes of `tree` in preorder (one tree-cursor walk).
void read_node_table(const TSTree* tree, NodeTable& table);

// Updates table.nodes, the nodes of the text before `edit`, to those of `tree`, the incremental
// re-parse after it, where `changed` are tree-sitter's changed ranges. Only the children that
// touch a changed range (or the edit) are read again, at the deepest node that holds them all;
// the nodes after them shift by the edit's length. Returns false, leaving the table as it was,
// when the old and the new tree do not line up outside the changed ranges (the caller then reads
// the whole tree).
bool splice_node_table(NodeTable& table, const TSTree* tree, const TSInputEdit& edit,
                       const std::vector<TextRange>& changed);

}  // namespace rung
