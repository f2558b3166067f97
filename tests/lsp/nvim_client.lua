-- A real editor as the language server's client: Neovim (0.7+) headless.
-- Opens $EDSC_EDS, starts `$EDSC_BIN lsp`, waits for the diagnostics, asks
-- for hover, definition, a code action (applied), then formatting (applied),
-- and writes what it got, one line per fact, to $EDSC_OUT; the formatted
-- buffer goes to $EDSC_OUT.formatted. Run by tests/lsp/test_neovim.cpp:
--   nvim --headless --clean -n -u NONE -c 'luafile tests/lsp/nvim_client.lua'
local out = {}
-- Waits scale with the build (EDSC_TIME_SCALE: 10 under ASan, tests/time_scale.hpp).
local scale = tonumber(os.getenv('EDSC_TIME_SCALE') or '1') or 1
local function say(fmt, ...) table.insert(out, string.format(fmt, ...)) end
local function finish()
  local f = io.open(os.getenv('EDSC_OUT'), 'w')
  f:write(table.concat(out, '\n') .. '\n')
  f:close()
  vim.cmd('qa!')
end

local ok, err = pcall(function()
  vim.cmd('edit ' .. vim.fn.fnameescape(os.getenv('EDSC_EDS')))
  local buf = vim.api.nvim_get_current_buf()
  local client_id = vim.lsp.start_client({
    name = 'edsc',
    cmd = { os.getenv('EDSC_BIN'), 'lsp' },
    root_dir = vim.fn.getcwd(),
    init_options = { warnings = { '-Wpedantic' } },
  })
  vim.lsp.buf_attach_client(buf, client_id)
  local client = vim.lsp.get_client_by_id(client_id)
  local enc = 'utf-16'

  local function diagnostics()
    local got = vim.diagnostic.get(buf)
    table.sort(got, function(a, b) return a.lnum < b.lnum end)
    return got
  end
  local function lsp_code(d)
    return d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code) or '?'
  end
  if not vim.wait(20000 * scale, function() return #vim.diagnostic.get(buf) > 0 end, 20) then
    error('no diagnostics within ' .. 20 * scale .. ' s')
  end
  local names = { 'error', 'warning', 'info', 'hint' }
  for _, d in ipairs(diagnostics()) do
    say('diagnostic %d:%d %s %s %s', d.lnum, d.col, names[d.severity], lsp_code(d), d.message)
  end

  local function at(pattern, offset)
    vim.api.nvim_win_set_cursor(0, { 1, 0 })
    local line = vim.fn.search(pattern, 'cW')
    local col = vim.fn.col('.') - 1 + (offset or 0)
    return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = line - 1, character = col } }
  end
  local function request(method, params)
    local r = client.request_sync(method, params, 10000 * scale, buf)
    if not r then error(method .. ': no answer') end
    if r.err then return nil, r.err end
    return r.result
  end

  -- Hover on a keyword.
  local hover = request('textDocument/hover', at('ProdType ='))
  if hover and hover.contents then
    local text = type(hover.contents) == 'table' and (hover.contents.value or '') or hover.contents
    say('hover ProdType: %s', (text:gsub('\n.*', '')))
  else
    say('hover ProdType: none')
  end

  -- Definition of the parameter a group names (the last '1' of Group1).
  local defs = request('textDocument/definition', at('Group1 =.*\\zs1;$'))
  if defs and defs[1] then
    say('definition of Group1 member: line %d character %d', defs[1].range.start.line, defs[1].range.start.character)
  else
    say('definition of Group1 member: none')
  end

  -- The quick fix for the missing ';', applied as the editor would.
  local semi = at('EDS"$', 5)
  local actions = request('textDocument/codeAction', {
    textDocument = semi.textDocument,
    range = { start = semi.position, ['end'] = semi.position },
    context = { diagnostics = {} },
  })
  for _, a in ipairs(actions or {}) do
    say('code action: %s (%s%s)', a.title, a.kind, a.isPreferred and ', preferred' or '')
  end
  if actions and actions[1] and actions[1].edit then
    vim.lsp.util.apply_workspace_edit(actions[1].edit, enc)
  end
  -- The fix removes the syntax error: wait for the new list.
  vim.wait(20000 * scale, function()
    for _, d in ipairs(vim.diagnostic.get(buf)) do
      if lsp_code(d) == 'syntax-missing-semicolon' then return false end
    end
    return true
  end, 20)
  say('diagnostics after the fix: %d', #vim.diagnostic.get(buf))

  local edits, ferr = request('textDocument/formatting', {
    textDocument = { uri = vim.uri_from_bufnr(buf) },
    options = { tabSize = 8, insertSpaces = true },
  })
  if ferr then
    say('formatting: error %s', ferr.message)
  else
    say('formatting: %d edit(s)', #(edits or {}))
    vim.lsp.util.apply_text_edits(edits or {}, buf, enc)
  end
  local lines = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
  local f = io.open(os.getenv('EDSC_OUT') .. '.formatted', 'w')
  f:write(table.concat(lines, '\n') .. '\n')
  f:close()

  client.stop()
  vim.wait(5000 * scale, function() return client.is_stopped() end, 20)
  say('stopped: %s', tostring(client.is_stopped()))
end)
if not ok then say('lua error: %s', tostring(err)) end
finish()
