-- rung's language server in Neovim 0.7 and 0.8, which have vim.lsp.start_client but not
-- vim.lsp.start: the setup docs/editors/neovim.md shows for those versions. The end-to-end tests
-- load this file as the user's configuration, so the documented setup is the tested one.
-- RUNG_LSP_COMMAND lets the tests point at the freshly built binary; users have `rung` on PATH.

vim.g.do_filetype_lua = 1 -- Neovim 0.7 only reads vim.filetype.add() with this set
vim.filetype.add({ extension = { st = "iec61131", il = "iec61131", exp = "iec61131" } })

local rung_command = os.getenv("RUNG_LSP_COMMAND") or "rung"
local clients = {} -- one server per project folder

-- The project folder: the nearest folder above the file that holds rung.toml, else the file's.
local function project_root(file)
  local found = vim.fn.findfile("rung.toml", vim.fn.fnamemodify(file, ":p:h") .. ";")
  if found ~= "" then
    return vim.fn.fnamemodify(found, ":p:h")
  end
  return vim.fn.fnamemodify(file, ":p:h")
end

vim.api.nvim_create_autocmd("FileType", {
  pattern = "iec61131",
  callback = function(args)
    local root = project_root(vim.api.nvim_buf_get_name(args.buf))
    if not clients[root] then
      clients[root] = vim.lsp.start_client({
        name = "rung",
        cmd = { rung_command, "lsp" },
        root_dir = root,
      })
    end
    vim.lsp.buf_attach_client(args.buf, clients[root])
    vim.bo[args.buf].omnifunc = "v:lua.vim.lsp.omnifunc"
  end,
})
