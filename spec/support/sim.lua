-- Small simulations shared by the specs: a mover stepped through a list of solids with
-- one of the discrete methods, and a single hit on a wall judged by where it ends up.
local budge = require("budge")
local judge = require("fixtures.judge")

local sim = {}

---Replaces every solid with its fat cross for `max_speed`: a list of {tall, wide}.
function sim.crossed(solids, max_speed)
  local crosses = {}
  for i = 1, #solids do
    local tall, wide = budge.fat_cross(solids[i], max_speed)
    crosses[i] = {tall, wide}
  end
  return crosses
end

---One discrete step: move by (dx, dy), then resolve against each solid in list order
---(for "fat_cross", `solids` is a list of {tall, wide} pairs).
function sim.step(mover, dx, dy, solids, method)
  mover.prev_y = mover.y
  mover.x, mover.y = mover.x + dx, mover.y + dy
  for i = 1, #solids do
    local solid = solids[i]
    if method == "fat_cross" then
      budge.resolve_fat_cross(mover, solid[1], solid[2])
    else
      budge.resolve_collision(mover, solid, method)
    end
  end
end

---A row (dx = width) or column (dy = height) of `count` separate tiles.
function sim.tiles(x, y, size, count, across, wall_type)
  local tiles = {}
  for i = 0, count - 1 do
    tiles[#tiles + 1] = {x = across and x + i * size or x, y = across and y or y + i * size,
      width = size, height = size, wall_type = wall_type}
  end
  return tiles
end

local DIRECTIONS = {
  left = {1, 0}, right = {-1, 0}, top = {0, 1}, bottom = {0, -1},
}

-- The judge's kinds (fixtures/judge.lua) in the words of these specs.
local VERDICTS = {["residual overlap"] = "inside", teleported = "teleported",
  ["wrong side"] = "wrong side", tunnelled = "tunnelled"}

---A `size` x `size` mover starts touching `wall` on side `from` ("left" means it comes
---from the left, moving right), centred on the wall's span, and moves `speed` toward it
---in one step; then `method` resolves it. Returns the verdict: "correct" (back where it
---touched the wall), "wrong side" (pushed out through the far face), "teleported"
---(pushed along the other axis), "tunnelled" (no overlap after the step: it passed), or
---"inside" (still overlapping); fixtures/judge.lua judges the resolved step.
function sim.hit(method, from, speed, wall, size, max_speed)
  local direction = DIRECTIONS[from]
  local mover = {width = size, height = size}
  if direction[1] ~= 0 then
    mover.x = direction[1] > 0 and wall.x - size or wall.x + wall.width
    mover.y = wall.y + (wall.height - size) / 2
  else
    mover.x = wall.x + (wall.width - size) / 2
    mover.y = direction[2] > 0 and wall.y - size or wall.y + wall.height
  end
  local start_x, start_y = mover.x, mover.y
  local solids
  if method == "fat_cross" then
    solids = sim.crossed({wall}, max_speed)
  else
    solids = {wall}
  end
  mover.prev_y = mover.y
  local dx, dy = direction[1] * speed, direction[2] * speed
  mover.x, mover.y = mover.x + dx, mover.y + dy
  if not budge.detect_collision(mover, wall) then return "tunnelled" end
  sim.step(mover, 0, 0, solids, method)
  local kind = judge.move(judge.wall(wall, direction[1], direction[2]), start_x, start_y, size,
    size, dx, dy, mover.x, mover.y)
  return kind and VERDICTS[kind] or "correct"
end

return sim
