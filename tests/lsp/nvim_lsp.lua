-- Neovim's own LSP client (0.7) attached to `arbc lsp` by docs/editors.md's init.lua (which
-- nvim_test.py hands to nvim with -u), driven as a person would: open a spec, break a name,
-- wait for the diagnostic, hover, go to definition, apply the quick fix, rename a constant
-- and back, a module and back, see a port's rename refused with the reason; open a second spec
-- and read the first again, on the same server. Each check is written to $RESULT as JSON;
-- nvim_test.py runs this inside tmux and reads it, then takes the screenshot once $READY
-- exists. Env: SPEC (a copy to edit), OTHER (a second spec), RESULT, READY.
local spec, other, result_file, ready_file =
  os.getenv('SPEC'), os.getenv('OTHER'), os.getenv('RESULT'), os.getenv('READY')
local results = {}

local function check(name, ok, detail)
  table.insert(results, { name = name, ok = ok and true or false, detail = vim.inspect(detail) })
end

local function write(path, text)
  local f = assert(io.open(path, 'w'))
  f:write(text)
  f:close()
end

-- The 0-based row and column of the first `needle` in the buffer.
local function find(needle)
  for row, line in ipairs(vim.api.nvim_buf_get_lines(0, 0, -1, false)) do
    local col = line:find(needle, 1, true)
    if col then return row - 1, col - 1 end
  end
  error('not in the buffer: ' .. needle)
end

local function request(method, params)
  local answers = vim.lsp.buf_request_sync(0, method, params, 10000) or {}
  for _, a in pairs(answers) do return a.result, a.err end
end

local function at(row, col)
  return { textDocument = { uri = vim.uri_from_bufnr(0) }, position = { line = row, character = col } }
end

local function break_name()
  local row, col = find('e_arm_idle and e_pull_idle and not e_arm_pulling and')
  vim.api.nvim_buf_set_text(0, row, col, row, col + #'e_arm_idle', { 'e_arm_idel' })
  local seen = vim.wait(20000, function() return #vim.diagnostic.get(0) > 0 end, 20)
  return seen, row, col
end

-- The ids of the clients attached to the current buffer.
local function attached()
  return vim.tbl_keys(vim.lsp.buf_get_clients(0))
end

local function run()
  vim.cmd('edit ' .. spec)
  check('a .spec file is an arbc file, not an RPM spec', vim.bo.filetype == 'arbc', vim.bo.filetype)
  check('the server starts and initializes', vim.wait(20000, function()
    local ids = attached()
    local client = #ids == 1 and vim.lsp.get_client_by_id(ids[1])
    return client and client.initialized
  end, 20), attached())
  local id = attached()[1]
  if id then write(result_file .. '.pid', tostring(vim.lsp.get_client_by_id(id).rpc.pid)) end
  check('K is the hover', vim.fn.maparg('K', 'n', false, true).buffer == 1,
        vim.fn.maparg('K', 'n', false, true))

  vim.cmd('edit ' .. other)
  vim.cmd('edit #')
  vim.cmd('edit!')
  check('a second spec and a file read again share the one server',
        vim.deep_equal(attached(), { id }) and #vim.lsp.get_active_clients() == 1,
        { attached = attached(), active = #vim.lsp.get_active_clients() })

  local seen, row, col = break_name()
  check('a diagnostic arrives for the broken name', seen)
  local d = vim.diagnostic.get(0)[1] or {}
  check('it is arbc check\'s diagnostic, on the name',
        d.code == 'unknown-event' and d.message == "unknown event 'e_arm_idel'" and d.lnum == row
          and d.col == col and d.end_col == col + #'e_arm_idel' and d.severity == vim.diagnostic.severity.ERROR, d)

  local take_row, take_col = find('take: from')
  local hover = request('textDocument/hover', at(take_row, take_col))
  local text = hover and hover.contents and hover.contents.value or ''
  check('hover on a rule shows its effective guard and decision table',
        text:find('effective guard: `not e_taken and e_arm_idle and e_pull_idle and not e_arm_pulling and not e_arm_picking`', 1, true)
          and text:find('| 1 | 0 | 0 | 1 | 0 | 0 | take |', 1, true), text)

  local use_row, use_col = find('not e_taken')
  local def = request('textDocument/definition', at(use_row, use_col + 4))
  local decl_row, decl_col = find('e_taken, e_arm_idle }')
  check('definition of an event is its declaration',
        def and def.range and def.range.start.line == decl_row and def.range.start.character == decl_col, def)

  local actions = request('textDocument/codeAction', {
    textDocument = { uri = vim.uri_from_bufnr(0) },
    range = { start = { line = d.lnum, character = d.col }, ['end'] = { line = d.end_lnum, character = d.end_col } },
    context = { diagnostics = {} } }) or {}
  check('one quick fix is offered', #actions == 1 and actions[1].title == "Change to 'e_arm_idle'", actions)
  if actions[1] then vim.lsp.util.apply_workspace_edit(actions[1].edit, 'utf-16') end
  local line = vim.api.nvim_buf_get_lines(0, row, row + 1, false)[1]
  check('the fix restores the name', line:find('when not e_taken and e_arm_idle and e_pull_idle and not e_arm_pulling and', 1, true), line)
  check('and the diagnostic goes away', vim.wait(20000, function() return #vim.diagnostic.get(0) == 0 end, 20))

  -- Rename, as <leader>r does with the name typed: a constant, everywhere (`within
  -- SPEAK_PERIOD` too), then back; a module, then back; a port is refused. What nvim would
  -- show is recorded instead: a message that long would wait for Enter.
  local before = table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n')
  local function rename_at(needle, offset, name)
    local r, c = find(needle)
    vim.api.nvim_win_set_cursor(0, { r + 1, c + offset })
    vim.lsp.buf.rename(name)
  end
  local function buffer_has(text, count)
    local body = table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n')
    local _, n = body:gsub(text, '')
    return n == count
  end
  rename_at('const SPEAK_PERIOD', #'const ', 'SPEAK_EVERY')
  check('rename of a constant reaches every use', vim.wait(10000, function()
    return buffer_has('SPEAK_EVERY', 3) and buffer_has('SPEAK_PERIOD', 1)  -- and a comment's
  end, 20), vim.api.nvim_buf_get_lines(0, 0, -1, false))
  rename_at('const SPEAK_EVERY', #'const ', 'SPEAK_PERIOD')
  check('and back', vim.wait(10000, function()
    return table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n') == before
  end, 20))
  -- A module: every `PickAndPlace.` goes with it (not the comments' words), with a warning
  -- that its plugin still registers the old name; then back.
  local warned = {}
  local show_message = vim.lsp.handlers['window/showMessage']
  vim.lsp.handlers['window/showMessage'] = function(_, message) table.insert(warned, message) end
  local in_comments = select(2, table.concat(vim.tbl_map(function(l) return l:match('//.*') or '' end,
    vim.api.nvim_buf_get_lines(0, 0, -1, false)), '\n'):gsub('PickAndPlace', ''))
  local uses = select(2, before:gsub('PickAndPlace', '')) - in_comments
  rename_at('module PickAndPlace', #'module ', 'Arm')
  check('rename of a module reaches every Module.port', vim.wait(10000, function()
    return buffer_has('Arm', uses) and buffer_has('PickAndPlace', in_comments)
  end, 20), vim.api.nvim_buf_get_lines(0, 0, -1, false))
  check('and warns that its plugin registers the old name', vim.wait(10000, function()
    return warned[1] and warned[1].type == 2 and
           warned[1].message:find("its plugin still registers it as 'PickAndPlace'", 1, true)
  end, 20), warned)
  vim.lsp.handlers['window/showMessage'] = show_message
  rename_at('module Arm', #'module ', 'PickAndPlace')
  check('and back', vim.wait(10000, function()
    return table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n') == before
  end, 20))
  -- A port is refused with the reason (0.7 ignores a refused prepareRename, asks for the name
  -- anyway, then shows the rename's error).
  local shown = {}
  local notify = vim.notify
  vim.notify = function(message) table.insert(shown, message) end
  rename_at('in cmd: Cmd', #'in ', 'command')
  check('a refused rename of a port says why', vim.wait(10000, function()
    return shown[1] and shown[1]:find("port 'PickAndPlace.cmd' is not renamed here", 1, true)
  end, 20), shown)
  vim.notify = notify
  check('and changes nothing',
        table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '\n') == before)

  -- The screenshot: the name broken again, the cursor on the rule, its hover open.
  break_name()
  vim.api.nvim_win_set_cursor(0, { take_row + 1, take_col })
  vim.cmd('normal! zt')
  vim.lsp.buf.hover()
  vim.wait(10000, function() return #vim.api.nvim_list_wins() > 1 end, 20)
  vim.cmd('redraw!')
end

local ok, err = pcall(run)
check('the script ran to the end', ok, err)
write(result_file, vim.fn.json_encode(results))
write(ready_file, 'ready')
