-- examples/platformer/draw.lua: draws a game with love.graphics: plain rectangles, a
-- camera that follows the player, and a HUD. Reads the game; changes nothing.
local draw = {items = {}}

local COLORS = {
  ground = {0.35, 0.3, 0.25}, ledge = {0.6, 0.5, 0.3}, platform = {0.55, 0.55, 0.7},
  door = {0.6, 0.35, 0.2}, crusher = {0.5, 0.5, 0.5}, coin = {1, 0.85, 0.2},
  spikes = {0.9, 0.2, 0.2}, checkpoint = {0.3, 0.7, 1}, switch = {0.9, 0.5, 1},
  goal = {0.3, 1, 0.4}, player = {1, 1, 1}, enemy = {1, 0.4, 0.2}, bullet = {1, 1, 0.6},
}

local function rect(gfx, color, item, mode)
  gfx.setColor(color)
  gfx.rectangle(mode or "fill", item.x, item.y, item.width, item.height)
end

local function tiles(gfx, layer, color)
  gfx.setColor(color)
  local grid = layer.grid
  for row = 1, layer.rows do
    for col = 1, layer.cols do
      local id = grid.data[(row - 1) * layer.cols + col]
      if id ~= 0 then
        gfx.rectangle("fill", layer.x + (col - 1) * layer.tile_width,
          layer.y + (row - 1) * layer.tile_height, layer.tile_width,
          id == 2 and 4 or layer.tile_height)
      end
    end
  end
end

---Draws the game into a view of width x height pixels.
---@param gfx table love.graphics
---@param run table the game
---@param width number
---@param height number
function draw.frame(gfx, run, width, height)
  local world, player = run.world, run.player
  gfx.clear(0.08, 0.09, 0.12)
  local level_width = run.level.width * run.level.tilewidth
  local camera = player.x + player.width / 2 - width / 2
  if camera < 0 then camera = 0 elseif camera > level_width - width then camera = level_width - width end
  gfx.push()
  gfx.translate(-math.floor(camera), math.floor((height - run.level.height * run.level.tileheight) / 2))
  tiles(gfx, run.ground, COLORS.ground)
  tiles(gfx, run.ledges, COLORS.ledge)
  local items = world:query_rect(camera - 32, -64, width + 64, height + 128, draw.items)
  for _, item in ipairs(items) do
    local color = COLORS[item.kind]
    if color and item ~= player then rect(gfx, color, item) end
  end
  rect(gfx, COLORS.player, player)
  gfx.pop()
  gfx.setColor(0, 0, 0, 0.6)
  gfx.rectangle("fill", 0, 0, width, 22)
  gfx.setColor(1, 1, 1)
  gfx.print(("score %d   coins %d/%d   enemies %d/%d   deaths %d%s"):format(
    run.coins * 10 + run.kills * 50, run.coins, run.total_coins, run.kills, run.total_enemies,
    run.deaths, run.goal and "   GOAL!" or ""), 8, 4)
end

return draw
