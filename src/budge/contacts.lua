-- budge.contacts: frame contacts. Each actor's and sensor's box moves in a straight line
-- from where it was when the frame began (the last world:contacts, or its add or update)
-- to where it is now; a pair is in contact when the two boxes overlap strictly at some
-- moment of that frame, found from both motions at once, so neither can pass through the
-- other between two calls whatever order the game moved them in.
--
-- Broad phase: sweep and prune over the boxes each swept in its frame, along the axis
-- they spread out along the more (a tall level's coins prune along y). The actors' order
-- is kept from call to call (an insertion sort of an order that barely changes is nearly
-- linear; a merge sort when it changed much). Only pairs that can be reported are
-- walked: an actor and a sensor, and an actor with a filter and any actor (never two
-- sensors, nor two actors without filters). The sensors are swept with the actors, in
-- an order kept likewise, while there are at most four to an actor; past that, only
-- those world:update moved in the frame are (sorted afresh each call), and the actors
-- find the others in the sensor hash, so that sensors no actor comes near cost nothing.
-- Narrow phase: the two motions relative to each other, one slab clip.
-- Nothing here iterates with pairs(); the records are the world's, reused.

local here = (...):match("^(.*)%.[^%.]+$")
local hits = require(here .. ".hits")
local prune_moved = require(here .. ".actors").prune_moved

local response_of, CROSS = hits.response, hits.CROSS
local sort, HUGE, min, max = table.sort, math.huge, math.min, math.max
-- LuaJIT takes the branch-free forms (math.min and math.max compile to no branch there);
-- Lua 5.1-5.4 the ones with comparisons.
local BRANCH_FREE = rawget(_G, "jit") ~= nil

local contacts = {}

---One pair of things that touched during the frame. Owned by the world and reused:
---valid until the next world:contacts.
---@class budge.Contact
---@field item table the actor whose filter chose "cross" (the one added first when both
---did), or the actor that met a sensor
---@field other table the other actor, or the sensor
---@field t number the first moment of the frame (0..1) at which they overlap
---@field began boolean false when they overlapped already when the frame began
---@field ended boolean true when they no longer overlap at its end
---@field package _item_id integer sort keys after t: the order item and other were added
---@field package _other_id integer

-- The fractions of the frame during which [a + s * va, a + s * va + size_a] overlaps
-- [b + s * vb, ...] strictly on one axis, as (enter, exit); nil when never.
local function overlap_times(a, size_a, va, b, size_b, vb)
  local gap, speed = a - b, va - vb -- a's low edge relative to b's: overlap while -size_a < gap < size_b
  if speed == 0 then
    if -size_a < gap and gap < size_b then return -HUGE, HUGE end
    return nil, nil
  end
  local t1, t2 = (-size_a - gap) / speed, (size_b - gap) / speed
  if t1 > t2 then return t2, t1 end
  return t1, t2
end

-- When the two records' boxes overlap during the frame: (enter, exit) of the overlap,
-- nil when they never do.
local function frame_overlap(a, b)
  local ax, ay, bx, by = a._fx, a._fy, b._fx, b._fy
  local enter_x, exit_x = overlap_times(ax, a[3], a[1] - ax, bx, b[3], b[1] - bx)
  if enter_x == nil then return nil, nil end
  local enter_y, exit_y = overlap_times(ay, a[4], a[2] - ay, by, b[4], b[2] - by)
  if enter_y == nil then return nil, nil end
  local enter = enter_x > enter_y and enter_x or enter_y
  local exit = exit_x < exit_y and exit_x or exit_y
  if enter < exit and enter < 1 and exit > 0 then return enter, exit end
  return nil, nil
end

-- Whether the actor's filter reports it crossing `other` (any response for a sensor).
local function wants(record, other)
  local actor = record.item
  local filter = actor.filter
  if other[5] == "sensor" then
    return filter == nil or response_of(filter(actor, other.item), other.item) ~= nil
  end
  return filter ~= nil and response_of(filter(actor, other.item), other.item) == CROSS
end

local function contact_before(a, b)
  if a.t ~= b.t then return a.t < b.t end
  if a._item_id ~= b._item_id then return a._item_id < b._item_id end
  return a._other_id < b._other_id
end

-- Appends a contact to the world's pool.
local function add(world, n, item, other, enter, exit)
  local pool = world._contact_pool
  local record = pool[n]
  if record == nil then
    record = {}
    pool[n] = record
  end
  record.item, record.other = item.item, other.item
  record.t = enter > 0 and enter or 0
  record.began = enter >= 0
  record.ended = exit <= 1
  record._item_id, record._other_id = item.id, other.id
end

-- order[first..last] by insertion, by the swept box's low side along the axis (_s0), then
-- the order added. Returns how many places records were moved, or stops and returns
-- false once that passes `budget`.
local function insertion(order, first, last, budget)
  local shifts = 0
  for i = first + 1, last do
    local record = order[i]
    local low, id = record._s0, record.id
    local j = i - 1
    while j >= first do
      local other = order[j]
      local other_low = other._s0
      if other_low < low or (other_low == low and other.id < id) then break end
      order[j + 1] = other
      j = j - 1
    end
    order[j + 1] = record
    shifts = shifts + (i - 1 - j)
    if shifts > budget then return false end
  end
  return shifts
end

local RUN = 16 -- the merge sort's runs, each by insertion

-- Merges the sorted runs from[low..mid] and from[mid + 1..high] into to[low..high].
local function merge(from, to, low, mid, high)
  local i, j, k = low, mid + 1, low
  while i <= mid and j <= high do
    local a, b = from[i], from[j]
    local a_low, b_low = a._s0, b._s0
    if b_low < a_low or (b_low == a_low and b.id < a.id) then
      to[k], j = b, j + 1
    else
      to[k], i = a, i + 1
    end
    k = k + 1
  end
  for m = i, mid do to[k], k = from[m], k + 1 end
  for m = j, high do to[k], k = from[m], k + 1 end
end

-- order[first..last] in insertion's order, by runs of RUN merged through `scratch` (left
-- empty).
local function merge_sort(order, first, last, scratch)
  for low = first, last, RUN do
    insertion(order, low, low + RUN - 1 < last and low + RUN - 1 or last, HUGE)
  end
  local from, to, width = order, scratch, RUN
  while width <= last - first do
    for low = first, last, 2 * width do
      local mid = low + width - 1
      if mid > last then mid = last end
      local high = mid + width
      if high > last then high = last end
      merge(from, to, low, mid, high)
    end
    from, to, width = to, from, width * 2
  end
  if from ~= order then
    for i = first, last do order[i] = from[i] end
  end
  for i = first, last do scratch[i] = nil end
end

-- Sorts a frame order, order[1..n], of which the first `kept` were in order at the last
-- call (refresh): those by insertion while they are nearly in order still (most frames),
-- by merge_sort (the same order) once the insertion has moved them more places than
-- there are of them (the axis changed, a crowd reshuffled, bullets fired again: at most
-- that much work lost before the merge sort); the rest (added since) by merge_sort, then
-- merged in. Linear in the frame order when little moved, n log n at worst. (A tenth of
-- 16000 actors replaced each frame, anywhere: 1111 ms per call on Lua 5.4 by insertion
-- alone, 80-95 ms so, most of it the passes over the 16000: `lua5.4 bench/crowds.lua`.
-- bench/contacts.lua's scene, interpreter instructions per actor per call on Lua 5.4:
-- with a budget of 4, 2, 1 or 0 moves a record before the merge sort 599, 571, 558 and
-- 545; 1 keeps the insertion for orders that did not change much, 2026-12-06.)
local function sort_order(world, order, n, kept)
  if not insertion(order, 1, kept, kept + 64) then
    merge_sort(order, 1, kept, world._frame_scratch)
  end
  if n > kept then
    local scratch = world._frame_scratch
    merge_sort(order, kept + 1, n, scratch)
    if kept > 0 then
      merge(order, scratch, 1, kept, n)
      for i = 1, n do order[i], scratch[i] = scratch[i], nil end
    end
  end
end

-- Brings a frame order (the actors', the sensors') up to date: drops what left the world
-- and appends what was added to `list` since (in the list's order). Returns how many,
-- and how many of them were in it before.
local function refresh(order, list, stamp)
  local kept = 0
  for i = 1, #order do
    local record = order[i]
    order[i] = nil
    if record.index ~= nil and not record.removed then
      kept = kept + 1
      order[kept] = record
      record._frame_in = stamp
    end
  end
  local old = kept
  for i = 1, #list do
    local record = list[i]
    if record._frame_in ~= stamp then
      record._frame_in = stamp
      kept = kept + 1
      order[kept] = record
    end
  end
  return kept, old
end

-- Computes the box each of order[1..n] swept in the frame: in x and y (_sx0 ..), and
-- along the axis the orders are sorted by (_s0, _s1) and across it (_o0, _o1); adds to
-- `stats` the sums of the swept widths and heights and the least and most of their left
-- and top sides (for choose_axis).
-- LuaJIT shaping: math.min and math.max, which compile to no branch there (with
-- comparisons, each way a thing moved and each new least or most was a side trace: 32
-- of the example game's traces started here); comparisons on Lua 5.1-5.4, where those
-- are calls into C.
local function swept(world, order, n, stats)
  local abox, along_x = world._abox, world._frame_axis == 1
  local width, height, left0, left1, top0, top1 = stats[1], stats[2], stats[3], stats[4],
    stats[5], stats[6]
  for i = 1, n do
    local record = order[i]
    if record[5] == "actor" then -- (its box as world:move left it: actors.lua)
      local at = record.index * 6
      record[1], record[2], record[3], record[4] = abox[at - 4], abox[at - 3], abox[at - 2],
        abox[at - 1]
    end
    local x, y, fx, fy = record[1], record[2], record._fx, record._fy
    local x0, y0, x1, y1
    if BRANCH_FREE then
      x0, y0, x1, y1 = min(fx, x), min(fy, y), max(fx, x) + record[3], max(fy, y) + record[4]
      left0, left1, top0, top1 = min(left0, x0), max(left1, x0), min(top0, y0), max(top1, y0)
    else
      x0, y0 = fx < x and fx or x, fy < y and fy or y
      x1, y1 = (fx < x and x or fx) + record[3], (fy < y and y or fy) + record[4]
      if x0 < left0 then left0 = x0 end
      if x0 > left1 then left1 = x0 end
      if y0 < top0 then top0 = y0 end
      if y0 > top1 then top1 = y0 end
    end
    record._sx0, record._sx1, record._sy0, record._sy1 = x0, x1, y0, y1
    if along_x then
      record._s0, record._s1, record._o0, record._o1 = x0, x1, y0, y1
    else
      record._s0, record._s1, record._o0, record._o1 = y0, y1, x0, x1
    end
    width, height = width + (x1 - x0), height + (y1 - y0)
  end
  stats[1], stats[2], stats[3], stats[4], stats[5], stats[6] = width, height, left0, left1,
    top0, top1
end

-- The axis for the next call to prune along (1: x, 2: y), from this call's swept boxes:
-- the one along which they would overlap the fewest others if spread evenly (their mean
-- size over the spread of their sides), kept unless the other axis is better by half (no
-- flapping between two near-equal ones: a change costs a merge sort of the orders). A
-- tall level's coins and actors prune along y from the second call on.
local function choose_axis(world, stats, count)
  if count == 0 then return world._frame_axis end
  local width, height = stats[1], stats[2]
  local spread_x = stats[4] - stats[3] + width / count
  local spread_y = stats[6] - stats[5] + height / count
  -- along x: width / spread_x; along y: height / spread_y (both > 0 unless sizes are 0)
  local along_x, along_y = width * spread_y, height * spread_x
  if world._frame_axis == 1 then
    if 2 * along_y < along_x then return 2 end
    return 1
  end
  if 2 * along_x < along_y then return 1 end
  return 2
end

-- A pair that overlaps in the frame, with the times of it: `a` is an actor, `b` a sensor
-- (actors false) or an actor (actors true: `a` has a filter). Appends its contact to the
-- pool when the rules of world:contacts report it; returns the pool's count.
-- LuaJIT shaping: left to the interpreter, as move.lua's filtered phases (the filters'
-- answers are paths of their own), and reached only by pairs that do overlap.
local function report(world, n, a, b, actors, enter, exit)
  -- (what a filter removed earlier in the call is not met again, as in a move)
  if a.removed or b.removed then return n end
  if not actors then
    if wants(a, b) then
      n = n + 1
      add(world, n, a, b, enter, exit)
    end
    return n
  end
  -- (a pair of actors with filters comes up twice, once from each: kept from the one
  -- added first)
  if b._frame_filtered == world._frame_stamp and b.id < a.id then return n end
  local first, second = a, b
  if b.id < a.id then first, second = b, a end
  if wants(first, second) then
    n = n + 1
    add(world, n, first, second, enter, exit)
  elseif wants(second, first) then
    n = n + 1
    add(world, n, second, first, enter, exit)
  end
  return n
end

-- Every pair of a record of `one` and one of `two` (each sorted by _s0) whose swept boxes
-- overlap strictly, each pair once, through report: the lists merged by _s0 (`one` first
-- on a tie), each record met against the other list's records not merged yet, while they
-- start before it ends. No pair within a list is walked.
-- LuaJIT shaping: one inner loop for both lists, one call out of it.
local function sweep(world, n, one, n1, two, n2, actors)
  local i, j = 1, 1
  while i <= n1 and j <= n2 do
    local p, q = one[i], two[j]
    local from_one = p._s0 <= q._s0
    local record, list, k, last = q, one, i, n1
    if from_one then
      record, list, k, last, i = p, two, j, n2, i + 1
    else
      j = j + 1
    end
    local low, right, top, bottom = record._s0, record._s1, record._o0, record._o1
    while k <= last do
      local other = list[k]
      if other._s0 >= right then break end
      local near -- (the two overlap across the axis, and along it from this side)
      if BRANCH_FREE then near = min(other._s1 - low, bottom - other._o0, other._o1 - top) > 0
      else near = low < other._s1 and other._o0 < bottom and top < other._o1 end
      if near and other ~= record then -- (an actor with a filter is in both lists)
        local a, b = other, record
        if from_one then a, b = record, other end
        local enter, exit = frame_overlap(a, b)
        if enter ~= nil then n = report(world, n, a, b, actors, enter, exit) end
      end
      k = k + 1
    end
  end
  return n
end

-- How many sensors that did not move in the frame world:contacts sweeps with the actors
-- at most, per actor; past that, it finds those in the sensor hash (meet_still).
local SWEPT_SENSORS = 4

-- The actors against the sensors that stayed where they were in the frame (every sensor
-- not on the moved list): those found in the sensor hash under each actor's swept box,
-- the hash's boxes being theirs for the whole frame. Sensors cost nothing here where no
-- actor comes near them.
local function meet_still(world, n, order, n_actors)
  local sensors, found = world._sensors, world._frame_found
  for i = 1, n_actors do
    local actor = order[i]
    local x0, y0, x1, y1 = actor._sx0, actor._sy0, actor._sx1, actor._sy1
    if sensors:occupied_between(x0, y0, x1, y1) then
      local count = sensors:collect_between(x0, y0, x1, y1, found, 0)
      for k = 1, count do
        local sensor = found[k]
        found[k] = nil
        -- (the boxes' test as the sweep's, first: frame_overlap's rounded times can say
        -- two boxes that only touch at the frame's end overlap an ulp before it)
        local sx, sy = sensor[1], sensor[2]
        if not sensor._frame_moved and x0 < sx + sensor[3] and sx < x1
          and y0 < sy + sensor[4] and sy < y1 then
          local enter, exit = frame_overlap(actor, sensor)
          if enter ~= nil then n = report(world, n, actor, sensor, false, enter, exit) end
        end
      end
    end
  end
  return n
end

-- The actors of order[1..n] with a filter (only those can report another actor) into
-- `filtered`, in the same order, each marked with the call's stamp; clears the rest of
-- it. Returns their count.
local function list_filtered(order, n, filtered, stamp)
  local count = 0
  for i = 1, n do
    local record = order[i]
    if record.item.filter ~= nil then
      count = count + 1
      filtered[count] = record
      record._frame_filtered = stamp
    end
  end
  for i = count + 1, #filtered do filtered[i] = nil end
  return count
end

-- Drops the items of the pool's contacts past the first n (the records are kept for
-- reuse).
local function release(pool, n)
  for i = n + 1, #pool do pool[i].item = nil end
end

-- The next frame starts where each record of `order` is now.
local function restart(order)
  for i = 1, #order do
    local record = order[i]
    record._fx, record._fy = record[1], record[2]
  end
end

-- The same for the moved sensors' list, emptied.
local function restart_moved(moved)
  for i = 1, #moved do
    local record = moved[i]
    moved[i] = nil
    record._fx, record._fy, record._frame_moved = record[1], record[2], false
  end
end

-- from[1..n] into to[1..n], clearing `to` after them up to `old` (its length before).
local function copy_list(to, from, n, old)
  for i = 1, n do to[i] = from[i] end
  for i = n + 1, old do to[i] = nil end
end

-- Empties a list, from its end.
local function empty(list)
  for i = #list, 1, -1 do list[i] = nil end
end

---Finds the frame's contacts into the world's pool, sorted by t, then by the order item
---and other were added; returns how many. Calls the actors' filters (under the caller's
---guard); the frame's start is left unchanged (contacts.finish starts the next one).
---@param world budge.World
---@return integer n
function contacts.find(world)
  local stamp = world._frame_stamp + 1
  world._frame_stamp = stamp
  local stats = world._frame_stats
  stats[1], stats[2], stats[3], stats[4], stats[5], stats[6] = 0, 0, HUGE, -HUGE, HUGE, -HUGE
  local order, moved = world._frame_order, world._moved_sensors
  local n_actors, old_actors = refresh(order, world._actor_list, stamp)
  local n_moved = prune_moved(moved)
  -- the sensors swept with the actors: all of them while those that stayed put are few
  -- beside the actors, else those moved in the frame (meet_still finds the others in the
  -- sensor hash; sensors that all move are swept in an order kept from call to call, not
  -- sorted afresh each call from the moved list)
  local sensors, n_sensors, old_sensors = world._frame_sensor_order
  if world._sensor_count - n_moved <= SWEPT_SENSORS * n_actors then
    n_sensors, old_sensors = refresh(sensors, world._sensor_list, stamp)
  else
    empty(sensors)
    sensors, n_sensors, old_sensors = moved, n_moved, 0
  end
  swept(world, order, n_actors, stats)
  swept(world, sensors, n_sensors, stats)
  sort_order(world, order, n_actors, old_actors)
  sort_order(world, sensors, n_sensors, old_sensors)
  local filtered = world._frame_filtered_list
  local n_filtered = list_filtered(order, n_actors, filtered, stamp)
  local n = 0
  if sensors == moved and world._sensor_count > n_moved then
    n = meet_still(world, n, order, n_actors)
  end
  n = sweep(world, n, order, n_actors, sensors, n_sensors, false)
  n = sweep(world, n, filtered, n_filtered, order, n_actors, true)
  world._frame_axis = choose_axis(world, stats, n_actors + n_sensors)
  release(world._contact_pool, n)
  world._n_contacts = n
  return n
end

---Starts the next frame where every actor and sensor is now, and copies the found
---contacts, sorted, into `out` (clearing the rest of it).
---@param world budge.World
---@param out table
---@return table out, integer n
function contacts.finish(world, out)
  local pool, n = world._contact_pool, world._n_contacts
  local order, sensors, moved = world._frame_order, world._frame_sensor_order,
    world._moved_sensors
  restart(order)
  restart(sensors)
  restart_moved(moved)
  world._moved_dead = 0
  -- (sorted here, in the pool's own range: table.sort sees exactly the n records)
  local sorted = world._contact_sorted
  copy_list(sorted, pool, n, #sorted) -- (a list with no holes: its length before is the same)
  sort(sorted, contact_before)
  copy_list(out, sorted, n, #out)
  return out, n
end

-- LuaJIT shaping: contacts.find and contacts.finish, once a call each, are left to the
-- interpreter; their loops are functions of their own (list_filtered, release, restart,
-- restart_moved, copy_list, empty, and refresh, swept, sort_order, sweep, meet_still),
-- which still compile. Compiled, each exit of a loop in them was a side trace carrying
-- the rest of the call. The example game's play-through (`luajit bench/game.lua --frames
-- 5000 --way default`, 12 runs each, interleaved, 2026-12-08; move_solid, gather_all and
-- Hash:moved's re-registration in the interpreter in both) needed 182 KB of machine
-- code instead of 245 (median; its largest run 220 instead of 285), at 67 us a frame
-- against 69. bench/contacts.lua's contacts (1100 actors and 200 sensors, `--budget
-- large`, 7 runs each): 481 ns per actor against 511; bench/crowds.lua's scenes the same
-- within the machine's noise.
do
  local jit = rawget(_G, "jit")
  if jit and jit.off then
    jit.off(report)
    jit.off(contacts.find)
    jit.off(contacts.finish)
  end
end

return contacts
