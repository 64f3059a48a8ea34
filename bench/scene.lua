-- The world bench's scene, shared by bench/world.lua and bench/run.lua: a 200x200 map
-- of 16 px tiles (border walls, 20% random solid tiles) and actors of 12x12 in free
-- cells, each with a fixed velocity of 1..8 px per frame in a random direction.
local common = require("bench.common")

local scene = {}

local MAP, TILE, SIZE = 200, 16, 12
scene.MAP, scene.TILE, scene.SIZE = MAP, TILE, SIZE

function scene.make_scene(seed)
  local random = common.new_random(seed)
  local grid = {}
  for row = 1, MAP do
    local line = {}
    for col = 1, MAP do
      line[col] = row == 1 or row == MAP or col == 1 or col == MAP or random() < 0.2
    end
    grid[row] = line
  end
  return grid, random
end

function scene.make_actors(grid, random, count)
  local starts = {}
  while #starts < count do
    local col, row = random(2, MAP - 1), random(2, MAP - 1)
    if not grid[row][col] then
      local angle = random() * 2 * math.pi
      local speed = 1 + random() * 7
      starts[#starts + 1] = {
        x = (col - 1) * TILE + 2, y = (row - 1) * TILE + 2,
        dx = math.cos(angle) * speed, dy = math.sin(angle) * speed,
      }
    end
  end
  return starts
end

return scene
