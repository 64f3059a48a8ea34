-- budge.world: the World class. Solids never move by themselves and never collide;
-- actors move with world:move and stop against solids and solid tiles (and against other
-- actors when a filter asks); sensors never block and are reported when crossed; tile
-- layers are read by index. Each public method checks its arguments and then delegates:
-- solids.lua and actors.lua keep the items, move.lua moves actors, carry.lua moves
-- solids, query.lua answers queries, contacts.lua finds frame contacts.
--
-- A move allocates nothing once the world is warm: candidates go into a reused struct
-- of arrays, contacts into reused records, and nothing iterates with pairs(). Every
-- scratch table belongs to its world, so two worlds never disturb each other.
-- A filter callback must not move, add to or query the world it is called from.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local sweep = require(here .. ".sweep")
local hash = require(here .. ".hash")
local layer = require(here .. ".layer")
local tilegrid = require(here .. ".tilegrid")
local solids = require(here .. ".solids")
local actors = require(here .. ".actors")
local hits = require(here .. ".hits")
local move = require(here .. ".move")
local carry = require(here .. ".carry")
local query = require(here .. ".query")
local entry = require(here .. ".entry")
local contacts = require(here .. ".contacts")

local check_box, check_wall_type, check_number = box.check_box, box.check_wall_type,
  box.check_number
local describe, is_finite, check_filter = box.describe, box.is_finite, box.check_filter
local METHOD, NAME_LIST = move.BY_NAME, move.NAME_LIST
local format, error, type, pcall, rawequal = string.format, error, type, pcall, rawequal
-- LuaJIT: world:move tries the slot after the last move's first (see World:move)
local TRY_NEXT_SLOT = rawget(_G, "jit") ~= nil

local SOLID, ACTOR, TILES, SENSOR = entry.SOLID, entry.ACTOR, entry.TILES, entry.SENSOR
local A_KIND = entry.A_KIND
local enter, guarded, check_span, check_out = entry.enter, entry.guarded, entry.check_span,
  entry.check_out
local find_record, refuse_duplicate, abandon_move = entry.find_record, entry.refuse_duplicate,
  entry.abandon_move
local check_self, check_box_span = entry.check_self, entry.check_box_span
local check_delta_span, check_layer_span = entry.check_delta_span, entry.check_layer_span
local check_tile_side = entry.check_tile_side

-- The range within which every operation is exact, terminates and does bounded work:
-- coordinates (x, y, x + width, y + height) within 2^24 cells of the origin either way,
-- and within 2^40 px. The hash's cell keys are exact below 2^25 cells; 2^40 px keeps
-- sums of coordinates exact to 2^-12 px and far from integer overflow on Lua 5.3 / 5.4.
local RANGE_CELLS, RANGE_MAX = 2 ^ 24, 2 ^ 40

local world = {}

---What the world keeps for each item: one per solid, actor and tile layer. What a move
---reads of it is in its array part, with the box (budge.HashRecord): [5] its kind; the
---rest is in its hash part (world:move itself reads no actor's record: actors.lua).
---(A move reads one run of memory instead of six nodes spread over the hash: at 10000
---movers, `lua5.4 bench/world.lua --way tiles --count 10000` under cachegrind missed its
---2 MB cache 13.2 times a move instead of 14.0 with the box there, and 10.2 with these
---two as well; LuaJIT's tile moves, 7 fresh runs each, interleaved, 2026-12-02: 244 ->
---215 ns.)
---@class budge.Record : budge.HashRecord
---@field item table the user's box, or the tile layer handle
---@field [5] "solid"|"actor"|"sensor"|"tiles" its kind
---@field [6] integer the id again, in the array part: a move's hit with a box reads it
---@field [7] any the item again, for scans that report it (budge.bump: the game's item)
---@field [14] number budge.bump's mark of its item (bump.lua's plan_move), else 0
---@field id integer the order it was added (the last tie-breaker everywhere)
---@field oneway boolean a solid with wall_type "oneway"
---@field index? integer an actor's place in the actor list (a sensor's in the sensor list)
---@field ride_stamp? integer the move_solid that found this actor riding
---@field crush_stamp? integer the move_solid that crushed it
---@field package _t? number scratch of query_segment: where the segment enters it
---@field removed? boolean taken out of the world (while a callback ran: not met again)
---@field package _in_hash? boolean a solid's record is in the solid hash
---@field package _cross_stamp? integer the last move that reported crossing it
---@field package _fx? number an actor's or sensor's box when the frame began (world:contacts)
---@field package _fy? number
---@field package _sx0? number scratch of world:contacts: the box swept in the frame
---@field package _sy0? number
---@field package _sx1? number
---@field package _sy1? number
---@field package _s0? number scratch of world:contacts: the swept box along its axis
---@field package _s1? number
---@field package _o0? number and across it
---@field package _o1? number
---@field package _frame_filtered? integer the contacts call that found it with a filter
---@field package _frame_moved? boolean a sensor on the world's moved list (true)
---@field package _frame_in? integer the contacts call that last saw it in the world
---@field package _mark? number budge.bump's mark: which move met it, or which leg's filter
---ignored it (bump.lua, plan_move)


---A world of solids, actors and tile layers. Made by budge.new_world.
---@class budge.World
---@field cell_size number side of a spatial hash cell
---@field range number coordinates stay within [-range, range]: 2^24 cells, at most 2^40 px
---@field package _records table<table, budge.Record> item -> record
---@field package _next_id integer the id of the last item added
---@field package _solids budge.Hash the solid boxes
---@field package _solid_count integer how many solid boxes
---@field package _layers budge.TileLayer[] the tile layers, in the order they were added
---@field package _bounds budge.Bounds of everything solid ever added
---@field package _box_bounds budge.Bounds of the hashed solid boxes ever added
---@field package _actors budge.Hash the actors, brought up to date lazily
---@field package _actor_list budge.Record[] the actors' records, in the world's actor order
---@field package _sensors budge.Hash the sensors
---@field package _sensor_list budge.Record[] the sensors' records (added order, a removal
---moving the last one into the gap)
---@field package _sensor_count integer how many sensors
---@field package _slot_of table<table, integer> each actor's slot: its place in _actor_list
---@field package _abox (table|number|boolean)[] the world's copy of each actor's box, as
---world:move left it (the record's copy until actors.rehash): the actor at 6 * slot - 5;
---x, y, width, height at 6 * slot - 4 to 6 * slot - 1; at 6 * slot whether world:move
---moved it since actors.rehash
---@field package _next_at integer 6 * (the slot after the last move's, wrapping): where
---world:move on LuaJIT looks for its actor first (a hint: past the last slot after a removal)
---@field package _last_at integer 6 * the number of actors (the last slot's end)
---@field package _stale budge.Record[] those actors' records
---@field package _n_stale integer
---@field package _hits budge.Hit[] the last move's contacts (reused)
---@field package _n_hits integer
---@field package _check_hits budge.Hit[] the last check's contacts (swapped in while it runs)
---@field package _round integer the phase of the move now recording contacts
---@field package _mixed integer more than 0 when a move's contacts may be out of order
---(a phase met several layers or boxes, or the move crossed sensors: move.lua)
---@field package _move_stamp integer counts moves (what a move crossed carries its stamp)
---@field package _probe budge.AxisProbe the axis scans' scratch
---@field package _set budge.CandidateSet the candidates of one move
---@field package _cross budge.CandidateSet what it only crosses
---@field package _crossed integer[] scratch of a filtered axis phase: indices into _set
---@field package _candidate_before fun(i: integer, j: integer): boolean orders _set
---@field package _order integer[] indices into _set, sorted by the discrete methods
---@field package _scratch budge.Box stands for a tile in the discrete methods
---@field package _tall budge.Box the fat cross of one candidate
---@field package _wide budge.Box
---@field package _found budge.Record[] hash output of queries and gathering
---@field package _near budge.Record[] actors near a moving solid
---@field package _crushed budge.Box[] the last move_solid's crushed actors
---@field package _n_crushed integer
---@field package _crush_stamp integer counts move_solid calls
---@field package _crush_lists budge.Box[][] one crushed list per nesting depth of move_solid
---@field package _crush_depth integer how many move_solid calls are running their on_crush
---@field package _busy string|false the callback running now ("an actor's filter"), or false
---@field package _pending budge.Record[] items removed while a callback ran, to take out after
---@field package _n_pending integer
---@field package _pending_actors integer how many of them are actors
---@field package _pending_layers integer and tile layers
---@field package _frame_order budge.Record[] the actors, by their frame's sweep (contacts.lua)
---@field package _frame_sensor_order budge.Record[] the sensors likewise, while swept with the actors
---@field package _moved_sensors budge.Record[] the sensors world:update moved since the last world:contacts
---@field package _moved_dead integer how many on that list were removed from the world since
---@field package _frame_found budge.Record[] scratch: the sensors near an actor
---@field package _frame_filtered_list budge.Record[] scratch: the actors with a filter
---@field package _frame_scratch budge.Record[] scratch of the merge sort
---@field package _frame_stats number[] scratch: sizes and spreads of the swept boxes
---@field package _frame_axis integer the axis the orders are sorted along (1: x, 2: y)
---@field package _frame_stamp integer counts world:contacts calls
---@field package _contact_pool budge.Contact[] the frame contacts (reused)
---@field package _contact_sorted budge.Contact[] scratch: the pool's first n, sorted
---@field package _n_contacts integer
local World = {}
World.__index = World

---True when `value` is a world made by budge.new_world.
---@param value any
---@return boolean
function world.is_world(value)
  return rawequal(getmetatable(value), World) -- (a game class's metatable may have an __eq)
end

---Creates an empty world.
---@param opts? {cell_size?: number} cell_size: side of a spatial hash cell (default 64)
---@return budge.World
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
  local set = sweep.new_set()
  local range = cell_size * RANGE_CELLS
  if range > RANGE_MAX then range = RANGE_MAX end
  local self = setmetatable({
    cell_size = cell_size, range = range,
    _records = {}, _next_id = 0,
    -- (the solids' hash keeps packed copies of their boxes, with their items (a record's
    -- [7]) in place of the records: hash.new says why)
    _solids = hash.new(cell_size, true, 7), _solid_count = 0, _layers = {},
    _bounds = solids.new_bounds(), _box_bounds = solids.new_bounds(),
    _actors = hash.new(cell_size), _actor_list = {},
    _slot_of = {}, _abox = {}, _next_at = 6, _last_at = 0, _stale = {}, _n_stale = 0,
    _sensors = hash.new(cell_size), _sensor_list = {}, _sensor_count = 0,
    _hits = hits.new_list(), _n_hits = 0, _check_hits = hits.new_list(), _round = 0,
    _mixed = 0,
    _move_stamp = 0,
    _probe = sweep.new_probe(),
    _set = set, _cross = sweep.new_set(), _crossed = {}, _candidate_before = move.candidate_order(set), _order = {},
    _scratch = {x = 0, y = 0, width = 0, height = 0},
    _tall = {x = 0, y = 0, width = 0, height = 0, wall_type = "horizontal"},
    _wide = {x = 0, y = 0, width = 0, height = 0, wall_type = "vertical"},
    _found = {},
    _near = {}, _crushed = {}, _n_crushed = 0, _crush_stamp = 0,
    _crush_lists = {}, _crush_depth = 0,
    _busy = false, _pending = {}, _n_pending = 0, _pending_actors = 0, _pending_layers = 0,
    _frame_order = {}, _frame_sensor_order = {}, _moved_sensors = {}, _moved_dead = 0,
    _frame_found = {}, _frame_filtered_list = {},
    _frame_scratch = {}, _frame_stats = {0, 0, 0, 0, 0, 0}, _frame_axis = 1,
    _frame_stamp = 0, _contact_pool = {}, _contact_sorted = {}, _n_contacts = 0,
  }, World)
  return self
end

local function new_record(self, item, kind)
  local id = self._next_id + 1
  self._next_id = id
  -- the array part (budge.Record, budge.HashRecord): the box, kind, id, item, cells, the
  -- packed cells' last column and row, budge.bump's mark (made here, so that the array
  -- part never grows: LuaJIT keeps an array part of up to 15 slots made by the
  -- constructor beside the table's header, where a move's hit reads [6] and [7])
  local record
  if kind == ACTOR or kind == SENSOR then -- (and world:contacts' fields, made here: a
    -- table's hash part grown later, at its first contacts call, was 400 bytes more a
    -- thing added, 2026-12-06)
    record = {0, 0, 0, 0, kind, id, item, 0, 0, 0, 0, 0, 0, 0,
      item = item, id = id, oneway = false, _stamp = 0, _fx = 0, _fy = 0, _frame_in = 0,
      _sx0 = 0, _sx1 = 0, _sy0 = 0, _sy1 = 0, _s0 = 0, _s1 = 0, _o0 = 0, _o1 = 0,
      _frame_filtered = 0, _frame_moved = false}
  else
    record = {0, 0, 0, 0, kind, id, item, 0, 0, 0, 0, 0, 0, 0,
      item = item, id = id, oneway = false, _stamp = 0}
  end
  self._records[item] = record
  return record
end

---Adds a solid box: actors stop against it. `wall_type = "oneway"` makes it block
---only actors coming down onto it from above.
---@param solid budge.Box
---@return budge.Box solid
function World:add_solid(solid)
  enter(self, "add_solid")
  refuse_duplicate(self, solid, "box")
  check_box(solid, "box", 2)
  check_wall_type(solid, "box", 2)
  check_box_span(self, solid, "box")
  solids.hash(self, new_record(self, solid, SOLID))
  self._solid_count = self._solid_count + 1
  return solid
end

---Adds an actor box: it moves with world:move and stops against solids and solid tiles,
---and crosses sensors. An optional `actor.filter(actor, other, col, row, id)` chooses
---the response to each thing it meets (README.md, "Responses"): "slide" (or true),
---"touch", "bounce", "cross", or false/nil to ignore it; with a filter, other actors are
---met too.
---@param actor budge.Box
---@return budge.Box actor
function World:add_actor(actor)
  enter(self, "add_actor")
  refuse_duplicate(self, actor, "box")
  check_box(actor, "box", 2)
  check_box_span(self, actor, "box")
  actors.insert(self, new_record(self, actor, ACTOR))
  return actor
end

---Adds a sensor box: a zone that never blocks anything (a coin, spikes, water, a
---checkpoint). An actor's move reports the sensors its path crosses as "cross" hits
---(unless its filter returns false or nil for one), and world:contacts reports actors
---meeting it. Move it by changing its box and calling world:update(sensor).
---@param sensor budge.Box
---@return budge.Box sensor
function World:add_sensor(sensor)
  enter(self, "add_sensor")
  refuse_duplicate(self, sensor, "box")
  check_box(sensor, "box", 2)
  check_box_span(self, sensor, "box")
  actors.insert(self, new_record(self, sensor, SENSOR))
  self._sensor_count = self._sensor_count + 1
  return sensor
end

---Adds a tile layer: `grid[row][col]` is a tile id (a flat array with `opts.width`
---tiles per row, or a Tiled layer `{width =, data =}`, are read the same way); any id but
---nil, false and 0 (or, when given, one for which `opts.is_solid(id)` is true) is solid,
---and one for which `opts.is_oneway(id)` is true is a oneway platform. Tile (col, row)
---covers x + (col-1)*tile_width onward. The grid is read now; call world:update(handle)
---after changing it. 0 is empty by default because Tiled and most tile maps use it so.
---Tile sides are at least the world's range over 2^61 (2^-31 px at the default cell size).
---@param grid table grid[row][col], a flat array with opts.width, or a Tiled layer
---@param tile_width number
---@param tile_height number
---@param opts? budge.LayerOptions
---@return budge.TileLayer handle world:remove and world:update take it, hits name it as `other`
function World:add_tiles(grid, tile_width, tile_height, opts)
  enter(self, "add_tiles")
  if type(grid) ~= "table" then
    error(format("grid must be a table of rows (grid[row][col]), got %s", describe(grid)), 2)
  end
  opts = tilegrid.check_options(tile_width, tile_height, opts, 2)
  check_tile_side(self, tile_width, "tile_width")
  check_tile_side(self, tile_height, "tile_height")
  local tiles = layer.new(grid, tile_width, tile_height, opts, 2)
  check_layer_span(self, tiles.x, tiles.cols, tile_width, "opts.x", "tile_width", "columns")
  check_layer_span(self, tiles.y, tiles.rows, tile_height, "opts.y", "tile_height", "rows")
  new_record(self, tiles, TILES)
  solids.add_layer(self, tiles)
  return tiles
end

---Removes a solid, an actor or a tile layer (by its handle). Allowed from inside the
---world's own callbacks: an item removed there is not met again by the move running.
---@param item table
function World:remove(item)
  check_self(self, "remove", 3)
  local record = find_record(self, item, 2)
  self._records[item] = nil
  record.removed = true
  local kind = record[5]
  if kind == SOLID then self._solid_count = self._solid_count - 1
  elseif kind == SENSOR then self._sensor_count = self._sensor_count - 1 end
  if self._busy then -- a move is walking the structures: take it out when it is done
    if kind == SOLID then solids.retire(self, record) end
    local n = self._n_pending + 1
    self._pending[n] = record
    self._n_pending = n
    if kind == ACTOR then self._pending_actors = self._pending_actors + 1
    elseif kind == TILES then self._pending_layers = self._pending_layers + 1 end
    return
  end
  if kind == SOLID then
    solids.unhash(self, record)
  elseif kind == TILES then
    solids.remove_layer(self, item)
  else
    actors.remove(self, record)
  end
end

---Tells the world that a box's position, size or wall_type changed outside world:move
---(for an actor, a teleport: its frame for world:contacts starts here; for a sensor, its
---move: its frame still sweeps from where it began), or that a tile layer's grid changed.
---@param item table a box or a tile layer handle of this world
function World:update(item)
  enter(self, "update")
  local record = find_record(self, item, 2)
  local kind = record[5]
  if kind == SOLID then
    check_box(item, "box", 2)
    check_wall_type(item, "box", 2)
    check_box_span(self, item, "box")
    solids.unhash(self, record)
    solids.hash(self, record)
  elseif kind == ACTOR or kind == SENSOR then
    check_box(item, "box", 2)
    check_box_span(self, item, "box")
    actors.rehash_one(self, record)
    -- an actor was teleported: its frame starts here; a sensor moves only this way, so
    -- its frame still sweeps from where it began
    if kind == ACTOR then
      record._fx, record._fy = record[1], record[2]
    elseif not record._frame_moved then -- (world:contacts sweeps it apart: contacts.lua)
      record._frame_moved = true
      local moved = self._moved_sensors
      moved[#moved + 1] = record
    end
  else
    check_number(item.x, "layer.x", 2)
    check_number(item.y, "layer.y", 2)
    check_span(self, item.x, item.cols * (item.tile_width - 0.0), "layer.x", "the layer")
    check_span(self, item.y, item.rows * (item.tile_height - 0.0), "layer.y", "the layer")
    layer.reread(item, 2)
    solids.grow_layer(self, item) -- it may have moved
  end
end

---True when `item` (a box or a tile layer handle) is in this world.
---@param item any
---@return boolean
function World:has(item)
  check_self(self, "has", 3)
  return self._records[item] ~= nil
end

---Counts of the world's items: solids, actors, tile layers, sensors.
---@return integer solids, integer actors, integer layers, integer sensors
function World:count()
  check_self(self, "count", 3)
  return self._solid_count, #self._actor_list - self._pending_actors,
    #self._layers - self._pending_layers, self._sensor_count
end

-- A query's width or height: finite and >= 0 (errors at the caller of the query).
local function check_size(value, name)
  if not is_finite(value) or value < 0 then
    error(format("%s must be a finite number >= 0, got %s", name, describe(value)), 3)
  end
end

-- The checks world:move and world:check make (errors at their caller): the actor's
-- record, the method's entry and the filter.
local function check_move(self, actor, dx, dy, method)
  local record = self._records[actor]
  if record == nil or record[5] ~= ACTOR then
    if record then
      error(format("actor must be an actor of this world, got %s", record[5] == SOLID
        and "a solid (world:move_solid moves solids)" or A_KIND[record[5]] .. " (world:move "
        .. "moves actors only)"), 3)
    end
    error(format("actor must be an actor of this world (add it with world:add_actor), got %s",
      describe(actor)), 3)
  end
  check_box(actor, "actor", 3)
  check_span(self, actor.x, actor.width, "actor.x", "the actor", 4)
  check_span(self, actor.y, actor.height, "actor.y", "the actor", 4)
  check_number(dx, "dx", 3)
  check_number(dy, "dy", 3)
  local range, to_x, to_y = self.range, actor.x + dx, actor.y + dy
  if to_x < -range or to_x > range or to_x - 0.0 + actor.width > range or to_y < -range
    or to_y > range or to_y - 0.0 + actor.height > range then -- (inline: this entry is
    -- hot; see check_span for to_x > range and - 0.0)
    check_delta_span(self, actor.x, dx, actor.width, "dx", "the actor", 4)
    check_delta_span(self, actor.y, dy, actor.height, "dy", "the actor", 4)
  end
  local method_entry = METHOD[method == nil and "axis_sweep" or method]
  if method_entry == nil then
    error(format("method must be %s, got %s", NAME_LIST, describe(method)), 3)
  end
  local filter = actor.filter
  if filter ~= nil and type(filter) ~= "function" then
    error(format("actor.filter must be a function or nil, got %s", describe(filter)), 3)
  end
  return record, method_entry, filter
end

-- The move itself, its hits sorted (unless the move says they are in order: then they
-- may lack the sort keys, see hits.add_line_pair); a filter's bad return value is an
-- error `level` levels up from here.
local function run_move(self, actor, dx, dy, filter, method_entry, level)
  self._n_hits = 0
  local in_order = false
  if filter == nil then -- no callback can run: nothing to guard
    in_order = method_entry.move(self, actor, dx, dy, nil, method_entry)
  else
    guarded(self, "an actor's filter", level, method_entry.move, abandon_move, actor, dx, dy,
      filter, method_entry)
  end
  if not in_order and self._n_hits > 1 then hits.sort(self) end
end

---Moves `actor` by (dx, dy) against the world's solids and tiles (and, as its filter
---chooses, other actors), writes its new position into it and returns it, with the
---contacts of this move in the order they happened: what stopped it, and what it
---crossed (sensors, and whatever its filter answered "cross" for).
---@param actor budge.Box an actor of this world
---@param dx number
---@param dy number
---@param method? "axis_sweep"|"swept"|"auto"|"seed"|"wall_type"|"min_axis"|"fat_cross"
---@return number x, number y, integer n, budge.Hit[] hits owned by the world, valid until the next move
function World:move(actor, dx, dy, method)
  if self._busy ~= false then enter(self, "move") end -- (one field read: this is hot)
  -- Speed: check_move's checks and run_move written out here (world:check calls them):
  -- through those two calls and the phases' own, the world bench's tile moves took 2540
  -- ns instead of 2237 on Lua 5.4 (`lua5.4 bench/world.lua --profile tiles --frames 100`,
  -- median of 5, 2026-12-01).
  -- The actor's slot. On LuaJIT, the one after the last move's first (games move their
  -- actors in the order they added them, most of them), the lookup by actor when that
  -- holds another: the world's copy holds each actor beside its box, so the try reads
  -- the cache line the move reads anyway, where the lookup in a table of 10000 actors
  -- missed the cache. `luajit bench/world.lua --way tiles --count N`, 5 fresh runs each,
  -- interleaved with the lookup alone, 2026-12-04: 104 ns per move instead of 113 at 100
  -- actors, 105 instead of 117 at 1000, 124 instead of 142 at 10000. The next slot wraps
  -- by `%`, not a branch: with a branch the first move of each frame took a side trace
  -- carrying the whole move (make bench-jit's crowd 107 traces and 155 KB instead of 98
  -- and 117). rawequal, not ==: an actor's __eq must not make it another's (a game's
  -- entities may compare by id), and a nil actor must not match an empty slot. On Lua
  -- 5.x rawequal is a call into C, dearer than the lookup: they look up.
  local at = self._next_at -- (where the entries of the slot after the last move's end)
  do -- (LuaJIT: each local still in scope at the move is carried into its side traces)
    local abox = self._abox
    if not TRY_NEXT_SLOT or actor == nil or not rawequal(abox[at - 5], actor) then
      at = self._slot_of[actor] -- (the actor's slot, then where its entries end)
      if at == nil then check_move(self, actor, dx, dy, method) end
      at = at * 6
    end
    if TRY_NEXT_SLOT then -- (after the last slot, the first: no branch)
      self._next_at = at % self._last_at + 6
    end
    -- check_box's and check_number's tests written out (x - x is 0 for a finite number
    -- only); the functions run only to raise their error. Through them, 9 calls per move:
    -- `lua5.4 bench/world.lua --way tiles --count 1000 --frames 60` took 2369 ns per move
    -- instead of 2189 (median of 5, 2026-12-01). A box equal to the world's copy (the
    -- box as the world last checked it, or placed it: actors.lua) is not checked again: four
    -- comparisons instead of four calls to type on Lua 5.x (same command, 5 fresh runs
    -- each, interleaved, 2026-12-02: 1574 ns per move against 1646 with the checks).
    -- (and the box where the game put it within the world's range, as at its add: a move
    -- from 9e18 px back into range ended inside a solid, found by review, 2026-12-06)
    local x, y, width, height = actor.x, actor.y, actor.width, actor.height
    if (x ~= abox[at - 4] or y ~= abox[at - 3] or width ~= abox[at - 2]
      or height ~= abox[at - 1])
      and (type(x) ~= "number" or type(y) ~= "number" or type(width) ~= "number"
        or type(height) ~= "number" or x - x ~= 0 or y - y ~= 0 or width - width ~= 0
        or height - height ~= 0 or width < 0 or height < 0 or x < -self.range
        or x > self.range or x - 0.0 + width > self.range or y < -self.range
        or y > self.range or y - 0.0 + height > self.range) then
      check_box(actor, "actor", 2)
      check_span(self, x, width, "actor.x", "the actor", 3)
      check_span(self, y, height, "actor.y", "the actor", 3)
    end
    if type(dx) ~= "number" or type(dy) ~= "number" or dx - dx ~= 0 or dy - dy ~= 0 then
      check_number(dx, "dx", 2)
      check_number(dy, "dy", 2)
    end
    local range, to_x, to_y = self.range, x + dx, y + dy
    if to_x < -range or to_x > range or to_x - 0.0 + width > range or to_y < -range
      or to_y > range or to_y - 0.0 + height > range then -- (to_x > range, - 0.0: see
      -- check_span)
      check_delta_span(self, x, dx, width, "dx", "the actor")
      check_delta_span(self, y, dy, height, "dy", "the actor")
    end
  end
  local method_entry = METHOD[method == nil and "axis_sweep" or method]
  local filter = actor.filter
  if method_entry == nil or (filter ~= nil and type(filter) ~= "function") then
    check_move(self, actor, dx, dy, method) -- (raises the error)
  end
  self._n_hits = 0
  local in_order = false
  if filter == nil then -- no callback can run: nothing to guard
    in_order = method_entry.move(self, actor, dx, dy, nil, method_entry)
  else
    guarded(self, "an actor's filter", 2, method_entry.move, abandon_move, actor, dx, dy,
      filter, method_entry)
    -- (the filter may have removed an actor, this one or the one whose slot moved here)
    at = self._slot_of[actor]
    if at == nil then -- (gone: its hits are still its move's, sorted)
      if self._n_hits > 1 then hits.sort(self) end
      return actor.x, actor.y, self._n_hits, self._hits
    end
    at = at * 6
  end
  -- (in_order first: on a path where the move returns a constant true LuaJIT compiles no
  -- test of the count, which differs from move to move)
  if not in_order and self._n_hits > 1 then hits.sort(self) end
  local abox = self._abox
  abox[at - 4], abox[at - 3] = actor.x, actor.y
  local width, height = actor.width, actor.height
  if width ~= abox[at - 2] or height ~= abox[at - 1] then
    actors.copy_size(self, at, width, height)
  end
  if not abox[at] then actors.stale(self, at) end
  return actor.x, actor.y, self._n_hits, self._hits
end

---What world:move(actor, dx, dy, method) would return, without moving anything: the
---actor, the world and the next move's result are as they were. Its hits are records of
---their own (valid until the next check), so the last move's hits stay valid.
---@param actor budge.Box an actor of this world
---@param dx number
---@param dy number
---@param method? "axis_sweep"|"swept"|"auto"|"seed"|"wall_type"|"min_axis"|"fat_cross"
---@return number x, number y, integer n, budge.Hit[] hits owned by the world, valid until the next check
function World:check(actor, dx, dy, method)
  enter(self, "check")
  local _, method_entry, filter = check_move(self, actor, dx, dy, method)
  local x, y, n_move = actor.x, actor.y, self._n_hits
  self._hits, self._check_hits = self._check_hits, self._hits
  local ok, err = pcall(run_move, self, actor, dx, dy, filter, method_entry, 4)
  local to_x, to_y, n, list = actor.x, actor.y, self._n_hits, self._hits
  actor.x, actor.y = x, y
  self._hits, self._check_hits, self._n_hits = self._check_hits, list, n_move
  if not ok then error(err, 0) end
  return to_x, to_y, n, list
end

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
  enter(self, "move_solid")
  local record = self._records[solid]
  if record == nil or record[5] ~= SOLID then
    error(format("solid must be a solid of this world (add it with world:add_solid), got %s",
      record and A_KIND[record[5]] or describe(solid)), 2)
  end
  check_box(solid, "solid", 2)
  -- (where the game put it, as at its add: from 2^62 px back by as much, it ended 25 px
  -- short, a review found, 2026-12-06)
  check_span(self, solid.x, solid.width, "solid.x", "the solid")
  check_span(self, solid.y, solid.height, "solid.y", "the solid")
  check_number(dx, "dx", 2)
  check_number(dy, "dy", 2)
  check_delta_span(self, solid.x, dx, solid.width, "dx", "the solid")
  check_delta_span(self, solid.y, dy, solid.height, "dy", "the solid")
  local n, crushed = carry.run(self, record, dx, dy) -- (no tail call: errors name your line)
  return n, crushed
end


-- The results of a query into `out` (and `out_t`), the filter's refusals left out; the
-- filter runs under the callback guard.
local function finish(self, n, out, filter, out_t)
  if filter == nil then return query.finish(self, n, out, nil, out_t) end
  return guarded(self, "a query's filter", 3, query.finish, query.abandon, n, out, filter,
    out_t)
end

---Every solid, actor, sensor and tile layer (once, when any of its solid tiles does)
---that strictly contains the point, in the order they were added, less those
---`filter(item)` returns false or nil for. Points on an edge are outside, as touching
---boxes do not collide.
---@param x number
---@param y number
---@param out? table reused for the result
---@param filter? fun(item: any): any
---@return table out, integer n
function World:query_point(x, y, out, filter)
  enter(self, "query_point")
  check_number(x, "x", 2)
  check_number(y, "y", 2)
  check_span(self, x, 0, "x", "the point")
  check_span(self, y, 0, "y", "the point")
  out = check_out(out, "out")
  check_filter(filter, 2)
  return out, finish(self, query.area(self, x, y, 0, 0), out, filter, nil)
end

---Every solid, actor, sensor and tile layer overlapping the rectangle (strictly), in the
---order they were added, less those `filter(item)` returns false or nil for.
---@param x number
---@param y number
---@param width number >= 0
---@param height number >= 0
---@param out? table reused for the result
---@param filter? fun(item: any): any
---@return table out, integer n
function World:query_rect(x, y, width, height, out, filter)
  enter(self, "query_rect")
  check_number(x, "x", 2)
  check_number(y, "y", 2)
  check_size(width, "width")
  check_size(height, "height")
  check_span(self, x, width, "x", "the rectangle")
  check_span(self, y, height, "y", "the rectangle")
  out = check_out(out, "out")
  check_filter(filter, 2)
  return out, finish(self, query.area(self, x, y, width, height), out, filter, nil)
end

---Every solid, actor, sensor and tile layer the segment passes through (strictly
---inside), sorted by distance along it (then by the order they were added), less those
---`filter(item)` returns false or nil for. `out_t[i]` is the fraction of the segment
---where it enters `out[i]` (0 when it starts inside), so the entry point is
---x1 + (x2 - x1) * t, y1 + (y2 - y1) * t. For a tile layer, the first solid tile met.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param out? table reused for the result
---@param out_t? number[] reused for the entry fractions
---@param filter? fun(item: any): any
---@return table out, integer n, number[] out_t
function World:query_segment(x1, y1, x2, y2, out, out_t, filter)
  enter(self, "query_segment")
  check_number(x1, "x1", 2)
  check_number(y1, "y1", 2)
  check_number(x2, "x2", 2)
  check_number(y2, "y2", 2)
  check_span(self, x1, 0, "x1", "the segment")
  check_span(self, y1, 0, "y1", "the segment")
  check_span(self, x2, 0, "x2", "the segment")
  check_span(self, y2, 0, "y2", "the segment")
  out = check_out(out, "out")
  out_t = check_out(out_t, "out_t")
  check_filter(filter, 2)
  local n = finish(self, query.sweep(self, x1, y1, x2, y2, 0, 0), out, filter, out_t)
  return out, n, out_t
end

---Every solid, actor, sensor and tile layer that a box at (x, y) of (width, height)
---would overlap (strictly) moving in a straight line by (dx, dy), nearest first (then
---in the order they were added), less those `filter(item)` returns false or nil for:
---nothing stops it, nothing moves. For a box not in the world: a ledge probe, "can I
---stand up here", a thrown object's path. `out_t[i]` is the fraction of the motion at
---which the box enters `out[i]` (0 when it overlaps it at the start). For a tile layer,
---the first solid tile met.
---@param x number
---@param y number
---@param width number >= 0
---@param height number >= 0
---@param dx number
---@param dy number
---@param out? table reused for the result
---@param out_t? number[] reused for the entry fractions
---@param filter? fun(item: any): any
---@return table out, integer n, number[] out_t
function World:query_sweep(x, y, width, height, dx, dy, out, out_t, filter)
  enter(self, "query_sweep")
  check_number(x, "x", 2)
  check_number(y, "y", 2)
  check_size(width, "width")
  check_size(height, "height")
  check_number(dx, "dx", 2)
  check_number(dy, "dy", 2)
  check_span(self, x, width, "x", "the box")
  check_span(self, y, height, "y", "the box")
  check_delta_span(self, x, dx, width, "dx", "the box")
  check_delta_span(self, y, dy, height, "dy", "the box")
  out = check_out(out, "out")
  out_t = check_out(out_t, "out_t")
  check_filter(filter, 2)
  local n = finish(self, query.sweep(self, x, y, x + dx, y + dy, width, height), out, filter,
    out_t)
  return out, n, out_t
end

-- What an error a filter raised during world:contacts leaves: no contacts, the frame
-- not begun again.
local function abandon_contacts(self)
  self._n_contacts = 0
end

---Every pair of things that touched during the frame, from both motions: each actor's
---and sensor's box moves in a straight line from where it was at the previous call (or
---where it was added, or where world:update teleported an actor) to where it is now, and a pair is
---reported when the two boxes overlap strictly at some moment of that, whichever order
---the game moved them in. A pair is reported when either actor's filter returns "cross"
---for the other, or for an actor and a sensor unless the actor's filter returns false
---or nil for it (every sensor, with no filter). Records (owned by the world, valid until
---the next call) come sorted by `t`, then by the order `item` and `other` were added.
---The call starts the next frame where everything is now.
---@param out? table reused for the result
---@return table out, integer n
function World:contacts(out)
  enter(self, "contacts")
  out = check_out(out, "out")
  local list = self._actor_list
  for i = 1, #list do
    local filter = list[i].item.filter
    if filter ~= nil and type(filter) ~= "function" then
      error(format("actor.filter must be a function or nil, got %s for %s", describe(filter),
        describe(list[i].item)), 2)
    end
  end
  guarded(self, "an actor's filter (during world:contacts)", 2, contacts.find,
    abandon_contacts)
  return contacts.finish(self, out)
end

return world
