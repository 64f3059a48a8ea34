-- bench/mcode.lua: where LuaJIT's machine code for a world bench way goes. LuaJIT only.
--
--   luajit bench/mcode.lua --way bump_boxes [--count 1000] [--frames 200] [--top 20]
--
-- Runs one way of bench/world.lua (its scene, its actors, its warm-up and frames) with a
-- budget that never runs out, then sums the machine code of every trace by where the
-- trace starts (file:line, root or side trace) and counts the aborted traces by reason,
-- as `luajit -jv` words them. What LuaJIT compiles varies from run to run: run it a few
-- times, and compare trees in fresh processes. A loop whose own trace keeps failing
-- ("leaving loop in root trace" at its end) is unrolled into every trace that runs it,
-- and shows up here as many side traces starting inside it (README.md, "LuaJIT's
-- compiled-code budget").
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local jit = rawget(_G, "jit")
if not jit then
  print("bench/mcode.lua measures LuaJIT's compiler: run it with luajit")
  return
end
local util = require("jit.util")
local vmdef = require("jit.vmdef")
local common = require("bench.common")
local options = common.options(arg, {way = "tiles", count = 1000, frames = 200, top = 20,
  seed = 12345})
jit.opt.start("maxtrace=100000", "maxmcode=1000000")

local function where(func, pc)
  local info = util.funcinfo(func, pc)
  return info.loc and info.loc:gsub("^.*/", "") or "?"
end

local starts, aborts, flushes = {}, {}, 0
local function on_trace(what, trace, func, pc, parent, info)
  if what == "start" then
    starts[trace] = where(func, pc) .. ((parent and parent ~= 0) and " (side)" or " (root)")
  elseif what == "flush" then
    flushes = flushes + 1
  elseif what == "abort" then
    local reason = vmdef.traceerr[parent] or tostring(parent)
    if type(info) == "function" then info = where(info) end
    local key = where(func, pc) .. ": " .. reason:format(info)
    aborts[key] = (aborts[key] or 0) + 1
  end
end
jit.attach(on_trace, "trace")

local world = require("bench.world")
local grid = world.make_scene(options.seed)
local actors = world.make_actors(grid, require("fixtures.random").new(options.seed
  + options.count), options.count)
local ns = world.run(options.way, grid, actors, options.frames)
jit.attach(on_trace) -- (detached: the counting below is not the bench's)

local by, total, traces = {}, 0, 0
for trace = 1, 100000 do
  local mcode = util.tracemc(trace)
  if mcode then
    local key = starts[trace] or "?"
    local entry = by[key] or {key, 0, 0}
    by[key] = entry
    entry[2], entry[3] = entry[2] + 1, entry[3] + #mcode
    traces, total = traces + 1, total + #mcode
  end
end
local function sorted(map, field)
  local list = {}
  for _, entry in pairs(map) do list[#list + 1] = entry end
  table.sort(list, function(a, b)
    if a[field] ~= b[field] then return a[field] > b[field] end
    return a[1] < b[1]
  end)
  return list
end
print(("%s, %d actors, %d frames: %.0f ns per move, %d traces, %.1f KB of machine code, "
  .. "%d flushes"):format(options.way, options.count, options.frames, ns, traces,
  total / 1024, flushes))
for i, entry in ipairs(sorted(by, 3)) do
  if i > options.top then break end
  print(("%8.1f KB %5d traces  %s"):format(entry[3] / 1024, entry[2], entry[1]))
end
local reasons = {}
for key, count in pairs(aborts) do reasons[key] = {key, count} end
for i, entry in ipairs(sorted(reasons, 2)) do
  if i > options.top then break end
  print(("%8d aborts  %s"):format(entry[2], entry[1]))
end
