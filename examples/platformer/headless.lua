-- examples/platformer/headless.lua: the game without LÖVE, for tests and benches.
--
--   luajit examples/platformer/headless.lua --script S [--frames N]
--
-- Plays the input script S (a file of examples/platformer/scripts/, or a path) at a
-- fixed 1/60 s, prints the one-line verdict and exits 1 when the outcome is not the one
-- the script expects.
local here = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = here .. "/?.lua;" .. here .. "/?/init.lua;" .. here .. "/../../src/?.lua;"
  .. here .. "/../../src/?/init.lua;"
  .. package.path
local game = require("game")
local outcome = require("outcome")

local options = {frames = nil, script = "playthrough"}
local i = 1
while arg[i] do
  local key = arg[i]:match("^%-%-(%a+)$")
  if not key or arg[i + 1] == nil then error("usage: headless.lua --script S [--frames N]", 0) end
  options[key] = tonumber(arg[i + 1]) or arg[i + 1]
  i = i + 2
end
local script = outcome.load_script(here, options.script)
local run = game.new(dofile(here .. "/level.lua"))
local input = game.player_input(script.input)
local frames = options.frames or script.frames
local started = os.clock()
for frame = 1, frames do run:update(input(frame)) end
local seconds = os.clock() - started
local ok, why = outcome.check(run, script.expect)
print(("%s: %s (%.1f us/frame) %s"):format(options.script, run:verdict(), seconds * 1e6 / frames,
  ok and "OK" or ("WRONG: " .. why)))
os.exit(ok and 0 or 1)
