-- The LSP scenarios of the Neovim end-to-end tests, run by init.lua in a copy of
-- tests/editors/fixture. Each drives Neovim's own LSP client the way a user does (commands,
-- cursor, buffer edits) and records what Neovim then shows; neovim_lsp_test.cpp asserts on it.

local scenarios = {}

-- Diagnostics of the file as opened, after a typo typed into it, and after the typo is undone.
function scenarios.diagnostics(h)
  local buf = h.open("src/PLC_PRG.st")
  h.wait_for("the first diagnostics", function()
    return #vim.diagnostic.get(buf) > 0
  end)
  h.result.opened = h.diagnostics(buf)
  vim.api.nvim_buf_set_lines(buf, 8, 9, false, { "bRunning := fbMixr.bMotor;" })
  h.wait_for("E001 after the typo", function()
    return h.has_diagnostic(buf, "E001")
  end)
  h.result.typo = h.diagnostics(buf)
  vim.api.nvim_buf_set_lines(buf, 8, 9, false, { "bRunning := fbMixer.bMotor;" })
  h.wait_for("E001 to go away", function()
    return not h.has_diagnostic(buf, "E001")
  end)
  h.result.fixed = h.diagnostics(buf)
end

-- K: the hover window Neovim opens on FB_Mixer (a type from another file) and on tRun (an
-- instance of the standard TON).
function scenarios.hover(h)
  local function hover_lines(line, word)
    h.cursor_on(line, word)
    local before = vim.api.nvim_list_wins()
    vim.lsp.buf.hover()
    local float
    h.wait_for("the hover window on " .. word, function()
      for _, win in ipairs(vim.api.nvim_list_wins()) do
        if not vim.tbl_contains(before, win) and vim.api.nvim_win_get_config(win).relative ~= "" then
          float = win
          return true
        end
      end
      return false
    end)
    local lines = vim.api.nvim_buf_get_lines(vim.api.nvim_win_get_buf(float), 0, -1, false)
    vim.api.nvim_win_close(float, true)
    return lines
  end
  h.open("src/PLC_PRG.st")
  if not h.result.capabilities.hoverProvider then
    return
  end
  h.result.type_hover = hover_lines(3, "FB_Mixer")
  h.open("src/FB_Mixer.st")
  h.result.standard_fb_hover = hover_lines(12, "TON")
end

-- gd: from the use of a type and of an FB output in PLC_PRG.st to their declarations in
-- FB_Mixer.st; Neovim opens the other file and puts the cursor on the name.
function scenarios.definition(h)
  local function jump(line, word)
    local from = vim.api.nvim_get_current_buf()
    h.cursor_on(line, word)
    vim.lsp.buf.definition()
    h.wait_for("the jump from " .. word, function()
      return vim.api.nvim_get_current_buf() ~= from
    end)
    local cursor = vim.api.nvim_win_get_cursor(0)
    return {
      file = vim.fn.fnamemodify(vim.api.nvim_buf_get_name(0), ":t"),
      line = cursor[1],
      col = cursor[2],
      text = vim.api.nvim_get_current_line(),
    }
  end
  h.open("src/PLC_PRG.st")
  h.result.type = jump(3, "FB_Mixer")
  h.open("src/PLC_PRG.st")
  h.result.member = jump(9, "bMotor")
end

-- Omni completion (<C-x><C-o>) after "fbMixer." typed on a new line: the menu Neovim shows.
function scenarios.completion(h)
  local buf = h.open("src/PLC_PRG.st")
  if not h.result.capabilities.completionProvider then
    return
  end
  vim.api.nvim_buf_set_lines(buf, 9, 9, false, { "fbMixer." })
  vim.api.nvim_win_set_cursor(0, { 10, 0 })
  vim.api.nvim_create_autocmd("CompleteChanged", {
    once = true,
    callback = function()
      local words = {}
      for _, item in ipairs(vim.fn.complete_info({ "items" }).items) do
        table.insert(words, item.word)
      end
      h.result.items = words
      h.finish()
    end,
  })
  -- The keys run after this function returns, in Neovim's main loop, as typed keys do.
  vim.api.nvim_feedkeys(vim.api.nvim_replace_termcodes("A<C-x><C-o>", true, false, true), "n", false)
  return true
end

-- :lua vim.lsp.buf.rename("bMotorOn") on the use of the FB output bMotor in PLC_PRG.st, then :wall.
-- Neovim applies the workspace edit to both files (loading FB_Mixer.st) and writes them.
function scenarios.rename(h)
  local buf = h.open("src/PLC_PRG.st")
  h.cursor_on(9, "bMotor")
  local before = h.lines(buf)[9]
  vim.lsp.buf.rename("bMotorOn")
  h.wait_for("the rename to reach PLC_PRG.st", function()
    return h.lines(buf)[9] ~= before
  end)
  vim.cmd("silent wall")
end

-- vim.lsp.buf.formatting_sync() (0.7's name of vim.lsp.buf.format()) on a badly laid out file,
-- then :write.
function scenarios.format(h)
  local buf = h.open("src/Messy.st")
  h.result.before = h.lines(buf)
  vim.lsp.buf.formatting_sync(nil, 10000)
  h.result.after = h.lines(buf)
  vim.cmd("silent write")
end

-- The code action on the CASE without ELSE that rung lint reports (L030): Neovim lists the
-- actions through vim.ui.select; the test picks the one that fixes L030 or names ELSE.
function scenarios.code_action(h)
  local buf = h.open("src/PLC_PRG.st")
  if not h.result.capabilities.codeActionProvider then
    return
  end
  h.wait_for("L030 on the CASE", function()
    return h.has_diagnostic(buf, "L030")
  end)
  h.cursor_on(10, "CASE")
  h.result.titles = {}
  local function choose(items, opts)
    local chosen
    for _, item in ipairs(items) do
      local action = item[2]
      table.insert(h.result.titles, (opts.format_item(item)))
      for _, d in ipairs(action.diagnostics or {}) do
        if d.code == "L030" then
          chosen = chosen or item
        end
      end
      if not chosen and action.title:upper():find("ELSE", 1, true) then
        chosen = item
      end
    end
    return chosen
  end
  vim.ui.select = function(items, opts, on_choice)
    -- Called from Neovim's response handler: an error here would not reach init.lua's pcall.
    local ok, chosen = pcall(choose, items, opts)
    if not ok then
      h.finish(chosen)
    end
    on_choice(chosen)
  end
  local before = vim.api.nvim_buf_get_changedtick(buf)
  vim.lsp.buf.code_action()
  h.wait_for("the code action's edit", function()
    return vim.api.nvim_buf_get_changedtick(buf) ~= before
  end)
  h.result.lines = h.lines(buf)
  h.wait_for("L030 to go away", function()
    return not h.has_diagnostic(buf, "L030")
  end)
  h.result.diagnostics = h.diagnostics(buf)
end

return scenarios
