-- bench/instructions.lua: what one world bench way costs per move in instructions and
-- cache misses, counted by valgrind (callgrind) over its timed frames alone: figures that
-- do not move with the machine's load, for A/B comparisons on a shared, noisy machine.
--
--   lua bench/instructions.lua --way tiles [--count 1000] [--frames 60] [--lua luajit]
--                              [--traces 12] [--method swept]
--
-- Runs `--lua` (default luajit) on bench/world.lua's scene and actors for one way (its
-- warm-up, then `--frames` frames; the world's moves with `--method`, axis_sweep if none)
-- under `valgrind --tool=callgrind`, which writes its counts out each time the C
-- library's clock() is called: fixtures/garbage.lua calls it
-- at the start and at the end of the timed frames, so the second part holds them alone.
-- Prints instructions, first-level data cache misses and last-level misses per move, the
-- last level modelled as 512 KB, 8-way (one core's L2 on the EPYC machines these benches
-- run on: the L3 beyond it is shared with other tenants; BUDGE_LL=size,ways,line sets
-- another, 2097152,16,64 for the 2 MB L2 of the Xeon machines). With `--traces N` on LuaJIT,
-- also the N traces that run the most instructions per move, by where each starts, with
-- the last-level misses of each (the machine code a miss happened in: a trace's loads).
-- What these do not tell: time. The real machine prefetches, and its L3 holds what the
-- model misses: a change that cut the model's misses per move of budge.bump at 10000
-- items by 29% (its hash's cells halved) ran 18% slower in interleaved fresh runs
-- (2026-12-03). Instructions are the better guide on Lua 5.x (interpreted); on LuaJIT,
-- count them for the same compile (a bare loop compiles two ways from run to run, and so
-- may a move): run a few times. Needs valgrind (Debian: apt-get install valgrind).
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local common = require("bench.common")
local options = common.options(arg, {way = "tiles", count = 1000, frames = 60,
  lua = "luajit", traces = 0, seed = 12345, inner = "", map = "", method = ""})

if options.inner ~= "" then -- under valgrind: one run of the way, then the trace map
  local jit = rawget(_G, "jit")
  local starts = {}
  if options.map ~= "" and jit then
    local util = require("jit.util")
    jit.attach(function(what, trace, func, pc, parent)
      if what == "start" then
        local info = util.funcinfo(func, pc)
        starts[trace] = (info.loc or "?"):gsub("^.*/", "")
          .. ((parent and parent ~= 0) and " (side)" or " (root)")
      end
    end, "trace")
  end
  local world_bench = require("bench.world")
  local new_random = require("fixtures.random").new
  local grid = world_bench.make_scene(options.seed)
  local actors = world_bench.make_actors(grid, new_random(options.seed + options.count),
    options.count)
  world_bench.run(options.way, grid, actors, options.frames,
    options.method ~= "" and options.method or nil)
  if options.map ~= "" and jit then
    local util = require("jit.util")
    local file = assert(io.open(options.map, "w"))
    for trace = 1, 1e6 do
      local code, address = util.tracemc(trace)
      if code == nil and starts[trace] == nil then break end
      if code then
        file:write(("%d %d %d %s\n"):format(address, #code, trace, starts[trace] or "?"))
      end
    end
    file:close()
  end
  return
end

local function shell_quote(text) return "'" .. text:gsub("'", "'\\''") .. "'" end
local directory = os.tmpname()
os.remove(directory)
assert(os.execute("mkdir -p " .. shell_quote(directory)))
local map = options.traces > 0 and directory .. "/map.txt" or ""
local command = table.concat({"valgrind --tool=callgrind --dump-before=clock",
  "--cache-sim=yes --LL=${BUDGE_LL:-524288,8,64}", map ~= "" and "--dump-instr=yes" or "",
  "--callgrind-out-file=" .. shell_quote(directory .. "/out"), options.lua,
  "bench/instructions.lua --inner 1",
  ("--way %s --count %d --frames %d --seed %d"):format(options.way, options.count,
    options.frames, options.seed),
  options.method ~= "" and "--method " .. shell_quote(options.method) or "",
  map ~= "" and "--map " .. shell_quote(map) or "",
  ">" .. shell_quote(directory .. "/log"), "2>&1"}, " ")
os.execute(command) -- (its status differs by interpreter: the counts file says)
local timed = io.open(directory .. "/out.2", "r")
if not timed then
  local log = io.open(directory .. "/log", "r")
  io.stderr:write("bench/instructions.lua: no counts for the timed frames (is valgrind "
    .. "installed?)\n" .. (log and log:read("*a") or "") .. "\n")
  os.execute("rm -rf " .. shell_quote(directory))
  os.exit(1)
end

-- The callgrind file: "events:" names the columns; each cost line is "<instr> <line>
-- <counts...>" (with --dump-instr) or "<line> <counts...>", positions either absolute
-- (0x...) or relative to the previous line's (+n, -n, *); the line after "calls=" is a
-- call's inclusive cost, counted where it was spent already.
local moves = options.count * options.frames
local events, totals = {}, {}
local ranges = {}
if map ~= "" then
  for line in io.lines(map) do
    local address, size, trace, start = line:match("^(%d+) (%d+) (%d+) (.*)$")
    ranges[#ranges + 1] = {tonumber(address), tonumber(size), tonumber(trace), start}
  end
  table.sort(ranges, function(a, b) return a[1] < b[1] end)
end
local function trace_at(address) -- binary search of the sorted ranges
  local low, high = 1, #ranges
  while low <= high do
    local middle = math.floor((low + high) / 2)
    local range = ranges[middle]
    if address < range[1] then high = middle - 1
    elseif address >= range[1] + range[2] then low = middle + 1
    else return range end
  end
  return nil
end
local by_trace, address, skip = {}, 0, false
for line in timed:lines() do
  if line:match("^events:") then
    for name in line:gmatch("%S+") do if name ~= "events:" then events[#events + 1] = name end end
  elseif line:match("^summary:") then
    local i = 0
    for value in line:gmatch("%d+") do i = i + 1; totals[events[i]] = tonumber(value) end
  elseif map ~= "" then
    if skip then skip = false
    elseif line:match("^calls=") then skip = true
    else
      local position, counts = line:match("^([0-9a-fx+%-*]+)%s+%S+%s+(%d[%d ]*)")
      if position then
        if position:sub(1, 2) == "0x" then address = tonumber(position:sub(3), 16)
        elseif position:sub(1, 1) == "+" then address = address + tonumber(position:sub(2))
        elseif position:sub(1, 1) == "-" then address = address - tonumber(position:sub(2)) end
        local range = trace_at(address)
        if range then
          local key = range[3]
          local entry = by_trace[key] or {range[3], range[4], 0, 0}
          by_trace[key] = entry
          -- (the counts in the order of "events:"; absent ones at the end are 0)
          local i = 0
          for value in counts:gmatch("%d+") do
            i = i + 1
            local name = events[i]
            if name == "Ir" then entry[3] = entry[3] + tonumber(value)
            elseif name == "DLmr" or name == "DLmw" then entry[4] = entry[4] + tonumber(value) end
          end
        end
      end
    end
  end
end
timed:close()
os.execute("rm -rf " .. shell_quote(directory))

local function per_move(name) return (totals[name] or 0) / moves end
print(("%s%s, %d actors, %s, %d timed frames: %.0f instructions, %.2f D1 misses, %.2f "
  .. "last-level misses (%d KB model) per move"):format(options.way,
  options.method ~= "" and " (" .. options.method .. ")" or "", options.count,
  options.lua, options.frames, per_move("Ir"),
  per_move("D1mr") + per_move("D1mw"), per_move("DLmr") + per_move("DLmw"),
  math.floor(tonumber((os.getenv("BUDGE_LL") or "524288"):match("^%d+")) / 1024)))
if map ~= "" then
  local list = {}
  for _, entry in pairs(by_trace) do list[#list + 1] = entry end
  table.sort(list, function(a, b) return a[3] > b[3] or (a[3] == b[3] and a[1] < b[1]) end)
  print("  instr.  LL miss  (per move, by trace)")
  for i = 1, math.min(options.traces, #list) do
    local entry = list[i]
    print(("%8.1f  %6.2f  trace %d, %s"):format(entry[3] / moves, entry[4] / moves, entry[1],
      entry[2]))
  end
end
