-- budge.contacts: frame contacts. Each actor's and sensor's box moves in a straight line
-- from where it was when the frame began (the last world:contacts, or its add or update)
-- to where it is now; a pair is in contact when the two boxes overlap strictly at some
-- moment of that frame, found from both motions at once, so neither can pass through the
-- other between two calls whatever order the game moved them in.
--
-- Broad phase: sweep and prune along x over the boxes each swept in its frame, in an
-- order kept from call to call (an insertion sort of an order that barely changes is
-- nearly linear). Narrow phase: the two motions relative to each other, one slab clip.
-- Nothing here iterates with pairs(); the records are the world's, reused.

local here = (...):match("^(.*)%.[^%.]+$")
local hits = require(here .. ".hits")

local response_of, CROSS = hits.response, hits.CROSS
local sort, HUGE = table.sort, math.huge

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

-- Brings the world's frame order up to date: drops what left the world, appends what was
-- added (actors, then sensors, in their lists' order), and computes each one's swept box.
local function refresh(world)
  local order, kept = world._frame_order, 0
  local stamp = world._frame_stamp + 1
  world._frame_stamp = stamp
  for i = 1, #order do
    local record = order[i]
    order[i] = nil
    if record.index ~= nil and not record.removed then
      kept = kept + 1
      order[kept] = record
      record._frame_in = stamp
    end
  end
  local lists = world._frame_lists
  for l = 1, 2 do
    local list = lists[l]
    for i = 1, #list do
      local record = list[i]
      if record._frame_in ~= stamp then
        record._frame_in = stamp
        kept = kept + 1
        order[kept] = record
      end
    end
  end
  local abox = world._abox
  for i = 1, kept do
    local record = order[i]
    if record[5] == "actor" then -- (its box as world:move left it: actors.lua)
      local at = record.index * 6
      record[1], record[2], record[3], record[4] = abox[at - 4], abox[at - 3], abox[at - 2],
        abox[at - 1]
    end
    local x, y, fx, fy = record[1], record[2], record._fx, record._fy
    record._sx0, record._sx1 = (fx < x and fx or x), (fx < x and x or fx) + record[3]
    record._sy0, record._sy1 = (fy < y and fy or y), (fy < y and y or fy) + record[4]
  end
  -- insertion sort by the swept box's left edge, then the order added
  for i = 2, kept do
    local record = order[i]
    local left, id = record._sx0, record.id
    local j = i - 1
    while j >= 1 and (order[j]._sx0 > left or (order[j]._sx0 == left and order[j].id > id)) do
      order[j + 1] = order[j]
      j = j - 1
    end
    order[j + 1] = record
  end
  return kept
end

---Finds the frame's contacts into the world's pool, sorted by t, then by the order item
---and other were added; returns how many. Calls the actors' filters (under the caller's
---guard); the frame's start is left unchanged (contacts.finish starts the next one).
---@param world budge.World
---@return integer n
function contacts.find(world)
  local count = refresh(world)
  local order = world._frame_order
  local n = 0
  for i = 1, count do
    local a = order[i]
    local right, top, bottom = a._sx1, a._sy0, a._sy1
    local a_sensor = a[5] == "sensor" -- (a record's [5]: its kind)
    for j = i + 1, count do
      local b = order[j]
      if b._sx0 >= right then break end
      if b._sy0 < bottom and top < b._sy1 and not (a_sensor and b[5] == "sensor") then
        local enter, exit = frame_overlap(a, b)
        if enter then
          local first, second = a, b
          if b.id < a.id then first, second = b, a end
          local item, other
          if a_sensor then item, other = b, a
          elseif b[5] == "sensor" then item, other = a, b
          end
          if item then
            if not wants(item, other) then item = nil end
          elseif wants(first, second) then
            item, other = first, second
          elseif wants(second, first) then
            item, other = second, first
          end
          if item then
            n = n + 1
            add(world, n, item, other, enter, exit)
          end
        end
      end
    end
  end
  local pool = world._contact_pool
  for i = n + 1, #pool do pool[i].item = nil end -- (kept for reuse; drop references)
  world._n_contacts = n
  return n
end

---Starts the next frame where every actor and sensor is now, and copies the found
---contacts, sorted, into `out` (clearing the rest of it).
---@param world budge.World
---@param out table
---@return table out, integer n
function contacts.finish(world, out)
  local order, pool, n = world._frame_order, world._contact_pool, world._n_contacts
  for i = 1, #order do
    local record = order[i]
    record._fx, record._fy = record[1], record[2]
  end
  -- (sorted here, in the pool's own range: table.sort sees exactly the n records)
  local sorted = world._contact_sorted
  for i = 1, n do sorted[i] = pool[i] end
  for i = n + 1, #sorted do sorted[i] = nil end
  sort(sorted, contact_before)
  local old = #out
  for i = 1, n do out[i] = sorted[i] end
  for i = n + 1, old do out[i] = nil end
  return out, n
end

return contacts
