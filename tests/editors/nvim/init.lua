-- Harness of the Neovim end-to-end tests (tests/editors/neovim_*_test.cpp start it as
-- `nvim --headless -u init.lua`). It loads the documented LSP setup, runs one scenario from
-- lsp_scenarios.lua or highlight_scenarios.lua after startup and writes what Neovim saw as JSON
-- to $RUNG_EDITOR_RESULT; the C++ test asserts on that. Any Lua error ends up in the JSON too.

local here = vim.fn.fnamemodify(debug.getinfo(1, "S").source:sub(2), ":p:h")
local scenario = assert(os.getenv("RUNG_EDITOR_SCENARIO"), "RUNG_EDITOR_SCENARIO is not set")
local result_path = assert(os.getenv("RUNG_EDITOR_RESULT"), "RUNG_EDITOR_RESULT is not set")
local time_limit_ms = tonumber(os.getenv("RUNG_EDITOR_TIME_LIMIT_MS") or "20000")

vim.opt.swapfile = false
vim.opt.shadafile = "NONE"

local harness = { result = {} }
local finished = false

function harness.finish(err)
  if finished then
    return
  end
  finished = true
  if err then
    harness.result.error = tostring(err)
  end
  local file = assert(io.open(result_path, "w"))
  file:write(vim.fn.json_encode(harness.result))
  file:close()
  vim.schedule(function()
    vim.cmd("qall!")
  end)
end

-- Waits until cond() is true; raises an error naming what it waited for after `ms`.
function harness.wait_for(what, cond, ms)
  if not vim.wait(ms or 10000, cond, 20) then
    error("timed out waiting for " .. what, 2)
  end
end

function harness.client()
  local clients = vim.lsp.buf_get_clients(0)
  local _, client = next(clients)
  return client
end

-- Opens a file of the project, waits until rung lsp is initialised and attached to it.
function harness.open(relative)
  vim.cmd("edit " .. vim.fn.fnameescape(os.getenv("RUNG_EDITOR_PROJECT") .. "/" .. relative))
  harness.wait_for("rung lsp to attach", function()
    local client = harness.client()
    return client ~= nil and client.initialized == true
  end)
  harness.result.capabilities = harness.client().server_capabilities
  return vim.api.nvim_get_current_buf()
end

-- The diagnostics Neovim shows for a buffer, as plain data.
function harness.diagnostics(buf)
  local list = {}
  for _, d in ipairs(vim.diagnostic.get(buf)) do
    table.insert(list, {
      lnum = d.lnum,
      col = d.col,
      end_lnum = d.end_lnum,
      end_col = d.end_col,
      severity = d.severity,
      code = d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code),
      message = d.message,
    })
  end
  return list
end

function harness.has_diagnostic(buf, code)
  for _, d in ipairs(harness.diagnostics(buf)) do
    if d.code == code then
      return true
    end
  end
  return false
end

function harness.lines(buf)
  return vim.api.nvim_buf_get_lines(buf, 0, -1, false)
end

-- Puts the cursor on the first occurrence of `word` on 1-based line `line`.
function harness.cursor_on(line, word)
  local text = vim.api.nvim_buf_get_lines(0, line - 1, line, false)[1]
  local col = assert(text:find(word, 1, true), word .. " is not on line " .. line)
  vim.api.nvim_win_set_cursor(0, { line, col - 1 })
end

local group, name = scenario:match("^([%w_]+)%.([%w_]+)$")
if group == "lsp" then
  -- At startup, like a user's init.lua: the filetype setup must come before filetype detection.
  dofile(here .. "/rung_lsp_0_7.lua")
end

local timer = vim.loop.new_timer()
timer:start(time_limit_ms, 0, vim.schedule_wrap(function()
  harness.finish("scenario '" .. scenario .. "' did not finish within " .. time_limit_ms .. " ms")
end))

vim.api.nvim_create_autocmd("VimEnter", {
  once = true,
  callback = function()
    vim.schedule(function()
      local ok, err = pcall(function()
        local scenarios = dofile(here .. "/" .. group .. "_scenarios.lua")
        local run = assert(scenarios[name], "no scenario " .. scenario)
        -- A scenario returns true when it finishes later by itself (it calls harness.finish).
        return run(harness)
      end)
      if not ok then
        harness.finish(err)
      elseif err ~= true then
        harness.finish()
      end
    end)
  end,
})
