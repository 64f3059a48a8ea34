-- budge.carry: moving solids.
--
-- The actors-and-solids rule of the Celeste and TowerFall games, done with exact faces:
-- a solid moves along x, then along y, and is never blocked. On each axis, an actor in
-- the band the solid sweeps is pushed ahead of it, to exactly its new face; an actor
-- that was riding it (standing on its top when the move began) and is not pushed is
-- carried by the same distance. Pushed and carried actors move like any actor (the
-- moving solid aside), so they stop against other solids; a pushed actor that cannot get
-- out of the way is crushed. Actors are handled in the world's actor order.
--
-- A solid pushes only with its leading face: an actor that reaches out past that face,
-- within the distance moved, is pushed; one behind the face (wholly inside the solid, or
-- across its trailing face, as a crushed actor is when its crusher retracts) is never
-- carried across the solid. Whatever overlaps a (not oneway) solid after its move is
-- reported crushed, whichever way it moved: no actor is left inside it unreported.

local here = (...):match("^(.*)%.[^%.]+$")
local sweep = require(here .. ".sweep")
local solids = require(here .. ".solids")
local actors = require(here .. ".actors")
local hits = require(here .. ".hits")
local move = require(here .. ".move")
local entry = require(here .. ".entry")

local before = sweep.before
local push_phase = move.push_phase
local response_of, CROSS = hits.response, hits.CROSS
local near_actors = actors.near
local type, pcall, error = type, pcall, error

local carry = {}

-- One push_phase of `actor`, whose box is at (x, y), from `pos` on the axis by `delta`.
local function push_step(world, filter, is_x, actor, pos, x, y, delta)
  if is_x then
    return push_phase(world, filter, true, pos, y, actor.width, actor.height, delta)
  end
  return push_phase(world, filter, false, pos, x, actor.height, actor.width, delta)
end

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
  local range = world.range
  if target < -range or target - 0.0 + (is_x and actor.width or actor.height) > range then
    return false -- pushed out of the world's range: crushed instead, left where it is
  end
  if target ~= pos then
    local blocked
    local forward = target > pos
    pos, blocked = push_step(world, filter, is_x, actor, pos, x, y, target - pos)
    -- (pos + (target - pos) can round off target, and the push checked the box's far side
    -- there. Short of target: a second step, target minus a value this near it, is exact
    -- and ends on target, so the faces are checked where the box ends. Past it, or
    -- stopped at or past it: the faces were checked beyond where the box ends, and it fits
    -- on target; a step back would be a move the other way, which a face it overlaps or
    -- a oneway top can refuse)
    -- (stopped a rounding short of target, as sweep.before can stop a box whose far side
    -- would touch the face exactly on it: the same exact step, which a face at target +
    -- size does not stop)
    local gap = forward and target - pos or pos - target
    if gap > 0 and (not blocked
      or gap <= ((target < 0 and -target or target) + (is_x and actor.width or actor.height))
        * 2 ^ -48) then
      pos, blocked = push_step(world, filter, is_x, actor, pos, x, y, target - pos)
    end
    if blocked and (forward and pos >= target or not forward and pos <= target) then
      blocked = false
    end
    if not blocked then pos = target end
    if is_x then x = pos else y = pos end
  end
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
  actors.placed(world, record)
  return pos == target
end

-- Whether a moving solid acts on the actor: not when the actor's filter ignores or
-- crosses it.
local function blocks(actor, filter, solid)
  if filter == nil or type(filter) ~= "function" then return true end
  local response = response_of(filter(actor, solid), solid)
  return response ~= nil and response ~= CROSS
end

local function crush(world, record)
  if record.removed or record.crush_stamp == world._crush_stamp then return end
  record.crush_stamp = world._crush_stamp
  local n = world._n_crushed + 1
  world._crushed[n] = record.item
  world._n_crushed = n
end

-- One axis of a solid's move: push what is in its sweep, carry its riders. Leaves in
-- world._near the actors near the band it swept (which holds the solid's new box) and
-- returns their count.
local function solid_phase(world, solid, oneway, is_x, delta, ride_stamp)
  local x, y, width, height = solid.x, solid.y, solid.width, solid.height
  local near = world._near
  local count
  -- (the band to the solid's far side where it ends, (x + delta) + width, as computed
  -- below: x + (width + delta) can round below it)
  if is_x then
    count = near_actors(world, delta < 0 and x + delta or x, y - 1,
      delta < 0 and x + width or x + delta + width, y + height)
    solid.x = x + delta
  else
    count = near_actors(world, x, delta < 0 and y + delta - 1 or y - 1, x + width,
      delta < 0 and y + height or y + delta + height)
    solid.y = y + delta
  end
  for k = 1, count do
    local record = near[k]
    if world._n_pending > 0 and world._records[solid] == nil then
      return count -- a filter removed the solid
    end
    local actor = record.item
    local filter = actor.filter
    -- skipped: an actor a filter removed earlier in this move, and one whose own filter
    -- lets it pass through this solid (it is neither pushed nor carried by it)
    if not record.removed and blocks(actor, filter, solid) then
      local ax, ay, aw, ah = actor.x, actor.y, actor.width, actor.height
      local target
      if is_x then
        -- the band swept along x ahead of the leading face, for actors overlapping it
        -- strictly on y that reach out past that face, or lie on it with no width (such
        -- an actor overlaps nothing there, and the face would pass over it)
        if not oneway and ay < y + height and y < ay + ah then
          if delta > 0 and (ax + aw > x + width or ax >= x + width)
            and ax < x + delta + width then
            target = x + delta + width -- (the solid's far side where it ends)
          elseif delta < 0 and (ax < x or ax + aw <= x) and ax + aw > x + delta then
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
          if delta < 0 and (ay < y or ay + ah <= y) and ay + ah > y + delta
            and (not oneway or ay + ah <= y) then
            target = before(y + delta, ah)
          elseif delta > 0 and not oneway and (ay + ah > y + height or ay >= y + height)
            and ay < y + delta + height then
            target = y + delta + height
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
  return count
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
---crushes actors as the module comment says, the crushed ones into world._crushed.
---@param world budge.World
---@param record budge.Record the solid's record
---@param dx number
---@param dy number
function carry.move_solid(world, record, dx, dy)
  local solid = record.item
  local stamp = world._crush_stamp + 1
  world._crush_stamp = stamp
  -- riders are decided once, where the solid stands before it moves
  local top, left, right = solid.y, solid.x, solid.x + solid.width
  local near = world._near
  for k = 1, near_actors(world, left, top - 1, right, top) do
    local actor = near[k].item
    if actor.x < right and left < actor.x + actor.width and actor.y == before(top, actor.height) then
      near[k].ride_stamp = stamp
    end
  end
  solids.unhash(world, record) -- out of every actor's way while it moves
  local oneway = record.oneway
  local count -- of world._near, the actors near the last band swept
  if dx ~= 0 then count = solid_phase(world, solid, oneway, true, dx, stamp) end
  if dy ~= 0 and not record.removed then
    count = solid_phase(world, solid, oneway, false, dy, stamp)
  end
  world._n_hits = 0
  -- whatever is left inside the solid (it was inside already, or behind a face the
  -- solid never pushes with) is reported crushed: no actor ends inside it unreported.
  -- (Before the solid is hashed again: a filter here that raises an error leaves the
  -- record at the start, which carry.abandon counts from.)
  if not oneway and not record.removed then
    local x, y, width, height = solid.x, solid.y, solid.width, solid.height
    -- (the last phase's near actors hold every actor that can overlap the new box)
    for k = 1, count or near_actors(world, x, y, x + width, y + height) do
      local near_record = near[k]
      local actor = near_record.item
      local filter = actor.filter
      if not near_record.removed and actor.x < x + width and x < actor.x + actor.width
        and actor.y < y + height and y < actor.y + actor.height
        and blocks(actor, filter, solid) then
        crush(world, near_record)
      end
    end
  end
  if not record.removed then solids.hash(world, record) end
end

-- LuaJIT shaping: the rest of a solid's move (its riders, unhash and hash, the crush
-- check) is left to the interpreter too; what it calls (actors.near's loop, the hash's
-- loops) still compiles its own traces. Compiled, each exit of those loops was a side
-- trace carrying the rest of the move up to the next loop that had a trace (3-4 KB each:
-- one per call of actors.near and per path). With this, 12 runs each, interleaved,
-- 2026-12-08 (solids.gather_all and Hash:moved's re-registration in the interpreter in
-- both): the example game's play-through (`luajit bench/game.lua --frames 5000 --way
-- default`) needed 238 KB of machine code instead of 277 (median), make
-- bench-jit's platformer 226 instead of 263. Cost: with few actors about it, a
-- move_solid's own steps show: `luajit bench/platforms.lua --actors 20` (100 solids)
-- took 103-120 us a frame instead of 80-93 or 122-180 (compiled, it ran at two speeds
-- from run to run); with 1000 actors the same, 1.90 ms a frame (9 runs each).
if jit and jit.off then jit.off(carry.move_solid) end

---What an error raised by a filter during carry.move_solid leaves: the solid where it
---was going (its record agrees), the actors it had pushed or carried where they got to,
---no actor reported crushed. An actor it had not reached yet may now overlap it, as if
---teleported there: such an actor can move out, never deeper.
---@param world budge.World
---@param record budge.Record
---@param dx number
---@param dy number
function carry.abandon(world, record, dx, dy)
  local solid = record.item
  solid.x, solid.y = record[1] + dx, record[2] + dy -- the record still holds the start
  if not record.removed then
    solids.unhash(world, record)
    solids.hash(world, record)
  end
  local probe = world._probe
  probe.actor, probe.filter = nil, nil
  world._n_crushed, world._n_hits = 0, 0
end

---world:move_solid once its arguments are checked: the move under the callback guard
---(entry.guarded, with carry.abandon as what an error leaves), then each victim's
---on_crush. on_crush runs once the move is complete: it may call into the world,
---move_solid too (a nested call fills a crushed list of its own, one per depth); every
---call is made, and the first error any of them raised propagates after the last.
---@param world budge.World
---@param record budge.Record the solid's record
---@param dx number
---@param dy number
---@return integer n, budge.Box[] crushed owned by the world, valid until the next call at this depth
function carry.run(world, record, dx, dy)
  local depth = world._crush_depth + 1
  local crushed = world._crush_lists[depth]
  if crushed == nil then
    crushed = {}
    world._crush_lists[depth] = crushed
  end
  world._crushed, world._n_crushed = crushed, 0
  entry.guarded(world, "an actor's filter (during world:move_solid)", 3, carry.move_solid,
    carry.abandon, record, dx, dy)
  local n = world._n_crushed
  for i = n + 1, #crushed do crushed[i] = nil end
  world._crush_depth = depth
  local solid, failure = record.item, nil
  for i = 1, n do
    local victim = crushed[i]
    local on_crush = victim.on_crush
    -- (a victim an earlier on_crush removed from the world is not called)
    if type(on_crush) == "function" and world._records[victim] then
      local ok, err = pcall(on_crush, victim, solid)
      if not ok and failure == nil then failure = {err} end
    end
  end
  world._crush_depth = depth - 1
  if failure then error(failure[1], 0) end
  return n, crushed
end

return carry
