-- The tree-sitter scenario of the Neovim end-to-end tests: rung's parser (parser/iec61131.so)
-- and grammar/queries (queries/iec61131/) on the runtimepath, as docs/editors/neovim.md sets
-- them up. Records every capture of highlights.scm on the sample file, in Neovim's order (a
-- later capture of the same node wins); neovim_highlight_test.cpp picks the tokens it checks.

local scenarios = {}

function scenarios.captures(h)
  local runtime = assert(os.getenv("RUNG_EDITOR_RUNTIME"), "RUNG_EDITOR_RUNTIME is not set")
  local sample = assert(os.getenv("RUNG_EDITOR_SAMPLE"), "RUNG_EDITOR_SAMPLE is not set")
  vim.opt.runtimepath:prepend(runtime)
  vim.cmd("edit " .. vim.fn.fnameescape(sample))
  local buf = vim.api.nvim_get_current_buf()
  local parser = vim.treesitter.get_parser(buf, "iec61131")
  local tree = parser:parse()[1]
  local query = vim.treesitter.query.get_query("iec61131", "highlights")
  assert(query, "Neovim found no queries/iec61131/highlights.scm on the runtimepath")
  h.result.has_error = tree:root():has_error()
  h.result.captures = {}
  for id, node in query:iter_captures(tree:root(), buf, 0, -1) do
    local start_row, start_col, end_row, end_col = node:range()
    table.insert(h.result.captures, {
      name = query.captures[id],
      line = start_row + 1,
      col = start_col,
      end_line = end_row + 1,
      end_col = end_col,
      text = vim.treesitter.query.get_node_text(node, buf),
    })
  end
end

-- Every query file Neovim uses (folding and indentation with nvim-treesitter) parses against
-- this parser with this Neovim's query engine: unknown node names or predicates are errors.
function scenarios.query_files(h)
  vim.opt.runtimepath:prepend(assert(os.getenv("RUNG_EDITOR_RUNTIME"), "RUNG_EDITOR_RUNTIME is not set"))
  h.result.loaded = {}
  for _, name in ipairs({ "highlights", "folds", "indents", "locals", "injections" }) do
    local ok, query = pcall(vim.treesitter.query.get_query, "iec61131", name)
    if not ok then
      error(name .. ".scm: " .. tostring(query))
    end
    h.result.loaded[name] = query ~= nil
  end
end

return scenarios
