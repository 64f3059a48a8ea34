-- budge.carry: moving solids.
--
-- The actors-and-solids rule of the Celeste and TowerFall games, done with exact faces:
-- a solid moves along x, then along y, and is never blocked. On each axis, an actor in
-- the band the solid sweeps is pushed ahead of it, to exactly its new face; an actor
-- that was riding it (standing on its top when the move began) and is not pushed is
-- carried by the same distance. Pushed and carried actors move like any actor (the
-- moving solid aside), so they stop against other solids; a pushed actor that cannot get
-- out of the way is crushed. Actors are handled in the world's actor order.

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")
local solids = require(here .. ".solids")
local actors = require(here .. ".actors")
local move = require(here .. ".move")

local before = sweep.before
local axis_phase = move.axis_phase
local near_actors = actors.near
local type = type

local carry = {}

-- Moves `actor` along one axis to `target` against everything but the moving solid
-- (already out of the hash); lands exactly on `target` when nothing is in the way.
-- Returns true when it got there.
local function shove(world, record, is_x, target)
  local actor = record.item
  local filter = actor.filter
  if filter ~= nil and type(filter) ~= "function" then filter = nil end
  world._n_hits = 0
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  local x, y = actor.x, actor.y
  local pos = is_x and x or y
  if target ~= pos then
    if is_x then
      pos = axis_phase(world, actor, filter, true, x, y, actor.width, actor.height, target - pos)
    else
      pos = axis_phase(world, actor, filter, false, y, x, actor.height, actor.width, target - pos)
    end
    if world._n_hits == 0 then pos = target end
    if is_x then x = pos else y = pos end
  end
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
  actors.rehash_one(world, record)
  return pos == target
end

local function crush(world, record)
  if record.crush_stamp == world._crush_stamp then return end
  record.crush_stamp = world._crush_stamp
  local n = world._n_crushed + 1
  world._crushed[n] = record.item
  world._n_crushed = n
end

-- One axis of a solid's move: push what is in its sweep, carry its riders.
local function solid_phase(world, solid, oneway, is_x, delta, ride_stamp)
  local x, y, width, height = solid.x, solid.y, solid.width, solid.height
  local reach = delta < 0 and -delta or delta
  local near = world._near
  local count
  if is_x then
    count = near_actors(world, delta < 0 and x + delta or x, y - 1, width + reach, height + 1)
    solid.x = x + delta
  else
    count = near_actors(world, x, delta < 0 and y + delta - 1 or y - 1, width, height + reach + 1)
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
        if not shove(world, record, true, target) then crush(world, record) end
      elseif record.ride_stamp == ride_stamp then
        shove(world, record, true, ax + delta)
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
        if not shove(world, record, false, target) then crush(world, record) end
      elseif record.ride_stamp == ride_stamp then
        -- carried down (or along, if pushed no further): rest exactly on the new top
        shove(world, record, false, before(y + delta, ah))
      end
    end
  end
end

-- LuaJIT shaping: the loop over the actors near a moving solid is left to the
-- interpreter: compiled, it inlines a whole actor move per actor (tiles, hash, pushes,
-- crushes) and spawns more side traces than LuaJIT keeps (1000), which flushes every
-- trace in the program again and again (5000 traces and 12 flushes in 300 frames of
-- bench/platforms.lua, commit 2e07fe1; make bench-jit). The moves it calls still run
-- their own compiled loops.
local jit = rawget(_G, "jit")
if jit and jit.off then jit.off(solid_phase) end

---Moves a solid of the world by (dx, dy) (checked by the caller): pushes, carries and
---crushes actors as the module comment says. Returns the crushed actors' count and the
---world's array of them, after calling each one's on_crush.
---@param world budge.World
---@param record budge.Record the solid's record
---@param dx number
---@param dy number
---@return integer n, budge.Box[] crushed
function carry.move_solid(world, record, dx, dy)
  local solid = record.item
  local stamp = world._crush_stamp + 1
  world._crush_stamp = stamp
  world._n_crushed = 0
  -- riders are decided once, where the solid stands before it moves
  local top, left, right = solid.y, solid.x, solid.x + solid.width
  local near = world._near
  for k = 1, near_actors(world, left, top - 1, solid.width, 1) do
    local actor = near[k].item
    if actor.x < right and left < actor.x + actor.width and actor.y == before(top, actor.height) then
      near[k].ride_stamp = stamp
    end
  end
  solids.remove(world, record) -- out of every actor's way while it moves
  local oneway = record.oneway
  if dx ~= 0 then solid_phase(world, solid, oneway, true, dx, stamp) end
  if dy ~= 0 then solid_phase(world, solid, oneway, false, dy, stamp) end
  solids.insert(world, record)
  world._n_hits = 0
  local crushed, n = world._crushed, world._n_crushed
  for i = n + 1, #crushed do crushed[i] = nil end
  for i = 1, n do
    local on_crush = crushed[i].on_crush
    if type(on_crush) == "function" then on_crush(crushed[i], solid) end
  end
  return n, crushed
end

return carry
