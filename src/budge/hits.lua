-- budge.hits: the contact records of one move, and the responses a filter may choose.
-- The world owns an array of records, reused from move to move (no garbage once warm);
-- a move fills them from index 1 and sorts them into the order they happened.

local box = require((...):match("^(.*)%.[^%.]+$") .. ".box")

local describe = box.describe
local format, error, setmetatable = string.format, error, setmetatable

local hits = {}

---One contact of a move. Owned by the world and reused: valid until the next move (a
---check has records of its own).
---@class budge.Hit
---@field other table the solid, sensor or actor box, or the tile layer handle
---@field side? "floor"|"ceiling"|"left"|"right" which side of the actor touched (nil: a
---"cross" hit the actor was already inside at the start of the move, or of a phase of it)
---@field col? integer the tile's column, for a tile layer
---@field row? integer the tile's row, for a tile layer
---@field response "slide"|"touch"|"bounce"|"cross" what the filter chose ("slide" with no filter; "cross" for a sensor)
---@field t number the fraction of the move at which the contact happened (0: at its start)
---@field nx integer the face's normal, from `other` toward the actor: -1, 0 or 1
---@field ny integer
---@field package _top number sort keys after t: the top and left of what was met,
---@field package _left number
---@field package _id integer the order its item was added,
---@field package _round integer and the phase of the move it happened in

-- The responses, and the one a filter's `true` stands for.
local RESPONSE = {slide = "slide", touch = "touch", bounce = "bounce", cross = "cross"}
RESPONSE[true] = "slide"
hits.SLIDE, hits.TOUCH, hits.BOUNCE, hits.CROSS = "slide", "touch", "bounce", "cross"
local SLIDE = hits.SLIDE

-- The normal of the face each side of the actor meets (0, 0 for no side), written into
-- each hit with its side.
-- LuaJIT shaping: written, not read through a metatable's __index: a store into a table
-- with a metatable compiles to a test of the type of the value it replaces (a nil there
-- would ask the metatable for __newindex), so a record that held a box's contact (no col,
-- no row) and then a tile's took a side trace at each such field. Written: make
-- bench-jit's platformer needed 322 KB of machine code instead of 414 with a budget that
-- never runs out (`luajit bench/jit.lua --scene platformer --budget large`, 7 fresh runs
-- each, interleaved, medians, 2026-12-02); the world bench's tile moves on LuaJIT were
-- unchanged (193 against 194 ns, 11 runs each) and on Lua 5.4 ran 1.8% more instructions
-- (24015 against 23586 a move, under cachegrind).
local NX = {left = 1, right = -1, floor = 0, ceiling = 0}
local NY = {left = 0, right = 0, floor = -1, ceiling = 1}
setmetatable(NX, {__index = function() return 0 end})
setmetatable(NY, {__index = function() return 0 end})
hits.NX, hits.NY = NX, NY

-- A new hit record, its fields made in one order.
local function new_hit()
  return {other = false, side = false, col = false, row = false, response = SLIDE, t = 0,
    nx = 0, ny = 0, _top = 0, _left = 0, _id = 0, _round = 0}
end

-- An error a filter's return value caused: entry.guarded raises its message at the line
-- that called the world (a game's own errors pass through unchanged).
local BadResponse = {}
BadResponse.__index = BadResponse
hits.BadResponse = BadResponse

---What a filter's return value means: "slide", "touch", "bounce" or "cross", or nil to
---ignore (false and nil). Raises a BadResponse error for any other value.
---@param value any what the filter returned
---@param other any what it was asked about (named in the error)
---@return "slide"|"touch"|"bounce"|"cross"|nil
function hits.response(value, other)
  if value == nil or value == false then return nil end
  local response = RESPONSE[value]
  if response == nil then
    error(setmetatable({message = format("actor.filter must return \"slide\" (or true), "
      .. "\"touch\", \"bounce\", \"cross\", or false/nil to ignore, got %s for %s",
      describe(value), describe(other))}, BadResponse))
  end
  return response
end

---A new list of hit records, with room for a few contacts already made (hits.add_tiles
---writes two at a time).
---@return budge.Hit[]
function hits.new_list()
  local list = {}
  for i = 1, 8 do list[i] = new_hit() end
  return list
end

---Appends a contact with `other` (a box, or a tile layer with the tile's col and row) to
---the world's hits, in the world's current round; `top` and `left` are the corner of
---what was met (the box's, or the tile's), its sort keys after `t`.
---LuaJIT shaping: the callers pass top and left, which they have at hand; computed here
---from `other`, the branch made make bench-jit's platformer compile 606 traces and
---790-813 KB instead of 535 and 621-627 (median of 6 runs with a budget that never runs
---out, 2026-12-01).
---@param world budge.World
---@param other table
---@param side? "floor"|"ceiling"|"left"|"right"
---@param col? integer
---@param row? integer
---@param top number
---@param left number
---@param id integer
---@param response "slide"|"touch"|"bounce"|"cross"
---@param t number
function hits.add(world, other, side, col, row, top, left, id, response, t)
  local n = world._n_hits + 1
  local hit = world._hits[n]
  if hit == nil then
    hit = new_hit()
    world._hits[n] = hit
  end
  hit.other, hit.side, hit.col, hit.row = other, side, col, row
  hit.nx, hit.ny = NX[side], NY[side]
  hit.response, hit.t = response, t
  hit._top, hit._left = top, left
  hit._id, hit._round = id, world._round
  world._n_hits = n
end

-- Writes tile (col, row) of `tiles` into `hit` as a "slide" contact (hits.add's fields).
local function fill_tile(hit, tiles, side, col, row, id, round, t)
  hit.other, hit.side, hit.col, hit.row, hit.response, hit.t = tiles, side, col, row, SLIDE, t
  hit.nx, hit.ny = NX[side], NY[side]
  hit._top, hit._left = tiles.y + (row - 1) * tiles.tile_height,
    tiles.x + (col - 1) * tiles.tile_width
  hit._id, hit._round = id, round
end

---Appends the `count` tiles of `tiles` listed in cols and rows (1-based) as "slide"
---contacts on `side` at time t.
---LuaJIT shaping: one or two tiles (a box at most two tiles across) are written without
---a loop or a branch: both records are filled (the second is left past the end when
---count is 1), so that a move's trace does not fork on how many tiles it met. With the
---loop, every run of `luajit -jv bench/world.lua --way tiles --count 1000` had 16-24
---"NYI: register coalescing too complex" aborts there and 7-13 side traces left to the
---interpreter; written this way, 0 and 3-5 (3 runs each); make bench-jit's platformer
---needs 515 KB instead of 549 with a budget that never runs out (medians of 9 runs each,
---interleaved, 2026-12-02).
---@param world budge.World
---@param tiles budge.TileLayer
---@param side "floor"|"ceiling"|"left"|"right"
---@param cols integer[] at least two entries, numbers
---@param rows integer[]
---@param count integer
---@param t number
function hits.add_tiles(world, tiles, side, cols, rows, count, t)
  local n = world._n_hits
  local list = world._hits
  if count > 2 or list[n + 2] == nil then
    local id = world._records[tiles].id
    for c = 1, count do
      local col, row = cols[c], rows[c]
      hits.add(world, tiles, side, col, row, tiles.y + (row - 1) * tiles.tile_height,
        tiles.x + (col - 1) * tiles.tile_width, id, SLIDE, t)
    end
    return
  end
  local id, round = world._records[tiles].id, world._round
  fill_tile(list[n + 1], tiles, side, cols[1], rows[1], id, round, t)
  fill_tile(list[n + 2], tiles, side, cols[2], rows[2], id, round, t)
  world._n_hits = n + count
end

---Moves the hits after index `from` down to follow index `first` (first <= from): those
---between are dropped (their records go past the new end, for later moves to reuse).
---@param world budge.World
---@param first integer
---@param from integer
function hits.shift(world, first, from)
  local list, n = world._hits, world._n_hits
  if from == first then return end
  for i = from + 1, n do -- (i's record is never one moved there: first + i - from < i)
    local to = first + i - from
    list[to], list[i] = list[i], list[to]
  end
  world._n_hits = n - (from - first)
end

---Writes the sort keys (hits.add's) of the hits from index `first` on, all of them
---tiles (layer.tile_stop writes its hits without them).
---@param world budge.World
---@param first integer
function hits.key_tiles(world, first)
  local list, records, round = world._hits, world._records, world._round
  for i = first, world._n_hits do
    local hit = list[i]
    local tiles, col, row = hit.other, hit.col, hit.row
    hit._top, hit._left = tiles.y + (row - 1) * tiles.tile_height,
      tiles.x + (col - 1) * tiles.tile_width
    hit._id, hit._round = records[tiles].id, round
  end
end

---Appends one or two tiles of `tiles` on one line as "slide" contacts on `side` at time
---t: tile `across` (0-based across the axis: its row when is_x, else its column) and,
---when count is 2, tile `last`, both on line `line` (0-based along the axis). For a move
---whose hits are never sorted (it returns in_order to world:move and world:check): the
---sort keys (_top, _left, _id, _round) are not written.
---Speed: the tiles as values, not through probe.cols and probe.rows, and no sort keys:
---`luajit bench/world.lua --way tiles --count 1000`, 9 fresh runs each, interleaved,
---2026-12-02: 150 ns per move against 190 through list_line and hits.add_tiles.
---@param world budge.World
---@param tiles budge.TileLayer
---@param side "floor"|"ceiling"|"left"|"right"
---@param nx number NX[side]
---@param ny number NY[side]
---@param is_x boolean
---@param line integer
---@param across integer
---@param last integer
---@param count integer 1 or 2
---@param t number
function hits.add_line_pair(world, tiles, side, nx, ny, is_x, line, across, last, count, t)
  local n = world._n_hits
  local list = world._hits
  local col, row, last_col, last_row = across + 1, line + 1, last + 1, line + 1
  if is_x then col, row, last_col, last_row = line + 1, across + 1, line + 1, last + 1 end
  if list[n + 2] == nil then -- (the list grows: hits.add writes every field)
    local id = world._records[tiles].id
    hits.add(world, tiles, side, col, row, tiles.y + (row - 1) * tiles.tile_height,
      tiles.x + (col - 1) * tiles.tile_width, id, SLIDE, t)
    if count > 1 then
      hits.add(world, tiles, side, last_col, last_row, tiles.y + (last_row - 1)
        * tiles.tile_height, tiles.x + (last_col - 1) * tiles.tile_width, id, SLIDE, t)
    end
    return
  end
  local hit = list[n + 1]
  hit.other, hit.side, hit.col, hit.row, hit.response, hit.t = tiles, side, col, row, SLIDE, t
  hit.nx, hit.ny = nx, ny
  hit = list[n + 2] -- (past the end when count is 1)
  hit.other, hit.side, hit.col, hit.row, hit.response, hit.t = tiles, side, last_col, last_row,
    SLIDE, t
  hit.nx, hit.ny = nx, ny
  world._n_hits = n + count
end

-- Contacts of one move come out in the order they happened: by t; at the same t, by the
-- phase of the move (x before y, a slide's rounds in turn), then by position (top, then
-- left) and then by the order items were added. (The phase is compared first: each phase
-- takes a later part of the move than the one before it, so that is the same order, and
-- the contacts of one phase mostly share their t.)
local function hit_before(a, b)
  if a._round ~= b._round then return a._round < b._round end
  if a.t ~= b.t then return a.t < b.t end
  if a._top ~= b._top then return a._top < b._top end
  if a._left ~= b._left then return a._left < b._left end
  return a._id < b._id
end

---True when the world's hits from `first` on already hold the tile (col, row) of `tiles`.
---@param world budge.World
---@param first integer
---@param tiles table
---@param col integer
---@param row integer
---@return boolean
function hits.has_tile(world, first, tiles, col, row)
  local list = world._hits
  for i = first, world._n_hits do
    local hit = list[i]
    -- (col first: a hit on a game's box has none, and `==` on its table would run the
    -- game's __eq on Lua 5.3+)
    if hit.col == col and hit.row == row and hit.other == tiles then return true end
  end
  return false
end

-- Insertion sort of list[first..last] by hit_before (stable).
local function sort_run(list, first, last)
  for i = first + 1, last do
    local hit = list[i]
    local j = i - 1
    while j >= first and hit_before(hit, list[j]) do
      list[j + 1] = list[j]
      j = j - 1
    end
    list[j + 1] = hit
  end
end

-- Hits a move sorts by insertion alone; past that, runs of this many, merged.
local RUN = 16

---Merges list[1..n], sorted in runs of `width` (the last may be shorter), into one
---sorted run, stable: by `before(a, b, ctx)`, true when a comes strictly before b (an
---element of the right run goes first only then). Through `scratch` (a table the caller
---keeps, so that no garbage is made; left holding the elements it last held). Shared by
---the sorts that must not cost the square of their length: a move's hits, a filtered
---phase's candidates (move.lua), budge.bump's project.
---@param list any[]
---@param n integer
---@param width integer
---@param before fun(a: any, b: any, ctx: any): boolean
---@param ctx any passed to `before`
---@param scratch any[]
function hits.merge_runs(list, n, width, before, ctx, scratch)
  local from, to = list, scratch
  while width < n do
    for low = 1, n, 2 * width do
      local mid = low + width - 1
      if mid > n then mid = n end
      local high = low + 2 * width - 1
      if high > n then high = n end
      local i, j = low, mid + 1
      for k = low, high do -- (the right run's first only when strictly before: stable)
        if j > high or (i <= mid and not before(from[j], from[i], ctx)) then
          to[k] = from[i]
          i = i + 1
        else
          to[k] = from[j]
          j = j + 1
        end
      end
    end
    from, to, width = to, from, 2 * width
  end
  if not rawequal(from, list) then
    for k = 1, n do list[k] = from[k] end
  end
end

---Sorts list[1..n] by `before(a, b, ctx)` (true when a comes strictly before b),
---stable: by insertion in runs of `width`, then merge_runs through `scratch`, which it
---leaves empty. For sorts off the move's compiled path (budge.bump's project): hits.sort
---and move.lua's sort_met keep their comparisons in line.
---@param list any[]
---@param n integer
---@param width integer
---@param before fun(a: any, b: any, ctx: any): boolean
---@param ctx any passed to `before`
---@param scratch any[]
function hits.sort_runs(list, n, width, before, ctx, scratch)
  for first = 1, n, width do
    local last = first + width - 1
    if last > n then last = n end
    for k = first + 1, last do
      local value = list[k]
      local j = k - 1
      while j >= first and before(value, list[j], ctx) do
        list[j + 1] = list[j]
        j = j - 1
      end
      list[j + 1] = value
    end
  end
  if n > width then
    hits.merge_runs(list, n, width, before, ctx, scratch)
    for k = 1, n do scratch[k] = nil end
  end
end

---Sorts the world's hits 1.._n_hits into the order they happened.
---Speed: an insertion sort, not table.sort: a move has a handful of contacts, and
---table.sort's calls back into Lua leave LuaJIT's compiled code. With table.sort the
---world bench's tile moves take 304 ns instead of 232 on LuaJIT, 2454 instead of 2290 on
---Lua 5.4 (`luajit bench/world.lua --profile tiles`, median of 5, 2026-12-01). More than
---RUN hits (a player walking into a pile of coins) are sorted in runs of RUN, merged
---(hits.merge_runs), through a scratch list the world keeps: the insertion sort alone
---took a review's move into 8000 scattered coins 177 ms on LuaJIT and 1655 ms on Lua 5.4
---(quadratic in the hits).
---@param world budge.World
function hits.sort(world)
  local list, n = world._hits, world._n_hits
  if n <= RUN then sort_run(list, 1, n) return end
  for first = 1, n, RUN do sort_run(list, first, first + RUN <= n and first + RUN - 1 or n) end
  local scratch = world._sort_scratch
  if scratch == nil then scratch = {}; world._sort_scratch = scratch end
  hits.merge_runs(list, n, RUN, hit_before, nil, scratch)
end

return hits
