-- budge.entry: what the world's public methods do before they delegate. They refuse a
-- world called with "." instead of ":" or from inside one of its own callbacks, check
-- that boxes, moves and queries stay within the world's range, find the records of
-- items; and they run what may call a game's callbacks under a guard, so that an error
-- a callback raises leaves the world consistent (README.md, "Callbacks").

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local solids = require(here .. ".solids")
local actors = require(here .. ".actors")
local hits = require(here .. ".hits")

local describe = box.describe
local format, error, type, pcall = string.format, error, type, pcall
local getmetatable, rawequal = getmetatable, rawequal
local BadResponse = hits.BadResponse

local entry = {}

local SOLID, ACTOR, TILES, SENSOR = "solid", "actor", "tiles", "sensor"
entry.SOLID, entry.ACTOR, entry.TILES, entry.SENSOR = SOLID, ACTOR, TILES, SENSOR

-- How an error names each kind of item.
local A_KIND = {solid = "a solid", actor = "an actor", tiles = "tiles", sensor = "a sensor"}
entry.A_KIND = A_KIND

---Errors (at the caller of the entry) when `item` is in the world already.
---@param self budge.World
---@param item any
---@param name string the argument's name
function entry.refuse_duplicate(self, item, name)
  local record = self._records[item]
  if record then
    error(format("%s is already in this world (as %s)", name, A_KIND[record[5]]), 3)
  end
end

---The record of an item of the world; errors at `level` when it is not one.
---@param self budge.World
---@param item any
---@param level integer
---@return budge.Record
function entry.find_record(self, item, level)
  local record = self._records[item]
  if record == nil then
    error(format("item is not in this world (add it with add_solid, add_actor, add_sensor or "
      .. "add_tiles first), got %s", describe(item)), level + 1)
  end
  return record
end

---Every public method but move (which tests one field first) starts here: a world
---called with "." instead of ":", or from inside one of its own callbacks (other than to
---remove items), is refused with an error at the caller of the entry.
---@param self any what the method was called on
---@param call string the method's name
function entry.enter(self, call)
  entry.check_self(self, call, 4)
  if self._busy then
    error(format("world:%s was called from inside %s: a callback may remove items from its "
      .. "own world (world:remove) or use another world, but make no other call into its own",
      call, self._busy), 3)
  end
end

---Errors at `level` when a method was called with "." instead of ":" (`self` is then not
---a world). The methods a callback may call (remove, has, count) check only this.
---@param self any
---@param call string the method's name
---@param level integer
function entry.check_self(self, call, level)
  if type(self) ~= "table" or self._busy == nil then -- (every world has _busy, false or a name)
    error(format("call it as world:%s(...), with a colon, got %s for the world", call,
      describe(self)), level)
  end
end

---Errors (at the caller of the entry) when the box leaves the world's range on either axis.
---@param self budge.World
---@param b budge.Box checked already
---@param name string the argument's name ("box")
function entry.check_box_span(self, b, name)
  entry.check_span(self, b.x, b.width, name .. ".x", "the box", 4)
  entry.check_span(self, b.y, b.height, name .. ".y", "the box", 4)
end

---Takes out what was removed while a callback ran (world:remove only marked it).
---@param self budge.World
function entry.flush(self)
  local pending = self._pending
  for i = 1, self._n_pending do
    local record = pending[i]
    pending[i] = nil
    local kind = record[5]
    if kind == SOLID then solids.unhash(self, record)
    elseif kind == TILES then solids.remove_layer(self, record.item)
    else actors.remove(self, record) end -- an actor or a sensor
  end
  self._n_pending, self._pending_actors, self._pending_layers = 0, 0, 0
end

---Runs `body(self, a, ..., e)` while `busy` names the callback it may call: world:remove
---only marks items meanwhile, and an error raised inside leaves the world as
---`recover(self, a, ..., e)` puts it, the removals done, and then propagates: a game's
---own error unchanged, a filter's bad return value (hits.response) as an error at
---`level` (counted from the caller of guarded). Returns what body returned first.
---@param self budge.World
---@param busy string
---@param level integer
---@param body function
---@param recover function
---@param a any
---@param b any
---@param c any
---@param d any
---@param e any
---@return any
function entry.guarded(self, busy, level, body, recover, a, b, c, d, e)
  self._busy = busy
  local ok, result = pcall(body, self, a, b, c, d, e)
  self._busy = false
  if not ok then recover(self, a, b, c, d, e) end
  entry.flush(self)
  if not ok then
    -- (rawequal: the game's error may be a table whose metatable has an __eq of its own)
    if rawequal(getmetatable(result), BadResponse) then error(result.message, level + 1) end
    error(result, 0)
  end
  return result
end

-- The range errors' one message: "<name> must keep <what> within this world's range,
-- -R to R (...), got <value><detail>", raised at `level`.
local function range_error(self, name, what, value, detail, level)
  local range = describe(self.range)
  error(format("%s must keep %s within this world's range, -%s to %s (2^24 cells of %s px, "
    .. "at most 2^40 px), got %s%s", name, what, range, range, describe(self.cell_size),
    describe(value), detail), level + 1)
end

---Errors (at the caller of the entry) when the span [low, low + size] on one axis leaves
---the world's range.
---@param self budge.World
---@param low number
---@param size number
---@param name string the argument's name
---@param what string what must stay in range ("the box")
---@param level? integer where the error points (default 3: the caller of the entry)
function entry.check_span(self, low, size, name, what, level)
  local range = self.range
  -- (on Lua 5.3+ an integer low plus an integer size wraps around to a negative number
  -- when it passes math.maxinteger: low > range for a low near it, and the sum taken in
  -- floats, `low - 0.0 + size`, for a size near it; x - 0.0 is x for every float, -0
  -- too, and an integer's float is exact below 2^53, far past any range)
  if low < -range or low > range or low - 0.0 + size > range then
    -- (with the far side when it alone leaves the range: the size is at fault)
    local far = (low < -range or low > range) and "" or format(" (its size %s puts its "
      .. "far side at %s)", describe(size), describe(low - 0.0 + size))
    range_error(self, name, what, low, far, level or 3)
  end
end

---Errors (at the caller of the entry) when a displacement `delta` (the argument `name`)
---takes the span [start, start + size] on one axis out of the world's range, naming the
---argument's own value, then where it would take the span (as check_span's test, the sums
---taken in floats: an integer sum wraps around on Lua 5.3+).
---@param self budge.World
---@param start number
---@param delta number
---@param size number
---@param name string the argument's name ("dx")
---@param what string what must stay in range ("the actor")
---@param level? integer where the error points (default 3: the caller of the entry)
function entry.check_delta_span(self, start, delta, size, name, what, level)
  local range, low = self.range, start - 0.0 + delta
  if low < -range or low > range or low + size > range then
    range_error(self, name, what, delta, format(" (from %s to %s, size %s)", describe(start),
      describe(low), describe(size)), level or 3)
  end
end

---Errors (at the caller of the entry) when a tile layer from `origin` (the argument
---`origin_name`), `count` tiles of `size` (the argument `size_name`) on one axis, leaves
---the world's range: its origin named first, then its tile size.
---@param self budge.World
---@param origin number
---@param count integer
---@param size number
---@param origin_name string
---@param size_name string
---@param unit string "columns" or "rows"
function entry.check_layer_span(self, origin, count, size, origin_name, size_name, unit)
  entry.check_span(self, origin, 0, origin_name, "the layer", 4)
  -- (in floats: an integer product wraps around on Lua 5.3+, see check_span)
  local far = origin - 0.0 + count * (size - 0.0)
  if far > self.range then
    range_error(self, size_name, "the layer", size, format(" (%d %s from %s = %s reach %s)",
      count, count == 1 and unit:sub(1, -2) or unit, origin_name, describe(origin),
      describe(far)), 3)
  end
end

---Errors (at the caller of the entry) when a tile side is below the world's range over
---2^61. Two coordinates in range are at most twice the range apart, so a coordinate's
---tile index from a layer's origin stays within 2^62 either way; with a smaller side it
---can reach -2^63, which Lua 5.3 and 5.4 round to their least integer, and one less than
---that wraps round to the greatest: a move went through the layer with no hit there, as
---a review found (a 2^-64 px tile, an actor 0.5 px above it, 2026-12-07).
---@param self budge.World
---@param side number a tile_width or tile_height that check_options has passed
---@param name string
function entry.check_tile_side(self, side, name)
  local least = self.range * 2 ^ -61
  if side < least then
    error(format("%s must be at least this world's range over 2^61, %s px (a smaller tile's "
      .. "index can pass Lua 5.3's least integer), got %s", name, describe(least),
      describe(side)), 3)
  end
end

---A caller's output table, or a new one; errors (at the caller of the entry) for others.
---@param out any
---@param name string
---@return table
function entry.check_out(out, name)
  if out ~= nil and type(out) ~= "table" then
    error(format("%s must be a table or nil, got %s", name, describe(out)), 3)
  end
  return out or {}
end

---What an error raised by a filter during world:move leaves: the actor where it was,
---the hits of that move gone.
---@param self budge.World
function entry.abandon_move(self)
  local probe = self._probe
  probe.actor, probe.filter = nil, nil
  self._n_hits = 0
end

return entry
