-- Neovim's own LSP client against esi-lsp, run headless by nvim_test.cpp (`nvim --headless --clean`).
-- Opens ESI_NVIM_FILE, starts ESI_LSP on it, waits for the diagnostics and writes them to
-- ESI_NVIM_OUT/diagnostics.txt ("rule line" per finding), applies the first preferred quick fix,
-- writes the buffer to ESI_NVIM_OUT/buffer.txt and the diagnostics after the edit to after.txt.
-- With ESI_NVIM_AT="LINE,CHARACTER" (0-based, LSP units) it first hovers there (hover.txt: the
-- markdown shown) and jumps to the definition as the editor does (definition.txt: the cursor's
-- row and column after the jump, 1-based row, 0-based byte column, as nvim_win_get_cursor gives).
-- Works with the vim.lsp of Neovim 0.7 (Debian 12) and later.

local out_dir = os.getenv('ESI_NVIM_OUT')
local file = os.getenv('ESI_NVIM_FILE')
local server = os.getenv('ESI_LSP')

local function write(name, lines)
  local f = assert(io.open(out_dir .. '/' .. name, 'w'))
  f:write(table.concat(lines, '\n'))
  f:write('\n')
  f:close()
end

local function dump_diagnostics(bufnr, name)
  local lines = {}
  for _, d in ipairs(vim.diagnostic.get(bufnr)) do
    local code = d.code or (d.user_data and d.user_data.lsp and d.user_data.lsp.code) or '?'
    table.insert(lines, code .. ' ' .. (d.lnum + 1))
  end
  table.sort(lines)
  write(name, lines)
end

local ok, err = pcall(function()
  vim.cmd('edit ' .. vim.fn.fnameescape(file))
  local bufnr = vim.api.nvim_get_current_buf()
  local published = 0
  local handlers = {
    ['textDocument/publishDiagnostics'] = function(e, result, ctx, config)
      vim.lsp.diagnostic.on_publish_diagnostics(e, result, ctx, config)
      published = published + 1
    end,
  }
  local config = {
    name = 'esi-lsp',
    cmd = { server, '--debounce', '0' },
    root_dir = vim.fn.fnamemodify(file, ':p:h'),
    handlers = handlers,
  }
  local client_id
  if vim.lsp.start then
    client_id = vim.lsp.start(config)
  else
    client_id = vim.lsp.start_client(config)
    vim.lsp.buf_attach_client(bufnr, client_id)
  end
  assert(client_id, 'esi-lsp did not start')
  assert(vim.wait(30000, function() return published >= 1 end, 20), 'no diagnostics within 30 s')
  dump_diagnostics(bufnr, 'diagnostics.txt')

  local client = vim.lsp.get_client_by_id(client_id)
  local at = os.getenv('ESI_NVIM_AT')
  if at and at ~= '' then
    local line, character = at:match('^(%d+),(%d+)$')
    local position = { line = tonumber(line), character = tonumber(character) }
    local where = { textDocument = { uri = vim.uri_from_bufnr(bufnr) }, position = position }
    local hover = client.request_sync('textDocument/hover', where, 10000, bufnr)
    assert(hover and not hover.err and hover.result, 'no hover')
    local contents = hover.result.contents
    write('hover.txt', { type(contents) == 'table' and contents.value or tostring(contents) })
    vim.api.nvim_win_set_cursor(0, { position.line + 1, position.character })
    local definition = client.request_sync('textDocument/definition', where, 10000, bufnr)
    assert(definition and not definition.err and definition.result and definition.result[1], 'no definition')
    vim.lsp.util.jump_to_location(definition.result[1], 'utf-16')
    local cursor = vim.api.nvim_win_get_cursor(0)
    write('definition.txt', { cursor[1] .. ' ' .. cursor[2] })
  end
  local applied = false
  for _, d in ipairs(vim.diagnostic.get(bufnr)) do
    local params = {
      textDocument = { uri = vim.uri_from_bufnr(bufnr) },
      range = { start = { line = d.lnum, character = 0 }, ['end'] = { line = d.lnum, character = 100000 } },
      context = { diagnostics = { d.user_data and d.user_data.lsp or {} } },
    }
    local response = client.request_sync('textDocument/codeAction', params, 10000, bufnr)
    assert(response and not response.err, 'codeAction failed')
    for _, action in ipairs(response.result or {}) do
      if action.isPreferred and action.edit then
        vim.lsp.util.apply_workspace_edit(action.edit, 'utf-16')
        applied = true
        break
      end
    end
    if applied then break end
  end
  write('buffer.txt', vim.api.nvim_buf_get_lines(bufnr, 0, -1, false))
  if applied then
    local before = published
    assert(vim.wait(30000, function() return published > before end, 20), 'no diagnostics after the fix')
    dump_diagnostics(bufnr, 'after.txt')
  end
  vim.lsp.stop_client(client_id)
  vim.wait(5000, function() return vim.lsp.get_client_by_id(client_id) == nil end, 20)
  write('done.txt', { 'ok' })
end)
if not ok then write('error.txt', { tostring(err) }) end
vim.cmd('qa!')
