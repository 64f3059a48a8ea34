-- Helpers shared by the benchmarks: medians, interpreter and machine facts, options.
-- (The portable random generator they share with the specs is fixtures/random.lua.)
local common = {}

function common.median(values)
  local sorted = {}
  for i = 1, #values do sorted[i] = values[i] end
  table.sort(sorted)
  local middle = math.floor((#sorted + 1) / 2)
  if #sorted % 2 == 1 then return sorted[middle] end
  return (sorted[middle] + sorted[middle + 1]) / 2
end

---The interpreter's name, e.g. "LuaJIT 2.1.0-beta3" or "Lua 5.4".
function common.interpreter()
  local jit = rawget(_G, "jit")
  if jit then return jit.version .. (jit.status() and "" or " (JIT off)") end
  return _VERSION
end

---A short machine description: CPU model and core count when /proc tells them.
function common.machine()
  local model, cores = "unknown CPU", 0
  local file = io.open("/proc/cpuinfo", "r")
  if file then
    for line in file:lines() do
      local name = line:match("^model name%s*:%s*(.-)%s*$")
      if name then model = name; cores = cores + 1 end
    end
    file:close()
  end
  return ("%s x%d"):format(model, cores)
end

---Reads `--name value` pairs from the command line into a table of defaults.
function common.options(args, defaults)
  local options = {}
  for key, value in pairs(defaults) do options[key] = value end
  local i = 1
  while i <= #args do
    local key = args[i]:match("^%-%-(.+)$")
    if key and options[key] ~= nil then
      local value = args[i + 1]
      options[key] = tonumber(value) or value
      i = i + 2
    else
      error("unknown option " .. tostring(args[i]), 0)
    end
  end
  return options
end

return common
