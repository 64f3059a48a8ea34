-- budge.layer: tile layers. The caller's grid is read once (by tilegrid.lua) into a
-- flat array of kinds (EMPTY, SOLID, ONEWAY) indexed (row - 1) * cols + col, and every
-- question about tiles is answered from that array by index: no per-tile boxes, no
-- hashing. Tile (col, row) covers [x + (col - 1) * tile_width, x + col * tile_width] on
-- x and likewise on y, the one expression used for tile edges everywhere. Nothing here
-- iterates with pairs().

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")
local tilegrid = require(here .. ".tilegrid")
local hits = require(here .. ".hits")

local floor, ceil, min, max, abs, HUGE = math.floor, math.ceil, math.min, math.max,
  math.abs, math.huge
local format, error = string.format, error
local clip_axis, segment_enter, before = sweep.clip_axis, sweep.segment_enter, sweep.before
local add_hit, SLIDE = hits.add, hits.SLIDE
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
---@field package _spare_kinds? integer[] the arrays layer.reread reads into, then swaps
---@field package _spare_ids? any[]
---@field package _inverse_width number 1 / tile_width
---@field package _inverse_height number 1 / tile_height
---@field package _pow2 boolean its tiles' sides are powers of two (2^-64 to 2^64). With its
---origin at (0, 0) as well (x and y read at each call: a layer the game moves is met where
---it is, as before), from a coordinate of at least 1 the tile it lies in is floor(v / side)
---and its faces j * side, exactly, so tile_line and tile_stop skip the corrections for
---rounding there (most games' layers: the world bench's moves on LuaJIT ran 1218-1224
---machine instructions instead of 1299-1304, and, with the origin read once, 138 ns
---instead of 144 at 100 movers and 166 instead of 177 at 10000; on Lua 5.4 22424
---instead of 23674: `bench/instructions.lua --way tiles` and `bench/world.lua --way
---tiles`, 7 fresh runs each, interleaved, 2026-12-07). spec/layer_spec.lua holds both to
---the brute force there, hostile_spec.lua to a layer the game moves.
---@field package _width? integer opts.width, for a flat grid
---@field package _is_solid? fun(id: any): boolean
---@field package _is_oneway? fun(id: any): boolean

-- True when `size` is 2^k, -64 <= k <= 64: v / size, v * (1 / size) and j * size are then
-- exact for the coordinates a world allows, from 1 up (no rounding and no underflow).
local function exact_side(size)
  return size >= 2 ^ -64 and size <= 2 ^ 64 and sweep.power_of_two(size)
end

-- The reach table: for each tile, the nearest line at or beyond it (toward +x, -x, +y,
-- -y) that holds a solid tile in its row or column, as a 0-based column or row (cols or
-- rows when there is none toward +x or +y, -1 toward -x or -y), the four side by side
-- at 4 * (index - 1) + RIGHT, LEFT, DOWN or UP (so that a move reads one part of memory
-- for both of its axes); `_down_any` counts oneway tiles too, toward +y, at the tile's
-- index (false when the layer has none). The axis scan reads the line a box stops at
-- from them, one read per tile across the box, whatever the move's length. They take
-- four or five numbers per tile, built at add_tiles and at each update (four passes over
-- the grid).
local RIGHT, LEFT, DOWN, UP = 1, 2, 3, 4
local function build_reach(tiles)
  local kinds, cols, rows = tiles._kinds, tiles.cols, tiles.rows
  local reach = tiles._reach or {}
  local has_oneway = false
  for row = 0, rows - 1 do
    local base = row * cols
    local next_solid = cols
    for col = cols - 1, 0, -1 do
      local kind = kinds[base + col + 1]
      if kind == SOLID then next_solid = col elseif kind == ONEWAY then has_oneway = true end
      reach[(base + col) * 4 + RIGHT] = next_solid
    end
    next_solid = -1
    for col = 0, cols - 1 do
      if kinds[base + col + 1] == SOLID then next_solid = col end
      reach[(base + col) * 4 + LEFT] = next_solid
    end
  end
  local down_any = has_oneway and (tiles._down_any or {}) or false
  for col = 0, cols - 1 do
    local next_solid, next_any = rows, rows
    for row = rows - 1, 0, -1 do
      local index = row * cols + col
      local kind = kinds[index + 1]
      if kind == SOLID then next_solid, next_any = row, row
      elseif kind == ONEWAY then next_any = row end
      reach[index * 4 + DOWN] = next_solid
      if down_any then down_any[index + 1] = next_any end
    end
    next_solid = -1
    for row = 0, rows - 1 do
      local index = row * cols + col
      if kinds[index + 1] == SOLID then next_solid = row end
      reach[index * 4 + UP] = next_solid
    end
  end
  tiles._reach, tiles._down_any = reach, down_any
  tiles._pow2 = exact_side(tiles.tile_width) and exact_side(tiles.tile_height)
end

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
  build_reach(tiles)
  return tiles
end

---Rereads the layer's grid after the game changed it; the grid must keep its size.
---Errors at `level` and changes nothing when it cannot; an error that the game's
---is_solid or is_oneway raises changes nothing either, and one the grid raises (a row's
---__index) leaves what was read before it, with the reach table to match.
---@param tiles budge.TileLayer
---@param level integer
function layer.reread(tiles, level)
  local source = tiles.grid
  local data, cols, rows = measure(source, tiles._width, level + 1)
  if cols ~= tiles.cols or rows ~= tiles.rows then
    error(format("grid changed size from %dx%d to %dx%d: remove the layer and add it again",
      tiles.cols, tiles.rows, cols, rows), level + 1)
  end
  local is_solid, is_oneway = tiles._is_solid, tiles._is_oneway
  if is_solid == nil and is_oneway == nil then -- (the default test raises nothing, but the
    -- grid may: a row's __index. Then what was read stands, with its reach table, so
    -- that moves and queries agree, and the error goes on, the same value; a traceback
    -- taken of it starts here, not in the game's __index, which its message still names)
    local ok, err = pcall(read, source, data, cols, rows, nil, nil, tiles._kinds, tiles._ids)
    if not ok then
      build_reach(tiles)
      error(err, 0)
    end
  else
    -- into spare arrays, swapped in once all is read: an error that is_solid or
    -- is_oneway raises part-way leaves the layer as it was (read in place, the kinds it
    -- had read were new and the reach table old, so a move and a query disagreed). Kept
    -- for the next update: no garbage, and twice the memory of the layer's kinds and ids
    local kinds, ids = tiles._spare_kinds or {}, tiles._spare_ids or {}
    read(source, data, cols, rows, is_solid, is_oneway, kinds, ids)
    tiles._spare_kinds, tiles._spare_ids = tiles._kinds, tiles._ids
    tiles._kinds, tiles._ids = kinds, ids
  end
  build_reach(tiles)
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

---Appends to the candidate set the non-empty tiles that overlap the rectangle from (x0,
---y0) to (x1, y1) (strictly), row by row, each as a box with `other` = the layer and `id`
---its order, stopping once the set holds `limit` entries. The one loop over a rectangle
---of tiles: moves gather with it, queries ask it whether any tile is there. (The far
---sides as given: a filtered phase's band ends at its reach, and x0 + (x1 - x0) can round
---below it, leaving out a tile whose face lies between the two.)
---@param tiles budge.TileLayer
---@param x0 number
---@param y0 number
---@param x1 number
---@param y1 number
---@param set budge.CandidateSet
---@param id integer
---@param limit? integer
function layer.gather(tiles, x0, y0, x1, y1, set, id, limit)
  local tile_width, tile_height = tiles.tile_width, tiles.tile_height
  local col0, col1 = span(tiles.x, tile_width, tiles._inverse_width, tiles.cols, x0, x1)
  if col0 > col1 then return end
  local row0, row1 = span(tiles.y, tile_height, tiles._inverse_height, tiles.rows, y0, y1)
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
  layer.gather(tiles, x, y, x + width, y + height, set, 0, 1)
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
    layer.gather(tiles, left, top, left + ((ax < bx and bx - ax or ax - bx) + width),
      top + ((ay < by and by - ay or ay - by) + height), set, 0)
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

-- The scan reads the line a box stops at from the reach tables (build_reach): from the
-- first line ahead of the box's trailing edge (a face inside the box counts: the box
-- overlaps a solid tile there, and the caller refuses to go deeper), the nearest line
-- with a solid tile among the tiles across the box is the smallest (or, backward, the
-- largest) of their reach values; a move down also meets the oneway tiles from the first
-- line at or past its bottom edge. One read per tile across the box, whatever the length
-- of the move.
-- Speed: LuaJIT compiles a move of the world bench into one tree of traces when it
-- enters no loop (a loop is a trace of its own, and the step from trace to trace costs
-- more than the reads) and when few values are live at its branches: each local live
-- at a branch, in this function and in every caller up to the game's loop, is carried
-- into the branch's side trace, and with a dozen numbers there LuaJIT cannot compile the
-- side trace at all ("NYI: register coalescing too complex", thousands of aborts per run
-- of the world bench before this shape). Hence tile_line below says whether a tile
-- stops the box as a number, not a branch (its callers branch on it, where few values
-- are live), one or two tiles across are read without a loop, and the tiles on the line
-- are listed by list_line, apart.

-- This shape is LuaJIT's: in a world of tiles and actors Lua 5.1-5.4 answer with
-- layer.tile_stop below, the same arithmetic in one function with comparisons (there
-- each call, even to math.min, costs more than a branch).

---The line of tiles (0-based) the box at `pos` (of `size`) on the axis meets first when
---it moves by `delta` (`forward`: delta > 0), among the tiles across it from `cross` to
---`cross_end`: its face, 1 (or 0 when no tile stops the box: the other values are then
---meaningless), the line, and the tiles first..last (0-based) across. The same answer as
---tile_stop's. Whether a tile stops the box is a product of 0s and 1s, with no branch:
---the tile indices are clamped into the layer for the reads (min and max) and a factor
---says whether they were in it, and the face is checked against the move's reach as
---ceil(min(max(reach - face, 0), 1)), 1 when face < reach and 0 otherwise (for finite
---numbers b - a > 0 exactly when a < b). What branches is what is all but always the
---same for a box from one move to the next: the direction, a box more than two tiles
---across, oneway tiles, and the roundings checked at the tile edges.
---LuaJIT shaping: move.lua's lean_phase branches once on the answer. Through axis_phase,
---phase_stop and the tile_face before this one (which branched on each decision), the
---world bench's tile moves took 191 ns instead of 169 (`luajit bench/world.lua --profile
---tiles`, 11 runs each, interleaved, 2026-12-02). The edge checks are comparisons, not
---the same ceil(min(max())) form: that chain of roundings made tile_line take 26 ns a
---call instead of 14.5 (boxes at random on the bench map, 2026-12-02).
---@param tiles budge.TileLayer
---@param is_x boolean
---@param forward boolean
---@param pos number
---@param size number
---@param delta number
---@param cross number
---@param cross_end number
---The last two values are the reach values it read at `first` and `last` across: when
---the line comes from the reach table alone (no oneway tiles in a move down), a tile
---there is on the line exactly when its value is the line, so layer.pair lists the line
---from them without reading the table again.
---@return number face, integer hit, integer line, integer first, integer last, integer reach_first, integer reach_last
function layer.tile_line(tiles, is_x, forward, pos, size, delta, cross, cross_end)
  local origin, tile, inverse, count, stride, cross_stride, first, last
  local exact = tiles._pow2 and tiles.x == 0 and tiles.y == 0
  if is_x then
    origin, tile, inverse, count, stride, cross_stride = tiles.x, tiles.tile_width,
      tiles._inverse_width, tiles.cols, 1, tiles.cols
  else
    origin, tile, inverse, count, stride, cross_stride = tiles.y, tiles.tile_height,
      tiles._inverse_height, tiles.rows, tiles.cols, 1
  end
  local count_across = is_x and tiles.rows or tiles.cols
  if exact and cross >= 1 then -- (span's corrections never apply: budge.TileLayer's _pow2)
    local inverse_side = is_x and tiles._inverse_height or tiles._inverse_width
    first, last = floor(cross * inverse_side), min(ceil(cross_end * inverse_side) - 1,
      count_across - 1)
  elseif is_x then
    first, last = span(tiles.y, tiles.tile_height, tiles._inverse_height, tiles.rows, cross,
      cross_end)
  else
    first, last = span(tiles.x, tiles.tile_width, tiles._inverse_width, tiles.cols, cross,
      cross_end)
  end
  local hit = min(max(last - first + 1, 0), 1) -- (0: no tile across the box)
  first = min(first, count_across - 1)
  last = max(last, first)
  local edge = pos + size
  local reach = tiles._reach
  local line, face, reach_first, reach_last
  if forward then
    -- the first line whose low face is past pos (a box of size 0: at or past it)
    local j
    if exact and pos >= 1 then
      j = ceil(pos * inverse)
      if pos < edge and j * tile == pos then j = j + 1 end
    else
      j = ceil((pos - origin) * inverse)
      local near = origin + j * tile
      if near < pos or (pos < edge and near == pos) then j = j + 1
      else
        near = origin + (j - 1) * tile
        if near > pos or (pos >= edge and near == pos) then j = j - 1 end
      end
    end
    j = max(j, 0)
    hit = hit * min(max(count - j, 0), 1)
    j = min(j, count - 1)
    local at, step = (j * stride + first * cross_stride) * 4 + (is_x and RIGHT or DOWN),
      cross_stride * 4
    reach_first, reach_last = reach[at], reach[at + (last - first) * step]
    line = min(reach_first, reach_last)
    for i = 1, last - first - 1 do line = min(line, reach[at + i * step]) end
    local down_any = tiles._down_any
    if not is_x and down_any then -- oneway tiles, from the first row at or below the box
      j = ceil((edge - origin) * inverse)
      if origin + j * tile < edge then j = j + 1
      elseif origin + (j - 1) * tile >= edge then j = j - 1 end
      if j < 0 then j = 0 end
      if j < count then
        at = j * stride + first + 1
        for i = 0, last - first do line = min(line, down_any[at + i]) end
      end
    end
    hit = hit * min(max(count - line, 0), 1)
    line = min(line, count - 1)
    face = origin + line * tile
    hit = hit * ceil(min(max(pos + delta + size - face, 0), 1)) -- (the far side where it ends)
  else
    -- the last line whose high face is before edge (a box of size 0: at or before it)
    local j
    if exact and edge >= 1 then
      j = floor(edge * inverse) - 1
      if pos < edge and (j + 1) * tile == edge then j = j - 1 end
    else
      j = floor((edge - origin) * inverse) - 1
      local high = origin + (j + 1) * tile
      if high > edge or (pos < edge and high == edge) then j = j - 1
      else
        high = origin + (j + 2) * tile
        if high < edge or (pos >= edge and high == edge) then j = j + 1 end
      end
    end
    j = min(j, count - 1)
    hit = hit * min(max(j + 1, 0), 1)
    j = max(j, 0)
    local at, step = (j * stride + first * cross_stride) * 4 + (is_x and LEFT or UP),
      cross_stride * 4
    reach_first, reach_last = reach[at], reach[at + (last - first) * step]
    line = max(reach_first, reach_last)
    for i = 1, last - first - 1 do line = max(line, reach[at + i * step]) end
    hit = hit * min(max(line + 1, 0), 1)
    line = max(line, 0)
    face = origin + (line + 1) * tile
    hit = hit * ceil(min(max(face - (pos + delta), 0), 1))
  end
  return face, hit, line, first, last, reach_first, reach_last
end

-- Where line `line`'s tiles are in the reach tables, for a move on the axis (is_x) and
-- way (forward) a probe gives: the table, the index of the tile at 0 across and the step
-- across. A move down onto a face at or below the box's leading edge `edge` (`face`: the
-- line's) reads the table of tiles that block it there, oneway ones included.
local function line_base(tiles, is_x, forward, line, face, edge)
  if is_x then return tiles._reach, line * 4 + (forward and RIGHT or LEFT), tiles.cols * 4 end
  if forward and tiles._down_any and face >= edge then
    return tiles._down_any, line * tiles.cols + 1, 1
  end
  return tiles._reach, line * tiles.cols * 4 + (forward and DOWN or UP), 4
end

-- Of a box one or two tiles across (first and last, 0-based, last - first <= 1), which
-- are on line `line`, from their reach values (a tile is on the line when its value is
-- the line): the first of them (0-based across) and how many (1 or 2; the second, when 2,
-- is `last`). Without a branch (on LuaJIT each is a side trace to compile): `missed` is 1
-- for a tile whose reach is not the line (reach and line are whole numbers), and for a
-- box one tile across the "second" is the first again, not counted.
local function pair(line, first, last, reach_first, reach_last)
  local missed_first = min(abs(reach_first - line), 1)
  local missed_last = min(abs(reach_last - line), 1)
  return first + missed_first * (last - first),
    1 - missed_first + min(last - first, 1) * (1 - missed_last)
end

layer.pair = pair

-- pair's answer from the reach table `reach` (line_base's table, base and step).
local function line_pair(reach, base, step, line, first, last)
  return pair(line, first, last, reach[base + first * step], reach[base + last * step])
end

-- Lists the tiles on line `line` that stop the box (those whose reach is that line: the
-- face is `face`) into probe.cols and probe.rows (1-based); returns how many. One or two
-- tiles across are read without a loop (on LuaJIT a loop of one or two turns costs side
-- traces it could not compile: see the axis scan above; Lua 5.x takes tile_stop): both
-- are written, the second past the count when only one is on the line.
local function list_line(tiles, probe, line, first, last, face)
  local is_x = probe.is_x
  local reach, base, cross_stride = line_base(tiles, is_x, probe.forward, line, face,
    probe.edge)
  local out_cols, out_rows = probe.cols, probe.rows
  if last - first > 1 then
    local found = 0
    for i = first, last do
      if reach[base + i * cross_stride] == line then
        found = found + 1
        if is_x then out_cols[found], out_rows[found] = line + 1, i + 1
        else out_cols[found], out_rows[found] = i + 1, line + 1 end
      end
    end
    return found
  end
  local across, count = line_pair(reach, base, cross_stride, line, first, last)
  if is_x then
    out_cols[1], out_rows[1], out_cols[2], out_rows[2] = line + 1, across + 1, line + 1, last + 1
  else
    out_cols[1], out_rows[1], out_cols[2], out_rows[2] = across + 1, line + 1, last + 1, line + 1
  end
  return count
end

layer.list_line = list_line

---Of a box one or two tiles across (first and last, 0-based across, last - first <= 1)
---moving on the axis (is_x) and way (forward) of tile_line's answer (line, face), with
---its leading edge at `edge`: the first tile on the line (0-based across) and how many
---are (1 or 2: the second, when 2, is `last`). list_line's answer as values, for a caller
---that writes them straight into its hits (move.lua's lean_phase).
---@param tiles budge.TileLayer
---@param is_x boolean
---@param forward boolean
---@param line integer
---@param first integer
---@param last integer
---@param face number
---@param edge number
---@return integer across, integer count
function layer.line_pair(tiles, is_x, forward, line, first, last, face, edge)
  local reach, base, step = line_base(tiles, is_x, forward, line, face, edge)
  return line_pair(reach, base, step, line, first, last)
end

---Nearest tile face the probe's box meets in the layer. Returns the face coordinate
---and how many tiles lie on it (their 1-based col and row written to probe.cols and
---probe.rows), or nil, 0. A face inside the box (the box overlaps a solid tile) counts
---too, so the caller can refuse to go deeper.
---@param tiles budge.TileLayer
---@param probe budge.AxisProbe
---@return number? face, integer count
function layer.tile_face(tiles, probe)
  local face, hit, line, first, last = layer.tile_line(tiles, probe.is_x, probe.forward,
    probe.pos, probe.size, probe.delta, probe.cross, probe.cross_end)
  if hit == 0 then return nil, 0 end
  return face, list_line(tiles, probe, line, first, last, face)
end

---Lua 5.1-5.4's axis phase against one tile layer: layer.tile_face's answer, from the
---move's values rather than a probe, with the tiles written straight into the world's
---hits. The box at `pos` (of `size`) on the axis moving by `delta`, from `cross` to
---`cross_end` across it, `done` px into a move of `path` px: the tiles on the nearest face
---that stops it are appended to world's hits as "slide" contacts at the stop's time, in
---order across, without the sort keys (hits.key_tiles writes them where hits from several
---layers are sorted: move.lua's layers_stop). Returns where the box stops and the face,
---or nil when no tile of `tiles` stops it.
---Speed: the same arithmetic and reads as tile_line and list_line, with span and
---list_line written out and comparisons for min and max (on Lua 5.x a call, even to
---math.min, costs more than a branch). `lua5.4 bench/world.lua --way tiles
-----count 1000 --frames 60`, 3 fresh runs each, interleaved, 2026-12-02, with move.lua's
---layers_stop: 2196-2323 ns per move through tile_face and phase_stop, 1740-1750 through
---this. The hits written here, not listed into the probe's arrays for move.lua to write
---(a call and a round trip through two arrays less per phase): the world bench's tile
---moves at 100 movers ran 20760 machine instructions a move instead of 23614, 19121
---instead of 21510 at 1000 (`lua5.4 bench/instructions.lua --way tiles --count N --lua
---lua5.4`), and 1755 ns instead of 2113 at 100 movers (`lua5.4 bench/world.lua --way
---tiles --count 100 --frames 60`, 11 fresh runs each, interleaved with the reference,
---medians, 2026-12-07).
---On LuaJIT its loops cost more than the calls (the same move took 786 ns against 152):
---LuaJIT keeps tile_line. spec/layer_spec.lua holds it to a brute force.
---@param world budge.World
---@param tiles budge.TileLayer
---@param is_x boolean
---@param pos number
---@param cross number
---@param cross_end number
---@param size number
---@param delta number
---@param done number
---@param path number
---@return number? stop, number? face
function layer.tile_stop(world, tiles, is_x, pos, cross, cross_end, size, delta, done, path)
  local forward = delta > 0
  local cols = tiles.cols
  local origin, tile, inverse, count, stride
  local low, side, inverse_side, count_across, cross_stride
  if is_x then
    origin, tile, inverse, count, stride = tiles.x, tiles.tile_width, tiles._inverse_width, cols, 1
    low, side, inverse_side, count_across, cross_stride = tiles.y, tiles.tile_height,
      tiles._inverse_height, tiles.rows, cols
  else
    origin, tile, inverse, count, stride = tiles.y, tiles.tile_height, tiles._inverse_height,
      tiles.rows, cols
    low, side, inverse_side, count_across, cross_stride = tiles.x, tiles.tile_width,
      tiles._inverse_width, cols, 1
  end
  local exact = tiles._pow2 and origin == 0 and low == 0
  -- the tiles across (span)
  local first, last
  if exact and cross >= 1 then -- (budge.TileLayer's _pow2: the corrections never apply)
    first, last = floor(cross * inverse_side), ceil(cross_end * inverse_side) - 1
  else
    first = floor((cross - low) * inverse_side)
    if low + first * side > cross then first = first - 1
    elseif low + (first + 1) * side <= cross then first = first + 1 end
    last = ceil((cross_end - low) * inverse_side) - 1
    if low + (last + 1) * side < cross_end then last = last + 1
    elseif low + last * side >= cross_end then last = last - 1 end
  end
  if first < 0 then first = 0 end
  if last > count_across - 1 then last = count_across - 1 end
  if first > last then return nil end
  local edge = pos + size
  local strict = pos < edge
  local reach, down_any = tiles._reach, tiles._down_any
  local line, face, base, along -- (along: the step between the line's tiles in `reach`)
  if forward then
    local j, near
    if exact and pos >= 1 then -- (ahead)
      j = ceil(pos * inverse)
      if strict and j * tile == pos then j = j + 1 end
    else
      j = ceil((pos - origin) * inverse)
      near = origin + j * tile
      if near < pos or (strict and near == pos) then j = j + 1
      else
        near = origin + (j - 1) * tile
        if near > pos or (not strict and near == pos) then j = j - 1 end
      end
    end
    if j < 0 then j = 0 elseif j >= count then return nil end
    local at, step = (j * stride + first * cross_stride) * 4 + (is_x and RIGHT or DOWN),
      cross_stride * 4
    line = reach[at] -- (nearest_line)
    for i = 1, last - first do
      local next_line = reach[at + i * step]
      if next_line < line then line = next_line end
    end
    if not is_x and down_any then -- oneway tiles, from the first row at or below the box
      j = ceil((edge - origin) * inverse)
      near = origin + j * tile
      if near < edge then j = j + 1
      elseif origin + (j - 1) * tile >= edge then j = j - 1 end
      if j < 0 then j = 0 end
      if j < count then
        at = j * cols + first + 1
        for i = 0, last - first do
          local next_line = down_any[at + i]
          if next_line < line then line = next_line end
        end
      end
    end
    if line >= count then return nil end
    face = origin + line * tile
    if face >= pos + delta + size then return nil end -- (the far side where it ends)
    if is_x then base, along = line * 4 + RIGHT, cols * 4
    elseif down_any and face >= edge then -- (list_line: the oneway table's tiles)
      reach, base, along = down_any, line * cols + 1, 1
    else base, along = line * cols * 4 + DOWN, 4 end
  else
    local j
    if exact and edge >= 1 then -- (behind)
      j = floor(edge * inverse) - 1
      if strict and (j + 1) * tile == edge then j = j - 1 end
    else
      j = floor((edge - origin) * inverse) - 1
      local high = origin + (j + 1) * tile
      if high > edge or (strict and high == edge) then j = j - 1
      else
        high = origin + (j + 2) * tile
        if high < edge or (not strict and high == edge) then j = j + 1 end
      end
    end
    if j > count - 1 then j = count - 1 end
    if j < 0 then return nil end
    local at, step = (j * stride + first * cross_stride) * 4 + (is_x and LEFT or UP),
      cross_stride * 4
    line = reach[at]
    for i = 1, last - first do
      local next_line = reach[at + i * step]
      if next_line > line then line = next_line end
    end
    if line < 0 then return nil end
    face = origin + (line + 1) * tile
    if face <= pos + delta then return nil end
    if is_x then base, along = line * 4 + LEFT, cols * 4
    else base, along = line * cols * 4 + UP, 4 end
  end
  local stop = face
  if forward then stop = face >= edge and before(face, size, pos) or pos
  elseif face > pos then stop = pos end
  local t = (done + (forward and stop - pos or pos - stop)) / path
  local met, nx, ny -- (the side met; hits.NX's and hits.NY's: world_spec holds them there)
  if is_x then
    if forward then met, nx, ny = "right", -1, 0 else met, nx, ny = "left", 1, 0 end
  elseif forward then met, nx, ny = "floor", 0, -1
  else met, nx, ny = "ceiling", 0, 1 end
  local list, n = world._hits, world._n_hits
  for i = first, last do
    if reach[base + i * along] == line then -- (list_line)
      n = n + 1
      local col, row = i + 1, line + 1
      if is_x then col, row = row, col end
      local hit = list[n]
      if hit == nil then -- (a new record: hits.add writes every field)
        world._n_hits = n - 1
        add_hit(world, tiles, met, col, row, tiles.y + (row - 1) * tiles.tile_height,
          tiles.x + (col - 1) * tiles.tile_width, world._records[tiles].id, SLIDE, t)
      else
        hit.other, hit.side, hit.col, hit.row, hit.response, hit.t = tiles, met, col, row,
          SLIDE, t
        hit.nx, hit.ny = nx, ny
      end
    end
  end
  world._n_hits = n
  return stop, face
end

-- The line scan -------------------------------------------------------------------

-- Whether a tile of each kind stops a box (indexed kind + 1): oneway tiles or not.
local BLOCKS_SOLID = {[EMPTY + 1] = 0, [SOLID + 1] = 1, [ONEWAY + 1] = 0}
local BLOCKS_ANY = {[EMPTY + 1] = 0, [SOLID + 1] = 1, [ONEWAY + 1] = 1}

-- True when line `j` of tiles holds a tile that stops the box (rows or columns first..last
-- across it; `oneway_ok`: oneway tiles count).
-- LuaJIT shaping: a box one or two tiles across reads both without a loop or a test per
-- tile (a loop of one or two turns, and each tile's test, forked every trace through it):
-- make bench-jit's platformer needed 420 KB of machine code instead of 450 with a budget
-- that never runs out (`luajit bench/jit.lua --scene platformer --budget large`, 9 fresh
-- runs each, interleaved, medians, 2026-12-02).
local function line_blocks(kinds, base, cross_stride, first, last, oneway_ok)
  if last - first <= 1 then
    local blocks = oneway_ok and BLOCKS_ANY or BLOCKS_SOLID
    return max(blocks[kinds[base + first * cross_stride] + 1],
      blocks[kinds[base + last * cross_stride] + 1]) > 0
  end
  for i = first, last do
    local kind = kinds[base + i * cross_stride]
    if kind == SOLID or (kind == ONEWAY and oneway_ok) then return true end
  end
  return false
end

-- The scans start at the tile holding the box's trailing edge (a rounding can only move
-- that by one tile, onto or past a tile whose face is not a candidate anyway) and stop
-- at the first face beyond the leading edge's reach, or at the end of the layer. They
-- return the line and its face; list_line (reading the reach tables) lists its tiles.
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
        return j, near
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
        return j, high
      end
    end
  end
  return nil
end

---layer.tile_face's answer by scanning the lines of tiles outward from the box, for a
---world with hashed solids or sensors (see move.lua's phase_stop). Scans outward from the box and
---stops at the first face, so a huge move costs at most the layer's width.
---@param tiles budge.TileLayer
---@param probe budge.AxisProbe
---@return number? face, integer count
function layer.tile_face_scan(tiles, probe)
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
  local line, face
  if probe.forward then
    local from = floor((pos - origin) * inverse)
    if from < 0 then from = 0 end
    line, face = scan_forward(kinds, stride, cross_stride, first, last,
      origin, tile, from, count - 1, pos, edge, probe.reach, probe.blocks_oneway)
  else
    local from = ceil((edge - origin) * inverse) - 1
    if from > count - 1 then from = count - 1 end
    line, face = scan_backward(kinds, stride, cross_stride, first, last,
      origin, tile, from, pos, edge, probe.reach, probe.blocks_oneway)
  end
  if line == nil then return nil, 0 end
  return face, list_line(tiles, probe, line, first, last, face)
end

return layer
