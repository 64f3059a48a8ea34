-- budge.tiles: a tile grid turned into few rectangles, each typed so that the article's
-- one-axis method resolves it correctly.
--
-- Why merge: the discrete methods look at one box at a time. On raw tiles a mover that
-- slides along a floor meets the seam between two tiles, and a floor of tiles typed
-- "horizontal" lifts a mover that walks into its end. One rectangle per run of tiles has
-- no seams, and its wall_type can follow which of its faces are open:
--
-- * open only on top or bottom (a floor, a ceiling): "horizontal", pushes up or down;
-- * open only on the left or right (a wall): "vertical", pushes left or right;
-- * open on both axes (a floating block, a platform's ends): hit from both sides, so it
--   gets a fat cross sized for `opts.max_speed` when the block is big enough for it,
--   and no wall_type (solid on all sides, the shortest way out) otherwise;
-- * open nowhere (inside a mass of tiles): typed by its shape, it is never hit.
--
-- A face is open when any tile beside it is free. The map's own edges are closed unless
-- `opts.open_edges` is true. Rectangles are found greedily, once taking runs along rows
-- and growing them down, once taking runs down columns and growing them right; the
-- smaller result wins (rows on a tie). Row-major scanning makes the output deterministic.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local fatcross = require(here .. ".fatcross")
local tilegrid = require(here .. ".tilegrid")

local describe, is_finite = box.describe, box.is_finite
local format, error = string.format, error

local tiles = {}

---@class budge.MergeOptions : budge.LayerOptions
---@field max_speed? number the movers' largest step, to size fat crosses
---@field open_edges? boolean the map's edges count as open faces (default false)

-- Greedy rectangles over the tiles of `kind`: returns {col, row, cols, rows} records in
-- row-major order of their top-left tile. `along_rows` grows runs right and then down;
-- otherwise down and then right. `flat` keeps every rectangle one tile tall.
local function greedy(kinds, cols, rows, kind, along_rows, flat)
  local used, out = {}, {}
  -- tile (r, c) is of `kind` and in no rectangle yet
  local function free(r, c)
    local i = (r - 1) * cols + c
    return kinds[i] == kind and not used[i]
  end
  for row = 1, rows do
    for col = 1, cols do
      if free(row, col) then
        local width, height = 1, 1
        if along_rows or flat then
          while col + width <= cols and free(row, col + width) do width = width + 1 end
          while not flat and row + height <= rows do
            local full = true
            for c = col, col + width - 1 do
              if not free(row + height, c) then full = false break end
            end
            if not full then break end
            height = height + 1
          end
        else
          while row + height <= rows and free(row + height, col) do height = height + 1 end
          while col + width <= cols do
            local full = true
            for r = row, row + height - 1 do
              if not free(r, col + width) then full = false break end
            end
            if not full then break end
            width = width + 1
          end
        end
        for r = row, row + height - 1 do
          for c = col, col + width - 1 do used[(r - 1) * cols + c] = true end
        end
        out[#out + 1] = {col = col, row = row, cols = width, rows = height}
      end
    end
  end
  return out
end

-- True when any tile beside the rectangle on one face is free. (dc, dr) picks the face.
local function face_open(kinds, cols, rows, rect, dc, dr, open_edges)
  local first_col, first_row = rect.col, rect.row
  local last_col, last_row = first_col + rect.cols - 1, first_row + rect.rows - 1
  local col0, col1, row0, row1
  if dc ~= 0 then
    col0 = dc < 0 and first_col - 1 or last_col + 1
    col1, row0, row1 = col0, first_row, last_row
  else
    row0 = dr < 0 and first_row - 1 or last_row + 1
    row1, col0, col1 = row0, first_col, last_col
  end
  if col0 < 1 or col0 > cols or row0 < 1 or row0 > rows then return open_edges end
  for r = row0, row1 do
    for c = col0, col1 do
      if kinds[(r - 1) * cols + c] ~= tilegrid.SOLID then return true end
    end
  end
  return false
end

---Covers the solid tiles of a grid with few rectangles and types each one for the
---article's method (see the module comment). Returns a new array of boxes
---`{x, y, width, height, wall_type, col, row, cols, rows [, tall, wide]}` in row-major
---order: `col, row, cols, rows` name the tiles covered; `tall` and `wide` are the fat
---cross of a block open on both axes (for budge.resolve_fat_cross). Oneway tiles
---(`opts.is_oneway`) become one-tile-tall runs typed "oneway".
---
---`grid` is `grid[row][col]`, a flat array of ids with `opts.width` tiles per row, or a
---Tiled layer `{width =, data =}`. A tile is solid when `opts.is_solid(id)` says so; by
---default any id but nil, false and 0 is, as in world:add_tiles.
---@param source table
---@param tile_width number > 0
---@param tile_height number > 0
---@param opts? budge.MergeOptions
---@return budge.Box[] boxes
function tiles.merge(source, tile_width, tile_height, opts)
  opts = tilegrid.check_options(tile_width, tile_height, opts, 2)
  local max_speed = opts.max_speed
  if max_speed ~= nil and (not is_finite(max_speed) or max_speed <= 0) then
    error(format("opts.max_speed must be a finite number > 0 or nil, got %s",
      describe(max_speed)), 2)
  end
  local data, cols, rows = tilegrid.measure(source, opts.width, 2)
  local kinds = tilegrid.read(source, data, cols, rows, opts.is_solid, opts.is_oneway, {})
  local origin_x, origin_y, open_edges = opts.x or 0, opts.y or 0, opts.open_edges == true

  local by_rows = greedy(kinds, cols, rows, tilegrid.SOLID, true, false)
  local by_cols = greedy(kinds, cols, rows, tilegrid.SOLID, false, false)
  local rects = #by_cols < #by_rows and by_cols or by_rows
  local oneway = greedy(kinds, cols, rows, tilegrid.ONEWAY, true, true)

  local boxes = {}
  for _, rect in ipairs(rects) do
    local item = {x = origin_x + (rect.col - 1) * tile_width,
      y = origin_y + (rect.row - 1) * tile_height,
      width = rect.cols * tile_width, height = rect.rows * tile_height,
      col = rect.col, row = rect.row, cols = rect.cols, rows = rect.rows}
    local open_x = face_open(kinds, cols, rows, rect, -1, 0, open_edges)
      or face_open(kinds, cols, rows, rect, 1, 0, open_edges)
    local open_y = face_open(kinds, cols, rows, rect, 0, -1, open_edges)
      or face_open(kinds, cols, rows, rect, 0, 1, open_edges)
    if open_x and open_y then
      if max_speed and max_speed < fatcross.speed_limit(item.width, item.height) then
        item.tall, item.wide = fatcross.fat_cross(item, max_speed)
      end
    elseif open_y or (not open_x and item.width >= item.height) then
      item.wall_type = "horizontal"
    else
      item.wall_type = "vertical"
    end
    boxes[#boxes + 1] = item
  end
  for _, rect in ipairs(oneway) do
    boxes[#boxes + 1] = {x = origin_x + (rect.col - 1) * tile_width,
      y = origin_y + (rect.row - 1) * tile_height,
      width = rect.cols * tile_width, height = tile_height, wall_type = "oneway",
      col = rect.col, row = rect.row, cols = rect.cols, rows = 1}
  end
  return boxes
end

return tiles
