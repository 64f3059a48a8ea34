-- bench/crowds.lua: world:contacts where a game has a great many things, or moves them all.
--
--   lua bench/crowds.lua [--scene tall|square|pile|churn] [--calls 5]
--
-- Four scenes a game can make, each of which cost the square of its size until 2026-12-06
-- (contacts pruned along x alone, walked every pair of sensors and of actors without a
-- filter, and kept its order by insertion alone):
--   tall    16000 coin sensors of 6x6 up a level 20 tiles wide, 50 actors of 12x12
--           walking up through them (the axis the broad phase prunes along is y);
--   square  16000 coins over a square level, 100 actors walking to and fro;
--   pile    10000 actors with no filter piled up on one spot;
--   churn   16000 actors of 4x4 anywhere on a 4000 px map, a tenth of them taken out and
--           new ones added anywhere each frame (bullets fired again).
-- Prints, per scene, ms per world:contacts call (os.clock, the mean of --calls calls after
-- two that settle the orders) and the contacts found. With no --scene, each scene runs in
-- its own fresh process, one after the other.
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local common = require("bench.common")
local options = common.options(arg, {scene = "", calls = 5})

local SCENES = {"tall", "square", "pile", "churn"}

if options.scene == "" then
  local interpreter = arg[-1] or "lua"
  print(("bench/crowds.lua on %s, %s, %s"):format(common.interpreter(), common.machine(),
    os.date("!%Y-%m-%d")))
  for _, scene in ipairs(SCENES) do
    local pipe = io.popen(("%s bench/crowds.lua --scene %s --calls %d"):format(interpreter,
      scene, options.calls))
    io.write(pipe:read("*a"))
    pipe:close()
  end
  return
end

local budge = require("budge")
local world = budge.new_world()
local actors, step = {}, nil
local scene = options.scene
if scene == "tall" then
  for i = 0, 15999 do
    world:add_sensor({x = (i % 20) * 16 + 5, y = math.floor(i / 20) * 16 + 5, width = 6,
      height = 6})
  end
  for i = 1, 50 do
    actors[i] = world:add_actor({x = (i % 20) * 16 + 2, y = i * 200, width = 12, height = 12})
  end
  step = function() for i = 1, #actors do world:move(actors[i], 0, 3) end end
elseif scene == "square" then
  for i = 0, 15999 do
    world:add_sensor({x = (i % 126) * 16 + 5, y = math.floor(i / 126) * 16 + 5, width = 6,
      height = 6})
  end
  for i = 1, 100 do
    actors[i] = world:add_actor({x = (i * 37 % 126) * 16 + 2, y = (i * 53 % 126) * 16,
      width = 12, height = 12})
  end
  local frame = 0
  step = function()
    frame = frame + 1
    for i = 1, #actors do world:move(actors[i], frame % 2 == 0 and 3 or -3, 0) end
  end
elseif scene == "pile" then
  for i = 1, 10000 do
    actors[i] = world:add_actor({x = 100 + i % 3, y = 100 + i % 5, width = 12, height = 12})
  end
  step = function() end
elseif scene == "churn" then
  local random = require("fixtures.random").new(1)
  local function anywhere()
    return {x = random(0, 64000) / 16, y = random(0, 64000) / 16, width = 4, height = 4}
  end
  for i = 1, 16000 do actors[i] = world:add_actor(anywhere()) end
  local next = 0
  step = function()
    for _ = 1, 1600 do
      next = next % #actors + 1
      world:remove(actors[next])
      actors[next] = world:add_actor(anywhere())
    end
  end
else
  error("--scene must be one of tall, square, pile, churn, got " .. scene)
end

local out = {}
for _ = 1, 2 do
  step()
  world:contacts(out)
end
local elapsed, found = 0, 0
for _ = 1, options.calls do
  step()
  local started = os.clock()
  local _, n = world:contacts(out)
  elapsed = elapsed + (os.clock() - started)
  found = found + n
end
print(("%-7s %9.2f ms per call, %.1f contacts per call"):format(scene,
  elapsed * 1000 / options.calls, found / options.calls))
