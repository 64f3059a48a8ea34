-- bench/platforms.lua: moving solids on the world bench's tile map.
--
--   lua bench/platforms.lua [--platforms 100] [--actors 1000] [--frames 600] [--runs 3]
--
-- 100 platforms of 48x8 in free space move back and forth (x or y, 1..3 px per frame,
-- turning every 60 frames) carrying and pushing 1000 actors of 12x12 that fall with
-- gravity and drift sideways. Reports ns per frame, ns per move_solid, KB allocated per
-- frame after a warm-up (GC stopped), and crushes seen.
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local budge = require("budge")
local garbage = require("fixtures.garbage")
local common = require("bench.common")
local scene = require("fixtures.scene")

local MAP, TILE = 200, 16
local options = common.options(arg, {platforms = 100, actors = 1000, frames = 600, runs = 3,
  seed = 4242})

local function build()
  local grid, random = scene.make_scene(options.seed)
  local world = budge.new_world()
  world:add_tiles(grid, TILE, TILE)
  local platforms, actors = {}, {}
  for i = 1, options.platforms do
    local col, row = random(3, MAP - 6), random(3, MAP - 3)
    local platform = world:add_solid({x = (col - 1) * TILE, y = (row - 1) * TILE + 4,
      width = 48, height = 8})
    local speed = random(1, 3)
    platform.vx = random() < 0.5 and speed or 0
    platform.vy = platform.vx == 0 and speed or 0
    platforms[i] = platform
  end
  while #actors < options.actors do
    local col, row = random(2, MAP - 1), random(2, MAP - 1)
    if not grid[row][col] then
      actors[#actors + 1] = world:add_actor({x = (col - 1) * TILE + 2, y = (row - 1) * TILE + 2,
        width = 12, height = 12, vx = random(-2, 2)})
    end
  end
  return world, platforms, actors
end

local function run()
  local world, platforms, actors = build()
  local crushes = 0
  local function frame(f)
    local turn = (f % 120) < 60 and 1 or -1
    for i = 1, #platforms do
      local platform = platforms[i]
      crushes = crushes + world:move_solid(platform, platform.vx * turn, platform.vy * turn)
    end
    for i = 1, #actors do
      local actor = actors[i]
      world:move(actor, actor.vx, 2)
    end
  end
  local bytes, elapsed = garbage.measure(frame, options.frames,
    {warm = function() for f = 1, 120 do frame(f) end end})
  return elapsed * 1e9 / options.frames, bytes / 1024 / options.frames, crushes
end

local per_frame, memory, crushes = {}, 0, 0
for i = 1, options.runs do
  local ns, kb, crushed = run()
  per_frame[i] = ns
  if kb > memory then memory = kb end
  crushes = crushed
end
local ns = common.median(per_frame)
print(("budge %s moving-platform bench on %s, %s"):format(budge._VERSION, common.interpreter(),
  common.machine()))
print(("%d platforms, %d actors, %d frames, median of %d runs"):format(options.platforms,
  options.actors, options.frames, options.runs))
print(("%.0f ns per frame (%.0f us), %.3f KB per frame, %d crushes in the last run"):format(ns,
  ns / 1000, memory, crushes))
