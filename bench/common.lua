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

---The median of `values[r] / references[r]` over the rounds r: each run against the
---reference run in the same round, so that drift between rounds cancels.
---@param values number[]
---@param references number[]
---@return number
function common.paired_ratio(values, references)
  assert(#values == #references, "paired_ratio: as many values as references")
  local ratios = {}
  for r = 1, #values do ratios[r] = values[r] / references[r] end
  return common.median(ratios)
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

---Runs `command(way)` (a shell command printing one line of `fields` numbers) in a fresh
---process for each way, `runs` times, the ways interleaved, and returns, for each way,
---the list of each field's values. On LuaJIT what one configuration compiles changes
---another's figures: each in its own process.
---@param ways string[]
---@param runs integer
---@param fields integer
---@param command fun(way: string): string
---@return table<string, number[][]>
function common.fresh_runs(ways, runs, fields, command)
  local results = {}
  for _ = 1, runs do
    for _, way in ipairs(ways) do
      local line = command(way)
      local pipe = assert(io.popen(line))
      local output = pipe:read("*l")
      pipe:close()
      local values = {}
      for number in (output or ""):gmatch("%S+") do values[#values + 1] = tonumber(number) end
      assert(#values == fields, "no figures from: " .. line)
      results[way] = results[way] or {}
      for k = 1, fields do
        results[way][k] = results[way][k] or {}
        table.insert(results[way][k], values[k])
      end
    end
  end
  return results
end

---Replaces what lies between the markers `<!-- KEY -->` and `<!-- end KEY -->` in the file
---with `lines`: the README's tables are written by the benches, never typed by hand.
---@param path string
---@param key string
---@param lines string[]
function common.write_readme(path, key, lines)
  local begin_mark, end_mark = ("<!-- %s -->"):format(key), ("<!-- end %s -->"):format(key)
  local file = assert(io.open(path, "r"))
  local text = file:read("*a")
  file:close()
  local _, last = text:find(begin_mark, 1, true)
  local tail = text:find(end_mark, 1, true)
  assert(last and tail and tail > last, "no markers " .. begin_mark .. " in " .. path)
  text = text:sub(1, last) .. "\n" .. table.concat(lines, "\n") .. "\n" .. text:sub(tail)
  file = assert(io.open(path, "w"))
  file:write(text)
  file:close()
  print("written into " .. path)
end

---The interpreter's short name in a README marker: "luajit" or "lua5.4".
function common.key()
  return rawget(_G, "jit") and "luajit" or (_VERSION:gsub("Lua ", "lua"))
end

return common
