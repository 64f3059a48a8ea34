-- bench/jit.lua: how much compiled code budge makes LuaJIT produce, and whether it fits
-- LuaJIT's default budget (1000 traces, 512 KB of machine code). LuaJIT only.
--
--   luajit bench/jit.lua [--frames 3000] [--runs 5] [--why N] [--readme README.md]
--
-- Two scenes: the platformer level (fixtures/levels.lua) with 7 runners that run and jump
-- and 2 moving platforms, and the world bench's crowd of 1000 actors. Each runs twice:
-- once with the default budget, counting flushes (LuaJIT throws every trace away when the
-- budget runs out) and aborted traces; once with a budget too big to run out, reporting
-- how many traces and how much machine code the scene needs. Each scene and budget runs
-- in its own fresh process (`--scene S --budget B` is one such run), `--runs` times, the
-- four interleaved; the medians are printed with their range (what LuaJIT compiles varies
-- from run to run), and --why N lists the N most frequent abort reasons over the runs.
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local jit = rawget(_G, "jit")
if not jit then
  print("bench/jit.lua measures LuaJIT's compiler: run it with luajit")
  return
end
local util = require("jit.util")
local common = require("bench.common")
local levels = require("fixtures.levels")
local runner_logic = require("examples.demo.runner")
local scene = require("fixtures.scene")

local options = common.options(arg, {frames = 3000, why = 0, readme = "", runs = 5, scene = "",
  budget = "default"})
local vmdef = require("jit.vmdef")

-- "file:line: reason" for an aborted trace, as luajit -jv words it.
local function abort_reason(func, pc, err, info)
  local where = "?"
  local fi = util.funcinfo(func, pc)
  if fi.loc then where = fi.loc:gsub("^.*/", "") end
  if type(err) == "number" then
    if type(info) == "function" then
      local callee = util.funcinfo(info)
      info = callee.loc or callee.name or "?"
    end
    err = vmdef.traceerr[err]:format(info)
  end
  return where .. ": " .. tostring(err)
end

local function platformer(budge)
  local world = budge.new_world()
  world:add_tiles(levels.grid("platformer"), levels.TILE, levels.TILE,
    {is_oneway = levels.is_oneway})
  local lift = world:add_solid({x = 704, y = 240, width = 48, height = 8})
  local ferry = world:add_solid({x = 176, y = 400, width = 48, height = 8})
  local runners = {}
  for i = 1, 7 do
    runners[i] = world:add_actor(runner_logic.new_runner(40 + i * 96, 40, i % 2 == 0 and 1 or -1,
      23 + i * 6))
  end
  local input, step, move = runner_logic.runner_input, runner_logic.step_runner, world.move
  return function(frame)
    world:move_solid(lift, 0, (frame % 240 < 120) and -1 or 1)
    world:move_solid(ferry, (frame % 128 < 64) and 1 or -1, 0)
    for i = 1, #runners do
      local runner = runners[i]
      local left, right, jump = input(runner, frame)
      step(runner, left, right, jump, move, world)
    end
  end
end

local function crowd(budge)
  local grid = scene.make_scene(12345)
  local world = budge.new_world()
  world:add_tiles(grid, scene.TILE, scene.TILE)
  local actors = {}
  for i, start in ipairs(scene.make_actors(grid, require("fixtures.random").new(13345), 1000)) do
    actors[i] = world:add_actor({x = start.x, y = start.y, width = scene.SIZE,
      height = scene.SIZE, dx = start.dx, dy = start.dy})
  end
  return function()
    for i = 1, #actors do
      local actor = actors[i]
      world:move(actor, actor.dx, actor.dy)
    end
  end
end

local function fresh_budge()
  for name in pairs(package.loaded) do
    if name == "budge" or name:match("^budge%.") then package.loaded[name] = nil end
  end
  return require("budge")
end

local function run(make, frames, budget)
  jit.flush()
  if budget == "default" then
    jit.opt.start("maxtrace=1000", "maxmcode=512")
  else
    jit.opt.start("maxtrace=20000", "maxmcode=65536")
  end
  local flushes, aborts, reasons = 0, 0, {}
  local function on_trace(what, _, func, pc, err, info)
    if what == "flush" then
      flushes = flushes + 1
    elseif what == "abort" then
      aborts = aborts + 1
      local reason = abort_reason(func, pc, err, info)
      reasons[reason] = (reasons[reason] or 0) + 1
    end
  end
  jit.attach(on_trace, "trace")
  local step = make(fresh_budge())
  local started = os.clock()
  for frame = 1, frames do step(frame) end
  local seconds = os.clock() - started
  jit.attach(on_trace)
  local traces, bytes = 0, 0
  for trace = 1, 20000 do
    local mcode = util.tracemc(trace)
    if mcode then traces, bytes = traces + 1, bytes + #mcode end
  end
  return {flushes = flushes, aborts = aborts, traces = traces, kb = bytes / 1024,
    ms_per_frame = seconds * 1000 / frames, reasons = reasons}
end

local SCENES = {platformer = platformer, crowd = crowd}
local unpack_list = rawget(table, "unpack") or rawget(_G, "unpack")

if options.scene ~= "" then -- one configuration in this fresh process: its figures on a line
  local result = run(SCENES[options.scene], options.frames, options.budget)
  local list = {}
  for reason, count in pairs(result.reasons) do list[#list + 1] = {reason, count} end
  table.sort(list, function(a, b) return a[2] > b[2] or (a[2] == b[2] and a[1] < b[1]) end)
  local why = {}
  for i = 1, math.min(options.why, #list) do
    why[#why + 1] = ("%d=%s"):format(list[i][2], list[i][1]:gsub("[%s;]", "_"))
  end
  print(("%d %d %d %.1f %.4f %s"):format(result.flushes, result.aborts, result.traces, result.kb,
    result.ms_per_frame, table.concat(why, ";")))
  os.exit(0)
end

-- The driver: each scene and budget in its own fresh process (what one configuration
-- compiles would change another's figures), the configurations interleaved, medians.
local CONFIGS = {"platformer default", "platformer large", "crowd default", "crowd large"}
local figures, reasons = {}, {}
for _ = 1, options.runs do
  for _, config in ipairs(CONFIGS) do
    local name, budget = config:match("^(%S+) (%S+)$")
    local command = ("%s bench/jit.lua --scene %s --budget %s --frames %d --why %d"):format(
      arg[-1] or "luajit", name, budget, options.frames, options.why)
    local pipe = assert(io.popen(command))
    local line = pipe:read("*l") or ""
    pipe:close()
    local values = {line:match("^(%S+) (%S+) (%S+) (%S+) (%S+) ?(.*)$")}
    assert(#values == 6, "no figures from: " .. command)
    figures[config] = figures[config] or {{}, {}, {}, {}, {}}
    for k = 1, 5 do table.insert(figures[config][k], tonumber(values[k])) end
    reasons[config] = reasons[config] or {}
    for count, reason in values[6]:gmatch("(%d+)=([^;]+)") do
      reasons[config][reason] = (reasons[config][reason] or 0) + tonumber(count)
    end
  end
end

local function spread(values, format)
  local low, high = math.huge, -math.huge
  for _, value in ipairs(values) do low, high = math.min(low, value), math.max(high, value) end
  return (format .. " (" .. format .. "-" .. format .. ")"):format(common.median(values), low, high)
end
print(("budge JIT budget on %s, %s; %d frames per scene; medians of %d fresh processes"):format(
  common.interpreter(), common.machine(), options.frames, options.runs))
local lines = {("`luajit bench/jit.lua --frames %d --runs %d`, %s, on %s, %s: each scene and "
  .. "budget in its own fresh process, interleaved; the median of %d runs, their range in "
  .. "brackets (what LuaJIT compiles varies from run to run)."):format(options.frames,
  options.runs, os.date("!%Y-%m-%d"), common.interpreter(), common.machine(), options.runs), "",
  "| scene | budget | flushes | aborts | traces | KB of machine code | ms/frame |",
  "|---|---|---|---|---|---|---|"}
print(("%-11s %-8s %12s %16s %16s %18s %24s"):format("scene", "budget", "flushes", "aborts",
  "traces", "mcode KB", "ms/frame"))
for _, config in ipairs(CONFIGS) do
  local name, budget = config:match("^(%S+) (%S+)$")
  local f = figures[config]
  local cells = {spread(f[1], "%g"), spread(f[2], "%g"), spread(f[3], "%g"), spread(f[4], "%.0f"),
    spread(f[5], "%.3f")}
  print(("%-11s %-8s %12s %16s %16s %18s %24s"):format(name, budget, unpack_list(cells)))
  lines[#lines + 1] = ("| %s | %s | %s |"):format(name, budget, table.concat(cells, " | "))
  if options.why > 0 then -- the most frequent abort reasons, summed over the runs
    local list = {}
    for reason, count in pairs(reasons[config]) do list[#list + 1] = {reason, count} end
    table.sort(list, function(a, b) return a[2] > b[2] or (a[2] == b[2] and a[1] < b[1]) end)
    for i = 1, math.min(options.why, #list) do
      print(("    %5d  %s"):format(list[i][2], list[i][1]:gsub("_", " ")))
    end
  end
end
if options.readme ~= "" then common.write_readme(options.readme, "bench/jit.lua", lines) end
