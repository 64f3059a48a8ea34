-- budge.query: the bodies of the world's queries, called with checked arguments.
--
-- Boxes (solids and actors) come from the two spatial hashes, tile layers from their
-- grids; results are sorted into the order items were added (segments: by where the
-- segment enters them, then that order) with table.sort and a total order, never by
-- pairs(). With a caller-given `out` a query allocates nothing once the world is warm.

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")
local layer = require(here .. ".layer")
local solids = require(here .. ".solids")
local actors = require(here .. ".actors")

local sort = table.sort
local segment_enter = sweep.segment_enter
local segment_first, touches = layer.segment_first, layer.touches

local query = {}

local function record_before(a, b) return a.id < b.id end

local function segment_before(a, b)
  local ta, tb = a._t, b._t
  if ta ~= tb then return ta < tb end
  return a.id < b.id
end

-- Records of boxes (solids and actors) that touch the rectangle, into world._found.
local function collect_boxes(world, x, y, width, height)
  actors.rehash(world)
  local found = world._found
  local n = 0
  local cx, cy, cx1, cy1 = solids.clip_to_boxes(world, x, y, x + width, y + height)
  if world._solid_count > 0 and cx <= cx1 and cy <= cy1 then
    n = world._solids:collect(cx, cy, cx1 - cx, cy1 - cy, found, n)
  end
  -- actors can be anywhere: a huge rectangle walks the actor list instead of the cells
  local list = world._actor_list
  if #list > 0 and world._actors:cell_count(x, y, width, height) <= 4 * #list then
    n = world._actors:collect(x, y, width, height, found, n)
  else
    for i = 1, #list do n = n + 1; found[n] = list[i] end
  end
  return n
end

-- The items of found[1..n] into out[1..n]; clears found and the rest of out.
local function finish(found, n, out)
  local old = #out
  for i = 1, n do out[i] = found[i].item; found[i] = nil end
  for i = n + 1, old do out[i] = nil end
  return out, n
end

---Every solid, actor and tile layer (once, when any of its solid tiles does) that
---strictly overlaps the rectangle, in the order they were added, into `out`.
---@param world budge.World
---@param x number
---@param y number
---@param width number
---@param height number
---@param out table
---@return table out, integer n
function query.area(world, x, y, width, height, out)
  local found = world._found
  local count = collect_boxes(world, x, y, width, height)
  local n = 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    -- the record's copy of the box: where the world last saw it (checked then)
    local bx, by = record.x, record.y
    if bx < x + width and x < bx + record.width and by < y + height
      and y < by + record.height then
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
  return finish(found, n, out)
end

---Every solid, actor and tile layer the segment from (x1, y1) to (x2, y2) passes
---through (strictly inside), sorted by where it enters them, then by the order they were
---added; out_t[i] is that fraction of the segment. For a tile layer, the first solid
---tile met.
---@param world budge.World
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param out table
---@param out_t number[]
---@return table out, integer n, number[] out_t
function query.segment(world, x1, y1, x2, y2, out, out_t)
  local dx, dy = x2 - x1, y2 - y1
  local left, top = x1 < x2 and x1 or x2, y1 < y2 and y1 or y2
  local width, height = dx < 0 and -dx or dx, dy < 0 and -dy or dy
  local found = world._found
  local count = collect_boxes(world, left, top, width, height)
  local n = 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    local t = segment_enter(x1, y1, dx, dy, record.x, record.y, record.width, record.height)
    if t then
      n = n + 1
      found[n] = record
      record._t = t
    end
  end
  local layers, records, set = world._layers, world._records, world._set
  for k = 1, #layers do
    local tiles = layers[k]
    local t = segment_first(tiles, x1, y1, dx, dy, set)
    if t then
      local record = records[tiles]
      n = n + 1
      found[n] = record
      record._t = t
    end
  end
  for i = n + 1, #found do found[i] = nil end
  sort(found, segment_before)
  local old = #out_t
  for i = 1, n do out_t[i] = found[i]._t end
  for i = n + 1, old do out_t[i] = nil end
  local result, total = finish(found, n, out)
  return result, total, out_t
end

return query
