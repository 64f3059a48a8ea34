-- budge.solids: what actors stop against. Solid boxes live in the world's spatial hash,
-- each record holding a copy of its box (read in the hot loops; solids change only
-- through world:update and world:move_solid, which refresh it); tile layers live in a
-- list, in the order they were added. Two sets of bounds let long moves skip empty
-- space: the bounds of everything solid ever added, and those of the hashed boxes alone.
--
-- Gathering fills the world's candidate set (sweep.lua's budge.CandidateSet) with what
-- a rectangle may meet, skipping what the actor's filter refuses.

local here = (...):match("^(.*)%.[^%.]+$")
local layer = require(here .. ".layer")
local sweep = require(here .. ".sweep")

local clip_axis = sweep.clip_axis
local gather_layer = layer.gather

local solids = {}

---A rectangle that only grows: the bounds of what was ever added to it.
---@class budge.Bounds
---@field min_x number
---@field min_y number
---@field max_x number
---@field max_y number

---Empty bounds (min above max).
---@return budge.Bounds
function solids.new_bounds()
  return {min_x = math.huge, min_y = math.huge, max_x = -math.huge, max_y = -math.huge}
end

local function grow(bounds, x, y, x1, y1)
  if x < bounds.min_x then bounds.min_x = x end
  if y < bounds.min_y then bounds.min_y = y end
  if x1 > bounds.max_x then bounds.max_x = x1 end
  if y1 > bounds.max_y then bounds.max_y = y1 end
end

---Puts a solid's record into the hash with a fresh copy of its box and grows the bounds.
---(The world counts its solids; this only hashes them.)
---@param world budge.World
---@param record budge.Record
function solids.hash(world, record)
  local item = record.item
  local x, y, width, height = item.x, item.y, item.width, item.height
  record.oneway = item.wall_type == "oneway"
  record.x, record.y, record.width, record.height = x, y, width, height
  world._solids:insert(record, x, y, width, height)
  record._in_hash = true
  local x1, y1 = x + width, y + height
  grow(world._bounds, x, y, x1, y1)
  grow(world._box_bounds, x, y, x1, y1)
end

---Takes a solid's record out of the hash, if it is there.
---@param world budge.World
---@param record budge.Record
function solids.unhash(world, record)
  if record._in_hash then
    world._solids:remove(record)
    record._in_hash = false
  end
end

---Appends a tile layer to the world's list and grows the bounds.
---@param world budge.World
---@param tiles budge.TileLayer
function solids.add_layer(world, tiles)
  local layers = world._layers
  layers[#layers + 1] = tiles
  solids.grow_layer(world, tiles)
end

---Grows the bounds of everything solid to hold the layer where it is now.
---@param world budge.World
---@param tiles budge.TileLayer
function solids.grow_layer(world, tiles)
  grow(world._bounds, tiles.x, tiles.y, tiles.x + tiles.cols * tiles.tile_width,
    tiles.y + tiles.rows * tiles.tile_height)
end

---Takes a tile layer out of the world's list, keeping the others' order.
---@param world budge.World
---@param tiles budge.TileLayer
function solids.remove_layer(world, tiles)
  local layers = world._layers
  for i = 1, #layers do
    if layers[i] == tiles then table.remove(layers, i) break end
  end
end

---The rectangle (x, y)-(x1, y1) clipped to the bounds of the hashed solid boxes; empty
---(x > x1 or y > y1) when no box can be in it.
---@param world budge.World
---@param x number
---@param y number
---@param x1 number
---@param y1 number
---@return number x, number y, number x1, number y1
function solids.clip_to_boxes(world, x, y, x1, y1)
  local bounds = world._box_bounds
  if x < bounds.min_x then x = bounds.min_x end
  if y < bounds.min_y then y = bounds.min_y end
  if x1 > bounds.max_x then x1 = bounds.max_x end
  if y1 > bounds.max_y then y1 = bounds.max_y end
  return x, y, x1, y1
end
local clip_to_boxes = solids.clip_to_boxes

---The part [enter, leave] of a move (as fractions of it) during which the moving box can
---meet anything solid: its sweep clipped to the bounds of all solids; nil when never.
---@param world budge.World
---@param x number
---@param y number
---@param width number
---@param height number
---@param dx number
---@param dy number
---@return number? enter, number? leave
function solids.clip_to_bounds(world, x, y, width, height, dx, dy)
  local bounds = world._bounds
  if bounds.min_x > bounds.max_x then return nil, nil end -- nothing solid was ever added
  local enter, leave = clip_axis(x, dx, bounds.min_x - width, bounds.max_x, 0, 1, false)
  if enter == nil then return nil, nil end
  enter, leave = clip_axis(y, dy, bounds.min_y - height, bounds.max_y, enter, leave, false)
  if enter == nil or enter > leave then return nil, nil end
  return enter, leave
end

---Fills the world's candidate set with the hashed solid boxes that touch the rectangle,
---skipping those the moving actor's filter refuses, and then with the tiles of every
---layer the filter accepts. The actor and its filter are the world's probe's (set by the
---move). Returns the set.
---@param world budge.World
---@param x number
---@param y number
---@param width number
---@param height number
---@return budge.CandidateSet
function solids.gather(world, x, y, width, height)
  local probe = world._probe
  local actor, filter = probe.actor, probe.filter
  local set = world._set
  local n = 0
  local bx, by, bx1, by1 = clip_to_boxes(world, x, y, x + width, y + height)
  if bx <= bx1 and by <= by1 and world._solid_count > 0 then
    local found = world._found
    local count = world._solids:collect(bx, by, bx1 - bx, by1 - by, found, 0)
    local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
    local cols, rows, ids = set.col, set.row, set.id
    for i = 1, count do
      local record = found[i]
      found[i] = nil
      local solid = record.item
      if not record.removed and (filter == nil or filter(actor, solid)) then
        n = n + 1
        xs[n], ys[n], ws[n], hs[n] = record.x, record.y, record.width, record.height
        oneway[n], other[n], cols[n], rows[n], ids[n] = record.oneway, solid, nil, nil, record.id
      end
    end
  end
  set.n = n
  local layers, records = world._layers, world._records
  for k = 1, #layers do
    local tiles = layers[k]
    local record = records[tiles] -- (read before the filter, which may remove the layer)
    if record and (filter == nil or filter(actor, tiles)) then
      gather_layer(tiles, x, y, width, height, set, record.id)
    end
  end
  return set
end

return solids
