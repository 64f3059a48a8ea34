-- budge.sweep: the continuous rungs of the ladder, solved over a candidate set.
--
-- A candidate set is a struct of parallel arrays (x, y, w, h, oneway, other, col, row,
-- id) filled by the broad phase, so that a move allocates nothing. Two solvers:
--
-- * stop_forward / stop_backward: where a box moving along one axis stops against one
--   candidate ("axis_sweep" applies them for x, then for y from where x ended: the
--   actors-and-solids model of the Celeste and TowerFall games, done with exact faces
--   instead of pixel by pixel; layer.lua and hash.lua run them over tiles and boxes).
-- * first_contact: the time of impact of a box moving along a straight diagonal
--   ("swept": the classic swept AABB of the Minkowski-sum literature), with each
--   contact classified by the axis it came in on.
--
-- Touching is not a collision: a face counts only when the mover's interval overlaps
-- the candidate's strictly on the other axis, so sliding along a floor made of separate
-- tiles never catches on a seam.

local HUGE = math.huge

local sweep = {}

sweep.NORMAL_X, sweep.NORMAL_Y, sweep.NORMAL_CORNER = 1, 2, 3

-- The largest number below 1: the time of a contact the box where a motion ends
-- shows but the rounded entry times put at its end or later.
local BELOW_ONE = 1 - 2 ^ -53

---The candidates of one move, as parallel arrays indexed 1..n, filled by the broad phase
---(solids.lua) and read by first_contact and the discrete methods. Owned by one world.
---@class budge.CandidateSet
---@field n integer how many candidates
---@field x number[] each candidate's box
---@field y number[]
---@field w number[]
---@field h number[]
---@field oneway boolean[] blocks only moves down onto its top
---@field other table[] what a hit names: the solid box, or the tile layer handle
---@field col (integer|nil)[] the tile's column (1-based), nil for a box
---@field row (integer|nil)[] the tile's row (1-based), nil for a box
---@field id integer[] the order its item was added to the world (the last tie-breaker)
---@field response string[] what the moving actor's filter chose for each (read only when it has one)
---@field record (budge.Record|false)[] each box's record (false for a tile), where kept
---@field key number[] scratch of a filtered axis phase: how far along the path each is met
---@field touch integer[] first_contact's output: indices of the candidates met first
---@field normal integer[] and how each was met (NORMAL_X, NORMAL_Y or NORMAL_CORNER)
---@field touch_n integer how many of touch/normal are valid
---@field scratch integer[] scratch of a filtered axis phase's merge sort (move.lua's sort_met)

---A new, empty candidate set.
---@return budge.CandidateSet
function sweep.new_set()
  return {
    n = 0, x = {}, y = {}, w = {}, h = {}, oneway = {}, other = {}, col = {}, row = {},
    id = {}, response = {}, record = {}, key = {},
    touch = {}, normal = {}, touch_n = 0, scratch = {},
  }
end

---One box moving along one axis, filled by move.lua and read by the axis scans of
---hash.lua (Hash:axis_stop) and layer.lua (layer.tile_face), with the best stop found so
---far. (move.lua's lean_solids_phase hands the box's values to Hash:lean_stop instead and
---writes only the outputs' start: after its phases the inputs hold an earlier phase's.)
---Owned by one world, so a filter that moves an actor of another world cannot disturb it.
---LuaJIT shaping: these values travel in a table rather than as arguments, which keeps
---each compiled scan loop small: LuaJIT aborts a trace whose exits carry more live values
---than it can coalesce (commit 2e07fe1; aborts listed by make bench-jit). (The scan of a
---packed hash takes its loop's values as arguments: its loop only reads them, see
---hash.lua's packed_scan.)
---@class budge.AxisProbe
---@field is_x boolean moving along x (else y)
---@field forward boolean toward +x or +y
---@field pos number the box's low coordinate on the axis
---@field size number its extent on the axis
---@field edge number pos + size
---@field reach number where the leading edge gets to after the whole move
---@field delta number the move along the axis (+ forward)
---@field cross number the box's low coordinate across the axis
---@field cross_end number and its high one
---@field blocks_oneway boolean oneway candidates stop this move (moving down)
---@field actor? table the moving box, passed to the filter
---@field filter? fun(actor: table, other: any, col?: integer, row?: integer, id?: any): any
---the moving actor's filter (gathering reads it)
---@field before number px of the move's path before this phase (hits' times: move.lua)
---@field path number the move's whole path, px
---@field best? number output: the nearest stop found so far
---@field touch any[] output: the hashed records that stop the box at best (or what the
---hash's entries hold instead of its records: their payload, see hash.new)
---@field touch_id integer[] output: their ids (a world record's [6]), read from the store
---for a packed entry
---@field payload integer|false Hash:axis_stop's: the hash's payload slot (hash.new)
---@field touched integer output: how many of touch are valid
---@field touch_left number[] output: their boxes' left sides, as the hash holds them (the
---hits' sort keys, read there rather than from each record's item: at 10000 actors moving
---among boxes, another cache miss per hit)
---@field touch_top number[] output: their top sides
---@field sources integer output: how many layers and boxes the phase's hits at best come
---from (move.lua: hits from one are already in order)
---@field cols integer[] output of layer.tile_face: the tiles on the face found
---@field rows integer[]

---A new, empty axis probe.
---@return budge.AxisProbe
function sweep.new_probe()
  return {is_x = true, forward = true, pos = 0, size = 0, edge = 0, reach = 0, delta = 0,
    cross = 0, cross_end = 0, blocks_oneway = false, before = 0, path = 1, touch = {},
    touched = 0, touch_left = {}, touch_top = {}, touch_id = {}, payload = false,
    sources = 0, cols = {1, 1}, rows = {1, 1}}
end

---One axis of a slab clip (Liang-Barsky): narrows [enter, leave], the fractions of the
---motion start + delta * t, to where the coordinate lies between low and high. With
---delta 0 the coordinate never changes: it must lie between them (strictly when `open`).
---Returns nil when the motion never gets there.
---@param start number
---@param delta number
---@param low number
---@param high number
---@param enter number
---@param leave number
---@param open boolean
---@return number? enter, number? leave
function sweep.clip_axis(start, delta, low, high, enter, leave, open)
  if delta == 0 then
    if open then
      if not (low < start and start < high) then return nil, nil end
    elseif start < low or start > high then
      return nil, nil
    end
    return enter, leave
  end
  local t0, t1 = (low - start) / delta, (high - start) / delta
  if t0 > t1 then t0, t1 = t1, t0 end
  if t0 > enter then enter = t0 end
  if t1 < leave then leave = t1 end
  return enter, leave
end

---True when `size` is a power of two (2^k for some integer k): the hash's cells and the
---tile layers whose divisions by their sides are exact (hash.lua's packed_end, layer.lua's
---_pow2). False for 0, negative sizes, infinity and NaN.
---@param size number
---@return boolean
function sweep.power_of_two(size)
  if not (size > 0 and size < math.huge) then return false end
  while size >= 2 do size = size / 2 end
  while size < 1 do size = size * 2 end
  return size == 1
end

---The largest position p with p + size <= face: where a box of `size` stops with its
---leading edge on `face`. Equal to face - size whenever that is exact (integers, and
---halves, quarters... of them); otherwise a few ulps less, never an overlap. `low`, when
---given, is where the box is now: if it already fits (low + size <= face) and lies
---beyond face - size by a rounding, the box stays there instead of stepping back an ulp
---(into whatever touches its trailing edge).
---@param face number
---@param size number
---@param low? number
---@return number
function sweep.before(face, size, low)
  local position = face - size
  if position + size > face then
    local step = ((face < 0 and -face or face) + size) * 2 ^ -52
    repeat position = position - step until position + size <= face
  end
  if low ~= nil and low > position and low + size <= face then return low end
  return position
end

---Fraction of the segment (x1, y1) + (dx, dy) * t, 0 <= t <= 1, at which it enters the
---open box, or nil if it never does.
---@param x1 number
---@param y1 number
---@param dx number
---@param dy number
---@param bx number
---@param by number
---@param bw number
---@param bh number
---@return number?
function sweep.segment_enter(x1, y1, dx, dy, bx, by, bw, bh)
  local enter, leave = sweep.clip_axis(x1, dx, bx, bx + bw, 0, 1, true)
  if enter == nil then return nil end
  enter, leave = sweep.clip_axis(y1, dy, by, by + bh, enter, leave, true)
  if enter == nil then return nil end
  if enter < leave or (enter == leave and dx == 0 and dy == 0) then return enter end
  return nil
end

-- The axis rules: where a box moving along one axis stops against one candidate.
-- `pos` and `edge` are the box's low and high coordinates on that axis, `reach` the
-- leading edge's coordinate after the full move. The caller has checked that the
-- candidate overlaps the box strictly on the other axis.
--
-- A candidate stops the box when its near face lies ahead within reach. A box the game
-- teleported into a candidate may leave it but not go deeper: a candidate whose near
-- face is inside the box stops it where it is, which keeps an actor squeezed between two
-- walls in place instead of passing it through one. Oneway candidates stop only moves
-- that `blocks_oneway` (down), and only from outside.

---Moving toward +x or +y against a candidate whose low face is at `near`: the position
---where the box stops, or nil.
---@param near number
---@param pos number
---@param edge number
---@param reach number
---@param size number
---@param oneway boolean
---@param blocks_oneway boolean
---@return number?
function sweep.stop_forward(near, pos, edge, reach, size, oneway, blocks_oneway)
  if near >= reach then return nil end
  -- ahead of the leading edge first: for a box of size 0 (pos == edge) a face touching it
  -- is ahead, not behind
  if near >= edge then
    if blocks_oneway or not oneway then return sweep.before(near, size, pos) end
    return nil
  end
  if near <= pos or oneway then return nil end
  return pos
end

---Moving toward -x or -y against a candidate whose high face is at `far`: the position
---where the box stops, or nil.
---@param far number
---@param pos number
---@param edge number
---@param reach number
---@param oneway boolean
---@param blocks_oneway boolean
---@return number?
function sweep.stop_backward(far, pos, edge, reach, oneway, blocks_oneway)
  if far <= reach then return nil end
  if far <= pos then -- (before the edge test, for a box of size 0)
    if blocks_oneway or not oneway then return far end
    return nil
  end
  if far >= edge or oneway then return nil end
  return pos
end

---The far sides (right, bottom) of candidate i of the set: for a tile, its layer's edge
---`origin + col * tile`, as the layer's scans and queries have it (with a fractional
---origin or tile size, `x + w` can round below it); for a box, x + w and y + h.
---@param set budge.CandidateSet
---@param i integer
---@return number right, number bottom
function sweep.far_sides(set, i)
  local col = set.col[i]
  if col ~= nil then -- (a tile: every gather writes col, nil for a box)
    local tiles = set.other[i]
    return tiles.x + col * tiles.tile_width, tiles.y + set.row[i] * tiles.tile_height
  end
  return set.x[i] + set.w[i], set.y[i] + set.h[i]
end

-- Entry and exit times of [pos, pos + size] moving `delta` against [other, other_far]
-- (strict overlap). nil when they never overlap on this axis.
local function interval_times(pos, size, delta, other, other_far)
  if delta > 0 then
    return (other - (pos + size)) / delta, (other_far - pos) / delta
  elseif delta < 0 then
    return (other_far - pos) / delta, (other - (pos + size)) / delta
  elseif pos < other_far and other < pos + size then
    return -HUGE, HUGE
  end
  return nil, nil
end

-- Whether the box (x, y, w, h) moving by (dx, dy) only touches the box from (bx, by) to
-- (right, bottom) along the whole line: it comes in across both axes no earlier than it
-- leaves across one (first_contact's test for a step, on the whole motion).
local function grazed(x, y, w, h, dx, dy, bx, by, right, bottom)
  local enter_x, exit_x = interval_times(x, w, dx, bx, right)
  local enter_y, exit_y = interval_times(y, h, dy, by, bottom)
  if enter_x == nil or enter_y == nil then return true end
  local enter = enter_x > enter_y and enter_x or enter_y
  local exit = exit_x < exit_y and exit_x or exit_y
  return not (enter < exit) -- luacheck: ignore (not >=: the test first_contact makes)
end

---When the box (x, y, w, h) moving by (dx, dy), 0 <= t <= 1, first overlaps the box (bx,
---by, bw, bh) strictly: the fraction t (0 when it overlaps at the start) and the axis it
---came in across (1 for x, 2 for y, also for both at once; 0 when it overlapped at the
---start), or nil when it never does.
---@param x number
---@param y number
---@param w number
---@param h number
---@param dx number
---@param dy number
---@param bx number
---@param by number
---@param bw number
---@param bh number
---@return number? t, integer? axis
function sweep.box_enter(x, y, w, h, dx, dy, bx, by, bw, bh)
  local enter_x, exit_x = interval_times(x, w, dx, bx, bx + bw)
  if enter_x == nil then return nil, nil end
  local enter_y, exit_y = interval_times(y, h, dy, by, by + bh)
  if enter_y == nil then return nil, nil end
  local enter = enter_x > enter_y and enter_x or enter_y
  local exit = exit_x < exit_y and exit_x or exit_y
  if enter >= exit or enter >= 1 or exit <= 0 then return nil, nil end
  if enter < 0 then return 0, 0 end
  return enter, enter_x > enter_y and 1 or 2
end


---box_enter's time for a motion that ends with the box at (end_x, end_y) (x + dx can
---round elsewhere), where that box decides what the rounded times cannot: a box that
---overlaps the other there entered it (at the largest time below 1 when the times say 1
---or later), and one still short of it on an axis it moves along never did (the times
---can put the entry an ulp before the end of a motion that ends touching it).
---@param x number
---@param y number
---@param w number
---@param h number
---@param dx number
---@param dy number
---@param bx number
---@param by number
---@param bw number
---@param bh number
---@param end_x number
---@param end_y number
---@return number? t
function sweep.box_enter_to(x, y, w, h, dx, dy, bx, by, bw, bh, end_x, end_y)
  local ends = sweep.ends(w, h, dx, dy, bx, by, bx + bw, by + bh, end_x, end_y)
  if ends < 0 then return nil end
  local t = sweep.box_enter(x, y, w, h, dx, dy, bx, by, bw, bh)
  if t == nil and ends > 0 then return BELOW_ONE end
  return t
end

---Where a box (w, h) moving by (dx, dy) ends, at (end_x, end_y), against the box from
---(bx, by) to its far sides (right, bottom): 1 when it overlaps it there (it entered it),
----1 when it is still short of it on an axis it moves along (it never entered it: on
---that axis it was short all along), 0 otherwise (the times decide).
---@param w number
---@param h number
---@param dx number
---@param dy number
---@param bx number
---@param by number
---@param right number
---@param bottom number
---@param end_x number
---@param end_y number
---@return integer
function sweep.ends(w, h, dx, dy, bx, by, right, bottom, end_x, end_y)
  if end_x < right and bx < end_x + w and end_y < bottom and by < end_y + h then return 1 end
  if (dx > 0 and end_x + w <= bx) or (dx < 0 and end_x >= right) or (dy > 0 and end_y + h <= by)
    or (dy < 0 and end_y >= bottom) then
    return -1
  end
  return 0
end

---The axis (1: x, 2: y) across which the box (x, y, w, h) moving by (dx, dy) comes into
---the box from (bx, by) to its far sides (right, bottom) last, as box_enter has it (y on a
---tie): for a contact the rounded times put at the end of the motion or past it, which the
---box where the motion ends shows (see first_contact).
---@param x number
---@param y number
---@param w number
---@param h number
---@param dx number
---@param dy number
---@param bx number
---@param by number
---@param right number
---@param bottom number
---@return integer axis
function sweep.entry_axis(x, y, w, h, dx, dy, bx, by, right, bottom)
  local enter_x = interval_times(x, w, dx, bx, right)
  local enter_y = interval_times(y, h, dy, by, bottom)
  return (enter_x or -HUGE) > (enter_y or -HUGE) and 1 or 2
end

sweep.BELOW_ONE = BELOW_ONE

---Time of impact in [0, 1) of the box (x, y, w, h) moving (dx, dy) against the set, or
---nil. A candidate that overlaps the box at (start_x, start_y), where the move began,
---stops it at time 0 on each axis where the move goes deeper into it (its near face is
---inside the box), as the axis rules above do, and lets it leave otherwise; any other candidate
---that overlaps at (x, y) already (by rounding between steps of a long move) is met at
---time 0. A candidate the box overlaps where the step ends, at (end_x, end_y) (the
---caller's end: x + dx can round elsewhere), is met within the step whatever the entry
---times' roundings say (at the largest time below 1 when they put it at the end or
---later), so that a step never ends inside what stops it. Lists the candidates met at
---that time in set.touch and how each was met in set.normal: NORMAL_X when it came in
---across x last, NORMAL_Y across y, NORMAL_CORNER when both at the same instant. A
---oneway candidate is met only from above: moving down, its top at or below the box's
---bottom at the start, and entered across y. A tile's far sides are its layer's edges
---(far_sides).
---@param set budge.CandidateSet
---@param start_x number where the whole move began
---@param start_y number
---@param x number where this step of it begins
---@param y number
---@param w number
---@param h number
---@param dx number
---@param dy number
---@param end_x number where this step ends
---@param end_y number
---@param move_dx? number the whole motion from (start_x, start_y), when the step is a part
---of it: a candidate the step's times say it enters, whose whole motion's times say it
---only touches (a corner grazed: entry and exit at the same time), is not met. (A step's
---ends are the motion's points rounded, which can tilt the step's line by an ulp, and a
---graze became an overlap one ulp of time long.)
---@param move_dy? number
---@return number? t
function sweep.first_contact(set, start_x, start_y, x, y, w, h, dx, dy, end_x, end_y,
                             move_dx, move_dy)
  local xs, ys, ws, hs, oneway, cols = set.x, set.y, set.w, set.h, set.oneway, set.col
  local touch, normal = set.touch, set.normal
  local touched = 0
  local best = 1
  for i = 1, set.n do
    local bx, by = xs[i], ys[i]
    local right, bottom -- (far_sides written out: a call per candidate cost more)
    local col = cols[i]
    if col ~= nil then
      local tiles = set.other[i]
      right, bottom = tiles.x + col * tiles.tile_width, tiles.y + set.row[i] * tiles.tile_height
    else
      right, bottom = bx + ws[i], by + hs[i]
    end
    if start_x < right and bx < start_x + w and start_y < bottom and by < start_y + h then
      if not oneway[i] then
        local deeper_x = (dx > 0 and bx > start_x) or (dx < 0 and right < start_x + w)
        local deeper_y = (dy > 0 and by > start_y) or (dy < 0 and bottom < start_y + h)
        if deeper_x or deeper_y then
          if best > 0 then best = 0; touched = 0 end
          if deeper_x then
            touched = touched + 1
            touch[touched], normal[touched] = i, 1
          end
          if deeper_y then
            touched = touched + 1
            touch[touched], normal[touched] = i, 2
          end
        end
      end
    else
      local enter_x, exit_x = interval_times(x, w, dx, bx, right)
      if enter_x then
        local enter_y, exit_y = interval_times(y, h, dy, by, bottom)
        if enter_y then
          local enter = enter_x > enter_y and enter_x or enter_y
          local exit = exit_x < exit_y and exit_x or exit_y
          if not (enter < exit and exit > 0) then enter = nil
          elseif move_dx ~= nil and grazed(start_x, start_y, w, h, move_dx, move_dy, bx, by,
            right, bottom) then
            enter = nil
          end
          if (enter == nil or enter >= 1) and end_x < right and bx < end_x + w
            and end_y < bottom and by < end_y + h then
            enter = BELOW_ONE -- (it ends inside it: entered within the step)
          end
          if enter ~= nil and enter <= best then
            if enter < 0 then enter = 0 end
            if not oneway[i] or (dy > 0 and by >= start_y + h and enter_y >= enter_x) then
              if enter < best then best = enter; touched = 0 end
              if enter < 1 then
                touched = touched + 1
                touch[touched] = i
                normal[touched] = enter_x > enter_y and 1 or (enter_y > enter_x and 2 or 3)
              end
            end
          end
        end
      end
    end
  end
  set.touch_n = touched
  if touched == 0 then return nil end
  return best
end

return sweep
