-- bench/contacts_count.lua: interpreter instructions per actor of world:contacts in
-- bench/contacts.lua's scene (1000 walkers, 200 coins, 100 bullets fired again at walls),
-- counted by a debug hook over 30 calls after 10: a figure that does not move with the
-- machine's load, for A/B comparisons of contacts.lua on Lua 5.1-5.4 (on LuaJIT the hook
-- sees only what runs in the interpreter: use Lua 5.x). Its moves are world:move's, not
-- bench/contacts.lua's exactly (its own free cells and firing order).
--
--   lua5.4 bench/contacts_count.lua
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local budge = require("budge")
local scene = require("fixtures.scene")
local TILE, MAP = scene.TILE, scene.MAP

local grid, random = scene.make_scene(12345)
local starts = scene.make_actors(grid, random, 1000)
local world = budge.new_world()
world:add_tiles(grid, TILE, TILE)
local actors = {}
for i = 1, #starts do
  local start = starts[i]
  local walker = world:add_actor({x = start.x, y = start.y, width = 12, height = 12})
  walker.vx, walker.vy, walker.walker = start.dx, start.dy, true
  actors[#actors + 1] = walker
end
local cells = {}
while #cells < 1197 do
  local col, row = random(2, MAP - 1), random(2, MAP - 1)
  if not grid[row][col] then cells[#cells + 1] = {(col - 1) * TILE, (row - 1) * TILE} end
end
for i = 1, 200 do
  world:add_sensor({x = cells[i][1] + 5, y = cells[i][2] + 5, width = 6, height = 6})
end
local function bullet_filter(_, other)
  if other.walker then return "cross" end
  if other.width == 6 then return nil end -- coins
  return "slide"
end
local DIRECTIONS = {{40, 0}, {0, 40}, {-40, 0}, {0, -40}, {28, 28}, {-28, 28}, {28, -28},
  {-28, -28}}
local next_cell = 200
local function fire(bullet) -- from the next free cell after the coins'
  next_cell = next_cell % #cells + 1
  if next_cell <= 200 then next_cell = 201 end
  local cell, direction = cells[next_cell], DIRECTIONS[next_cell % #DIRECTIONS + 1]
  bullet.x, bullet.y, bullet.vx, bullet.vy = cell[1] + 6, cell[2] + 6, direction[1],
    direction[2]
end
for _ = 1, 100 do
  local bullet = {x = 0, y = 0, width = 4, height = 4, filter = bullet_filter}
  fire(bullet)
  actors[#actors + 1] = world:add_actor(bullet)
end

local total, found = 0, 0
for frame = 1, 40 do
  for i = 1, #actors do
    local actor = actors[i]
    local _, _, n, hits = world:move(actor, actor.vx, actor.vy)
    if actor.filter then
      for k = 1, n do
        if hits[k].response == "slide" then
          fire(actor)
          world:update(actor)
          break
        end
      end
    end
  end
  local count = 0
  if frame > 10 then debug.sethook(function() count = count + 1 end, "", 10) end
  local _, n = world:contacts()
  debug.sethook()
  total, found = total + count, found + n
end
print(("%.1f interpreter instructions per actor per world:contacts call, %d contacts in "
  .. "40 calls (%s)"):format(total * 10 / 30 / #actors, found, _VERSION))
