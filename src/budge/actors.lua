-- budge.actors: the world's actors, in a list (the world's actor order: the order they
-- were added, a removal moving the last one into the gap) and in a spatial hash that is
-- brought up to date lazily. A move only notes that its actor moved; the next query
-- rehashes the noted actors, so a frame of moves pays nothing for the hash. Each record
-- keeps a copy of its actor's box as the world last checked it (at add, update and each
-- move; a moving solid that pushes it copies its position only): queries read the copy,
-- so a field the game overwrote since is never read, and a move whose actor's box equals
-- the copy need not check it again.
-- world:move touches no record: it finds the actor's slot (its place in the actor list)
-- and writes the box it leaves into the world's copy by slot (_abox: one flat array, six
-- entries a slot: the actor, its box and a mark), noting the slot once; the records catch
-- up with their cells (actors.rehash) before a query or a move that gathers actors
-- (world:contacts copies the boxes into the records it reads, without their cells). Speed: a record is a
-- table of its own, its box three or four cache lines away from the next actor's, and
-- the lookup of it by actor another; with the flat arrays cachegrind's model of a 512 KB
-- cache (`valgrind --tool=cachegrind --LL=524288,8,64`, 120 minus 60 frames of `bench/
-- world.lua --way tiles`) counts 2.6 misses per move instead of 6.8 with 1000 actors and
-- 8.0 instead of 10.4 with 10000 on LuaJIT, 4.0 instead of 9.5 on Lua 5.4 (1000); the
-- measured times are in the CHANGELOG (2026-12-03).
-- Sensors are kept the same way, in a list and a hash of their own (they move only
-- through world:update). Each record also keeps where its box was when the frame began
-- (the last world:contacts, its add or its update), for frame contacts.

local is_finite = require((...):match("^(.*)%.[^%.]+$") .. ".box").is_finite

local actors = {}

local function is_size(value) return is_finite(value) and value >= 0 end

-- The list and hash an actor's or a sensor's record lives in (a record's [5] is its kind:
-- budge.Record, world.lua).
local function home(world, record)
  if record[5] == "sensor" then return world._sensor_list, world._sensors end
  return world._actor_list, world._actors
end

---Adds an actor's (or a sensor's) record to its list and hash; its frame begins here.
---@param world budge.World
---@param record budge.Record
function actors.insert(world, record)
  local list, hash = home(world, record)
  local index = #list + 1
  list[index] = record
  record.index = index
  actors.copy(record)
  if record[5] == "actor" then
    world._slot_of[record.item] = index
    world._abox[index * 6 - 5], world._abox[index * 6] = record.item, false
    world._last_at = index * 6
    actors.mirror(world, record)
  end
  record._fx, record._fy = record[1], record[2]
  hash:insert(record, record[1], record[2], record[3], record[4])
end

---Writes an actor's record's box into the world's copy by slot (see actors.rehash).
---@param world budge.World
---@param record budge.Record an actor's, in the world
function actors.mirror(world, record)
  local abox, at = world._abox, record.index * 6
  abox[at - 4], abox[at - 3], abox[at - 2], abox[at - 1] = record[1], record[2], record[3],
    record[4]
end

---Copies the actor's box into its record (after the box was checked).
---@param record budge.Record
function actors.copy(record)
  local item = record.item
  record[1], record[2], record[3], record[4] = item.x, item.y, item.width, item.height
end

---Takes an actor's (or a sensor's) record out of its list and hash.
---@param world budge.World
---@param record budge.Record
function actors.remove(world, record)
  local list, hash = home(world, record)
  hash:remove(record)
  local index, count = record.index, #list
  local last = list[count]
  list[index] = last
  last.index = index
  list[count] = nil
  record.index = nil
  if record._frame_moved then -- on the moved sensors' list (world:update) until contacts
    local moved, dead = world._moved_sensors, world._moved_dead + 1
    if dead * 2 > #moved then -- mostly gone: kept short for a game that never calls contacts
      actors.prune_moved(moved)
      dead = 0
    end
    world._moved_dead = dead
  end
  if record[5] == "actor" then -- the last actor's slot moves into the gap, its mark too
    -- (a record left in _stale has its index: rehash finds its new slot, and skips this one;
    -- the cells of the moved actors are brought up to date at the next query, as before)
    local abox, at, from = world._abox, index * 6, count * 6
    for k = -5, 0 do
      abox[at + k] = abox[from + k]
      abox[from + k] = nil
    end
    world._slot_of[record.item] = nil
    world._last_at = from - 6
    if last ~= record then world._slot_of[last.item] = index end
  end
end

---Drops from the world's list of moved sensors (World:update; contacts.lua) those no
---longer in the world, in place; returns how many stay.
---@param moved budge.Record[]
---@return integer kept
function actors.prune_moved(moved)
  local kept = 0
  for i = 1, #moved do
    local record = moved[i]
    moved[i] = nil
    if record.index ~= nil and not record.removed then
      kept = kept + 1
      moved[kept] = record
    else
      record._frame_moved = false
    end
  end
  return kept
end

---Copies the actor's size (read after a move) into the world's copy by slot, if it is
---still a size (a filter may have changed it during the move; the next move checks it,
---see World:move); the caller marks the slot stale.
---@param world budge.World
---@param at integer 6 * the actor's slot
---@param width any
---@param height any
function actors.copy_size(world, at, width, height)
  if is_size(width) and is_size(height) then
    local abox = world._abox
    abox[at - 2], abox[at - 1] = width, height
  end
end

---Re-registers an actor's record in the cells of its box after a moving solid placed it:
---its new position, with the size the world last checked (the next move checks the
---actor's own, see World:move).
---@param world budge.World
---@param record budge.Record
function actors.placed(world, record)
  local item = record.item
  local abox, at = world._abox, record.index * 6
  local x, y, width, height = item.x, item.y, abox[at - 2], abox[at - 1]
  abox[at - 4], abox[at - 3] = x, y
  record[1], record[2], record[3], record[4] = x, y, width, height
  world._actors:moved(record, x, y, width, height)
end

---Marks the actor whose entries in world._abox end at `at` as moved by world:move: its
---record and cells are brought up to date by actors.rehash.
---@param world budge.World
---@param at integer 6 * the actor's slot
function actors.stale(world, at)
  world._abox[at] = true
  local n = world._n_stale + 1
  world._stale[n] = world._actor_list[at / 6]
  world._n_stale = n
end

---Re-registers an actor's (or a sensor's) record in the cells of its box now.
---@param world budge.World
---@param record budge.Record
function actors.rehash_one(world, record)
  actors.copy(record)
  if record[5] == "actor" then actors.mirror(world, record) end
  local _, hash = home(world, record)
  hash:moved(record, record[1], record[2], record[3], record[4])
end

---Brings the records and the cells of the actors world:move moved since the last call up
---to date, from the world's copy by slot. Queries and moves that gather actors run it
---first (world:contacts reads the world's copy itself).
---@param world budge.World
function actors.rehash(world)
  local stale, abox, hash = world._stale, world._abox, world._actors
  for i = 1, world._n_stale do
    local record = stale[i]
    stale[i] = nil
    local slot = record.index
    if slot then -- still in the world
      local at = slot * 6
      abox[at] = false
      local x, y, width, height = abox[at - 4], abox[at - 3], abox[at - 2], abox[at - 1]
      record[1], record[2], record[3], record[4] = x, y, width, height
      hash:moved(record, x, y, width, height)
    end
  end
  world._n_stale = 0
end

---The actor records whose boxes touch the rectangle from (x, y) to (x1, y1) (edges
---included; its far sides as the caller has them: a moving solid's is (x + delta) +
---width, which x + (width + delta) can round below), in the world's actor order, into
---world._near; returns their count.
---Speed: a straight pass over the actor list, one small loop. The actor hash (brought up
---to date, collected, sorted by actor order) is faster on bench/platforms.lua (100 moving
---solids, 1000 actors: LuaJIT 2.0-2.4 -> 1.0-2.3 ms per frame, Lua 5.4 10.3 -> 3.7 ms)
---but its extra compiled paths take make bench-jit's platformer from 1-3 trace flushes to
---4-7 at LuaJIT's default budget (0.02-0.04 -> 0.04-0.07 ms per frame), measured
---2026-12-01: left for the issue on LuaJIT's budget.
---@param world budge.World
---@param x number
---@param y number
---@param x1 number
---@param y1 number
---@return integer n
function actors.near(world, x, y, x1, y1)
  local near, list = world._near, world._actor_list
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

-- actors.near on LuaJIT: the four comparisons as one test of the least difference (for
-- finite numbers b - a >= 0 exactly when a <= b: hash.lua's scan_packs says why), which
-- math.min compiles with no branch: each comparison an actor failed was a side trace
-- carrying the rest of a platform's move (make bench-jit's platformer: 352 -> 308 KB of
-- machine code with a budget that never runs out, median of 9 runs each, interleaved,
-- 2026-12-02). Lua 5.1-5.4 keep the comparisons: there math.min is a call into C (and a
-- test of which form to take, in the loop, made `lua5.4 bench/platforms.lua` run 25% more
-- instructions a frame, under cachegrind).
if rawget(_G, "jit") then
  local min = math.min
  function actors.near(world, x, y, x1, y1)
    local near, list = world._near, world._actor_list
    local n = 0
    for i = 1, #list do
      local record = list[i]
      local actor = record.item
      local ax, ay = actor.x, actor.y
      if min(x1 - ax, ax + actor.width - x, y1 - ay, ay + actor.height - y) >= 0 then
        n = n + 1
        near[n] = record
      end
    end
    for i = n + 1, #near do near[i] = nil end
    return n
  end
end

return actors
