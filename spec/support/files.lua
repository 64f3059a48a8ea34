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

---The library's module files, src/budge/*.lua, sorted.
---@return string[]
function files.module_files()
  local lfs = require("lfs")
  local paths = {}
  for name in lfs.dir("src/budge") do
    if name:match("%.lua$") then paths[#paths + 1] = "src/budge/" .. name end
  end
  table.sort(paths)
  return paths
end

return files
