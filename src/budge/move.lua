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
local hash = require(here .. ".hash")

local overlaps = box.overlaps
local before, first_contact, far_sides = sweep.before, sweep.first_contact, sweep.far_sides
local entry_axis, sweep_ends = sweep.entry_axis, sweep.ends
local NORMAL_X, NORMAL_Y = sweep.NORMAL_X, sweep.NORMAL_Y
local tile_face, tile_face_scan, tile_stop = layer.tile_face, layer.tile_face_scan,
  layer.tile_stop
local tile_line, list_line, line_pair, pair = layer.tile_line, layer.list_line,
  layer.line_pair, layer.pair
local axis_stop, lean_stop = hash.axis_stop, hash.lean_stop
local gather, clip_to_boxes, clip_to_bounds = solids.gather, solids.clip_to_boxes,
  solids.clip_to_bounds
local gather_sensors, gather_all = solids.gather_sensors, solids.gather_all
local response_of, merge_runs = hits.response, hits.merge_runs
local stop_forward, stop_backward, box_enter = sweep.stop_forward, sweep.stop_backward,
  sweep.box_enter
local add_hit, has_tile, add_tile_hits, add_line_pair = hits.add, hits.has_tile,
  hits.add_tiles, hits.add_line_pair
local shift_hits, key_tiles = hits.shift, hits.key_tiles
local SLIDE, TOUCH, BOUNCE, CROSS = hits.SLIDE, hits.TOUCH, hits.BOUNCE, hits.CROSS
local RULES, oneway_rule, resolve_pair = resolve.RULES, resolve.oneway, fatcross.resolve_pair
local abs, ceil, floor, min, max, sort, format = math.abs, math.ceil, math.floor, math.min,
  math.max, table.sort, string.format

-- A "swept" move that meets a face slides along it; three rounds cover a face, then a
-- second face that stops the slide, then a corner.
local MAX_SLIDES = 3
-- A swept move looks at the world in steps of a cell, at most this many: beyond, the
-- steps grow (each still exact; the hash walks its box list for a big step) so that a
-- move across far-apart solids does bounded work.
local MAX_STEPS = 4096
-- An axis_sweep phase reflects off at most this many faces (a box bouncing in a gap
-- narrower than its move); it stops at the last one.
local MAX_BOUNCES = 16
local HUGE = math.huge
-- In a world of tiles and actors, LuaJIT takes lean_phase's shape with one layer (one
-- branch on layer.tile_line's answer) and phase_stop's with more (the move's values in
-- the probe, tile_face's reads), and Lua 5.1-5.4 layer.tile_stop's (positional values,
-- the hits written as it finds them), through layers_stop with more than one layer: see
-- those. Magnitudes and the low end of a sweep are math.abs and math.min on LuaJIT,
-- which compile to no branch (a test of a sign is a side trace carrying the rest of the
-- move: make bench-jit's platformer needed 346 KB of machine code instead of 366 with a
-- budget that never runs out, median of 9 runs each, interleaved, 2026-12-02), and the
-- tests on Lua 5.1-5.4, where those are calls into C (with them, the world bench's box
-- moves ran 3% more instructions on Lua 5.4).
local BRANCH_FREE = rawget(_G, "jit") ~= nil

local move = {}

-- axis_sweep -------------------------------------------------------------------------

-- The side a phase's contacts are on, from its axis and way. Where LuaJIT is the caller
-- (phase_stop): in a trace is_x and forward are known, so this is a constant, and so are
-- hits.add's NX[side] and NY[side] (with the side a string read from a table indexed by
-- `forward`, each was a hash lookup). Lua 5.x's tile path (layer.tile_stop) writes its
-- sides and normals out: there a call costs more than the branches.
local function side_of(is_x, forward)
  if is_x then return forward and "right" or "left" end
  return forward and "floor" or "ceiling"
end

-- The rectangle an axis phase sweeps, clipped to the bounds of the hashed solids: from
-- the box's start to its reach forward, from the reach to its leading edge back (the
-- sides the stops compare with, as computed: low + size + |delta| can round short of the
-- reach, and a solid's face between the two would be missed), `cross` to `cross_end`
-- across. Returns x, y, x1, y1 (empty when x > x1 or y > y1).
local function swept_rect(world, is_x, pos, delta, edge, reach, cross, cross_end)
  local low, high
  if BRANCH_FREE then low, high = min(pos, pos + delta), max(reach, edge)
  elseif delta > 0 then low, high = pos, reach
  else low, high = reach, edge end
  if is_x then return clip_to_boxes(world, low, cross, high, cross_end) end
  return clip_to_boxes(world, cross, low, cross_end, high)
end

-- The hash part of an axis phase: the swept rectangle scanned with the probe.
local function hash_phase(world, probe)
  local x, y, x1, y1 = swept_rect(world, probe.is_x, probe.pos, probe.delta, probe.edge,
    probe.reach, probe.cross, probe.cross_end)
  if x <= x1 and y <= y1 then
    axis_stop(world._solids, x, y, x1, y1, probe)
  end
end

-- Lua 5.1-5.4's form of phase_stop's layer half in a world of tiles and actors alone
-- (move_axis_sweep calls it; the LuaJIT shaping there is no help on Lua 5.x, and each
-- probe field written and read again costs there): the nearest stop among the tile layers
-- for the box at `pos` (of `size`) on the axis, from `cross` to `cross_end` across it,
-- moving by `delta`, `done` px into a move of `path` px, with its tiles as hits; nil when
-- no tile stops it. The same outcomes as phase_stop's loop with tile_face (the specs run
-- on every interpreter with the same expected values). With solids or sensors phase_stop
-- runs on every interpreter: its line scan (tile_face_scan) disagrees with the reach
-- tables in a layer whose tiles are narrower than the rounding at their coordinate
-- (spec/layer_spec.lua), and every interpreter must give the same answer.
-- Speed: `lua5.4 bench/world.lua --way tiles --count 1000 --frames 60`, 3 fresh runs
-- each, interleaved, 2026-12-02: 2196-2323 ns per move through axis_phase, phase_stop and
-- tile_face, 1740-1750 through this and layer.tile_stop.
-- Its stop and hits (layer.tile_stop's) are phase_stop's written again, on purpose: as
-- one function both call, LuaJIT's tile moves took 173 ns instead of 154 (7 runs), make
-- bench-jit's platformer 612 KB instead of 513 (5 runs), Lua 5.4's tile moves 1569
-- instead of 1509 (`bench/world.lua --way tiles --count 1000`, fresh runs interleaved,
-- 2026-12-02).
-- This form is for two layers or more: each layer's tiles are written as hits, kept when
-- its stop is at least as near as the nearest yet (a nearer one's moved down over a
-- farther layer's), and given the sort keys at the end (their hits are sorted). One
-- layer takes layer.tile_stop alone (its hits are in order, never sorted:
-- hits.add_line_pair says why); `tiles` is the first layer, unused here (the two have one
-- signature).
local function layers_stop(world, _, is_x, pos, cross, cross_end, size, delta, done, path)
  local first_hit, forward = world._n_hits, delta > 0
  local layers = world._layers
  local best
  for k = 1, #layers do -- (no callback runs in this move: no layer is removed during it)
    local n = world._n_hits
    local stop = tile_stop(world, layers[k], is_x, pos, cross, cross_end, size, delta, done,
      path)
    if stop ~= nil and (best == nil or (forward and stop < best)
      or (not forward and stop > best)) then
      best = stop
      shift_hits(world, first_hit, n)
    elseif stop ~= best then -- (a farther stop, or none: its tiles are not met)
      world._n_hits = n
    end
  end
  key_tiles(world, first_hit + 1)
  return best
end

-- LuaJIT's axis phase in a world of one tile layer and actors alone (move_axis_sweep
-- calls it; phase_stop's outcomes, read from layer.tile_line): the box at `pos` (of
-- `size`) on the axis, from `cross` across it (`cross_size` wide), moving by `delta`,
-- `done` px into a move of `path` px; returns where it stops, with its tiles as hits.
-- LuaJIT shaping: the one branch on whether a tile stops it is taken here, after
-- tile_line, where few values are live; the rest is read from the layer again when it
-- does. Through axis_phase and phase_stop, the world bench's tile moves took 191 ns
-- instead of 169 (`luajit bench/world.lua --profile tiles`, 11 runs each, interleaved,
-- 2026-12-02).
local function lean_phase(world, is_x, pos, cross, size, cross_size, delta, done, path)
  local tiles = world._layers[1]
  local forward = delta > 0
  local face, hit, line, first, last, reach_first, reach_last = tile_line(tiles, is_x,
    forward, pos, size, delta, cross, cross + cross_size)
  if hit == 0 then return pos + delta end
  local stop, t = face -- (the outcomes sweep.stop_forward / stop_backward give)
  if forward then
    if face >= pos + size then stop = before(face, size, pos) else stop = pos end
    t = (done + (stop - pos)) / path
  else
    if face > pos then stop = pos end
    t = (done + (pos - stop)) / path
  end
  -- (the side and its normal, hits.NX and NY, written out: in a trace is_x and forward
  -- are known and these are constants. Through side_of and NX[side] the same moves ran
  -- 1282-1761 machine instructions instead of 1217-1234, `luajit bench/instructions.lua
  -- --way tiles --count 100`, 2026-12-07; world_spec's normals test holds them to NX.)
  local side, nx, ny
  if is_x then
    if forward then side, nx, ny = "right", -1, 0 else side, nx, ny = "left", 1, 0 end
  elseif forward then side, nx, ny = "floor", 0, -1
  else side, nx, ny = "ceiling", 0, 1 end
  if last - first > 1 then -- (a box more than two tiles across: list them)
    local probe = world._probe
    probe.is_x, probe.forward, probe.blocks_oneway, probe.edge = is_x, forward,
      not is_x and forward, pos + size
    local count = list_line(tiles, probe, line, first, last, face)
    add_tile_hits(world, tiles, side, probe.cols, probe.rows, count, t)
  else
    local across, count
    if forward and not is_x and tiles._down_any then -- (oneway tiles: line_pair's reads)
      across, count = line_pair(tiles, is_x, forward, line, first, last, face, pos + size)
    else across, count = pair(line, first, last, reach_first, reach_last) end
    add_line_pair(world, tiles, side, nx, ny, is_x, line, across, last, count, t)
  end
  return stop
end

-- The rest of axis_phase, from what it wrote into the probe: the nearest stop among the
-- layers and the hashed solids, with its contacts. LuaJIT shaping: the move's values are
-- read from the probe, not carried in locals of axis_phase (see layer.lua's axis scan);
-- the layer's record is looked up again for its id rather than kept in a local across
-- the scan (with that local, 992 "register coalescing" aborts per run of the world
-- bench's tiles and 170 ns per move instead of 12 and 157, 2026-12-01).
local function phase_stop(world, probe)
  local first_hit, solid_count = world._n_hits, world._solid_count
  local best
  local layers = world._layers
  for k = 1, #layers do
    local tiles = layers[k]
    -- a layer removed by a filter earlier in this move is skipped (one the filter removes
    -- now, returning true, is met this once, as a solid is)
    if world._records[tiles] then
      local face, count
      -- LuaJIT shaping: the reach read (tile_face) only in a world of tiles and actors;
      -- with hashed solids or sensors, the line scan, whose loops end traces. The reach
      -- read has no loop, so every path through a move compiles on into the rest of the
      -- move (the hash scan, the sensors, the game's loop) as traces of its own: in the
      -- world bench's tile scene that is 157 ns per move instead of 263, but with
      -- solids (make bench-jit's platformer) LuaJIT could not compile the hash scan's side
      -- traces (20-26 flushes in 3000 frames and 0.5-0.8 ms per frame instead of 4 and
      -- 0.036), and with sensors (bench/contacts.lua) it needed 2980 traces instead of
      -- 2481, so that at the default budget its moves took 19400 ns per actor instead of
      -- 8100 (2026-12-01); with sensors_crossed left to the interpreter, 1611-1811 ns
      -- instead of 1213-1222 with a budget that never runs out. Both scans give the same
      -- answer (spec/layer_spec.lua), but in a layer whose tiles are narrower than the
      -- rounding at their coordinate, where several faces round onto one value.
      if solid_count > 0 or world._sensor_count > 0 then
        face, count = tile_face_scan(tiles, probe)
      else
        face, count = tile_face(tiles, probe)
      end
      if face then -- the stop there, and its tiles as hits when it is the nearest yet
        local pos, size, forward = probe.pos, probe.size, probe.forward
        local stop = face -- (the outcomes sweep.stop_forward / stop_backward give)
        if forward then stop = face >= pos + size and before(face, size, pos) or pos
        elseif face > pos then stop = pos end
        if best == nil or (forward and stop <= best) or (not forward and stop >= best) then
          if stop ~= best then best = stop; world._n_hits = first_hit; probe.sources = 0 end
          local side = side_of(probe.is_x, forward)
          local t = (probe.before + (forward and stop - pos or pos - stop)) / probe.path
          add_tile_hits(world, tiles, side, probe.cols, probe.rows, count, t)
          probe.sources = probe.sources + 1
        end
      end
    end
  end
  if solid_count > 0 then
    probe.best, probe.touched = nil, 0
    hash_phase(world, probe)
    local stop = probe.best
    local forward = probe.forward
    if stop and (best == nil or (forward and stop <= best) or (not forward and stop >= best)) then
      if stop ~= best then best = stop; world._n_hits = first_hit; probe.sources = 0 end
      local side = side_of(probe.is_x, forward)
      local touch, pos = probe.touch, probe.pos
      local t = (probe.before + (forward and stop - pos or pos - stop)) / probe.path
      for c = 1, probe.touched do -- (the solids' items and ids: their records are not read)
        add_hit(world, touch[c], side, nil, nil, probe.touch_top[c], probe.touch_left[c],
          probe.touch_id[c], SLIDE, t)
      end
      probe.sources = probe.sources + probe.touched
    end
  end
  -- (hits from one layer or one box are in order; from more, the move sorts them)
  world._mixed = world._mixed + max(probe.sources - 1, 0)
  if best == nil then return probe.pos + probe.delta end
  return best
end

-- LuaJIT's axis phase in a world of solids and actors alone (no tile layer, no sensor;
-- move_axis_sweep calls it for an actor with no filter): phase_stop's outcomes with its
-- layer loop, its bookkeeping of sources and the probe's before and path left out (the
-- move's `done` and `path` come as arguments, as lean_phase's do), the hash's stop and
-- touch list read once. The box at `pos` (of `size`) on the axis, from `cross` across it
-- (`cross_size` wide), moving by `delta`; returns where it stops, its solids as hits.
-- Speed: `luajit bench/world.lua --way W --count N`, 7 fresh runs from each tree,
-- interleaved, medians in ns per move, 2026-12-07 (AMD EPYC): merged boxes 283 -> 271
-- at N = 100 and 339 -> 321 at 10000; box per tile 293 -> 282 and 360 -> 339. Machine
-- instructions a move (`bench/instructions.lua --way W --count 100 --frames 300`):
-- merged 3702-3970 -> 3512-3816, box per tile 3867-3869 -> 3617-3647 (2 to 4 runs each:
-- LuaJIT compiles a move differently from run to run). Traces LuaJIT compiles for the
-- moves alone (the world built with the JIT off, then 200 frames of 1000 movers): merged
-- boxes 79-81 instead of 91-93, box per tile 60-63 instead of 72-75 (3 runs each).
-- It hands the hash the box's values (Hash:lean_stop) and writes into the probe only the
-- outputs' start: see hash.lua's packed_scan for what that saved.
local function lean_solids_phase(world, is_x, pos, cross, size, cross_size, delta, done, path)
  local probe = world._probe
  local forward = delta > 0
  local edge, cross_end = pos + size, cross + cross_size
  local reach = forward and pos + delta + size or pos + delta
  probe.best, probe.touched = nil, 0
  local x, y, x1, y1 = swept_rect(world, is_x, pos, delta, edge, reach, cross, cross_end)
  if x <= x1 and y <= y1 then
    lean_stop(world._solids, x, y, x1, y1, probe, is_x, forward, pos, edge, reach, size,
      cross, cross_end)
  end
  local stop = probe.best
  if stop == nil then return pos + delta end
  local t = (done + (forward and stop - pos or pos - stop)) / path
  local side, touched = side_of(is_x, forward), probe.touched
  for c = 1, touched do
    add_hit(world, probe.touch[c], side, nil, nil, probe.touch_top[c], probe.touch_left[c],
      probe.touch_id[c], SLIDE, t)
  end
  if touched > 1 then world._mixed = world._mixed + touched - 1 end
  return stop
end

-- Moves `actor`'s box, at `pos` on the axis and `cross` across it, by `delta` along the
-- axis, up to the nearest stop among tiles and boxes; returns the new position on that
-- axis and records the contacts that stop it there, at the time probe.before (px of the
-- move's path before this phase) and probe.path (its whole length) give. For an actor
-- with no filter: everything blocks and slides (filtered_phase
-- below asks a filter).
-- LuaJIT shaping: positional parameters, on purpose. Reading the sizes from the probe
-- inside made make bench-jit's platformer compile more code (580
-- traces, 758 KB against 512 and 643, median of 5 runs with a budget that never runs
-- out, 2026-12-01) and flush more often at the default budget.
local function axis_phase(world, is_x, pos, cross, size, cross_size, delta)
  local probe = world._probe
  local forward = delta > 0
  probe.is_x, probe.forward, probe.delta = is_x, forward, delta
  probe.pos, probe.size, probe.edge = pos, size, pos + size
  probe.reach = forward and pos + delta + size or pos + delta -- (the far side where it ends)
  probe.cross, probe.cross_end = cross, cross + cross_size
  probe.blocks_oneway = not is_x and forward
  probe.sources = 0
  return phase_stop(world, probe) -- (a tail call: this frame's values leave the traces)
end

-- Records candidate i of the set as a "cross" hit at time t, entered by `side` (nil: the
-- box was inside it already), unless this move reported it already: a record stamped by
-- this move, or, from the move's second phase on, a tile among its hits.
local function add_crossing(world, set, i, side, t)
  local record = set.record[i]
  if record then
    if record._cross_stamp == world._move_stamp then return end
    record._cross_stamp = world._move_stamp
  elseif world._round > 1 and has_tile(world, 1, set.other[i], set.col[i], set.row[i]) then
    return
  end
  add_hit(world, set.other[i], side, set.col[i], set.row[i], set.y[i], set.x[i], set.id[i],
    CROSS, t)
end

-- How far along the box's path on the axis candidate i of the set is entered (negative:
-- the box overlaps it where it starts), or nil when the path, from `pos` until the
-- leading face reaches `far`, never overlaps it (strictly across the axis too).
-- A tile's far sides are its layer's edges (sweep.far_sides, written out here: through
-- the call, `lua bench/instructions.lua --lua lua5.4 --way
-- blocking --count 1000 --frames 5` ran 85852 instructions per move instead of 84622;
-- 83463 with every far side x + w, 2026-12-03)
local function entry_distance(set, i, is_x, forward, pos, edge, far, cross_lo, cross_hi)
  local x, y = set.x[i], set.y[i]
  local right, bottom
  if set.record[i] == false then
    local tiles = set.other[i]
    right, bottom = tiles.x + set.col[i] * tiles.tile_width, tiles.y + set.row[i] * tiles.tile_height
  else
    right, bottom = x + set.w[i], y + set.h[i]
  end
  local low, high, across, across_high
  if is_x then low, high, across, across_high = x, right, y, bottom
  else low, high, across, across_high = y, bottom, x, right end
  if across >= cross_hi or cross_lo >= across_high then return nil end
  if forward then
    if low < far and high > pos then return low - edge end
  elseif high > far and low < edge then
    return pos - high
  end
  return nil
end

-- Reports the candidates of the cross set that the box's path along the axis passes
-- through (strictly), from `pos` to `final`, as "cross" hits: entered (the leading edge
-- reaching them) at (passed + distance) / path of the move, or at passed / path with no
-- side when the box overlaps
-- them at `pos` already. Only those entered between `from` and `to` along the path (a
-- chunk of a long move) are reported, so a candidate two chunks gather is reported once;
-- and once per move: a record stamped by this move, or a tile already among the hits
-- (looked for from the second phase on), is not reported again.
local function report_crossings(world, cross, is_x, forward, pos, final, size, cross_lo,
                                cross_hi, passed, path, from, to)
  local ws, hs = cross.w, cross.h
  local edge = pos + size
  local side
  if is_x then side = forward and "right" or "left" else side = forward and "floor" or "ceiling" end
  local far = forward and final + size or final
  for i = 1, cross.n do
    local distance = entry_distance(cross, i, is_x, forward, pos, edge, far, cross_lo, cross_hi)
    -- (two extents of 0 on the axis never overlap strictly)
    if distance and (is_x and ws[i] or hs[i]) + size > 0 and distance >= from
      and distance < to then
      local inside = distance < 0
      add_crossing(world, cross, i, not inside and side or nil,
        (inside and passed or passed + distance) / path)
    end
  end
end

-- Of two candidates of a filtered phase's set met at the same distance along the path
-- (keys), true when a comes before b: added earlier (ids), then by row and column (a
-- layer's tiles).
local function tie_before(ids, rows, cols, a, b)
  local ia, ib = ids[a], ids[b]
  if ia ~= ib then return ia < ib end
  local ra, rb = rows[a] or 0, rows[b] or 0
  if ra ~= rb then return ra < rb end
  return (cols[a] or 0) < (cols[b] or 0)
end

-- sort_met's order for hits.merge_runs: a before b in `set`.
local function met_before(a, b, set)
  local keys = set.key
  local ka, kb = keys[a], keys[b]
  return ka < kb or ka == kb and tie_before(set.id, set.row, set.col, a, b)
end

-- Candidates a filtered phase sorts by insertion alone; past that, runs of this many,
-- merged.
local MET_RUN = 16

-- Sorts order[1..n], indices into `set`, by distance along the path (set.key), then
-- tie_before (stable): by insertion, and past MET_RUN in runs of MET_RUN merged
-- (hits.merge_runs, through set.scratch). By insertion alone (until 2026-12-07), a move
-- through a pile of k actors its filter passes over cost k^2: 256 piled, each ignored,
-- 1689 ms for 300 moves on Lua 5.4 under a line hook, 56% of it in the insertion. (The key compared in line, the
-- tie-breaks in a call: most candidates are met at distances of their own, and the
-- moves of a few candidates cost what they did.)
local function sort_met(set, order, n)
  local keys, ids, rows, cols = set.key, set.id, set.row, set.col
  for first = 1, n, MET_RUN do
    local last = first + MET_RUN - 1
    if last > n then last = n end
    for k = first + 1, last do
      local i = order[k]
      local key = keys[i]
      local j = k - 1
      while j >= first and (keys[order[j]] > key
        or keys[order[j]] == key and tie_before(ids, rows, cols, i, order[j])) do
        order[j + 1] = order[j]
        j = j - 1
      end
      order[j + 1] = i
    end
  end
  if n > MET_RUN then merge_runs(order, n, MET_RUN, met_before, set, set.scratch) end
end

-- axis_phase for an actor with a filter: the filter chooses each thing's response, other
-- actors and sensors are met too, and the move is looked at in chunks of at least a cell
-- (at most MAX_STEPS of them), nearest first, so that the work follows the distance to
-- the first stop. In each chunk the filter is asked about what the box's path meets, in
-- the order it meets it (at the same distance: by the order added, then row, then
-- column), up to the first thing that stops it: nothing beyond is asked about. Returns
-- the new position and the response that stopped the box there (nil when nothing did):
-- "touch" if any of what it met there chose it, else "bounce" if any did, else "slide".
-- Records the contacts at the stop and the crossings on the way.
local function filtered_phase(world, is_x, pos, cross, size, cross_size, delta, passed, path,
                              with_actors)
  local probe = world._probe
  local actor, filter = probe.actor, probe.filter
  local records_of = world._records
  local forward = delta > 0
  local edge = pos + size
  local reach = forward and pos + delta + size or pos + delta -- (see axis_phase)
  local blocks_oneway = not is_x and forward
  local cross_end = cross + cross_size
  local total = forward and delta or -delta
  local step = world.cell_size
  if total > step * MAX_STEPS then step = total / MAX_STEPS end
  local chunks = ceil(total / step)
  local side
  if is_x then side = forward and "right" or "left" else side = forward and "floor" or "ceiling" end
  for k = 0, chunks - 1 do
    local from = k == 0 and -HUGE or k * step
    local to = k == chunks - 1 and HUGE or (k + 1) * step
    local low, high -- the band of the axis this chunk looks at
    if forward then
      low, high = k == 0 and pos or edge + k * step, k == chunks - 1 and reach or edge + to
    else
      low, high = pos - (k == chunks - 1 and total or to), k == 0 and edge or pos - k * step
    end
    local set
    -- (the band's far side as computed: low + (high - low) can round below high, and the
    -- hashes and layers would then leave out a box whose face lies between the two)
    if is_x then
      set = gather_all(world, low, cross, high, cross_end, with_actors)
    else
      set = gather_all(world, cross, low, cross_end, high, with_actors)
    end
    local xs, ys, ws, hs, oneway, other = set.x, set.y, set.w, set.h, set.oneway, set.other
    local cols, rows, ids, records, keys = set.col, set.row, set.id, set.record, set.key
    local order, met = set.touch, 0
    -- what the path meets in this chunk, by distance along it (0: at the start)
    for i = 1, set.n do
      local distance = entry_distance(set, i, is_x, forward, pos, edge, reach, cross, cross_end)
      if distance then
        if distance >= from and distance < to then
          keys[i] = distance > 0 and distance or 0
          met = met + 1
          order[met] = i
        end
      end
    end
    if met > 1 then sort_met(set, order, met) end
    -- ask the filter in that order, up to the first stop
    local best, best_key, touched = nil, nil, 0
    local crossed = world._crossed
    local n_crossed = 0
    for c = 1, met do
      local i = order[c]
      local key = keys[i]
      if best_key ~= nil and key > best_key then break end
      local record = records[i]
      local response
      if record then
        if not record.removed then
          response = response_of(filter(actor, other[i]), other[i])
          if response ~= nil and record[5] == "sensor" then response = CROSS end
        end
      else
        local tiles = other[i]
        local layer_record = records_of[tiles]
        if layer_record and not layer_record.removed then
          local col, row = cols[i], rows[i]
          response = response_of(filter(actor, tiles, col, row,
            tiles._ids[(row - 1) * tiles.cols + col]), tiles)
        end
      end
      if response == CROSS then
        n_crossed = n_crossed + 1
        crossed[n_crossed] = i
      elseif response ~= nil then
        local stop
        local near = is_x and xs[i] or ys[i]
        if forward then
          stop = stop_forward(near, pos, edge, reach, size, oneway[i], blocks_oneway)
        else
          local right, bottom = far_sides(set, i)
          stop = stop_backward(is_x and right or bottom, pos, edge, reach, oneway[i],
            blocks_oneway)
        end
        if stop and (best == nil or (forward and stop <= best) or (not forward and stop >= best)) then
          if stop ~= best then best = stop; touched = 0 end
          best_key = key
          touched = touched + 1
          set.normal[touched] = i
          set.response[i] = response
        end
      end
    end
    -- the crossings before the stop (or overlapping the box where it started): entered
    -- before the box's far side where it stops (its box there, as the move without a
    -- filter judges them: a distance compared with the stop's can round the other way)
    for c = 1, n_crossed do
      local i = crossed[c]
      local near, length = is_x and xs[i] or ys[i], is_x and ws[i] or hs[i]
      local right, bottom = far_sides(set, i)
      local far_face = is_x and right or bottom
      local distance = forward and near - edge or pos - far_face
      if length + size > 0 and (best == nil or distance < 0
        or (forward and near < best + size) or (not forward and far_face > best)) then
        local inside = distance < 0
        add_crossing(world, set, i, not inside and side or nil,
          (inside and passed or passed + distance) / path)
      end
    end
    if best then
      local response = SLIDE
      local t = (passed + (forward and best - pos or pos - best)) / path
      local responses, touch = set.response, set.normal
      for c = 1, touched do
        local i = touch[c]
        local chosen = responses[i]
        if chosen == TOUCH then response = TOUCH
        elseif chosen == BOUNCE and response ~= TOUCH then response = BOUNCE end
        add_hit(world, other[i], side, cols[i], rows[i], ys[i], xs[i], ids[i], chosen, t)
      end
      return best, response
    end
  end
  return pos + delta, nil
end

-- The sensors an axis_sweep move with no filter crossed, from (x0, y0) along x to
-- (x1, y0) and then along y to (x1, y1), as "cross" hits: one look at the sensor hash
-- for the whole move, nothing more when its cells are empty.
-- LuaJIT shaping: once per move and after it, not after each phase: each of its branches
-- is a side trace carrying a copy of the rest of the move. Looked at after each phase,
-- bench/contacts.lua's 1000 walkers compiled 667 traces and 1215 KB of machine code
-- (238 KB without sensors) and flushed 12 times in 50 frames.
local function sensors_crossed(world, actor, x0, y0, x1, y1, dx, dy, path)
  local width, height = actor.width, actor.height
  local left, top = x0 < x1 and x0 or x1, y0 < y1 and y0 or y1
  local right = (x0 < x1 and x1 or x0) + width
  local bottom = (y0 < y1 and y1 or y0) + height
  if not world._sensors:occupied_between(left, top, right, bottom) then return end
  world._mixed = 1 -- (its crossings come at their own times: the move sorts its hits)
  world._move_stamp = world._move_stamp + 1
  local crossing = gather_sensors(world, left, top, right, bottom)
  if dx ~= 0 then -- (the phases as the move asked them, blocked or not)
    world._round = 1
    report_crossings(world, crossing, true, dx > 0, x0, x1, width, y0, y0 + height, 0, path,
      -HUGE, HUGE)
  end
  if dy ~= 0 then
    world._round = 2
    report_crossings(world, crossing, false, dy > 0, y0, y1, height, x1, x1 + width,
      (dx < 0 and -dx or dx) + 0, path, -HUGE, HUGE)
  end
end

-- LuaJIT shaping: left to the interpreter (what it calls still compiles its own loops):
-- compiled, each of its paths (a sensor near or not, crossed on x, on y, entered or
-- inside) was a side trace carrying the rest of the move and the game's loop after it.
-- bench/contacts.lua (1000 walkers with no filter crossing 200 coins), moves in ns per
-- actor, `luajit bench/contacts.lua --runs 3`, two sets, 2026-12-01: default budget
-- 4730 and 4633 -> 1606 and 1533; with --budget large 1238 and 1164 -> 1208 and 1191.
do
  local jit = rawget(_G, "jit")
  if jit and jit.off then jit.off(sensors_crossed) end
end

-- One axis of an axis_sweep move with a filter, `passed` px into the move's path of
-- `path` px: the contacts that stop it, whatever it crosses on the way, and bounces. Returns the
-- new position and the response that stopped it ("touch" ends the whole move).
local function run_phase(world, is_x, pos, cross, size, cross_size, delta, passed, path)
  world._round = world._round + 1
  local stuck = false
  for _ = 1, MAX_BOUNCES do
    local stop, response = filtered_phase(world, is_x, pos, cross, size, cross_size, delta,
      passed, path, true)
    if response ~= BOUNCE then return stop, response end
    local travelled = stop < pos and pos - stop or stop - pos
    local rest = (delta < 0 and -delta or delta) - travelled
    -- (a box held both ways, as inside a solid, stops: it bounced without moving twice)
    if rest <= 0 or (stuck and travelled == 0) then return stop, response end
    stuck = travelled == 0
    passed = passed + travelled
    pos, delta = stop, delta > 0 and -rest or rest
    world._round = world._round + 1
  end
  return pos, BOUNCE
end

---One axis of a push (carry.lua): moves the actor's box by `delta` along the axis against
---what blocks it (the filter's "slide", "touch" and "bounce" all block; nothing bounces),
---the moving solid aside. Returns the new position and whether anything stopped it.
---probe.actor and probe.filter are set by the caller.
---@param world budge.World
---@param filter? function
---@param is_x boolean
---@param pos number
---@param cross number
---@param size number
---@param cross_size number
---@param delta number
---@return number position, boolean blocked
function move.push_phase(world, filter, is_x, pos, cross, size, cross_size, delta)
  world._n_hits = 0
  if filter == nil then
    local probe = world._probe
    probe.before, probe.path = 0, delta < 0 and -delta or delta
    local stop = axis_phase(world, is_x, pos, cross, size, cross_size, delta)
    return stop, world._n_hits > 0
  end
  world._round, world._move_stamp = 1, world._move_stamp + 1
  -- (other actors never block a push)
  local stop, response = filtered_phase(world, is_x, pos, cross, size, cross_size, delta, 0,
    delta < 0 and -delta or delta, false)
  return stop, response ~= nil
end

-- With a filter: each phase asks it (run_phase, filtered_phase).
local function move_filtered(world, actor, dx, dy, filter)
  world._round, world._move_stamp = 0, world._move_stamp + 1
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  local x, y = actor.x, actor.y
  local adx = (dx < 0 and -dx or dx) + 0 -- (+ 0: |-0| is +0, as math.abs gives it)
  local path = adx + (dy < 0 and -dy or dy) -- x takes the first adx of the path
  local response
  if dx ~= 0 then
    x, response = run_phase(world, true, x, y, actor.width, actor.height, dx, 0, path)
  end
  if dy ~= 0 and response ~= TOUCH then
    y = run_phase(world, false, y, x, actor.height, actor.width, dy, adx, path)
  end
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
end

-- LuaJIT shaping: a move with a filter is left to the interpreter (move_filtered,
-- run_phase, filtered_phase, so also a push of an actor with a filter by a moving solid;
-- what they call still compiles its own loops, and a move with no filter is compiled as
-- before). A trace that runs into such a move cannot go on through it: LuaJIT aborts it
-- ("JIT compilation disabled for function") and after a few tries stops trying where
-- that trace starts (luajit -jv says "blacklisted"); the code before and after the move
-- still compiles from its own loops. Compiled, each answer a filter can give and each
-- count of candidates is a path of its own through the rest of the move and into the
-- game's loop: the example platformer (21 actors with filters, queries, moving solids)
-- made LuaJIT compile 900-1300 traces and 2-3 MB of machine code, more than its default
-- budget, which it then flushed about 52 times in 5000 frames. `luajit bench/game.lua
-- --frames 5000 --runs 3`, 2026-12-01, before -> this and query.lua's: default budget
-- 433-448 -> 38 us per frame and 51-53 -> 0 flushes; raised budget 97-174 -> 39-42; JIT
-- off 55 (this alone: 182-198 us and 29-33 flushes; query.lua's alone: 180-209 and
-- 13-16). bench/contacts.lua's moves (100 bullets with a filter): default budget
-- 8040-8070 -> 4030-4903 ns per actor, large budget 1330-1374 -> 1262-1326.
do
  local jit = rawget(_G, "jit")
  if jit and jit.off then
    jit.off(move_filtered)
    jit.off(run_phase)
    jit.off(filtered_phase)
    jit.off(sort_met) -- (and what it calls: the insertion was in filtered_phase before)
    jit.off(tie_before)
    jit.off(met_before)
  end
end

-- Returns true when the move's hits are already in the order they happened (hits.sort's
-- order), so that the world need not sort them: with no filter, when each phase met one
-- layer or one box and the move crossed no sensor. A phase's hits all have its stop's time;
-- from one layer they are one line of tiles listed from the low side across, and the x
-- phase's come first (spec/world_spec.lua checks the order against an oracle). The sort's
-- loop is a trace exit on LuaJIT and a call per hit on Lua 5.x; in make bench-jit's
-- platformer 43% of the moves sorted their hits, 3% of them changed the order, and the
-- sort's side traces took 44 KB of its 538 KB of machine code (2026-12-02).
-- Speed: with no filter, the two phases are called straight from here and the contacts'
-- times written only when there are contacts: through run_phase, the world bench's tile
-- moves took 2540 ns instead of 2237 on Lua 5.4 (`lua5.4 bench/world.lua --profile tiles
-- --frames 100`, median of 5, 2026-12-01).
local function move_axis_sweep(world, actor, dx, dy, filter)
  if filter ~= nil then return move_filtered(world, actor, dx, dy, filter) end
  if not BRANCH_FREE and world._solid_count == 0 and world._sensor_count == 0 then
    -- Lua 5.x, tiles alone: straight to layer.tile_stop (or layers_stop), without the probe
    local path = (dx < 0 and -dx or dx) + (dy < 0 and -dy or dy)
    local x, y = actor.x, actor.y
    local layers = world._layers
    local tiles, one = layers[1], layers[2] == nil
    local stop = one and tiles and tile_stop or layers_stop -- (no layer: layers_stop's none)
    if dx ~= 0 then
      world._round = 1
      local width, height = actor.width, actor.height
      x = stop(world, tiles, true, x, y, y + height, width, dx, 0, path) or x + dx
    end
    if dy ~= 0 then
      world._round = 2
      local width, height = actor.width, actor.height
      y = stop(world, tiles, false, y, x, x + width, height, dy,
        (dx < 0 and -dx or dx) + 0, path) or y + dy
    end
    actor.x, actor.y = x, y
    return one -- (no solid and no sensor on this path: one layer's hits are in order)
  end
  if BRANCH_FREE and world._solid_count == 0 and world._sensor_count == 0
    and world._layers[2] == nil and world._layers[1] then
    -- LuaJIT, one tile layer and actors alone: straight to lean_phase (the hits are in
    -- order: one layer, x before y)
    local path = abs(dx) + abs(dy)
    local x, y = actor.x, actor.y
    if dx ~= 0 then
      world._round = 1
      x = lean_phase(world, true, x, y, actor.width, actor.height, dx, 0, path)
    end
    if dy ~= 0 then
      world._round = 2
      y = lean_phase(world, false, y, x, actor.height, actor.width, dy, abs(dx),
        path)
    end
    actor.x, actor.y = x, y
    return true
  end
  if BRANCH_FREE and world._sensor_count == 0 and world._layers[1] == nil
    and world._solid_count > 0 then
    -- LuaJIT, solids and actors alone: straight to lean_solids_phase (the hits are in
    -- order unless a phase met several solids: then the move sorts them). (With no solid
    -- left, phase_stop's path, which skips the hash: its bounds keep the solids' that
    -- were removed, and lean_solids_phase would scan its placeholders; found by review.)
    -- Kept apart from the tile layer's branch above on purpose: one branch choosing
    -- between the two phases (and reading _mixed for both) cost the tile moves 1246-1256
    -- machine instructions a move instead of 1228 (`bench/instructions.lua --way tiles
    -- --count 100 --frames 300`) and 82.3 ns instead of 80.9 at 10000 movers (7 fresh
    -- runs each, interleaved, 2026-12-07).
    local path = abs(dx) + abs(dy)
    world._mixed = 0
    local x, y = actor.x, actor.y
    if dx ~= 0 then
      world._round = 1
      x = lean_solids_phase(world, true, x, y, actor.width, actor.height, dx, 0, path)
    end
    if dy ~= 0 then
      world._round = 2
      y = lean_solids_phase(world, false, y, x, actor.height, actor.width, dy, abs(dx), path)
    end
    actor.x, actor.y = x, y
    return world._mixed == 0
  end
  local probe = world._probe
  -- (no local more than needed: every local here is carried into each side trace of the
  -- phases on LuaJIT, see layer.lua's axis scan)
  if BRANCH_FREE then probe.before, probe.path = 0, abs(dx) + abs(dy)
  else probe.before, probe.path = 0, (dx < 0 and -dx or dx) + (dy < 0 and -dy or dy) end
  world._mixed = 0
  local x, y = actor.x, actor.y
  if dx ~= 0 then
    world._round = 1
    x = axis_phase(world, true, x, y, actor.width, actor.height, dx)
  end
  if dy ~= 0 then
    world._round = 2
    -- (x takes the first |dx| of the path; + 0: |-0| is +0 on every interpreter, as
    -- math.abs gives it, so a contact at the start of the y phase has t = +0, not -0)
    probe.before = BRANCH_FREE and abs(dx) or (dx < 0 and -dx or dx) + 0
    y = axis_phase(world, false, y, x, actor.height, actor.width, dy)
  end
  if world._sensor_count > 0 then
    sensors_crossed(world, actor, actor.x, actor.y, x, y, dx, dy, probe.path)
  end
  actor.x, actor.y = x, y
  return world._mixed == 0
end

-- swept ------------------------------------------------------------------------------

-- Reports the candidates of the cross set that the box (x, y, width, height) moving by
-- (dx, dy) enters (strictly) at a fraction of that motion in [from, to) and before
-- `contact`, as "cross" hits at time t0 + (1 - t0) * fraction of the move; once per move,
-- as report_crossings does. When this step is where the motion ends, with the box at
-- (end_x, end_y), that box decides what the times cannot at a rounding: one that overlaps
-- the candidate there entered it (at `contact`, or the end, when the times say later; at
-- 0 with no side when it started inside, even stopped at 0), and one still short of it on
-- an axis it moves along never did (the times can put the entry an ulp before the end of
-- a move that ends touching it).
local function report_swept_crossings(world, cross, x, y, width, height, dx, dy, from, to,
                                      contact, t0, end_x, end_y)
  local xs, ys, ws, hs = cross.x, cross.y, cross.w, cross.h
  for i = 1, cross.n do
    local bx, by = xs[i], ys[i]
    local enter, axis = box_enter(x, y, width, height, dx, dy, bx, by, ws[i], hs[i])
    local inside = false
    if end_x ~= nil then
      local right, bottom = far_sides(cross, i)
      local ends = sweep_ends(width, height, dx, dy, bx, by, right, bottom, end_x, end_y)
      if ends > 0 then
        -- (whatever window the times put its entry in: a step before this one may not
        -- have seen it, its end box an ulp short of it; a tile the move has reported
        -- already is left, as a record is by its stamp. One it started inside stays at
        -- 0 with no side, even stopped at 0.)
        inside = cross.record[i] ~= false
          or not has_tile(world, 1, cross.other[i], cross.col[i], cross.row[i])
        if not inside then enter = nil
        elseif axis ~= 0 and (enter == nil or not (enter < to and enter < contact)) then
          enter = contact < 1 and contact or 1
          axis = entry_axis(x, y, width, height, dx, dy, bx, by, right, bottom)
        end
      elseif ends < 0 then
        enter = nil
      end
    end
    if enter and (inside or enter >= from and enter < to and enter < contact) then
      local side
      if axis == 1 then side = dx > 0 and "right" or "left"
      elseif axis == 2 then side = dy > 0 and "floor" or "ceiling" end
      add_crossing(world, cross, i, side, t0 + (1 - t0) * enter)
    end
  end
end

-- The position on one axis (is_x) of a box stopped on the other, where the straight line
-- put it (pos, with the other axis at cross), moved back out of any candidate of the set
-- it overlaps there that, where the step began (from, from_cross), it overlapped across
-- but not on this axis: one that only this axis's motion brings it into, at a rounding
-- of the line (first_contact's times have it entered later). A oneway candidate only
-- moving down onto it from above (start_y: where the motion began).
local function keep_out(set, is_x, pos, cross, from, from_cross, size, cross_size, step,
                        start_y)
  if step == 0 then return pos end
  local lows, cross_lows, oneway = set.x, set.y, set.oneway
  if not is_x then lows, cross_lows = set.y, set.x end
  for i = 1, set.n do
    local low, cross_low = lows[i], cross_lows[i]
    if low < pos + size and cross_low < cross + cross_size then -- (no far side needed yet)
      local right, bottom = far_sides(set, i)
      local high, cross_high = right, bottom
      if not is_x then high, cross_high = bottom, right end
      if pos < high and cross < cross_high and not (low < from + size and from < high)
        and cross_low < from_cross + cross_size and from_cross < cross_high
        and (not oneway[i] or not is_x and step > 0 and low >= start_y + size) then
        if step > 0 then pos = before(low, size, from) else pos = high end
      end
    end
  end
  return pos
end

-- Travels from (x, y) along (dx, dy) in chunks no longer than a cell, so a huge move
-- looks at a thin band of the world, until the first contact; this motion is the part
-- of the move from time t0 on, and ends at (goal_x, goal_y) (x + dx, or the move's target
-- on an axis nothing has stopped: x + dx can round off it). Returns the position reached
-- and, on a contact, whether x and y are blocked, the fraction travelled and the response
-- that stopped it.
local function advance(world, x, y, dx, dy, round, t0, goal_x, goal_y)
  local probe = world._probe
  local actor, filter = probe.actor, probe.filter
  local width, height = actor.width, actor.height
  local enter, leave = 0, 1
  -- only solids and tiles block an actor with no filter, and sensors are crossed
  if filter == nil and world._sensor_count == 0 then
    enter, leave = clip_to_bounds(world, x, y, width, height, dx, dy)
    -- the box where the motion ends is looked at whatever the clip's roundings say: the
    -- goal and its far sides are not the clip's arithmetic
    local bounds = world._bounds
    if goal_x < bounds.max_x and bounds.min_x < goal_x + width and goal_y < bounds.max_y
      and bounds.min_y < goal_y + height then
      if enter == nil then enter = 1 end
      leave = 1
    elseif enter == nil then return goal_x, goal_y, nil end
  end
  -- The steps are those of the whole motion, whatever part of it is looked at: the result
  -- is the same with or without sensors, a filter, or solids far away.
  local adx, ady = dx < 0 and -dx or dx, dy < 0 and -dy or dy
  local chunks = ceil((adx > ady and adx or ady) / world.cell_size)
  if chunks < 1 then chunks = 1 elseif chunks > MAX_STEPS then chunks = MAX_STEPS end
  local first, last = floor(enter * chunks) + 1, ceil(leave * chunks)
  if first > chunks then first = chunks end
  if last < first then last = first end
  world._round = round
  local from_x, from_y = x + dx * ((first - 1) / chunks), y + dy * ((first - 1) / chunks)
  for k = first, last do
    local t_from = (k - 1) / chunks
    local t_to = k == chunks and 1 or k / chunks
    -- Each step begins where the one before ended (one from x + dx * t_from could begin an
    -- ulp inside what the end box before it was checked against) and ends at x + dx *
    -- t_to, the last at the goal: the box's far side there, goal_x + width, must not pass
    -- into what stops it.
    local end_x, end_y = x + dx * t_to, y + dy * t_to
    if k == chunks then end_x, end_y = goal_x, goal_y end
    local step_x, step_y = end_x - from_x, end_y - from_y
    local left, far_x = from_x, end_x + width
    if end_x < from_x then left, far_x = end_x, from_x + width end
    local top, far_y = from_y, end_y + height
    if end_y < from_y then top, far_y = end_y, from_y + height end
    local set, crossing = gather(world, left, top, far_x, far_y)
    local t = first_contact(set, x, y, from_x, from_y, width, height, step_x, step_y, end_x,
      end_y, chunks > 1 and dx or nil, dy)
    local contact = t and t_from + (t_to - t_from) * t
    if not t and crossing.n > 0 then -- (with a contact: below, where it stops)
      local last_step = k == chunks
      report_swept_crossings(world, crossing, x, y, width, height, dx, dy,
        k == first and -HUGE or t_from, k == last and HUGE or t_to, HUGE, t0,
        last_step and end_x or nil, last_step and end_y or nil)
    end
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
      local xs, ys, other, cols, rows, ids = set.x, set.y, set.other, set.col, set.row, set.id
      local responses = set.response
      local time = t0 + (1 - t0) * contact
      local response = SLIDE
      for c = 1, set.touch_n do
        local i, kind = touch[c], normal[c]
        local chosen = filter and responses[i] or SLIDE
        -- a solid the actor started inside stops it where it is (t is 0): no snapping
        local right, bottom = far_sides(set, i)
        local outside = not (xs[i] < x + width and x < right and ys[i] < y + height
          and y < bottom)
        local side
        if kind == NORMAL_X then
          world._round = round
          if not outside then new_x = from_x
          elseif step_x > 0 then new_x = before(xs[i], width, from_x) else new_x = right end
          side = step_x > 0 and "right" or "left"
        elseif kind == NORMAL_Y or corners_block then
          world._round = round + 1
          if not outside then new_y = from_y
          elseif step_y > 0 then new_y = before(ys[i], height, from_y)
          else new_y = bottom end
          side = step_y > 0 and "floor" or "ceiling"
        end
        if side then
          if chosen == TOUCH then response = TOUCH
          elseif chosen == BOUNCE and response ~= TOUCH then response = BOUNCE end
          add_hit(world, other[i], side, cols[i], rows[i], ys[i], xs[i], ids[i], chosen, time)
        end
      end
      -- the axis nothing blocks is where the straight line is at the contact's time,
      -- which can round an ulp into a candidate the times have it enter just after:
      -- kept out of it (the next slide meets it)
      if not blocked_x then
        new_x = keep_out(set, true, new_x, new_y, from_x, from_y, width, height, step_x, y)
      elseif not blocked_y then
        new_y = keep_out(set, false, new_y, new_x, from_y, from_x, height, width, step_y, y)
      end
      if crossing.n > 0 then
        world._round = round
        report_swept_crossings(world, crossing, x, y, width, height, dx, dy,
          k == first and -HUGE or t_from, HUGE, contact, t0, new_x, new_y)
      end
      return new_x, new_y, blocked_x, blocked_y, contact, response
    end
    from_x, from_y = end_x, end_y
  end
  return goal_x, goal_y, nil
end

local function move_swept(world, actor, dx, dy, filter)
  world._move_stamp = world._move_stamp + 1
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  local x, y = actor.x, actor.y
  local target_x, target_y = x + dx, y + dy
  -- where the motion on each axis ends: the target until something blocks that axis
  -- (a slide's x + dx * rest can round off it)
  local goal_x, goal_y = target_x, target_y
  local t0 = 0
  for slide = 1, MAX_SLIDES do
    if dx == 0 and dy == 0 then break end
    local blocked_x, blocked_y, travelled, response
    x, y, blocked_x, blocked_y, travelled, response = advance(world, x, y, dx, dy,
      slide * 2 - 1, t0, goal_x, goal_y)
    if blocked_x == nil or response == TOUCH then break end
    -- slide (or bounce): what is left of the move, less (or reflecting) the blocked part
    local rest = 1 - travelled
    t0 = t0 + (1 - t0) * travelled
    local keep = response == BOUNCE and -rest or 0
    dx = blocked_x and dx * keep or dx * rest
    dy = blocked_y and dy * keep or dy * rest
    if blocked_x then goal_x = x + dx end
    if blocked_y then goal_y = y + dy end
  end
  -- the slides' pieces, each rounded, can add up to an ulp more than the move: never
  -- further than asked (comparisons, not the sign of a product: with Lua 5.3+ integers a
  -- product of two distances over about 3e9 wraps around, and a move of 8e9 px through
  -- a wall ended at its target; a float product of tiny ones rounds to 0)
  local x0, y0 = actor.x, actor.y
  if (target_x > x0 and x > target_x) or (target_x < x0 and x < target_x) then x = target_x end
  if (target_y > y0 and y > target_y) or (target_y < y0 and y < target_y) then y = target_y end
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

-- The push-outs of a discrete move: each candidate the actor overlaps, in candidate
-- order, with the method's one-box rule.
local function resolve_discrete(world, actor, set, n, dx, dy, prev_y, filter, entry)
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
  local responses = set.response
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
      if side then
        add_hit(world, other[i], side, cols[i], rows[i], ys[i], xs[i], ids[i],
          filter and responses[i] or SLIDE, 1)
      end
    end
  end
end

-- Moves the whole way, then pushes the actor out of each solid it overlaps, top row
-- first and left to right, with the entry's one-box rule. Every blocking response is
-- that push (a discrete method has no path to touch or bounce along); contacts have t 1.
local function move_discrete(world, actor, dx, dy, filter, entry)
  local prev_y = actor.y
  local x, y, width, height = actor.x + dx, actor.y + dy, actor.width, actor.height
  local probe = world._probe
  probe.actor, probe.filter = actor, filter
  -- the filter runs here, before the actor moves: if it raises an error, nothing moved
  local set, crossing = gather(world, x, y, x + width, y + height)
  probe.actor, probe.filter = nil, nil
  actor.x, actor.y = x, y
  local n = set.n
  world._round = 1
  if n > 0 then resolve_discrete(world, actor, set, n, dx, dy, prev_y, filter, entry) end
  -- what it crosses: what the box overlaps where it ends (a discrete method has no path)
  local xs, ys, ws, hs = crossing.x, crossing.y, crossing.w, crossing.h
  for i = 1, crossing.n do
    if xs[i] < actor.x + width and actor.x < xs[i] + ws[i] and ys[i] < actor.y + height
      and actor.y < ys[i] + hs[i] then
      add_hit(world, crossing.other[i], nil, crossing.col[i], crossing.row[i], ys[i], xs[i],
        crossing.id[i], CROSS, 1)
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
