-- budge.query: the bodies of the world's queries, called with checked arguments.
--
-- Boxes (solids, actors and sensors) come from the spatial hashes, tile layers from their
-- grids; results are sorted into the order items were added (segments and sweeps: by
-- where they enter them, then that order) with table.sort and a total order, never by
-- pairs(). With a caller-given `out` a query allocates nothing once the world is warm.
-- A query's filter(item) runs on the sorted results, under the caller's guard.

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")
local layer = require(here .. ".layer")
local solids = require(here .. ".solids")
local actors = require(here .. ".actors")

local sort = table.sort
local segment_enter, box_enter_to = sweep.segment_enter, sweep.box_enter_to
local segment_first, touches = layer.segment_first, layer.touches
local BELOW_ONE = sweep.BELOW_ONE

local query = {}

local function record_before(a, b) return a.id < b.id end

local function segment_before(a, b)
  local ta, tb = a._t, b._t
  if ta ~= tb then return ta < tb end
  return a.id < b.id
end

-- Records of boxes (solids, actors and sensors) that touch the rectangle from (x, y) to
-- (x1, y1), into world._found.
local function collect_boxes(world, x, y, x1, y1)
  actors.rehash(world)
  local found = world._found
  local n = 0
  local cx, cy, cx1, cy1 = solids.clip_to_boxes(world, x, y, x1, y1)
  if world._solid_count > 0 and cx <= cx1 and cy <= cy1 then
    -- (the clipped sides as they are: cx + (cx1 - cx) can round below cx1)
    n = world._solids:collect_between(cx, cy, cx1, cy1, found, n)
  end
  -- actors can be anywhere: a huge rectangle walks the actor list instead of the cells
  local list = world._actor_list
  if #list > 0 and world._actors:cell_count(x, y, x1 - x, y1 - y) <= 4 * #list then
    n = world._actors:collect_between(x, y, x1, y1, found, n)
  else
    for i = 1, #list do n = n + 1; found[n] = list[i] end
  end
  if world._sensor_count > 0 then
    n = world._sensors:collect_between(x, y, x1, y1, found, n)
  end
  return n
end

---The items of the query's results (world._found[1..n], sorted) into out[1..n], those
---`filter` refuses, or that it removed from the world before it was asked about them,
---left out (and their entries of out_t with them); clears the results
---and the rest of out and out_t. Returns the new count.
---@param world budge.World
---@param n integer
---@param out table
---@param filter? fun(item: any): any
---@param out_t? number[]
---@return integer n
function query.finish(world, n, out, filter, out_t)
  local found = world._found
  local old, kept = #out, 0
  for i = 1, n do
    local record = found[i]
    found[i] = nil
    -- (an item the filter removed while asked about another is not asked about or kept,
    -- as a move does not meet it again: README, "Callbacks"; one the filter removes when
    -- asked about it, and accepts, is kept)
    if filter == nil or not record.removed and filter(record.item) then
      kept = kept + 1
      out[kept] = record.item
      if out_t then out_t[kept] = record._t end
    end
  end
  for i = kept + 1, old do out[i] = nil end
  if out_t then
    for i = kept + 1, #out_t do out_t[i] = nil end
  end
  return kept
end

---Every solid, actor, sensor and tile layer (once, when any of its solid tiles does)
---that strictly overlaps the rectangle, sorted by the order they were added, into
---world._found (query.finish takes them out); returns how many.
---@param world budge.World
---@param x number
---@param y number
---@param width number
---@param height number
---@return integer n
function query.area(world, x, y, width, height)
  local found = world._found
  local count = collect_boxes(world, x, y, x + width, y + height)
  local n = 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    -- the record's copy of the box: where the world last saw it (checked then)
    local bx, by = record[1], record[2]
    if bx < x + width and x < bx + record[3] and by < y + height
      and y < by + record[4] then
      n = n + 1
      found[n] = record
    end
  end
  local layers, records, set = world._layers, world._records, world._set
  for k = 1, #layers do
    if touches(layers[k], x, y, width, height, set) then
      n = n + 1
      found[n] = records[layers[k]]
    end
  end
  for i = n + 1, #found do found[i] = nil end
  sort(found, record_before)
  return n
end

---Every solid, actor, sensor and tile layer that a box of (width, height) with its
---top-left corner moving from (x1, y1) to (x2, y2) overlaps (strictly) on the way (a
---segment when the size is 0), sorted by where it enters them, then by the order they
---were added, into world._found (query.finish takes them out, with the fraction of the
---motion where each is entered, 0 when it starts inside); returns how many. For a tile
---layer, the first solid tile met.
---@param world budge.World
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param width number
---@param height number
---@return integer n
function query.sweep(world, x1, y1, x2, y2, width, height)
  local dx, dy = x2 - x1, y2 - y1
  local left, top = x1 < x2 and x1 or x2, y1 < y2 and y1 or y2
  -- (the far sides of the box where it ends, x2 + width, or where it starts: left +
  -- (|dx| + width) can round below them)
  local right, bottom = (x1 < x2 and x2 or x1) + width, (y1 < y2 and y2 or y1) + height
  local found = world._found
  local count = collect_boxes(world, left, top, right, bottom)
  local n = 0
  local point = width == 0 and height == 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    local t
    if point then -- (the segment rule: a zero-size box inside a zero-size one is met)
      local bx, by = record[1], record[2]
      t = segment_enter(x1, y1, dx, dy, bx, by, record[3], record[4])
      -- the point where the sweep ends inside it: entered, though the rounded times say
      -- at the end or later (as box_enter_to has it for a box)
      if t == nil and bx < x2 and x2 < bx + record[3] and by < y2 and y2 < by + record[4] then
        t = BELOW_ONE
      end
    else
      t = box_enter_to(x1, y1, width, height, dx, dy, record[1], record[2], record[3],
        record[4], x2, y2)
    end
    if t then
      n = n + 1
      found[n] = record
      record._t = t
    end
  end
  local layers, records, set = world._layers, world._records, world._set
  for k = 1, #layers do
    local tiles = layers[k]
    local t = segment_first(tiles, x1, y1, dx, dy, set, width, height)
    -- the box where the sweep ends overlaps a tile: entered, though the rounded times
    -- (the segment against each tile grown by the box's size) say at the end or later
    if t == nil and touches(tiles, x2, y2, width, height, set) then t = BELOW_ONE end
    if t then
      local record = records[tiles]
      n = n + 1
      found[n] = record
      record._t = t
    end
  end
  for i = n + 1, #found do found[i] = nil end
  sort(found, segment_before)
  return n
end

---What an error a query's filter raised leaves: no results.
---@param world budge.World
function query.abandon(world)
  local found = world._found
  for i = #found, 1, -1 do found[i] = nil end
end

-- LuaJIT shaping: the queries are left to the interpreter (what they call still compiles
-- its own loops). Compiled, table.sort ends each trace and every query's continuation
-- after it, into the game's own code, is compiled again for each path through it: the
-- figures are in move.lua, where the filtered moves are left to the interpreter too.
do
  local jit = rawget(_G, "jit")
  if jit and jit.off then
    jit.off(query.area)
    jit.off(query.sweep)
    jit.off(query.finish)
  end
end

return query
