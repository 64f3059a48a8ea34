-- File and chunk helpers for the specs that read the project's own files.
local files = {}

function files.read(path)
  local file = assert(io.open(path, "rb"))
  local text = file:read("*a")
  file:close()
  return text
end

---Compiles `code` with `env` as its globals, on Lua 5.1 and later alike.
function files.load(code, name, env)
  local setfenv, loadstring = rawget(_G, "setfenv"), rawget(_G, "loadstring")
  if setfenv then
    local chunk = assert(loadstring(code, name))
    setfenv(chunk, env)
    return chunk
  end
  return assert(load(code, name, "t", env))
end

return files
