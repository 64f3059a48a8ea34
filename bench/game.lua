-- bench/game.lua: the example platformer as the measure of speed in a game.
--
--   luajit bench/game.lua [--frames 5000] [--runs 3]
--
-- Plays examples/platformer's play-through script headless (the level starts again each
-- time it is won) for F frames. On LuaJIT three ways, each run in its own fresh process,
-- interleaved: the default JIT budget, a raised one (maxtrace=4000, maxmcode=4096), and
-- the JIT off. Prints us per frame (median of the runs), the traces and KB of machine code
-- alive at the end, and how many times LuaJIT flushed every trace (its budget ran out).
-- On another interpreter, the one way it has.
package.path = "./examples/platformer/?.lua;./src/?.lua;./src/?/init.lua;./?.lua;"
  .. package.path
local common = require("bench.common")

local options = common.options(arg, {frames = 5000, runs = 3, way = "", readme = ""})
local jit = rawget(_G, "jit")

local function play()
  local game = require("game")
  local level = dofile("examples/platformer/level.lua")
  local script = dofile("examples/platformer/scripts/playthrough.lua")
  local input = game.player_input(script.input)
  local run, start = game.new(level), 0
  local began = os.clock()
  for frame = 1, options.frames do
    if run.goal then run, start = game.new(level), frame - 1 end
    run:update(input(frame - start))
  end
  return (os.clock() - began) * 1e6 / options.frames
end

if options.way ~= "" then -- one run of one way
  local flushes = 0
  if jit then
    if options.way == "large" then jit.opt.start("maxtrace=4000", "maxmcode=4096") end
    if options.way == "off" then jit.off() end
    jit.attach(function(what) if what == "flush" then flushes = flushes + 1 end end, "trace")
  end
  local us = play()
  local traces, bytes = 0, 0
  if jit then
    local util = require("jit.util")
    for trace = 1, 4000 do
      local mcode = util.tracemc(trace)
      if mcode then traces, bytes = traces + 1, bytes + #mcode end
    end
  end
  print(("%.1f %d %.0f %d"):format(us, traces, bytes / 1024, flushes))
  os.exit(0)
end

local interpreter = arg[-1] or "lua"
local ways = jit and {"default", "large", "off"} or {"plain"}
local results = common.fresh_runs(ways, options.runs, 4, function(way)
  return ("%s bench/game.lua --way %s --frames %d"):format(interpreter, way, options.frames)
end)
print(("bench/game.lua on %s, %s: the platformer's play-through, %d frames, median of %d "
  .. "fresh processes"):format(common.interpreter(), common.machine(), options.frames,
  options.runs))
print(("%-22s %12s %8s %10s %8s"):format("way", "us/frame", "traces", "mcode KB", "flushes"))
local names = {default = "JIT, default budget", large = "JIT, raised budget", off = "JIT off",
  plain = "interpreter"}
local lines = {("`%s bench/game.lua --frames %d --runs %d`, %s, on %s, %s: the play-through "
  .. "for %d frames, median of %d fresh processes (the ways interleaved)."):format(interpreter,
  options.frames, options.runs, os.date("!%Y-%m-%d"), common.interpreter(), common.machine(),
  options.frames, options.runs), "",
  "| way | µs/frame | traces | KB of machine code | flushes |", "|---|---|---|---|---|"}
for _, way in ipairs(ways) do
  local r = results[way]
  local us, traces, kb, flushes = common.median(r[1]), common.median(r[2]),
    common.median(r[3]), common.median(r[4])
  print(("%-22s %12.1f %8.0f %10.0f %8.0f"):format(names[way], us, traces, kb, flushes))
  lines[#lines + 1] = ("| %s | %.1f | %.0f | %.0f | %.0f |"):format(names[way], us, traces, kb,
    flushes)
end
if options.readme ~= "" then
  common.write_readme(options.readme, "bench/game.lua " .. common.key(), lines)
end
