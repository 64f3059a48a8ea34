-- bench/jit.lua: how much compiled code budge makes LuaJIT produce, and whether it fits
-- LuaJIT's default budget (1000 traces, 512 KB of machine code). LuaJIT only.
--
--   luajit bench/jit.lua [--frames 3000]
--
-- Two scenes: the platformer level (fixtures/levels.lua) with 7 runners that run and jump
-- and 2 moving platforms, and the world bench's crowd of 1000 actors. Each runs twice in
-- a fresh process state: once with the default budget, counting flushes (LuaJIT throws
-- every trace away when the budget runs out) and aborted traces; once with a budget too
-- big to run out, reporting how many traces and how much machine code the scene needs.
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

local options = common.options(arg, {frames = 3000, why = 0, readme = ""})
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

print(("budge JIT budget on %s, %s; %d frames per scene"):format(common.interpreter(),
  common.machine(), options.frames))
local lines = {("`luajit bench/jit.lua --frames %d`, %s, on %s, %s: one run (identical runs "
  .. "vary by about 20%%: what LuaJIT compiles depends on timing)."):format(options.frames,
  os.date("!%Y-%m-%d"), common.interpreter(), common.machine()), "",
  "| scene | budget | flushes | aborts | traces | KB of machine code | ms/frame |",
  "|---|---|---|---|---|---|---|"}
print(("%-11s %-8s %8s %8s %8s %10s %12s"):format("scene", "budget", "flushes", "aborts",
  "traces", "mcode KB", "ms/frame"))
for _, entry in ipairs({{"platformer", platformer}, {"crowd", crowd}}) do
  for _, budget in ipairs({"default", "large"}) do
    local result = run(entry[2], options.frames, budget)
    print(("%-11s %-8s %8d %8d %8d %10.0f %12.3f"):format(entry[1], budget, result.flushes,
      result.aborts, result.traces, result.kb, result.ms_per_frame))
    lines[#lines + 1] = ("| %s | %s | %d | %d | %d | %.0f | %.3f |"):format(entry[1], budget,
      result.flushes, result.aborts, result.traces, result.kb, result.ms_per_frame)
    if options.why > 0 then -- the most frequent abort reasons
      local list = {}
      for reason, count in pairs(result.reasons) do list[#list + 1] = {reason, count} end
      table.sort(list, function(a, b) return a[2] > b[2] or (a[2] == b[2] and a[1] < b[1]) end)
      for i = 1, math.min(options.why, #list) do
        print(("    %5d  %s"):format(list[i][2], list[i][1]))
      end
    end
  end
end
jit.opt.start("maxtrace=1000", "maxmcode=512")
if options.readme ~= "" then common.write_readme(options.readme, "bench/jit.lua", lines) end
