-- budge.world: solids, actors and tile layers, moved and queried.
--
-- Solids never move by themselves and never collide; actors move with world:move and
-- collide with solids and solid tiles only (not with each other). Solids live in a
-- spatial hash; tile layers are read by index; actors live in a second hash. A move
-- only notes that its actor moved; the next query or moving solid brings the noted
-- actors' cells up to date, so a frame of moves pays nothing for the hash.
--
-- A move allocates nothing once the world is warm: candidates go into a reused struct
-- of arrays, contacts into reused records, and nothing iterates with pairs().
-- A filter callback must not move, add to or query the world it is called from.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local resolve = require(here .. ".resolve")
local fatcross = require(here .. ".fatcross")
local sweep = require(here .. ".sweep")
local grid = require(here .. ".grid")

local check_box, check_wall_type, check_number = box.check_box, box.check_wall_type,
  box.check_number
local describe, is_finite, overlaps = box.describe, box.is_finite, box.overlaps
local before, first_contact = sweep.before, sweep.first_contact
local tile_face, gather_tiles, next_stamp = grid.tile_face, grid.gather_tiles, grid.next_stamp
local RULES, oneway_rule, resolve_pair = resolve.RULES, resolve.oneway, fatcross.resolve_pair
local NORMAL_X, NORMAL_Y = sweep.NORMAL_X, sweep.NORMAL_Y
local ceil, HUGE = math.ceil, math.huge
local format, error, type, sort = string.format, error, type, table.sort

local SOLID, ACTOR, TILES = "solid", "actor", "tiles"
-- A "swept" move that meets a face slides along it; three rounds cover a face, then a
-- second face that stops the slide, then a corner.
local MAX_SLIDES = 3

local world = {}

---@class budge.Hit
---@field other table the solid box, or the tile layer handle
---@field side "floor"|"ceiling"|"left"|"right" which side of the actor touched
---@field col? integer the tile's column, for a tile layer
---@field row? integer the tile's row, for a tile layer

---@class budge.World
---@field cell_size number
local World = {}
World.__index = World

local METHOD_LIST = '"axis_sweep", "swept", "auto", "seed", "wall_type", "min_axis" or '
  .. '"fat_cross"'

---Creates an empty world.
---@param opts? {cell_size?: number} cell_size: side of a spatial hash cell (default 64)
---@return budge.World
---True when `value` is a world made by budge.new_world.
function world.is_world(value)
  return getmetatable(value) == World
end

function world.new_world(opts)
  if opts ~= nil and type(opts) ~= "table" then
    error(format("opts must be a table or nil, got %s", describe(opts)), 2)
  end
  local cell_size = opts and opts.cell_size
  if cell_size == nil then
    cell_size = 64
  elseif not is_finite(cell_size) or cell_size <= 0 then
    error(format("opts.cell_size must be a finite number > 0, got %s", describe(cell_size)), 2)
  end
  return setmetatable({
    cell_size = cell_size,
    _solids = grid.new_hash(cell_size),
    _actors = grid.new_hash(cell_size),
    _actor_list = {},
    _layers = {},
    _records = {},
    _next_id = 0,
    _solid_count = 0,
    _hits = {}, _n_hits = 0,
    _set = sweep.new_set(),
    _found = {},
    _order = {},
    _near = {}, _crushed = {}, _n_crushed = 0, _crush_stamp = 0,
    _dirty = {}, _n_dirty = 0,
    _scratch = {x = 0, y = 0, width = 0, height = 0},
    _tall = {x = 0, y = 0, width = 0, height = 0, wall_type = "horizontal"},
    _wide = {x = 0, y = 0, width = 0, height = 0, wall_type = "vertical"},
    -- bounds of everything solid ever added: long moves only look inside them
    _min_x = HUGE, _min_y = HUGE, _max_x = -HUGE, _max_y = -HUGE,
    -- and of the hashed solid boxes alone: a move outside them skips the hash
    _box_min_x = HUGE, _box_min_y = HUGE, _box_max_x = -HUGE, _box_max_y = -HUGE,
  }, World)
end

local function grow_bounds(self, x, y, width, height)
  if x < self._min_x then self._min_x = x end
  if y < self._min_y then self._min_y = y end
  if x + width > self._max_x then self._max_x = x + width end
  if y + height > self._max_y then self._max_y = y + height end
end

local function new_record(self, item, kind)
  local id = self._next_id + 1
  self._next_id = id
  local record = {item = item, kind = kind, id = id, oneway = false, _stamp = 0}
  self._records[item] = record
  return record
end

local function refuse_duplicate(self, item, name)
  local record = self._records[item]
  if record then
    error(format("%s is already in this world (as %s)", name,
      record.kind == ACTOR and "an actor" or (record.kind == SOLID and "a solid" or "tiles")), 3)
  end
end

-- A solid's record keeps a copy of its box, read in the hot loops (solids move only
-- through world:update, which refreshes it).
local function hash_solid(self, record)
  local item = record.item
  record.oneway = item.wall_type == "oneway"
  record.x, record.y, record.width, record.height = item.x, item.y, item.width, item.height
  self._solids:insert(record, item.x, item.y, item.width, item.height)
  grow_bounds(self, item.x, item.y, item.width, item.height)
  local x, y, x1, y1 = item.x, item.y, item.x + item.width, item.y + item.height
  if x < self._box_min_x then self._box_min_x = x end
  if y < self._box_min_y then self._box_min_y = y end
  if x1 > self._box_max_x then self._box_max_x = x1 end
  if y1 > self._box_max_y then self._box_max_y = y1 end
end

---Adds a solid box: actors stop against it. `wall_type = "oneway"` makes it block
---only actors coming down onto it from above.
---@param solid budge.Box
---@return budge.Box solid
function World:add_solid(solid)
  check_box(solid, "box", 2)
  check_wall_type(solid, "box", 2)
  refuse_duplicate(self, solid, "box")
  hash_solid(self, new_record(self, solid, SOLID))
  self._solid_count = self._solid_count + 1
  return solid
end

---Adds an actor box: it moves with world:move and stops against solids. An optional
---`actor.filter(actor, other)` returning false lets it pass through `other`.
---@param actor budge.Box
---@return budge.Box actor
function World:add_actor(actor)
  check_box(actor, "box", 2)
  refuse_duplicate(self, actor, "box")
  local record = new_record(self, actor, ACTOR)
  local list = self._actor_list
  list[#list + 1] = record
  record.index = #list
  self._actors:insert(record, actor.x, actor.y, actor.width, actor.height)
  return actor
end

local function check_layer_input(rows, tile_width, tile_height, opts)
  grid.check_rows(rows, 3)
  local checked = grid.check_layer_options(tile_width, tile_height, opts, 3)
  return checked -- not a tail call: the error level counts this function's frame
end

---Adds a tile layer: `grid[row][col]` is a tile id; any id but nil, false and 0 (or,
---when given, one for which `opts.is_solid(id)` is true) is solid, and one for which
---`opts.is_oneway(id)` is true is a oneway platform. Tile (col, row) covers
---x + (col-1)*tile_width onward. The grid is read now; call world:update(handle) after
---changing it. 0 is empty by default because Tiled and most tile maps use it so.
---@param rows table grid[row][col]
---@param tile_width number
---@param tile_height number
---@param opts? {x?: number, y?: number, is_solid?: fun(id): boolean, is_oneway?: fun(id): boolean}
---@return table handle the layer; world:remove accepts it, hits name it as `other`
function World:add_tiles(rows, tile_width, tile_height, opts)
  opts = check_layer_input(rows, tile_width, tile_height, opts)
  local layer = grid.new_tiles(rows, tile_width, tile_height, opts.x or 0, opts.y or 0,
    opts.is_solid, opts.is_oneway)
  local record = new_record(self, layer, TILES)
  local layers = self._layers
  layers[#layers + 1] = layer
  record.layer = layer
  grow_bounds(self, layer.x, layer.y, layer.cols * tile_width, layer.rows * tile_height)
  return layer
end

local function find_record(self, item, level)
  local record = self._records[item]
  if record == nil then
    error(format("item is not in this world (add it with add_solid, add_actor or add_tiles "
      .. "first), got %s", describe(item)), level + 1)
  end
  return record
end

---Removes a solid, an actor or a tile layer (by its handle).
function World:remove(item)
  local record = find_record(self, item, 2)
  local kind = record.kind
  if kind == SOLID then
    self._solids:remove(record)
    self._solid_count = self._solid_count - 1
  elseif kind == ACTOR then
    self._actors:remove(record)
    local list = self._actor_list
    local last = list[#list]
    list[record.index] = last
    last.index = record.index
    list[#list] = nil
    record.index = nil
  else
    local layers = self._layers
    for i = 1, #layers do
      if layers[i] == item then table.remove(layers, i) break end
    end
  end
  self._records[item] = nil
end

---Tells the world that a box's position, size or wall_type changed outside world:move
---(a teleport), or that a tile layer's grid changed.
function World:update(item)
  local record = find_record(self, item, 2)
  local kind = record.kind
  if kind == SOLID then
    check_box(item, "box", 2)
    check_wall_type(item, "box", 2)
    self._solids:remove(record)
    hash_solid(self, record)
  elseif kind == ACTOR then
    check_box(item, "box", 2)
    self._actors:moved(record, item.x, item.y, item.width, item.height)
  else
    check_layer_input(item.grid, item.tile_width, item.tile_height, nil)
    if #item.grid ~= item.rows or (item.grid[1] and #item.grid[1] or 0) ~= item.cols then
      error(format("grid changed size from %dx%d to %dx%d: remove the layer and add it again",
        item.cols, item.rows, item.grid[1] and #item.grid[1] or 0, #item.grid), 2)
    end
    grid.read_tiles(item)
  end
end

---True when `item` (a box or a tile layer handle) is in this world.
function World:has(item)
  return self._records[item] ~= nil
end

---Counts of the world's items: solids, actors, tile layers.
---@return integer solids, integer actors, integer layers
function World:count()
  return self._solid_count, #self._actor_list, #self._layers
end

-- Contacts --------------------------------------------------------------------------

local function add_hit(self, other, side, col, row, top, left, id)
  local n = self._n_hits + 1
  local hit = self._hits[n]
  if hit == nil then
    hit = {}
    self._hits[n] = hit
  end
  hit.other, hit.side, hit.col, hit.row = other, side, col, row
  hit._top, hit._left, hit._id, hit._round = top, left, id, self._round
  self._n_hits = n
end

-- Contacts of one move come out in the order they happened (x before y), and within one
-- round by position (top, then left) and then by the order items were added.
local function hit_before(a, b)
  if a._round ~= b._round then return a._round < b._round end
  if a._top ~= b._top then return a._top < b._top end
  if a._left ~= b._left then return a._left < b._left end
  return a._id < b._id
end

-- Insertion sort: a move has a handful of contacts, and unlike table.sort this stays
-- inside LuaJIT's compiled code.
local function sort_hits(self)
  local hits = self._hits
  for i = 2, self._n_hits do
    local hit = hits[i]
    local j = i - 1
    while j >= 1 and hit_before(hit, hits[j]) do
      hits[j + 1] = hits[j]
      j = j - 1
    end
    hits[j + 1] = hit
  end
end

-- Candidates -------------------------------------------------------------------------

-- The rectangle (x, y)-(x1, y1) clipped to the bounds of the hashed solid boxes; empty
-- (x > x1 or y > y1) when no box can be in it.
local function clip_to_boxes(self, x, y, x1, y1)
  if x < self._box_min_x then x = self._box_min_x end
  if y < self._box_min_y then y = self._box_min_y end
  if x1 > self._box_max_x then x1 = self._box_max_x end
  if y1 > self._box_max_y then y1 = self._box_max_y end
  return x, y, x1, y1
end

-- Fills the candidate set with the solid boxes of the spatial hash that touch the
-- rectangle, skipping those the actor's filter refuses. Clipped to the solids' bounds.
local function gather_boxes(self, actor, filter, x, y, width, height)
  local set = self._set
  set.n = 0
  local x1, y1
  x, y, x1, y1 = clip_to_boxes(self, x, y, x + width, y + height)
  if x1 < x or y1 < y or self._solid_count == 0 then return set end
  local found = self._found
  local count = self._solids:collect(x, y, x1 - x, y1 - y, next_stamp(), found, 0)
  local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
  local cols, rows, ids = set.col, set.row, set.id
  local n = 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    local solid = record.item
    if filter == nil or filter(actor, solid) then
      n = n + 1
      xs[n], ys[n], ws[n], hs[n] = solid.x, solid.y, solid.width, solid.height
      oneway[n], other[n], cols[n], rows[n], ids[n] = record.oneway, solid, nil, nil, record.id
    end
  end
  set.n = n
  return set
end

-- Adds the tiles of every layer (that the filter accepts) touching the rectangle.
local function gather_all_tiles(self, actor, filter, x, y, width, height)
  local layers = self._layers
  local set = self._set
  for k = 1, #layers do
    local layer = layers[k]
    if filter == nil or filter(actor, layer) then
      gather_tiles(layer, x, y, width, height, set, self._records[layer].id)
    end
  end
  return set
end

-- axis_sweep -------------------------------------------------------------------------

-- (Indexed only by a boolean local: Lua 5.4.4 miscompiles T[a > b] when T is an upvalue.)
local SIDES_X = {[true] = "right", [false] = "left"}
local SIDES_Y = {[true] = "floor", [false] = "ceiling"}

local probe = grid.probe

-- The hash part of an axis phase: the swept rectangle, clipped to the bounds of the
-- hashed solids, scanned with the probe.
local function hash_phase(self, is_x, pos, cross, size, cross_size, delta)
  local reach = delta < 0 and -delta or delta
  local x, y, x1, y1
  if is_x then
    x = delta > 0 and pos or pos + delta
    x1, y, y1 = x + size + reach, cross, cross + cross_size
  else
    y = delta > 0 and pos or pos + delta
    y1, x, x1 = y + size + reach, cross, cross + cross_size
  end
  x, y, x1, y1 = clip_to_boxes(self, x, y, x1, y1)
  if x <= x1 and y <= y1 then
    local cx0, cy0, cx1, cy1 = self._solids:cells_of(x, y, x1 - x, y1 - y)
    self._solids:axis_stop(cx0, cy0, cx1, cy1, next_stamp(), probe)
  end
end

-- Moves along one axis up to the nearest stop among tiles and boxes; returns the new
-- position on that axis and records the contacts that stop it there.
local function axis_phase(self, actor, filter, is_x, pos, cross, size, cross_size, delta)
  local forward = delta > 0
  probe.is_x, probe.forward, probe.delta = is_x, forward, delta
  probe.pos, probe.size, probe.edge = pos, size, pos + size
  probe.reach = forward and pos + size + delta or pos + delta
  probe.cross, probe.cross_end = cross, cross + cross_size
  probe.blocks_oneway = not is_x and forward
  probe.actor, probe.filter = actor, filter
  local side = is_x and SIDES_X[forward] or SIDES_Y[forward]
  local first_hit = self._n_hits
  local best
  local layers = self._layers
  for k = 1, #layers do
    local layer = layers[k]
    if filter == nil or filter(actor, layer) then
      local face, count = tile_face(layer, probe)
      local stop = face
      if face then
        if forward then stop = face >= pos + size and before(face, size) or pos
        elseif face > pos then stop = pos end
      end -- the same outcomes as sweep.stop_forward / stop_backward give
      if stop and (best == nil or (forward and stop <= best) or (not forward and stop >= best)) then
        if stop ~= best then best = stop; self._n_hits = first_hit end
        local id = self._records[layer].id
        local cols, rows = probe.cols, probe.rows
        for c = 1, count do
          local col, row = cols[c], rows[c]
          add_hit(self, layer, side, col, row, layer.y + (row - 1) * layer.tile_height,
            layer.x + (col - 1) * layer.tile_width, id)
        end
      end
    end
  end
  if self._solid_count > 0 then
    probe.best, probe.touched = nil, 0
    hash_phase(self, is_x, pos, cross, size, cross_size, delta)
    local stop = probe.best
    if stop and (best == nil or (forward and stop <= best) or (not forward and stop >= best)) then
      if stop ~= best then best = stop; self._n_hits = first_hit end
      local touch = probe.touch
      for t = 1, probe.touched do
        local record = touch[t]
        local item = record.item
        add_hit(self, item, side, nil, nil, item.y, item.x, record.id)
      end
    end
  end
  probe.actor, probe.filter = nil, nil
  if best == nil then return pos + delta end
  return best
end

local function move_axis_sweep(self, actor, dx, dy, filter)
  local x, y, width, height = actor.x, actor.y, actor.width, actor.height
  if dx ~= 0 then
    self._round = 1
    x = axis_phase(self, actor, filter, true, x, y, width, height, dx)
  end
  if dy ~= 0 then
    self._round = 2
    y = axis_phase(self, actor, filter, false, y, x, height, width, dy)
  end
  actor.x, actor.y = x, y
end

-- swept ------------------------------------------------------------------------------

-- The part [enter, leave] of the move (as fractions of it) during which the moving box
-- can meet anything solid: its sweep clipped to the bounds of all solids.
local function clip_to_bounds(self, x, y, width, height, dx, dy)
  local enter, leave = 0, 1
  local lo_x, hi_x = self._min_x - width, self._max_x
  local lo_y, hi_y = self._min_y - height, self._max_y
  if dx == 0 then
    if x < lo_x or x > hi_x then return nil end
  else
    local t0, t1 = (lo_x - x) / dx, (hi_x - x) / dx
    if t0 > t1 then t0, t1 = t1, t0 end
    if t0 > enter then enter = t0 end
    if t1 < leave then leave = t1 end
  end
  if dy == 0 then
    if y < lo_y or y > hi_y then return nil end
  else
    local t0, t1 = (lo_y - y) / dy, (hi_y - y) / dy
    if t0 > t1 then t0, t1 = t1, t0 end
    if t0 > enter then enter = t0 end
    if t1 < leave then leave = t1 end
  end
  if enter > leave then return nil end
  return enter, leave
end

-- Travels from (x, y) along (dx, dy) in chunks no longer than a cell, so a huge move
-- looks at a thin band of the world, until the first contact. Returns the position
-- reached and, on a contact, whether x and y are blocked and the fraction travelled.
local function advance(self, actor, filter, x, y, width, height, dx, dy, round)
  local enter, leave = clip_to_bounds(self, x, y, width, height, dx, dy)
  if enter == nil then return x + dx, y + dy, nil end
  local adx, ady = dx < 0 and -dx or dx, dy < 0 and -dy or dy
  local length = (adx > ady and adx or ady) * (leave - enter)
  local chunks = ceil(length / self.cell_size)
  if chunks < 1 then chunks = 1 end
  local span = leave - enter
  for k = 1, chunks do
    local t_from = enter + span * (k - 1) / chunks
    local t_to = k == chunks and leave or enter + span * k / chunks
    local from_x, from_y = x + dx * t_from, y + dy * t_from
    local step_x, step_y = dx * (t_to - t_from), dy * (t_to - t_from)
    local left = step_x < 0 and from_x + step_x or from_x
    local top = step_y < 0 and from_y + step_y or from_y
    local reach_x, reach_y = step_x < 0 and -step_x or step_x, step_y < 0 and -step_y or step_y
    local set = gather_boxes(self, actor, filter, left, top, width + reach_x, height + reach_y)
    gather_all_tiles(self, actor, filter, left, top, width + reach_x, height + reach_y)
    local t = first_contact(set, x, y, from_x, from_y, width, height, step_x, step_y)
    if t then
      local touch, normal = set.touch, set.normal
      local blocked_x, blocked_y = false, false
      for c = 1, set.touch_n do
        local kind = normal[c]
        if kind == NORMAL_X then blocked_x = true elseif kind == NORMAL_Y then blocked_y = true end
      end
      -- Only corners met (a box aimed exactly at a corner): the tie rule, vertical wins.
      -- A corner met beside a real face (the next tile at a seam) blocks nothing.
      local corners_block = not blocked_x and not blocked_y
      if corners_block then blocked_y = true end
      local new_x, new_y = from_x + step_x * t, from_y + step_y * t
      local xs, ys, ws, hs, other, cols, rows, ids = set.x, set.y, set.w, set.h, set.other,
        set.col, set.row, set.id
      for c = 1, set.touch_n do
        local i, kind = touch[c], normal[c]
        -- a solid the actor started inside stops it where it is (t is 0): no snapping
        local outside = not (xs[i] < x + width and x < xs[i] + ws[i] and ys[i] < y + height
          and y < ys[i] + hs[i])
        if kind == NORMAL_X then
          self._round = round
          if not outside then new_x = from_x
          elseif step_x > 0 then new_x = before(xs[i], width) else new_x = xs[i] + ws[i] end
          add_hit(self, other[i], step_x > 0 and "right" or "left", cols[i], rows[i], ys[i], xs[i], ids[i])
        elseif kind == NORMAL_Y or corners_block then
          self._round = round + 1
          if not outside then new_y = from_y
          elseif step_y > 0 then new_y = before(ys[i], height) else new_y = ys[i] + hs[i] end
          add_hit(self, other[i], step_y > 0 and "floor" or "ceiling", cols[i], rows[i], ys[i], xs[i], ids[i])
        end
      end
      return new_x, new_y, blocked_x, blocked_y, t_from + (t_to - t_from) * t
    end
  end
  return x + dx, y + dy, nil
end

local function move_swept(self, actor, dx, dy, filter)
  local x, y, width, height = actor.x, actor.y, actor.width, actor.height
  for slide = 1, MAX_SLIDES do
    if dx == 0 and dy == 0 then break end
    local blocked_x, blocked_y, travelled
    x, y, blocked_x, blocked_y, travelled = advance(self, actor, filter, x, y, width, height,
      dx, dy, slide * 2 - 1)
    if blocked_x == nil then break end
    -- slide: what is left of the move, less the blocked component
    local rest = 1 - travelled
    dx = blocked_x and 0 or dx * rest
    dy = blocked_y and 0 or dy * rest
  end
  actor.x, actor.y = x, y
end

-- discrete methods ------------------------------------------------------------------

local order_set -- the set table.sort's comparator reads
local function candidate_before(i, j)
  local ys, xs = order_set.y, order_set.x
  if ys[i] ~= ys[j] then return ys[i] < ys[j] end
  if xs[i] ~= xs[j] then return xs[i] < xs[j] end
  return order_set.id[i] < order_set.id[j]
end

-- Moves the whole way, then pushes the actor out of each solid it overlaps, top row
-- first and left to right, with one of the core's one-box rules.
local function move_discrete(self, actor, dx, dy, filter, method)
  local prev_y = actor.y
  local x, y, width, height = actor.x + dx, actor.y + dy, actor.width, actor.height
  actor.x, actor.y = x, y
  local set = gather_boxes(self, actor, filter, x, y, width, height)
  gather_all_tiles(self, actor, filter, x, y, width, height)
  local n = set.n
  if n == 0 then return end
  local order = self._order
  for i = 1, n do order[i] = i end
  for i = n + 1, #order do order[i] = nil end
  order_set = set
  sort(order, candidate_before)
  order_set = nil
  local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
  local cols, rows, ids = set.col, set.row, set.id
  local scratch, tall, wide = self._scratch, self._tall, self._wide
  local rule = RULES[method]
  local speed = dx < 0 and -dx or dx
  if dy > speed then speed = dy elseif -dy > speed then speed = -dy end
  self._round = 1
  for k = 1, n do
    local i = order[k]
    local target = other[i]
    if cols[i] ~= nil then -- a tile: a scratch box stands for it
      target = scratch
      scratch.x, scratch.y, scratch.width, scratch.height = xs[i], ys[i], ws[i], hs[i]
      scratch.wall_type = oneway[i] and "oneway" or nil
    end
    if overlaps(actor, target) then
      local push_x, push_y
      if oneway[i] then
        push_x, push_y = oneway_rule(actor, target, prev_y)
      elseif method == "fat_cross" then
        -- each solid's cross is sized for this move's speed, capped so both hitboxes
        -- keep a quarter of the block's smaller side
        local smaller = ws[i] < hs[i] and ws[i] or hs[i]
        local inset = speed < smaller * 0.375 and speed or smaller * 0.375
        tall.x, tall.y, tall.width, tall.height = xs[i] + inset, ys[i], ws[i] - 2 * inset, hs[i]
        wide.x, wide.y, wide.width, wide.height = xs[i], ys[i] + inset, ws[i], hs[i] - 2 * inset
        push_x, push_y = resolve_pair(actor, tall, wide)
      else
        push_x, push_y = rule(actor, target)
      end
      local side
      if push_y < 0 then side = "floor" elseif push_y > 0 then side = "ceiling"
      elseif push_x < 0 then side = "right" elseif push_x > 0 then side = "left" end
      if side then add_hit(self, other[i], side, cols[i], rows[i], ys[i], xs[i], ids[i]) end
    end
  end
end

local MOVES = {
  axis_sweep = move_axis_sweep,
  swept = move_swept,
  seed = move_discrete, wall_type = move_discrete, min_axis = move_discrete,
  fat_cross = move_discrete,
  -- "auto" is the cheapest method that is safe for the move. Inside a world that is
  -- always axis_sweep: `make bench` measures it cheaper than every discrete method on the
  -- world bench scene (LuaJIT 368 ns per move against 670-737; Lua 5.4 1687 against
  -- 1745-1839) as well as right in every catalogue case, so no per-move choice can beat it.
  auto = move_axis_sweep,
}

---Moves `actor` by (dx, dy) against the world's solids and tiles, writes its new
---position into it and returns it, with the contacts of this move.
---@param actor budge.Box an actor of this world
---@param dx number
---@param dy number
---@param method? "axis_sweep"|"swept"|"auto"|"seed"|"wall_type"|"min_axis"|"fat_cross"
---@return number x, number y, integer n, budge.Hit[] hits owned by the world, valid until the next move
function World:move(actor, dx, dy, method)
  local record = self._records[actor]
  if record == nil or record.kind ~= ACTOR then
    if record then
      error(format("actor must be an actor of this world, got %s (use world:update to move "
        .. "it)", record.kind == SOLID and "a solid" or "a tile layer"), 2)
    end
    error(format("actor must be an actor of this world (add it with world:add_actor), got %s",
      describe(actor)), 2)
  end
  check_box(actor, "actor", 2)
  check_number(dx, "dx", 2)
  check_number(dy, "dy", 2)
  local move = MOVES[method or "axis_sweep"]
  if move == nil then
    error(format("method must be %s, got %s", METHOD_LIST, describe(method)), 2)
  end
  local filter = actor.filter
  if filter ~= nil and type(filter) ~= "function" then
    error(format("actor.filter must be a function or nil, got %s", describe(filter)), 2)
  end
  self._n_hits = 0
  move(self, actor, dx, dy, filter, method)
  if not record.dirty then
    record.dirty = true
    local n = self._n_dirty + 1
    self._dirty[n] = record
    self._n_dirty = n
  end
  sort_hits(self)
  return actor.x, actor.y, self._n_hits, self._hits
end

-- Moving solids ----------------------------------------------------------------------
--
-- The actors-and-solids rule of the Celeste and TowerFall games, done with exact faces:
-- a solid moves along x, then along y, and is never blocked. On each axis, an actor in
-- the band the solid sweeps is pushed ahead of it, to exactly its new face; an actor
-- that was riding it (standing on its top when the move began) and is not pushed is
-- carried by the same distance. Pushed and carried actors move like any actor (the
-- moving solid aside), so they stop against other solids; a pushed actor that cannot get
-- out of the way is crushed. Actors are handled in the world's actor order.

-- Moves `actor` along one axis to `target` against everything but the moving solid
-- (already out of the hash); lands exactly on `target` when nothing is in the way.
-- Returns true when it got there.
local function shove(self, record, is_x, target)
  local actor = record.item
  local filter = actor.filter
  if filter ~= nil and type(filter) ~= "function" then filter = nil end
  self._n_hits = 0
  local x, y, width, height = actor.x, actor.y, actor.width, actor.height
  local arrived
  if is_x then
    if target ~= x then
      x = axis_phase(self, actor, filter, true, x, y, width, height, target - x)
      if self._n_hits == 0 then x = target end
    end
    arrived = x == target
  else
    if target ~= y then
      y = axis_phase(self, actor, filter, false, y, x, height, width, target - y)
      if self._n_hits == 0 then y = target end
    end
    arrived = y == target
  end
  actor.x, actor.y = x, y
  self._actors:moved(record, x, y, width, height)
  return arrived
end

local function crush(self, record)
  if record.crush_stamp == self._crush_stamp then return end
  record.crush_stamp = self._crush_stamp
  local n = self._n_crushed + 1
  self._crushed[n] = record.item
  self._n_crushed = n
end

-- Brings the cells of the actors moved since the last call up to date.
local function rehash_moved(self)
  local dirty, actors = self._dirty, self._actors
  for i = 1, self._n_dirty do
    local record = dirty[i]
    dirty[i] = nil
    record.dirty = false
    if record.index then -- still in the world
      local item = record.item
      actors:moved(record, item.x, item.y, item.width, item.height)
    end
  end
  self._n_dirty = 0
end

-- The actor records whose boxes touch the rectangle (edges included), in the world's
-- actor order, into self._near; returns their count. A straight pass over the actor
-- list: one small loop that LuaJIT compiles once, cheaper here than keeping the actor
-- hash current on every move (100 solids x 1000 actors is 100000 box tests a frame).
local function near_actors(self, x, y, width, height)
  local near, list = self._near, self._actor_list
  local x1, y1 = x + width, y + height
  local n = 0
  for i = 1, #list do
    local record = list[i]
    local actor = record.item
    local ax, ay = actor.x, actor.y
    if ax <= x1 and x <= ax + actor.width and ay <= y1 and y <= ay + actor.height then
      n = n + 1
      near[n] = record
    end
  end
  for i = n + 1, #near do near[i] = nil end
  return n
end

-- One axis of a solid's move: push what is in its sweep, carry its riders.
local function solid_phase(self, solid, oneway, is_x, delta, ride_stamp)
  local x, y, width, height = solid.x, solid.y, solid.width, solid.height
  local reach = delta < 0 and -delta or delta
  local near = self._near
  local count
  if is_x then
    count = near_actors(self, delta < 0 and x + delta or x, y - 1, width + reach, height + 1)
    solid.x = x + delta
  else
    count = near_actors(self, x, delta < 0 and y + delta - 1 or y - 1, width, height + reach + 1)
    solid.y = y + delta
  end
  for k = 1, count do
    local record = near[k]
    local actor = record.item
    local ax, ay, aw, ah = actor.x, actor.y, actor.width, actor.height
    local target
    if is_x then
      -- the band swept along x, for actors overlapping it strictly on y
      if not oneway and ay < y + height and y < ay + ah then
        if delta > 0 and ax + aw > x and ax < x + width + delta then
          target = x + width + delta
        elseif delta < 0 and ax < x + width and ax + aw > x + delta then
          target = before(x + delta, aw)
        end
      end
      if target then
        if not shove(self, record, true, target) then crush(self, record) end
      elseif record.ride_stamp == ride_stamp then
        shove(self, record, true, ax + delta)
      end
    else
      if ax < x + width and x < ax + aw then
        if delta < 0 and ay < y + height and ay + ah > y + delta
          and (not oneway or ay + ah <= y) then
          target = before(y + delta, ah)
        elseif delta > 0 and not oneway and ay + ah > y + height and ay < y + height + delta then
          target = y + height + delta
        end
      end
      if target then
        if not shove(self, record, false, target) then crush(self, record) end
      elseif record.ride_stamp == ride_stamp then
        -- carried down (or along, if pushed no further): rest exactly on the new top
        shove(self, record, false, before(y + delta, ah))
      end
    end
  end
end

-- On LuaJIT, the loop over the actors near a moving solid is left to the interpreter:
-- compiled, it inlines a whole actor move per actor (tiles, hash, pushes, crushes) and
-- spawns more side traces than LuaJIT keeps (1000), which flushes every trace in the
-- program again and again (measured: 5000 traces and 12 flushes in 300 frames of
-- bench/platforms.lua). The moves it calls still run their own compiled loops.
local jit = rawget(_G, "jit")
if jit and jit.off then jit.off(solid_phase) end

---Moves a solid by (dx, dy), never blocked: it pushes actors in its way by exactly the
---distance needed, carries the actors riding it (standing on its top when the move
---begins), and crushes an actor that a push cannot move out of its way because another
---solid blocks it. A crushed actor is never moved through a solid; it is reported in
---the returned array (owned by the world, valid until the next move_solid) and, if it
---has one, by `actor.on_crush(actor, solid)`, once per move. A oneway solid carries its
---riders but never pushes from below or from the sides. Contacts of world:move are not
---valid after this call.
---@param solid budge.Box a solid of this world
---@param dx number
---@param dy number
---@return integer n, budge.Box[] crushed
function World:move_solid(solid, dx, dy)
  local record = self._records[solid]
  if record == nil or record.kind ~= SOLID then
    error(format("solid must be a solid of this world (add it with world:add_solid), got %s",
      record and ("an " .. record.kind) or describe(solid)), 2)
  end
  check_box(solid, "solid", 2)
  check_number(dx, "dx", 2)
  check_number(dy, "dy", 2)
  local stamp = self._crush_stamp + 1
  self._crush_stamp = stamp
  self._n_crushed = 0
  -- riders are decided once, where the solid stands before it moves
  local top, left, right = solid.y, solid.x, solid.x + solid.width
  local near = self._near
  for k = 1, near_actors(self, left, top - 1, solid.width, 1) do
    local actor = near[k].item
    if actor.x < right and left < actor.x + actor.width and actor.y == before(top, actor.height) then
      near[k].ride_stamp = stamp
    end
  end
  self._solids:remove(record)
  self._solid_count = self._solid_count - 1 -- out of every actor's way while it moves
  local oneway = record.oneway
  if dx ~= 0 then solid_phase(self, solid, oneway, true, dx, stamp) end
  if dy ~= 0 then solid_phase(self, solid, oneway, false, dy, stamp) end
  self._solid_count = self._solid_count + 1
  hash_solid(self, record)
  self._n_hits = 0
  local crushed, n = self._crushed, self._n_crushed
  for i = n + 1, #crushed do crushed[i] = nil end
  for i = 1, n do
    local on_crush = crushed[i].on_crush
    if type(on_crush) == "function" then on_crush(crushed[i], solid) end
  end
  return n, crushed
end

-- Queries ----------------------------------------------------------------------------

local function record_before(a, b) return a.id < b.id end

-- Records of boxes (solids and actors) that touch the rectangle, into self._found.
local function collect_boxes(self, x, y, width, height)
  rehash_moved(self)
  local found, stamp = self._found, next_stamp()
  local n = 0
  local cx, cy, cx1, cy1 = clip_to_boxes(self, x, y, x + width, y + height)
  if self._solid_count > 0 and cx <= cx1 and cy <= cy1 then
    n = self._solids:collect(cx, cy, cx1 - cx, cy1 - cy, stamp, found, n)
  end
  -- actors can be anywhere: a huge rectangle walks the actor list instead of the cells
  if #self._actor_list > 0 and self._actors:cell_count(x, y, width, height) <= 4 * #self._actor_list then
    n = self._actors:collect(x, y, width, height, stamp, found, n)
  else
    local list = self._actor_list
    for i = 1, #list do n = n + 1; found[n] = list[i] end
  end
  return n
end

local function finish(found, n, out)
  local old = #out
  for i = 1, n do out[i] = found[i].item; found[i] = nil end
  for i = n + 1, old do out[i] = nil end
  return out, n
end

local function check_out(out, name)
  if out ~= nil and type(out) ~= "table" then
    error(format("%s must be a table or nil, got %s", name, describe(out)), 3)
  end
  return out or {}
end

local function layer_touches_rect(layer, x, y, width, height)
  local col0, col1 = grid.span(layer.x, layer.tile_width, layer.inverse_width, layer.cols, x, x + width)
  local row0, row1 = grid.span(layer.y, layer.tile_height, layer.inverse_height, layer.rows, y, y + height)
  local kinds, cols = layer.kinds, layer.cols
  for row = row0, row1 do
    for col = col0, col1 do
      if kinds[row * cols + col + 1] ~= 0 then return true end
    end
  end
  return false
end

local function query_area(self, x, y, width, height, out)
  local found = self._found
  local count = collect_boxes(self, x, y, width, height)
  local n = 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    local item = record.item
    if item.x < x + width and x < item.x + item.width and item.y < y + height
      and y < item.y + item.height then
      n = n + 1
      found[n] = record
    end
  end
  local layers = self._layers
  for k = 1, #layers do
    if layer_touches_rect(layers[k], x, y, width, height) then
      n = n + 1
      found[n] = self._records[layers[k]]
    end
  end
  for i = n + 1, #found do found[i] = nil end
  sort(found, record_before)
  return finish(found, n, out)
end

---Every solid, actor and tile layer (once, when any of its solid tiles does) that
---strictly contains the point, in the order they were added. Points on an edge are
---outside, as touching boxes do not collide.
---@return table out, integer n
function World:query_point(x, y, out)
  check_number(x, "x", 2)
  check_number(y, "y", 2)
  return query_area(self, x, y, 0, 0, check_out(out, "out"))
end

---Every solid, actor and tile layer overlapping the rectangle (strictly), in the order
---they were added.
---@return table out, integer n
function World:query_rect(x, y, width, height, out)
  check_number(x, "x", 2)
  check_number(y, "y", 2)
  if not is_finite(width) or width < 0 then
    error(format("width must be a finite number >= 0, got %s", describe(width)), 2)
  end
  if not is_finite(height) or height < 0 then
    error(format("height must be a finite number >= 0, got %s", describe(height)), 2)
  end
  return query_area(self, x, y, width, height, check_out(out, "out"))
end

-- Fraction of the segment at which it enters the open box, or nil if it never does.
local function segment_enter(x1, y1, dx, dy, bx, by, bw, bh)
  local enter, leave = 0, 1
  if dx == 0 then
    if not (bx < x1 and x1 < bx + bw) then return nil end
  else
    local t0, t1 = (bx - x1) / dx, (bx + bw - x1) / dx
    if t0 > t1 then t0, t1 = t1, t0 end
    if t0 > enter then enter = t0 end
    if t1 < leave then leave = t1 end
  end
  if dy == 0 then
    if not (by < y1 and y1 < by + bh) then return nil end
  else
    local t0, t1 = (by - y1) / dy, (by + bh - y1) / dy
    if t0 > t1 then t0, t1 = t1, t0 end
    if t0 > enter then enter = t0 end
    if t1 < leave then leave = t1 end
  end
  if enter < leave or (enter == leave and dx == 0 and dy == 0) then return enter end
  return nil
end

local function segment_before(a, b)
  local ta, tb = a._t, b._t
  if ta ~= tb then return ta < tb end
  return a.id < b.id
end

---Every solid, actor and tile layer the segment passes through (strictly inside), sorted
---by distance along it (then by the order they were added). `out_t[i]` is the fraction
---of the segment where it enters `out[i]` (0 when it starts inside), so the entry point
---is x1 + (x2 - x1) * t, y1 + (y2 - y1) * t. For a tile layer, the first solid tile met.
---@return table out, integer n, number[] out_t
function World:query_segment(x1, y1, x2, y2, out, out_t)
  check_number(x1, "x1", 2)
  check_number(y1, "y1", 2)
  check_number(x2, "x2", 2)
  check_number(y2, "y2", 2)
  out = check_out(out, "out")
  out_t = check_out(out_t, "out_t")
  local dx, dy = x2 - x1, y2 - y1
  local left, top = x1 < x2 and x1 or x2, y1 < y2 and y1 or y2
  local width, height = dx < 0 and -dx or dx, dy < 0 and -dy or dy
  local found = self._found
  local count = collect_boxes(self, left, top, width, height)
  local n = 0
  for i = 1, count do
    local record = found[i]
    found[i] = nil
    local item = record.item
    local t = segment_enter(x1, y1, dx, dy, item.x, item.y, item.width, item.height)
    if t then
      n = n + 1
      found[n] = record
      record._t = t
    end
  end
  local layers = self._layers
  for k = 1, #layers do
    local layer = layers[k]
    local col0, col1 = grid.span(layer.x, layer.tile_width, layer.inverse_width, layer.cols, left, left + width)
    local row0, row1 = grid.span(layer.y, layer.tile_height, layer.inverse_height, layer.rows, top, top + height)
    local kinds, cols = layer.kinds, layer.cols
    local best
    for row = row0, row1 do
      for col = col0, col1 do
        if kinds[row * cols + col + 1] ~= 0 then
          local t = segment_enter(x1, y1, dx, dy, layer.x + col * layer.tile_width,
            layer.y + row * layer.tile_height, layer.tile_width, layer.tile_height)
          if t and (best == nil or t < best) then best = t end
        end
      end
    end
    if best then
      local record = self._records[layer]
      n = n + 1
      found[n] = record
      record._t = best
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

world.World = World
return world
