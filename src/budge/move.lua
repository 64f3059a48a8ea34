-- budge.move: how an actor moves through a world, and the registry of methods.
--
-- Every method has the same signature, move(world, actor, dx, dy, filter, entry): it
-- moves the actor against the world's solids and tiles, writes its new position into it
-- and records the contacts in the world's hit records (hits.lua). The registry below is
-- the one place the method names are written; the world's errors, budge.METHODS (used
-- by the bench, the lab and the advisor) and the `auto` rule all read it.
--
-- * axis_sweep: x, then y, each stopped at the nearest face ahead (the actors-and-solids
--   model of the Celeste and TowerFall games, done with exact faces);
-- * swept: the straight diagonal's time of impact, then a slide along what it met;
-- * seed, wall_type, min_axis, fat_cross: the discrete rungs (move, then push out).
--
-- The moving actor and its filter travel in the world's probe (sweep.lua's
-- budge.AxisProbe), set once per move, for the scans and the gathering that call the
-- filter. Geometry still goes by positional numbers where that was measured faster: the
-- tile scans (layer.lua) and axis_phase below say by how much.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local resolve = require(here .. ".resolve")
local fatcross = require(here .. ".fatcross")
local sweep = require(here .. ".sweep")
local layer = require(here .. ".layer")
local solids = require(here .. ".solids")
local hits = require(here .. ".hits")

local overlaps = box.overlaps
local before, first_contact = sweep.before, sweep.first_contact
local NORMAL_X, NORMAL_Y = sweep.NORMAL_X, sweep.NORMAL_Y
local tile_face = layer.tile_face
local gather, clip_to_boxes, clip_to_bounds = solids.gather, solids.clip_to_boxes,
  solids.clip_to_bounds
local add_hit = hits.add
local RULES, oneway_rule, resolve_pair = resolve.RULES, resolve.oneway, fatcross.resolve_pair
local ceil, sort, format = math.ceil, table.sort, string.format

-- A "swept" move that meets a face slides along it; three rounds cover a face, then a
-- second face that stops the slide, then a corner.
local MAX_SLIDES = 3
-- A swept move looks at the world in steps of a cell, at most this many: beyond, the
-- steps grow (each still exact; the hash walks its box list for a big step) so that a
-- move across far-apart solids does bounded work.
local MAX_STEPS = 4096

local move = {}

-- axis_sweep -------------------------------------------------------------------------

-- Lua 5.4 quirk: indexed only by a boolean local, because Lua 5.4.4 miscompiles T[a > b]
-- when T is an upvalue (the wrong side came back; spec/world_spec.lua's contact sides
-- fail on lua5.4 when written that way).
local SIDES_X = {[true] = "right", [false] = "left"}
local SIDES_Y = {[true] = "floor", [false] = "ceiling"}

-- The hash part of an axis phase: the swept rectangle, clipped to the bounds of the
-- hashed solids, scanned with the probe.
local function hash_phase(world, probe)
  local pos, size, delta = probe.pos, probe.size, probe.delta
  local reach = delta < 0 and -delta or delta
  local low = delta > 0 and pos or pos + delta
  local x, y, x1, y1
  if probe.is_x then
    x, x1, y, y1 = low, low + size + reach, probe.cross, probe.cross_end
  else
    y, y1, x, x1 = low, low + size + reach, probe.cross, probe.cross_end
  end
  x, y, x1, y1 = clip_to_boxes(world, x, y, x1, y1)
  if x <= x1 and y <= y1 then
    world._solids:axis_stop(x, y, x1 - x, y1 - y, probe)
  end
end

-- Moves `actor`'s box, at `pos` on the axis and `cross` across it, by `delta` along the
-- axis, up to the nearest stop among tiles and boxes; returns the new position on that
-- axis and records the contacts that stop it there. probe.actor and probe.filter are set
-- by the caller (the hash scan's filter calls read them there).
-- LuaJIT shaping: nine positional parameters, on purpose. Reading the actor, filter and
-- sizes from the probe inside made make bench-jit's platformer compile more code (580
-- traces, 758 KB against 512 and 643, median of 5 runs with a budget that never runs
-- out, 2026-12-01) and flush more often at the default budget.
local function axis_phase(world, actor, filter, is_x, pos, cross, size, cross_size, delta)
  local probe = world._probe
  local forward = delta > 0
  probe.is_x, probe.forward, probe.delta = is_x, forward, delta
  probe.pos, probe.size, probe.edge = pos, size, pos + size
  probe.reach = forward and pos + size + delta or pos + delta
  probe.cross, probe.cross_end = cross, cross + cross_size
  probe.blocks_oneway = not is_x and forward
  local side = is_x and SIDES_X[forward] or SIDES_Y[forward]
  local first_hit = world._n_hits
  local best
  local layers = world._layers
  for k = 1, #layers do
    local tiles = layers[k]
    -- a layer removed by a filter earlier in this move is skipped (one the filter removes
    -- now, returning true, is met this once, as a solid is)
    local record = world._records[tiles]
    if record and (filter == nil or filter(actor, tiles)) then
      local face, count = tile_face(tiles, probe)
      local stop = face
      if face then
        if forward then stop = face >= pos + size and before(face, size, pos) or pos
        elseif face > pos then stop = pos end
      end -- the same outcomes as sweep.stop_forward / stop_backward give
      if stop and (best == nil or (forward and stop <= best) or (not forward and stop >= best)) then
        if stop ~= best then best = stop; world._n_hits = first_hit end
        local id = record.id
        local cols, rows = probe.cols, probe.rows
        for c = 1, count do
          local col, row = cols[c], rows[c]
          add_hit(world, tiles, side, col, row, tiles.y + (row - 1) * tiles.tile_height,
            tiles.x + (col - 1) * tiles.tile_width, id)
        end
      end
    end
  end
  if world._solid_count > 0 then
    probe.best, probe.touched = nil, 0
    hash_phase(world, probe)
    local stop = probe.best
    if stop and (best == nil or (forward and stop <= best) or (not forward and stop >= best)) then
      if stop ~= best then best = stop; world._n_hits = first_hit end
      local touch = probe.touch
      for t = 1, probe.touched do
        local record = touch[t]
        local item = record.item
        add_hit(world, item, side, nil, nil, item.y, item.x, record.id)
      end
    end
  end
  if best == nil then return pos + delta end
  return best
end
move.axis_phase = axis_phase

local function move_axis_sweep(world, actor, dx, dy, filter)
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  local x, y = actor.x, actor.y
  if dx ~= 0 then
    world._round = 1
    x = axis_phase(world, actor, filter, true, x, y, actor.width, actor.height, dx)
  end
  if dy ~= 0 then
    world._round = 2
    y = axis_phase(world, actor, filter, false, y, x, actor.height, actor.width, dy)
  end
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
end

-- swept ------------------------------------------------------------------------------

-- Travels from (x, y) along (dx, dy) in chunks no longer than a cell, so a huge move
-- looks at a thin band of the world, until the first contact. Returns the position
-- reached and, on a contact, whether x and y are blocked and the fraction travelled.
local function advance(world, x, y, dx, dy, round)
  local actor = world._probe.actor
  local width, height = actor.width, actor.height
  local enter, leave = clip_to_bounds(world, x, y, width, height, dx, dy)
  if enter == nil then return x + dx, y + dy, nil end
  local adx, ady = dx < 0 and -dx or dx, dy < 0 and -dy or dy
  local length = (adx > ady and adx or ady) * (leave - enter)
  local chunks = ceil(length / world.cell_size)
  if chunks < 1 then chunks = 1 elseif chunks > MAX_STEPS then chunks = MAX_STEPS end
  local span = leave - enter
  for k = 1, chunks do
    local t_from = enter + span * (k - 1) / chunks
    local t_to = k == chunks and leave or enter + span * k / chunks
    local from_x, from_y = x + dx * t_from, y + dy * t_from
    local step_x, step_y = dx * (t_to - t_from), dy * (t_to - t_from)
    local left = step_x < 0 and from_x + step_x or from_x
    local top = step_y < 0 and from_y + step_y or from_y
    local reach_x, reach_y = step_x < 0 and -step_x or step_x, step_y < 0 and -step_y or step_y
    local set = gather(world, left, top, width + reach_x, height + reach_y)
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
          world._round = round
          if not outside then new_x = from_x
          elseif step_x > 0 then new_x = before(xs[i], width, from_x) else new_x = xs[i] + ws[i] end
          add_hit(world, other[i], step_x > 0 and "right" or "left", cols[i], rows[i], ys[i], xs[i], ids[i])
        elseif kind == NORMAL_Y or corners_block then
          world._round = round + 1
          if not outside then new_y = from_y
          elseif step_y > 0 then new_y = before(ys[i], height, from_y)
          else new_y = ys[i] + hs[i] end
          add_hit(world, other[i], step_y > 0 and "floor" or "ceiling", cols[i], rows[i], ys[i], xs[i], ids[i])
        end
      end
      return new_x, new_y, blocked_x, blocked_y, t_from + (t_to - t_from) * t
    end
  end
  return x + dx, y + dy, nil
end

local function move_swept(world, actor, dx, dy, filter)
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  local x, y = actor.x, actor.y
  local target_x, target_y = x + dx, y + dy
  for slide = 1, MAX_SLIDES do
    if dx == 0 and dy == 0 then break end
    local blocked_x, blocked_y, travelled
    x, y, blocked_x, blocked_y, travelled = advance(world, x, y, dx, dy, slide * 2 - 1)
    if blocked_x == nil then break end
    -- slide: what is left of the move, less the blocked component
    local rest = 1 - travelled
    dx = blocked_x and 0 or dx * rest
    dy = blocked_y and 0 or dy * rest
  end
  -- the slides' pieces, each rounded, can add up to an ulp more than the move: never
  -- further than asked
  if (target_x - actor.x) * (x - target_x) > 0 then x = target_x end
  if (target_y - actor.y) * (y - target_y) > 0 then y = target_y end
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
end

-- discrete methods ------------------------------------------------------------------

---The order the discrete methods resolve candidates in: top row first, left to right,
---then by the order items were added. A comparator for table.sort over indices into
---`set`, made once per world (it reads that world's set: no state shared between worlds).
---@param set budge.CandidateSet
---@return fun(i: integer, j: integer): boolean
function move.candidate_order(set)
  local ys, xs, ids = set.y, set.x, set.id
  return function(i, j)
    if ys[i] ~= ys[j] then return ys[i] < ys[j] end
    if xs[i] ~= xs[j] then return xs[i] < xs[j] end
    return ids[i] < ids[j]
  end
end

-- Moves the whole way, then pushes the actor out of each solid it overlaps, top row
-- first and left to right, with the entry's one-box rule.
local function move_discrete(world, actor, dx, dy, filter, entry)
  local prev_y = actor.y
  local x, y, width, height = actor.x + dx, actor.y + dy, actor.width, actor.height
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  -- the filter runs here, before the actor moves: if it raises an error, nothing moved
  local set = gather(world, x, y, width, height)
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
  local n = set.n
  if n == 0 then return end
  local order = world._order
  for i = 1, n do order[i] = i end
  for i = n + 1, #order do order[i] = nil end
  sort(order, world._candidate_before)
  local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
  local cols, rows, ids = set.col, set.row, set.id
  local scratch, tall, wide = world._scratch, world._tall, world._wide
  local rule, crossed = entry.rule, entry.name == "fat_cross"
  local speed = dx < 0 and -dx or dx
  if dy > speed then speed = dy elseif -dy > speed then speed = -dy end
  world._round = 1
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
      elseif crossed then
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
      if side then add_hit(world, other[i], side, cols[i], rows[i], ys[i], xs[i], ids[i]) end
    end
  end
end

-- The registry -----------------------------------------------------------------------

---One way to move an actor.
---@class budge.Method
---@field name string what world:move's `method` argument calls it
---@field rung integer its place on the ladder, cheapest first (bench and chart order)
---@field continuous boolean never tunnels (judged without a reference move)
---@field move fun(world: budge.World, actor: table, dx: number, dy: number, filter: function|nil, entry: budge.Method)
---@field rule? fun(a: budge.Box, b: budge.Box): number, number the discrete one-box rule

---Every method, in the order errors list them (the exact ones first).
---@type budge.Method[]
move.METHODS = {
  {name = "axis_sweep", rung = 5, continuous = true, move = move_axis_sweep},
  {name = "swept", rung = 6, continuous = true, move = move_swept},
  -- "auto" is the cheapest method that is safe for the move. Inside a world that is
  -- always axis_sweep: `make bench` measures it cheaper than every discrete method on the
  -- world bench scene (LuaJIT 368 ns per move against 670-737; Lua 5.4 1687 against
  -- 1745-1839) as well as right in every catalogue case, so no per-move choice can beat it.
  {name = "auto", rung = 7, continuous = true, move = move_axis_sweep},
  {name = "seed", rung = 1, continuous = false, move = move_discrete, rule = RULES.seed},
  {name = "wall_type", rung = 2, continuous = false, move = move_discrete,
    rule = RULES.wall_type},
  {name = "min_axis", rung = 4, continuous = false, move = move_discrete,
    rule = RULES.min_axis},
  {name = "fat_cross", rung = 3, continuous = false, move = move_discrete},
}

---The methods by name.
---@type table<string, budge.Method>
move.BY_NAME = {}
---The method names, cheapest rung first.
---@type string[]
move.LADDER = {}
do
  local quoted = {}
  for i, entry in ipairs(move.METHODS) do
    move.BY_NAME[entry.name] = entry
    move.LADDER[entry.rung] = entry.name
    quoted[i] = format("%q", entry.name)
  end
  ---The names as an error message lists them: '"axis_sweep", ... or "fat_cross"'.
  move.NAME_LIST = table.concat(quoted, ", ", 1, #quoted - 1) .. " or " .. quoted[#quoted]
end

return move
