-- budge.layer: tile layers. The caller's grid is read once (by tilegrid.lua) into a
-- flat array of kinds (EMPTY, SOLID, ONEWAY) indexed (row - 1) * cols + col, and every
-- question about tiles is answered from that array by index: no per-tile boxes, no
-- hashing. Tile (col, row) covers [x + (col - 1) * tile_width, x + col * tile_width] on
-- x and likewise on y, the one expression used for tile edges everywhere. Nothing here
-- iterates with pairs().

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")
local tilegrid = require(here .. ".tilegrid")

local floor, ceil, HUGE = math.floor, math.ceil, math.huge
local format, error = string.format, error
local clip_axis, segment_enter = sweep.clip_axis, sweep.segment_enter
local measure, read = tilegrid.measure, tilegrid.read

local layer = {}

local EMPTY, SOLID, ONEWAY = tilegrid.EMPTY, tilegrid.SOLID, tilegrid.ONEWAY

---The handle world:add_tiles returns: hits and queries name it, world:remove and
---world:update take it. Its public fields are for reading; change the grid, then call
---world:update(handle).
---@class budge.TileLayer
---@field x number the layer's left edge
---@field y number its top edge
---@field tile_width number
---@field tile_height number
---@field cols integer tiles per row
---@field rows integer rows of tiles
---@field grid table the caller's grid, as given (reread by world:update)
---@field package _kinds integer[] EMPTY, SOLID or ONEWAY at (row - 1) * cols + col
---@field package _ids any[] the grid's id of each non-empty tile, as read (filters get it)
---@field package _inverse_width number 1 / tile_width
---@field package _inverse_height number 1 / tile_height
---@field package _width? integer opts.width, for a flat grid
---@field package _is_solid? fun(id: any): boolean
---@field package _is_oneway? fun(id: any): boolean

---A tile layer read from the caller's grid; the options have been checked.
---@param source any
---@param tile_width number
---@param tile_height number
---@param opts budge.LayerOptions checked by layer.check_options
---@param level integer where grid errors point
---@return budge.TileLayer
function layer.new(source, tile_width, tile_height, opts, level)
  local data, cols, rows = measure(source, opts.width, level + 1)
  local tiles = {
    x = opts.x or 0, y = opts.y or 0, tile_width = tile_width, tile_height = tile_height,
    cols = cols, rows = rows, grid = source,
    _kinds = {}, _ids = {}, _inverse_width = 1 / tile_width, _inverse_height = 1 / tile_height,
    _width = opts.width, _is_solid = opts.is_solid, _is_oneway = opts.is_oneway,
  }
  read(source, data, cols, rows, tiles._is_solid, tiles._is_oneway, tiles._kinds, tiles._ids)
  return tiles
end

---Rereads the layer's grid after the game changed it; the grid must keep its size.
---Errors at `level` and changes nothing when it cannot.
---@param tiles budge.TileLayer
---@param level integer
function layer.reread(tiles, level)
  local source = tiles.grid
  local data, cols, rows = measure(source, tiles._width, level + 1)
  if cols ~= tiles.cols or rows ~= tiles.rows then
    error(format("grid changed size from %dx%d to %dx%d: remove the layer and add it again",
      tiles.cols, tiles.rows, cols, rows), level + 1)
  end
  read(source, data, cols, rows, tiles._is_solid, tiles._is_oneway, tiles._kinds, tiles._ids)
end

---The tile indices (0-based) whose span meets the open interval (from, to), clamped to
---[0, count - 1]; first > last when none does. A division that rounds onto a boundary
---is caught by checking the result against it.
---@param origin number
---@param size number
---@param inverse number 1 / size
---@param count integer
---@param from number
---@param to number
---@return integer first, integer last
local function span(origin, size, inverse, count, from, to)
  -- the divisions may round either way across a tile edge (an origin like 0.3 is not
  -- exact in binary): each result is checked against the edges themselves
  local first = floor((from - origin) * inverse)
  if origin + first * size > from then first = first - 1
  elseif origin + (first + 1) * size <= from then first = first + 1 end
  local last = ceil((to - origin) * inverse) - 1
  if origin + (last + 1) * size < to then last = last + 1
  elseif origin + last * size >= to then last = last - 1 end
  if first < 0 then first = 0 end
  if last > count - 1 then last = count - 1 end
  return first, last
end

---Appends to the candidate set the non-empty tiles that overlap the rectangle
---(strictly), row by row, each as a box with `other` = the layer and `id` its order,
---stopping once the set holds `limit` entries. The one loop over a rectangle of tiles:
---moves gather with it, queries ask it whether any tile is there.
---@param tiles budge.TileLayer
---@param x number
---@param y number
---@param width number
---@param height number
---@param set budge.CandidateSet
---@param id integer
---@param limit? integer
function layer.gather(tiles, x, y, width, height, set, id, limit)
  local tile_width, tile_height = tiles.tile_width, tiles.tile_height
  local col0, col1 = span(tiles.x, tile_width, tiles._inverse_width, tiles.cols, x, x + width)
  if col0 > col1 then return end
  local row0, row1 = span(tiles.y, tile_height, tiles._inverse_height, tiles.rows, y,
    y + height)
  local kinds, cols = tiles._kinds, tiles.cols
  local n = set.n
  limit = limit or HUGE
  local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
  local set_cols, set_rows, ids = set.col, set.row, set.id
  for row = row0, row1 do
    local base = row * cols + 1
    for col = col0, col1 do
      local kind = kinds[base + col]
      if kind ~= EMPTY then
        n = n + 1
        xs[n], ys[n] = tiles.x + col * tile_width, tiles.y + row * tile_height
        ws[n], hs[n] = tile_width, tile_height
        oneway[n] = kind == ONEWAY
        other[n], set_cols[n], set_rows[n], ids[n] = tiles, col + 1, row + 1, id
        if n >= limit then set.n = n return end
      end
    end
  end
  set.n = n
end

---True when any non-empty tile strictly overlaps the rectangle. `set` is scratch.
---@param tiles budge.TileLayer
---@param x number
---@param y number
---@param width number
---@param height number
---@param set budge.CandidateSet emptied
---@return boolean
function layer.touches(tiles, x, y, width, height, set)
  set.n = 0
  layer.gather(tiles, x, y, width, height, set, 0, 1)
  local found = set.n > 0
  set.n = 0
  return found
end


---Fraction of the segment at which it first enters a non-empty tile, or nil; with a
---size, the fraction at which a box of that size with its top-left corner on the segment
---first overlaps one (strictly). Walks the part of the path inside the layer in pieces
---no longer than a tile, nearest first, and stops at the first piece that holds the
---answer: the work follows the tiles along the path, not the rectangle around it. `set`
---is scratch.
---@param tiles budge.TileLayer
---@param x1 number
---@param y1 number
---@param dx number
---@param dy number
---@param set budge.CandidateSet emptied
---@param width? number the box's size (default 0: a point)
---@param height? number
---@return number?
function layer.segment_first(tiles, x1, y1, dx, dy, set, width, height)
  width, height = width or 0, height or 0
  local lx, ly = tiles.x, tiles.y
  local enter, leave = clip_axis(x1, dx, lx - width, lx + tiles.cols * tiles.tile_width, 0, 1,
    false)
  if enter == nil then return nil end
  enter, leave = clip_axis(y1, dy, ly - height, ly + tiles.rows * tiles.tile_height, enter,
    leave, false)
  if enter == nil or enter > leave then return nil end
  local adx, ady = dx < 0 and -dx or dx, dy < 0 and -dy or dy
  local tile = tiles.tile_width < tiles.tile_height and tiles.tile_width or tiles.tile_height
  local pieces = ceil((adx > ady and adx or ady) * (leave - enter) / tile)
  if pieces < 1 then pieces = 1 end
  local best
  local xs, ys, ws, hs = set.x, set.y, set.w, set.h
  for k = 1, pieces do
    local t0 = enter + (leave - enter) * (k - 1) / pieces
    local t1 = k == pieces and leave or enter + (leave - enter) * k / pieces
    local ax, ay, bx, by = x1 + dx * t0, y1 + dy * t0, x1 + dx * t1, y1 + dy * t1
    local left, top = ax < bx and ax or bx, ay < by and ay or by
    set.n = 0
    layer.gather(tiles, left, top, (ax < bx and bx - ax or ax - bx) + width,
      (ay < by and by - ay or ay - by) + height, set, 0)
    for i = 1, set.n do
      local t = segment_enter(x1, y1, dx, dy, xs[i] - width, ys[i] - height, ws[i] + width,
        hs[i] + height)
      if t and (best == nil or t < best) then best = t end
    end
    if best and best <= t1 then break end
  end
  set.n = 0
  return best
end

-- The axis scan --------------------------------------------------------------------

-- True when line `j` of tiles holds a tile that stops the box (rows or columns first..last
-- across it; `oneway_ok`: oneway tiles count).
local function line_blocks(kinds, base, cross_stride, first, last, oneway_ok)
  for i = first, last do
    local kind = kinds[base + i * cross_stride]
    if kind == SOLID or (kind == ONEWAY and oneway_ok) then return true end
  end
  return false
end

-- The scans start at the tile holding the box's trailing edge (a rounding can only move
-- that by one tile, onto or past a tile whose face is not a candidate anyway) and stop
-- at the first face beyond the leading edge's reach, or at the end of the layer. They
-- return the line, its face and whether oneway tiles counted on it.
-- Speed: the scans find the line only, in small functions, and the contacts on it are
-- listed afterwards by list_line: one loop doing both aborted its LuaJIT trace (too many
-- live values at its exits; commit e457877, aborts listed by make bench-jit). Their long
-- positional parameter lists are kept on purpose: the same values passed in the probe
-- cost nothing on LuaJIT (239 against 240 ns per move) but 4.7% on Lua 5.4 (2309 against
-- 2418 ns; `lua5.4 bench/world.lua --profile tiles --frames 300`, median of 5, 2026-12-01).
local function scan_forward(kinds, stride, cross_stride, first, last, origin, tile, from, to,
                            pos, edge, far, blocks_oneway)
  for j = from, to do
    local near = origin + j * tile
    if near >= far then return nil end
    if near > pos or near >= edge then -- (or: a box of size 0 touching the face)
      local ok = blocks_oneway and near >= edge
      if line_blocks(kinds, j * stride + 1, cross_stride, first, last, ok) then
        return j, near, ok
      end
    end
  end
  return nil
end

local function scan_backward(kinds, stride, cross_stride, first, last, origin, tile, from,
                             pos, edge, far, blocks_oneway)
  for j = from, 0, -1 do
    local high = origin + (j + 1) * tile
    if high <= far then return nil end
    if high < edge or high <= pos then -- (or: a box of size 0 touching the face)
      local ok = blocks_oneway and high <= pos
      if line_blocks(kinds, j * stride + 1, cross_stride, first, last, ok) then
        return j, high, ok
      end
    end
  end
  return nil
end

-- Lists the tiles on line `line` that stop the box into probe.cols and probe.rows
-- (1-based); returns how many.
local function list_line(kinds, base, cross_stride, first, last, oneway_ok, line, is_x, probe)
  local out_cols, out_rows = probe.cols, probe.rows
  local found = 0
  for i = first, last do
    local kind = kinds[base + i * cross_stride]
    if kind == SOLID or (kind == ONEWAY and oneway_ok) then
      found = found + 1
      if is_x then out_cols[found], out_rows[found] = line + 1, i + 1
      else out_cols[found], out_rows[found] = i + 1, line + 1 end
    end
  end
  return found
end

---Nearest tile face the probe's box meets in the layer. Returns the face coordinate
---and how many tiles lie on it (their 1-based col and row written to probe.cols and
---probe.rows), or nil, 0. A face inside the box (the box overlaps a solid tile) counts
---too, so the caller can refuse to go deeper. Scans outward from the box and stops at
---the first face, so a huge move costs at most the layer's width.
---@param tiles budge.TileLayer
---@param probe budge.AxisProbe
---@return number? face, integer count
function layer.tile_face(tiles, probe)
  local is_x, pos, edge = probe.is_x, probe.pos, probe.edge
  local origin, tile, inverse, count, stride, cross_stride, first, last
  if is_x then
    origin, tile, inverse, count, stride, cross_stride =
      tiles.x, tiles.tile_width, tiles._inverse_width, tiles.cols, 1, tiles.cols
    first, last = span(tiles.y, tiles.tile_height, tiles._inverse_height, tiles.rows,
      probe.cross, probe.cross_end)
  else
    origin, tile, inverse, count, stride, cross_stride =
      tiles.y, tiles.tile_height, tiles._inverse_height, tiles.rows, tiles.cols, 1
    first, last = span(tiles.x, tiles.tile_width, tiles._inverse_width, tiles.cols,
      probe.cross, probe.cross_end)
  end
  if first > last then return nil, 0 end
  local kinds = tiles._kinds
  local line, face, oneway_ok
  if probe.forward then
    local from = floor((pos - origin) * inverse)
    if from < 0 then from = 0 end
    line, face, oneway_ok = scan_forward(kinds, stride, cross_stride, first, last,
      origin, tile, from, count - 1, pos, edge, probe.reach, probe.blocks_oneway)
  else
    local from = ceil((edge - origin) * inverse) - 1
    if from > count - 1 then from = count - 1 end
    line, face, oneway_ok = scan_backward(kinds, stride, cross_stride, first, last,
      origin, tile, from, pos, edge, probe.reach, probe.blocks_oneway)
  end
  if line == nil then return nil, 0 end
  return face, list_line(kinds, line * stride + 1, cross_stride, first, last, oneway_ok,
    line, is_x, probe)
end

return layer
