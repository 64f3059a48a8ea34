-- budge.bump: bump.lua 3.1.7's API on budge's engine, so that a game written for bump
-- switches with one line: `local bump = require("budge.bump")`. README.md, "Coming from
-- bump.lua", lists what differs from bump and why.
--
-- Every bump item is an actor of a budge world, standing for itself through a proxy box
-- the front end owns (the game's own values are keys, never written to), so every item
-- can block every other, as in bump. world:move runs bump's response loop (legs toward
-- the goal; touch, cross, slide, bounce and custom responses; what a move met is not met
-- again) on budge's narrow phase: the items come from the world's spatial hash, entry
-- times are sweep.box_enter's, stops are placed by sweep.before, and the filter is asked
-- only about what a leg meets, nearest first. world:project and bump.rect.detectCollision
-- answer with the same rules: the exact-corner tie lands on the top or bottom face, and a
-- box that starts inside another is let out, never backed out along its move.
--
-- A move allocates nothing once the world is warm: the `cols` list it returns, and the
-- records in it, belong to the world and are reused by its next move (world:check and
-- world:project have lists of their own). Queries return new lists, as in bump.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local hash_module = require(here .. ".hash")
local sweep = require(here .. ".sweep")
local entry = require(here .. ".entry")
local world_module = require(here .. ".world")
local sort_runs = require(here .. ".hits").sort_runs

local describe, is_finite = box.describe, box.is_finite
-- LuaJIT takes the branch-free form of nearest (math.min and math.max compile to no
-- branch there); Lua 5.1-5.4 the one with comparisons.
local BRANCH_FREE = rawget(_G, "jit") ~= nil
local box_enter, before, entry_axis = sweep.box_enter, sweep.before, sweep.entry_axis
local BELOW_ONE = sweep.BELOW_ONE
local check_span = entry.check_span
local format, error, type, setmetatable, getmetatable, rawequal = string.format, error, type,
  setmetatable, getmetatable, rawequal
local floor, ceil, abs, min, max, HUGE = math.floor, math.ceil, math.abs, math.min, math.max,
  math.huge

local bump = {
  _VERSION = "0.1.0", -- budge's version (a spec ties them); the API is bump.lua 3.1.7's
  _DESCRIPTION = "bump.lua 3.1.7's API on budge's engine",
  _LICENSE = "MIT",
}

-- A move's marks (see plan_move): legs count up from the move's stamp; what it met is
-- marked MET above it; the next move's stamp is MARK_SPAN above (exact in a double for
-- 2^53 / 2^20 moves). A move of more than 2^19 legs (each meets a new item) would reach
-- MET: far beyond any scene.
local MET, MARK_SPAN = 2 ^ 19, 2 ^ 20
-- How many records a leg's nearest may scan in all (its rounds times its region's
-- records) before the leg sorts the rest of its candidates ("Crowds", above leg_time).
local CROWD_WORK = 256
-- Where a record keeps its mark: in its array part, beside its box (budge.Record's [14]:
-- the narrow phase's loop reads the box and the mark of each candidate from one run of
-- memory, not the mark from the record's hash part as well).
local MARK = 14

-- rect helpers (bump.rect) ---------------------------------------------------------

local function sign(value)
  if value > 0 then return 1 elseif value < 0 then return -1 end
  return 0
end

-- The one of a and b nearer to value (b when as near).
local function nearer(value, a, b)
  if abs(a - value) < abs(b - value) then return a end
  return b
end

---The corner of the rectangle nearest to the point (px, py).
local function nearest_corner(x, y, w, h, px, py)
  return nearer(px, x, x + w), nearer(py, y, y + h)
end

---Where the segment from (x1, y1) to (x2, y2) enters and leaves the rectangle, as
---fractions of it clipped to [t1, t2] (default 0 and 1), with the normals of the faces
---crossed there; nil when it misses (a segment along an edge misses).
local function segment_indices(x, y, w, h, x1, y1, x2, y2, t1, t2)
  t1, t2 = t1 or 0, t2 or 1
  local dx, dy = x2 - x1, y2 - y1
  local nx1, ny1, nx2, ny2 = 0, 0, 0, 0
  -- the four faces: left, right, top, bottom (each a slab bound p * t <= q)
  for face = 1, 4 do
    local nx, ny, p, q
    if face == 1 then nx, ny, p, q = -1, 0, -dx, x1 - x
    elseif face == 2 then nx, ny, p, q = 1, 0, dx, x + w - x1
    elseif face == 3 then nx, ny, p, q = 0, -1, -dy, y1 - y
    else nx, ny, p, q = 0, 1, dy, y + h - y1 end
    if p == 0 then
      if q <= 0 then return nil end
    else
      local r = q / p
      if p < 0 then
        if r > t2 then return nil end
        if r > t1 then t1, nx1, ny1 = r, nx, ny end
      else
        if r < t1 then return nil end
        if r < t2 then t2, nx2, ny2 = r, nx, ny end
      end
    end
  end
  return t1, t2, nx1, ny1, nx2, ny2
end

---The Minkowski difference of two rectangles: the rectangle of offsets at which the
---first overlaps the second.
local function rect_diff(x1, y1, w1, h1, x2, y2, w2, h2)
  return x2 - x1 - w1, y2 - y1 - h1, w1 + w2, h1 + h2
end

-- bump's tolerance for a point inside a rectangle
local DELTA = 1e-10

local function contains_point(x, y, w, h, px, py)
  return px - x > DELTA and py - y > DELTA and x + w - px > DELTA and y + h - py > DELTA
end

local function is_intersecting(x1, y1, w1, h1, x2, y2, w2, h2)
  return x1 < x2 + w2 and x2 < x1 + w1 and y1 < y2 + h2 and y2 < y1 + h1
end

local function square_distance(x1, y1, w1, h1, x2, y2, w2, h2)
  local dx = x1 - x2 + (w1 - w2) / 2
  local dy = y1 - y2 + (h1 - h2) / 2
  return dx * dx + dy * dy
end

-- bump's measure of how deep (x1, y1, w1, h1) starts inside (x2, y2, w2, h2), as a
-- negative ti: minus the item's size clipped to the nearest corner of their Minkowski
-- difference, on each axis, multiplied; never 0 or -0 (an underflow would make it read as
-- a touch at the start), so an overlap always sorts first. On Lua 5.3+, two integer sizes
-- multiply to an integer, as in bump (-25, not -25.0), unless that is not the exact
-- product: integer sizes of 2^32 wrapped around to 0, and the deepest overlap sorted last
-- (a review, 2026-12-07); then the product in floats.
local SMALLEST = 2 ^ -1074
local function overlap_ti(x1, y1, w1, h1, x2, y2, w2, h2)
  local x, y, w, h = rect_diff(x1, y1, w1, h1, x2, y2, w2, h2)
  local px, py = nearest_corner(x, y, w, h, 0, 0)
  local a, b = min(w1, abs(px)), min(h1, abs(py))
  local product = a * b
  if product ~= (a + 0.0) * b then product = (a + 0.0) * b end
  return min(-product, -SMALLEST), px, py
end

-- overlap_ti's ti alone, without a branch (LuaJIT: a branch here, deep in a move, is a
-- side trace carrying every value live in the move, which LuaJIT often cannot compile:
-- "NYI: register coalescing too complex"): the size of the nearer of the corner's two
-- sides on each axis is the smaller of their sizes, exactly the same number. (LuaJIT's
-- alone, nearest's: no integers there to wrap around.)
local function overlap_depth(x1, y1, w1, h1, x2, y2, w2, h2)
  local x, y, w, h = rect_diff(x1, y1, w1, h1, x2, y2, w2, h2)
  return min(-min(w1, abs(x), abs(x + w)) * min(h1, abs(y), abs(y + h)), -SMALLEST)
end

-- Fills `col` (a record with the tables move, normal, touch, itemRect and otherRect) with
-- what the rectangle (x1, y1, w1, h1) moving to (goal_x, goal_y) meets of (x2, y2, w2,
-- h2), by budge's rules; returns col, or nil when it meets nothing.
-- * Moving into it from outside: `ti` is the fraction of the move where it touches, and
--   the normal is the face's; aimed exactly at a corner, the top or bottom face (budge's
--   corner rule: it lands on it).
-- * Overlapping it at the start: `overlaps` is true and `ti` is negative (overlap_ti:
--   the deepest sorts first). Standing still, `touch` is the nearest place outside
--   (the minimum displacement, on y when x and y are as near), with its normal; moving,
--   the box is let out: `touch` is where it starts and the normal that displacement's.
local function detect_into(col, x1, y1, w1, h1, x2, y2, w2, h2, goal_x, goal_y)
  local dx, dy = goal_x - x1, goal_y - y1
  local ti, nx, ny, tx, ty
  local overlaps = is_intersecting(x1, y1, w1, h1, x2, y2, w2, h2)
  if overlaps then
    local px, py
    ti, px, py = overlap_ti(x1, y1, w1, h1, x2, y2, w2, h2)
    if abs(px) < abs(py) then py = 0 else px = 0 end
    nx, ny = sign(px), sign(py)
    if dx == 0 and dy == 0 then tx, ty = x1 + px, y1 + py else tx, ty = x1, y1 end
  else
    local axis
    ti, axis = box_enter(x1, y1, w1, h1, dx, dy, x2, y2, w2, h2)
    if ti == nil then
      -- the rectangle where the move ends overlaps it: entered, though the rounded times
      -- say at the end or later (the times are from x1 + w1, the goal's far side is
      -- goal_x + w1)
      if not is_intersecting(goal_x, goal_y, w1, h1, x2, y2, w2, h2) then return nil end
      ti, axis = BELOW_ONE, entry_axis(x1, y1, w1, h1, dx, dy, x2, y2, x2 + w2, y2 + h2)
    end
    if axis == 1 then nx, ny = dx > 0 and -1 or 1, 0 else nx, ny = 0, dy > 0 and -1 or 1 end
    tx, ty = x1 + dx * ti, y1 + dy * ti
    -- exactly on the face it touches, never an ulp into it (sweep.before)
    if axis == 1 then
      if dx > 0 then tx = before(x2, w1, x1) else tx = x2 + w2 end
    elseif dy > 0 then ty = before(y2, h1, y1)
    else ty = y2 + h2 end
  end
  col.overlaps, col.ti = overlaps, ti
  local m, normal, touch, ir, orr = col.move, col.normal, col.touch, col.itemRect, col.otherRect
  m.x, m.y = dx, dy
  normal.x, normal.y = nx, ny
  touch.x, touch.y = tx, ty
  ir.x, ir.y, ir.w, ir.h = x1, y1, w1, h1
  orr.x, orr.y, orr.w, orr.h = x2, y2, w2, h2
  return col
end

-- A col's own fields (those budge writes; slide and bounce only for those responses).
local COL_FIELDS = {item = true, other = true, type = true, overlaps = true, ti = true,
  move = true, normal = true, touch = true, itemRect = true, otherRect = true, slide = true,
  bounce = true, _slide = true, _bounce = true}

-- A field a game writes into a col (`col.didTouch = true` in a custom response, as many
-- bump games do) would stay in the record the world reuses, and a later collision would
-- carry it (bump makes every col anew). A write to a field the col does not have marks it
-- (_game), and col_at takes the game's fields out before the col is reused: a game that
-- writes none pays nothing (budge writes slide and bounce with rawset).
local COL_META = {__newindex = function(col, key, value)
  if not COL_FIELDS[key] then rawset(col, "_game", true) end
  rawset(col, key, value)
end}

local function new_col()
  return setmetatable({item = false, other = false, type = false, overlaps = false, ti = 0,
    move = {x = 0, y = 0}, normal = {x = 0, y = 0},
    touch = {x = 0, y = 0}, itemRect = {x = 0, y = 0, w = 0, h = 0},
    otherRect = {x = 0, y = 0, w = 0, h = 0}, _slide = {x = 0, y = 0},
    _bounce = {x = 0, y = 0}}, COL_META)
end

-- Takes the game's own fields out of a col about to be reused (see COL_META).
local function forget_game_fields(col)
  for key in pairs(col) do
    if not COL_FIELDS[key] then col[key] = nil end
  end
end

---bump.rect.detectCollision: a new collision record, or nil (see detect_into).
local function detect_collision(x1, y1, w1, h1, x2, y2, w2, h2, goal_x, goal_y)
  local col = detect_into(new_col(), x1, y1, w1, h1, x2, y2, w2, h2, goal_x or x1,
    goal_y or y1)
  if col then -- (a table of the game's own, bump's fields alone)
    col._slide, col._bounce, col.item, col.other, col.type = nil, nil, nil, nil, nil
    setmetatable(col, nil)
  end
  return col
end

bump.rect = {
  getNearestCorner = nearest_corner,
  getSegmentIntersectionIndices = segment_indices,
  getDiff = rect_diff,
  containsPoint = contains_point,
  isIntersecting = is_intersecting,
  getSquareDistance = square_distance,
  detectCollision = detect_collision,
}

-- responses ------------------------------------------------------------------------

-- Where a slide along col's face from its touch toward the goal ends: the goal, less the
-- part across the face.
local function slide_goal(col, goal_x, goal_y)
  local touch, m = col.touch, col.move
  if m.x ~= 0 or m.y ~= 0 then
    if col.normal.x ~= 0 then goal_x = touch.x else goal_y = touch.y end
  end
  return goal_x, goal_y
end

-- Where a bounce off col's face ends: the goal reflected in the face.
local function bounce_goal(col, goal_x, goal_y)
  local touch, m = col.touch, col.move
  local tx, ty = touch.x, touch.y
  if m.x == 0 and m.y == 0 then return tx, ty end
  local rx, ry = goal_x - tx, goal_y - ty
  if col.normal.x == 0 then ry = -ry else rx = -rx end
  return tx + rx, ty + ry
end

local function touch_response(_, col)
  return col.touch.x, col.touch.y, {}, 0
end

local function cross_response(world, col, x, y, w, h, goal_x, goal_y, filter)
  local cols, len = world:project(col.item, x, y, w, h, goal_x, goal_y, filter)
  return goal_x, goal_y, cols, len
end

local function slide_response(world, col, _, _, w, h, goal_x, goal_y, filter)
  local sx, sy = slide_goal(col, goal_x, goal_y)
  col.slide = {x = sx, y = sy}
  local cols, len = world:project(col.item, col.touch.x, col.touch.y, w, h, sx, sy, filter)
  return sx, sy, cols, len
end

local function bounce_response(world, col, _, _, w, h, goal_x, goal_y, filter)
  local bx, by = bounce_goal(col, goal_x, goal_y)
  col.bounce = {x = bx, y = by}
  local cols, len = world:project(col.item, col.touch.x, col.touch.y, w, h, bx, by, filter)
  return bx, by, cols, len
end

bump.responses = {touch = touch_response, cross = cross_response, slide = slide_response,
  bounce = bounce_response}

-- The built-in responses, by function: what budge's engine does itself.
local ENGINE = {[touch_response] = "touch", [cross_response] = "cross",
  [slide_response] = "slide", [bounce_response] = "bounce"}

-- the world ------------------------------------------------------------------------

---A bump world on a budge world. Made by bump.newWorld.
---@class budge.BumpWorld
---@field cellSize number
---@field responses table<string, function> the responses by name (world:addResponse)
---@field package _world budge.World the budge world underneath
---@field package _proxies table<any, table> item -> the proxy box standing for it
---@field package _list table[] the proxies, unordered (a removal moves the last into the gap)
---@field package _filter? function the running move's filter (nil: "slide" on everything)
---@field package _running boolean a move or check is running (its callbacks may be called)
---@field package _stamp number where the running move's marks begin (records' marks, [MARK]):
---_stamp + leg for one its leg's filter ignored, _stamp + MET for one it met (and its item)
---@field package _pass number _stamp + the running leg's number
---@field package _margin number how far a moved item's cells reach beyond its box
---@field package _x0 number where the running move began (what a custom response is given)
---@field package _y0 number
---@field package _region budge.Record[] what the move's first leg's rectangle overlaps
---(_region_n of them; the rectangle _region_left, _top, _right, _bottom)
---@field package _own budge.Record the running move's item's record (and _item, _w, _h)
---@field package _leg_x number the running leg's start (_leg_x, _leg_y), its motion
---(_leg_dx, _leg_dy), the start's far sides (_leg_x1, _leg_y1), its goal (_leg_goal_x,
---_leg_goal_y) and the rectangle it sweeps (_leg_left, _leg_top, _leg_right,
---_leg_bottom), for nearest to read where it uses them (run_leg writes them)
---@field package _best budge.Record|false|nil on LuaJIT, nearest's best candidate so far
---(nil: none; and _best_t, the leg time it is met at)
---@field package _out table[] the running move's cols list and their pool (_out_pool)
---@field package _n integer how many cols it has
---@field package _visited_filter function the filter a custom response is given
---@field package _move_cols table[] world:move's list (reused), its records from _move_pool
---@field package _move_pool table[]
---@field package _check_cols table[] world:check's
---@field package _check_pool table[]
---@field package _project_cols table[] world:project's
---@field package _project_pool table[]
---@field package _found table[] the budge world's query output (scratch)
---@field package _found_t number[] its entry fractions (segments)
---@field package _found_key number[] where the infinite line enters each (segments)
---@field package _projecting boolean a project is running (a nested one gets new lists)
---@field package _sort_scratch table[] project's merge of its cols (hits.sort_runs; left empty)
local World = {}
World.__index = World

-- The default filter: every item slides on every other.
local function default_filter() return "slide" end

-- The checks of an argument: an error at `level` (as error() counts from the check: 3
-- is the caller of the method that calls the check).
local function check_finite(value, name, level)
  if not is_finite(value) then
    error(format("%s must be a finite number, got %s", name, describe(value)), level)
  end
end

local function check_positive(value, name, level)
  if not is_finite(value) or value <= 0 then
    error(format("%s must be a finite number > 0, got %s", name, describe(value)), level)
  end
end


-- What a filter or a custom response may not call on the world that called it (they may
-- project and query it).
local MUTATES = {add = true, remove = true, update = true, move = true, check = true,
  addResponse = true}

-- The error level of the first caller outside this file: a callback's bad answer is
-- blamed on the game's line that called world:move (or check), however deep in the move
-- it was found.
local THIS_FILE = debug.getinfo(1, "S").source
local function game_level()
  local level = 2
  while true do
    local info = debug.getinfo(level + 1, "S")
    if info == nil or info.source ~= THIS_FILE then return level end
    level = level + 1
  end
end

local plan_move -- (below)

-- True when `fn` (plan_move or World.project) is running on the stack now for this world:
-- one of its callbacks called the world. False when the flag saying so was left by a
-- callback's error.
local function on_stack(self, fn)
  local level = 3
  while true do
    local info = debug.getinfo(level, "f")
    if info == nil then return false end
    if info.func == fn then
      local _, world = debug.getlocal(level, 1) -- (its self)
      if world == self then return true end
    end
    level = level + 1
  end
end

-- True when a move or check of the world is on the stack now (its _running is set); a
-- flag left by a callback's error is cleared.
local function still_running(self)
  if on_stack(self, plan_move) then return true end
  self._running = false
  return false
end

-- The start of every method: called with a colon, and not, when it changes the world or
-- moves in it, from inside a move's filter or custom response.
-- True when `self` is a world made by bump.newWorld given another metatable (a game's
-- subclass of bump's world, as some games make: an __index chain to World, World's
-- methods copied into a class, an __index function), by its own fields: its table of
-- items and its budge world (a world of budge's has _busy, false or a name).
local function subclassed(self)
  if type(self) ~= "table" or type(rawget(self, "_proxies")) ~= "table" then return false end
  local inner = rawget(self, "_world")
  return type(inner) == "table" and rawget(inner, "_busy") ~= nil
end

local function enter(self, call)
  -- (rawequal: a game item's class may have an __eq)
  if not rawequal(getmetatable(self), World) and not subclassed(self) then
    error(format("call it as world:%s(...), with a colon, got %s for the world", call,
      describe(self)), 3)
  end
  if self._running and MUTATES[call] and still_running(self) then
    error(format("world:%s was called from inside a move's filter or response: they may "
      .. "project and query the world, not add, remove, update, move or check items in it or "
      .. "add responses to it", call), 3)
  end
end

-- What bump.lua calls as a filter or a response: a function, or a table or userdata whose
-- metatable has a __call (bump calls whatever it is given; debug.getmetatable: a
-- __metatable field does not hide it).
local get_metatable = debug and debug.getmetatable or getmetatable
local function callable(value)
  local kind = type(value)
  if kind == "function" then return true end
  if kind ~= "table" and kind ~= "userdata" then return false end
  local meta = get_metatable(value)
  return type(meta) == "table" and rawget(meta, "__call") ~= nil
end

-- A filter as bump.lua takes one: nil or false (none: returned as nil), or callable;
-- else an error at `level`.
local function check_bump_filter(filter, level)
  if filter == nil or filter == false then return nil end
  if not callable(filter) then
    error(format("filter must be a function, a callable table, false or nil, got %s",
      describe(filter)), level + 1)
  end
  return filter
end

local function find_proxy(self, item)
  local proxy = self._proxies[item]
  if proxy == nil then
    error(format("item must be an item of this world (add it with world:add), got %s",
      describe(item)), 3)
  end
  return proxy
end

-- The checks of a rectangle given to add, update and the queries (at their caller).
local function check_rect(self, x, y, w, h)
  check_finite(x, "x", 4)
  check_finite(y, "y", 4)
  check_positive(w, "w", 4)
  check_positive(h, "h", 4)
  check_span(self._world, x, w, "x", "the rectangle", 4)
  check_span(self._world, y, h, "y", "the rectangle", 4)
end

---bump.newWorld(cellSize): a new world; cellSize (default 64) is the side of its cells.
---@param cell_size? number
---@return budge.BumpWorld
function bump.newWorld(cell_size)
  if cell_size == nil then cell_size = 64 end
  check_positive(cell_size, "cellSize", 3)
  -- The items are the actors of a budge world whose hash of actors keeps their boxes
  -- packed by cell (hash.new: a move reads its cells' boxes side by side, not each item's
  -- record; see hash.lua's collect_packed), set before any item is added.
  local world = world_module.new_world({cell_size = cell_size})
  world._actors = hash_module.new(cell_size, true)
  local self = setmetatable({
    cellSize = cell_size,
    responses = {},
    _world = world,
    _proxies = {},
    _list = {},
    _filter = nil, -- the running move's filter (nil: the default, "slide" on everything)
    _running = false, -- a move or check is running (its filter or a response may be called)
    _stamp = 0, -- counts moves: what a move met carries its stamp (visited)
    _pass = 0, -- the running leg's mark (see plan_move)
    _margin = cell_size / 4, -- how far a moved item's loose cells reach (World:move)
    _leg_x = 0, _leg_y = 0, _leg_dx = 0, _leg_dy = 0, _leg_x1 = 0, _leg_y1 = 0,
    _leg_goal_x = 0, _leg_goal_y = 0, _leg_left = 0, _leg_top = 0, _leg_right = 0, _leg_bottom = 0,
    _best = false, _best_t = 0, -- (false until the first leg)
    _best_enter_x = 0, _best_enter_y = 0, -- the best's entry times (offer)
    _region = {}, _region_n = 0, _region_left = 0, _region_top = 0, _region_right = 0,
    _region_bottom = 0, -- what the move's first leg's rectangle overlaps
    _move_cols = {}, _move_pool = {},
    _check_cols = {}, _check_pool = {},
    _project_cols = {}, _project_pool = {},
    _found = {}, _found_t = {}, _found_key = {},
    _crowd = {}, _crowd_t = {}, _crowd_axis = {}, _crowd_n = 0, _crowd_at = 1, -- (CROWD_WORK)
    _crowd_run = 0, _crowd_keys = {{}, {}, false}, -- (sort_run)
    _crowd_work = CROWD_WORK, -- (specs: huge, never sorted, or 0, from the first candidate)
    _projecting = false, -- a project is running (one its filter calls gets lists of its own)
    _sort_scratch = {},
  }, World)
  -- The filter a custom response is given: the move's, less what it met already (as bump
  -- does). Made once per world.
  local records = self._world._records
  self._visited_filter = function(item, other)
    local proxy = self._proxies[other]
    if proxy and records[proxy][MARK] >= self._stamp + MET then return false end
    local filter = self._filter
    if filter == nil then return "slide" end
    return filter(item, other)
  end
  self:addResponse("touch", touch_response)
  self:addResponse("cross", cross_response)
  self:addResponse("slide", slide_response)
  self:addResponse("bounce", bounce_response)
  return self
end

---world:addResponse(name, response): a response a filter may return by name.
---`response(world, col, x, y, w, h, goalX, goalY, filter)` returns the new goal (and, in
---bump, the collisions from there, which the front end finds itself).
---@param name string
---@param response function
---@param name string
---@param response fun(world: budge.BumpWorld, col: table, x: number, y: number, w: number,
---h: number, goal_x: number, goal_y: number, filter?: function): number, number
function World:addResponse(name, response)
  enter(self, "addResponse")
  if name == nil or name ~= name then -- (any other value is a name, as in bump)
    error(format("name must be a value other than nil and nan, got %s", describe(name)), 2)
  end
  if not callable(response) then
    error(format("response must be a function or a callable table, got %s",
      describe(response)), 2)
  end
  self.responses[name] = response
end

---world:add(item, x, y, w, h): adds any value but nil (and NaN) as an item; returns it.
---@param item any
---@param x number
---@param y number
---@param w number > 0
---@param h number > 0
---@return any item
function World:add(item, x, y, w, h)
  enter(self, "add")
  if item == nil or item ~= item then
    error(format("item must be a value other than nil and nan, got %s", describe(item)), 2)
  end
  if self._proxies[item] ~= nil then
    error(format("item is already in this world, got %s", describe(item)), 2)
  end
  check_rect(self, x, y, w, h)
  local proxy = {x = x, y = y, width = w, height = h, item = item}
  self._world:add_actor(proxy)
  local list = self._list
  local index = #list + 1
  list[index] = proxy
  proxy._index = index
  local record = self._world._records[proxy]
  record[MARK] = 0
  record[7] = item -- (what a col reports: read with the box, not through the proxy)
  proxy._record = record -- (a move reads it here, not from the world's table of records)
  self._proxies[item] = proxy
  return item
end

-- Past the region's last record, nearest's loop (LuaJIT) reads PAD of these: a record
-- no leg overlaps and every leg has passed (its box starts at +inf, its mark is +inf;
-- hash.lua says why the padding).
local PAD = 2
local SENTINEL = hash_module.SENTINEL

---world:remove(item).
---@param item any
function World:remove(item)
  enter(self, "remove")
  local proxy = find_proxy(self, item)
  self._world:remove(proxy)
  self._proxies[item] = nil
  -- What the world's scratch still holds of it, let go (see cut): a game's item the world
  -- no longer holds is collected once the game drops it, as in bump. The region (a
  -- move's candidates, read in no later call) cut back to the last move's, so that one
  -- long move makes no later remove slow. (The cols: see cut. A record the lists dropped
  -- before the item's removal holds it until it is reused; walking the pools here, as
  -- large as the longest list ever, made a remove after one long move cost 675 us.)
  local record, region, kept = proxy._record, self._region, self._region_n + PAD
  for i = 1, kept do
    if region[i] == record then region[i] = SENTINEL end
  end
  for i = #region, kept + 1, -1 do region[i] = nil end
  if self._best == record then self._best = false end
  if self._own == record then self._own = false end
  if rawequal(self._item, item) then self._item = false end
  local list = self._list
  local last = list[#list]
  list[proxy._index] = last
  last._index = proxy._index
  list[#list] = nil
end

---world:update(item, x, y, w, h): teleports it (w and h default to its own).
---@param item any
---@param x number
---@param y number
---@param w? number
---@param h? number
function World:update(item, x, y, w, h)
  enter(self, "update")
  local proxy = find_proxy(self, item)
  w, h = w or proxy.width, h or proxy.height
  check_rect(self, x, y, w, h)
  proxy.x, proxy.y, proxy.width, proxy.height = x, y, w, h
  self._world:update(proxy)
end

-- A col record of `list` (reused from `pool`) at index n.
local function col_at(list, pool, n)
  local col = pool[n]
  if col == nil then
    col = new_col()
    pool[n] = col
  elseif col._game then
    forget_game_fields(col)
  end
  list[n] = col
  return col
end

-- Ends `list` at n (so #list and ipairs see n records).
local function cut(list, n, proxies)
  for i = n + 1, #list do
    -- (a record dropped from the list lets go of an item the world no longer holds, so
    -- that the game's item is collected once the game drops it, as in bump; one the
    -- world still holds is left: a game's loop over the last move's cols that moves the
    -- crate it touched still reads its col, as it did before 2026-12-06, see the README)
    local col = list[i]
    if proxies[col.other] == nil then col.other = nil end -- (nil: false may be an item)
    if proxies[col.item] == nil then col.item = nil end
    list[i] = nil
  end
end

-- What the move does for a filter's answer: "touch", "cross", "slide" or "bounce" when it
-- names one of bump.responses (world.responses is read at each answer, so a response set
-- there directly counts too), "custom" for another function; else an error.
local function response_of(self, answer, other)
  local fn = self.responses[answer]
  local response = ENGINE[fn]
  if response == nil and callable(fn) then response = "custom" end
  if response == nil then
    error(format("filter must return the name of a response (\"touch\", \"cross\", \"slide\", "
      .. "\"bounce\" or one given to world:addResponse), or false/nil, got %s for %s",
      describe(answer), describe(other)), game_level())
  end
  return response
end

-- A box's face on `axis` (1: x, 2: y) that a move by `d` along it meets first, as a key
-- that is larger for the face nearer along the move: its low side negated moving forward,
-- its high side moving back.
local function near_face(axis, d, x, y, w, h)
  if axis == 1 then
    if d > 0 then return -x end
    return x + w
  end
  if d > 0 then return -y end
  return y + h
end

-- True when record b comes before record a met at the same time t (a leg time; negative
-- for an overlap at the start), b entered across axis_b and a across axis_a (see
-- offer): first the one whose face is nearer along the move, when both are
-- entered across the same axis (their times can round to the same t with faces apart,
-- and the move stops on the face of the one chosen: the other's, nearer, would be an ulp
-- inside); then the one whose centre is nearer the centre of the box (x, y, w, h), or as
-- near and added earlier.
local function comes_before(b, a, t, axis_b, axis_a, x, y, w, h, dx, dy)
  if t >= 0 and axis_b == axis_a then
    local d = axis_b == 1 and dx or dy
    local fb = near_face(axis_b, d, b[1], b[2], b[3], b[4])
    local fa = near_face(axis_b, d, a[1], a[2], a[3], a[4])
    if fb ~= fa then return fb > fa end
  end
  local da = square_distance(x, y, w, h, a[1], a[2], a[3], a[4])
  local db = square_distance(x, y, w, h, b[1], b[2], b[3], b[4])
  return db < da or db == da and b.id < a.id
end

-- The running leg's times (fractions of it) of reaching and leaving `record` on each
-- axis: near_x, far_x, near_y, far_y (a division by a negative delta swaps near and far;
-- by 0, the overlap the rectangle test found makes them -inf and inf: no branch on the
-- direction).
local function leg_times(self, record)
  local rx, ry = record[1], record[2]
  return (rx - self._leg_x1) / self._leg_dx, (rx + record[3] - self._leg_x) / self._leg_dx,
    (ry - self._leg_y1) / self._leg_dy, (ry + record[4] - self._leg_y) / self._leg_dy
end

-- The candidate `record`, met at leg time `first` (no later than the best so far) and
-- entered at leg times enter_x and enter_y on each axis, becomes the leg's best unless
-- the best so far comes before it. The axis a leg enters a record across (1: x, 2: y)
-- is that of the later of its entry times (y when as late: budge's corner rule). The
-- best's entry times are kept, not worked out again from its box at each tie (ties are
-- frequent: a box resting on two tiles meets both at 0; and the times are four
-- divisions): `luajit bench/world.lua --way bump_boxes`, see the CHANGELOG's entry
-- "Ties in budge.bump without the times again".
local function offer(self, record, first, enter_x, enter_y)
  if first == self._best_t then
    local best, x, y, w, h = self._best, self._leg_x, self._leg_y, self._w, self._h
    local dx, dy = self._leg_dx, self._leg_dy
    local axis = enter_x > enter_y and 1 or 2
    local best_axis = self._best_enter_x > self._best_enter_y and 1 or 2
    if not comes_before(record, best, first, axis, best_axis, x, y, w, h, dx, dy) then
      return
    end
  end
  self._best, self._best_t = record, first
  self._best_enter_x, self._best_enter_y = enter_x, enter_y
end

-- Makes the move's region (see plan_move) hold what the leg's rectangle overlaps: the
-- records the first leg's rectangle overlaps, looked up in the hash again only when a
-- leg leaves that rectangle (a bounce may; a slide never does). Then PAD sentinels.
local function cover(self, left, top, right, bottom)
  if left < self._region_left or top < self._region_top or right > self._region_right
    or bottom > self._region_bottom then
    local region = self._region
    local n = self._world._actors:collect_overlapping(left, top, right, bottom, region, 0)
    self._region_n = n
    region[n + 1], region[n + 2] = SENTINEL, SENTINEL -- (PAD of them: no loop)
    self._region_left, self._region_top = left, top
    self._region_right, self._region_bottom = right, bottom
  end
end

-- nearest on Lua 5.1-5.4: the leg read once into locals, and comparisons (there
-- math.min is a call into C, and a branch is cheap). With the LuaJIT
-- form, and overlapping_in_cell's (hash.lua), `lua5.4 bench/world.lua --way bump_boxes
-- --count 1000 --frames 60` took 6576 ns per move instead of 5321 (5 fresh runs each,
-- interleaved, 2026-12-01); with this one, 5004 against 4944. Its times' min and max by
-- comparisons (`lua5.4 bench/instructions.lua --way bump_boxes --count 1000 --frames 5
-- --lua lua5.4`, 2026-12-06): 60275 -> 57360 instructions per move.
local function nearest_compared(self)
  local x, y, dx, dy = self._leg_x, self._leg_y, self._leg_dx, self._leg_dy
  local left, top, right, bottom = self._leg_left, self._leg_top, self._leg_right,
    self._leg_bottom
  local w, h = self._w, self._h
  local x1, y1 = x + w, y + h
  local goal_x, goal_y = self._leg_goal_x, self._leg_goal_y
  local goal_right, goal_bottom = goal_x + w, goal_y + h
  local region, pass = self._region, self._pass
  local best, best_t, best_axis = nil, HUGE, 0
  for i = 1, self._region_n do
    local record = region[i]
    local rx, ry = record[1], record[2]
    if rx < right and left < rx + record[3] and ry < bottom and top < ry + record[4]
      and record[MARK] < pass then
      -- (the min and max of each pair by one comparison: math.min and math.max's results,
      -- a call into C each saved; the rectangle test leaves no NaN: with no motion on an
      -- axis, the times there are -inf and inf)
      local enter_x, exit_x = (rx - x1) / dx, (rx + record[3] - x) / dx
      if enter_x > exit_x then enter_x, exit_x = exit_x, enter_x end
      local enter_y, exit_y = (ry - y1) / dy, (ry + record[4] - y) / dy
      if enter_y > exit_y then enter_y, exit_y = exit_y, enter_y end
      -- (+ 0: -0 becomes 0, as nearest's)
      local first = (enter_y > enter_x and enter_y or enter_x) + 0
      local exit = exit_y < exit_x and exit_y or exit_x
      local met = first < exit and first < 1 and exit > 0
      if not met and goal_x < rx + record[3] and rx < goal_right and goal_y < ry + record[4]
        and ry < goal_bottom then
        first, met = BELOW_ONE, true -- (it ends in it: see nearest)
      end
      if met then
        if first < 0 then
          first = overlap_ti(x, y, w, h, rx, ry, record[3], record[4])
        end
        local axis = enter_x > enter_y and 1 or 2
        if first < best_t then
          best, best_t, best_axis = record, first, axis
        elseif first == best_t then
          if comes_before(record, best, first, axis, best_axis, x, y, w, h, dx, dy) then
            best, best_axis = record, axis
          end
        end
      end
    end
  end
  return best, best_t, best_axis
end

-- The first thing the running leg (run_leg wrote it into self._leg_x and the fields after
-- it) meets that the move has not met or passed over yet: its record, the leg time (an
-- overlap at the start: minus its area, so the deepest first) and the axis it is entered
-- across (1: x, 2: y; budge's corner rule: y when both at once), or nil. Ties go by
-- comes_before: the face nearer along the leg, the distance between centres, the order
-- items were added. Entry and exit times are
-- sweep.box_enter's (the same roundings); with no motion on an axis, the rectangle test
-- made it overlap on that axis.
-- LuaJIT shaping: one pass for the nearest, asked again only past what the filter lets
-- through, instead of sorting every candidate: short loops of varying length (the sort,
-- the passes over a few candidates) are unrolled into every trace that runs them. In the
-- loop, the leg's values and the best so far are read from self where they are used, and
-- each test is one comparison of a min of differences (exact: for finite numbers a - b > 0
-- if and only if a > b): with the leg's values in locals and five comparisons, LuaJIT
-- could not compile the loop's side exits ("NYI: register coalescing too complex", 1000 to
-- 4000 aborts a run) and tried again all run long. `luajit bench/world.lua --way
-- bump_boxes`, 7 fresh runs each, interleaved, 2026-12-01, with overlapping_in_cell's one
-- test (hash.lua): 1000 items 1552 -> 1195 ns per move, 10000 items 3487 -> 3014. The
-- branches left in the loop had the same trouble in some runs (the side traces carry every
-- value live in the move, in this frame and the callers'), so: the axis is found after the
-- loop, for the best alone; an overlap's measure is overlap_depth's, with no branch; and
-- run_leg keeps no local of the leg's live across its loop. 100 items, 10 fresh runs each,
-- interleaved, 2026-12-02: 0 to 500 of those aborts a run -> none, 880 -> 751 ns per move
-- (median; runs whose machine code overflows LuaJIT's budget still take 1.2 to 1.7 us).
-- The loop runs PAD turns past the region (sentinels that fail the first test), so that
-- LuaJIT keeps a trace of its own for it (hash.lua's SENTINEL says why): a region holds 2
-- to 7 records, and without them in 4 runs of 10 the loop was unrolled into every move,
-- which compiled 2 to 3 times the machine code and ran up to twice as slow. With them
-- (`luajit bench/world.lua --way bump_boxes`, unlimited budget, 200 frames, fresh runs
-- interleaved, 2026-12-03): 100 items 777 KB (438-1006) -> 295 (269-310), 10 runs; 1000
-- items 1595 KB (608-2426) -> 397 (332-422) and 1036 -> 804 ns per move, 6 runs.
local function nearest(self)
  local region = self._region
  self._best, self._best_t = nil, HUGE
  for i = 1, self._region_n + PAD do
    local record = region[i]
    local rx, ry = record[1], record[2]
    if min(self._leg_right - rx, rx + record[3] - self._leg_left, self._leg_bottom - ry,
      ry + record[4] - self._leg_top, self._pass - record[MARK]) > 0 then
      local near_x, far_x, near_y, far_y = leg_times(self, record)
      local enter_x, enter_y = min(near_x, far_x), min(near_y, far_y)
      -- (+ 0: -0 becomes 0, for math.max gives either zero on a tie, by interpreter)
      local first = max(enter_x, enter_y) + 0
      local exit = min(max(near_x, far_x), max(near_y, far_y))
      if min(exit - first, 1 - first, exit) > 0 then
        if first < 0 then -- overlapping at the start: bump's negative measure of it
          first = overlap_depth(self._leg_x, self._leg_y, self._w, self._h, rx, ry,
            record[3], record[4])
        end
        if first <= self._best_t then offer(self, record, first, enter_x, enter_y) end
      elseif min(self._leg_goal_x + self._w - rx, rx + record[3] - self._leg_goal_x,
        self._leg_goal_y + self._h - ry, ry + record[4] - self._leg_goal_y) > 0 then
        -- the box where the leg ends overlaps it: entered, though the times (from x + w;
        -- the goal's far side is goal_x + w) round its entry to the end or past it
        if BELOW_ONE <= self._best_t then offer(self, record, BELOW_ONE, enter_x, enter_y) end
      end
    end
  end
  local best = self._best
  if best == nil then return nil, HUGE, 0 end
  -- (the axis for the best alone: see offer)
  return best, self._best_t, self._best_enter_x > self._best_enter_y and 1 or 2
end

-- Crowds: a leg that passes over many candidates (a filter's nil or "cross" for each:
-- bullets among bullets, a player through a field of coins) sent nearest over the whole
-- region once per candidate, k + 1 passes of k records: k^2. So once a leg's rounds
-- would have scanned more than CROWD_WORK records of its region, its remaining
-- candidates are worked out once and sorted by time (then by place in the region,
-- nearest's scan order), and each round takes the next: the same candidates in the same
-- order as nearest gives (a run of candidates at one time goes by comes_before: sorted
-- by it once where it orders the run wholly, else scanned in the region's order at each
-- of the run's rounds, as nearest's scan compares them, see sort_run; bump_spec compares
-- both paths), in k log k. Below the
-- budget, nearest alone: a common move's path is as it was (its region holds 2 to 7
-- records). `luajit bench/bump_crowds.lua --one W K A M` (5 fresh runs each, interleaved
-- with the tree before and bump.lua 3.1.7, medians, 2026-12-07), 256 items piled in the
-- leg's way, each ignored: 132258 -> 29148 ns per move (bump.lua: 26788), each crossed:
-- 155587 -> 35556 (bump.lua: 9.1 ms); 64 items: 7491 -> 6442 and 9102 -> 8262; 16: as
-- before (README, "Crowds"). A budget of 4 candidates a leg instead ran the world bench's
-- movers passing through each other (`bench/world.lua --way bump_walls --count 10000`,
-- regions of a few to a few dozen records) twice as long on LuaJIT; with this one, 4203
-- against 4079 ns per move (5 runs each), and `--way bump_boxes --count 1000` 1206
-- against 1247 (11 runs); Lua 5.4, `bench/instructions.lua --way bump_boxes --lua
-- lua5.4`: 59662 -> 60195 instructions per move.

-- The leg time at which the running leg meets `record`, and the axis it enters it
-- across, or nil when it does not meet it: nearest_compared's numbers for one record
-- (the same divisions, roundings and tests; the specs compare the two paths).
local function leg_time(self, record)
  local rx, ry, rw, rh = record[1], record[2], record[3], record[4]
  if not (rx < self._leg_right and self._leg_left < rx + rw and ry < self._leg_bottom
    and self._leg_top < ry + rh) then
    return nil
  end
  local near_x, far_x, near_y, far_y = leg_times(self, record)
  local enter_x, enter_y = min(near_x, far_x), min(near_y, far_y)
  local first = max(enter_x, enter_y) + 0 -- (+ 0: -0 becomes 0, as nearest's)
  local exit = min(max(near_x, far_x), max(near_y, far_y))
  if not (first < exit and first < 1 and exit > 0) then
    local goal_x, goal_y = self._leg_goal_x, self._leg_goal_y
    if not (goal_x < rx + rw and rx < goal_x + self._w and goal_y < ry + rh
      and ry < goal_y + self._h) then
      return nil
    end
    first = BELOW_ONE -- (it ends in it: see nearest)
  elseif first < 0 then
    first = overlap_ti(self._leg_x, self._leg_y, self._w, self._h, rx, ry, rw, rh)
  end
  return first, enter_x > enter_y and 1 or 2
end

-- crowd_order's order: a before b when its time is earlier, or the same and its place
-- in the region is earlier.
local function earlier(times, a, b)
  local ta, tb = times[a], times[b]
  return ta < tb or ta == tb and a < b
end

-- A tie run's order (crowd_next), when comes_before is a total order on it: a before b
-- when its face is nearer along the leg (the keys are 0 when the faces do not count), then
-- its centre nearer, then it was added earlier. keys: {faces, distances} by region index.
local function run_before(keys, a, b)
  local faces, distances = keys[1], keys[2]
  local fa, fb = faces[a], faces[b]
  if fa ~= fb then return fa > fb end
  local da, db = distances[a], distances[b]
  if da ~= db then return da < db end
  return keys[3][a].id < keys[3][b].id
end

-- Sorts order[first..last] by precedes(ctx, a, b) (a strict total order), in place: a heap
-- sort, in Lua (LuaJIT compiles it; table.sort is a C function calling a Lua comparator,
-- which it does not), with no recursion and no garbage.
local function sift_down(order, base, root, n, precedes, ctx)
  local value = order[base + root]
  while true do
    local child = 2 * root
    if child > n then break end
    if child < n and precedes(ctx, order[base + child], order[base + child + 1]) then
      child = child + 1
    end
    if not precedes(ctx, value, order[base + child]) then break end
    order[base + root] = order[base + child]
    root = child
  end
  order[base + root] = value
end

local function heap_sort(order, first, last, precedes, ctx)
  local base, n = first - 1, last - first + 1
  for root = floor(n / 2), 1, -1 do sift_down(order, base, root, n, precedes, ctx) end
  for top = n, 2, -1 do
    order[base + 1], order[base + top] = order[base + top], order[base + 1]
    sift_down(order, base, 1, top - 1, precedes, ctx)
  end
end

-- The running leg's candidates not marked yet, as indices into the region, sorted
-- (see CROWD_WORK), with their times and axes by region index.
local function crowd_order(self)
  local region, pass = self._region, self._pass
  local order, times, axes = self._crowd, self._crowd_t, self._crowd_axis
  local n = 0
  for i = 1, self._region_n do
    local record = region[i]
    if record[MARK] < pass then
      local t, axis = leg_time(self, record)
      if t then
        n = n + 1
        order[n], times[i], axes[i] = i, t, axis
      end
    end
  end
  heap_sort(order, 1, n, earlier, times)
  self._crowd_n, self._crowd_at, self._crowd_run = n, 1, 0
end

-- Sorts the run of candidates at one time that begins at `at` (order[at..last]) by
-- comes_before, when that is a total order on it (all entered across one axis, or
-- overlapping at the start, where only distances count), and returns true; false when
-- it is not (some entered across x and some across y, after the start: the faces of
-- those across one axis are compared, and the distances across the two, which can go
-- round in a circle, so that only nearest's scan in the region's order tells which
-- comes first). Items piled exactly on one another all meet a leg at one time: scanned
-- at each of its k rounds, such a run cost k^2 comes_before calls (1024 piled, each
-- ignored: 226x the instructions of 64 on Lua 5.4), sorted, k log k.
local function sort_run(self, at, last, t)
  local order, axes, region = self._crowd, self._crowd_axis, self._region
  local axis = axes[order[at]]
  if t >= 0 then
    for j = at + 1, last do
      if axes[order[j]] ~= axis then return false end
    end
  end
  local keys = self._crowd_keys
  local faces, distances = keys[1], keys[2]
  keys[3] = region
  local x, y, w, h = self._leg_x, self._leg_y, self._w, self._h
  local d = axis == 1 and self._leg_dx or self._leg_dy
  for j = at, last do
    local i = order[j]
    local record = region[i]
    local rx, ry, rw, rh = record[1], record[2], record[3], record[4]
    faces[i] = t >= 0 and near_face(axis, d, rx, ry, rw, rh) or 0
    distances[i] = square_distance(x, y, w, h, rx, ry, rw, rh)
  end
  heap_sort(order, at, last, run_before, keys)
  keys[3] = false -- (the region is the world's: no reference kept past the sort)
  return true
end

-- The next candidate of the crowd: what nearest would return (its record, leg time and
-- axis; nil when none is left). Of the first run of candidates not marked yet that share
-- one time, the one comes_before puts first, in the region's order, as nearest's scan:
-- a run of two or more is sorted by it once where it is a total order (sort_run), and
-- read in that order; else scanned at each round.
local function crowd_next(self)
  local order, times, axes, region = self._crowd, self._crowd_t, self._crowd_axis,
    self._region
  local n, at, pass = self._crowd_n, self._crowd_at, self._pass
  while at <= n and region[order[at]][MARK] >= pass do at = at + 1 end
  self._crowd_at = at
  if at > n then return nil, HUGE, 0 end
  local t = times[order[at]]
  if at > self._crowd_run then -- (else inside a sorted run: the first not marked is it)
    local last = at
    while last < n and times[order[last + 1]] == t do last = last + 1 end
    if last == at or sort_run(self, at, last, t) then
      self._crowd_run = last
      -- (the sort may have put first a record of the run met at an earlier round, when the
      -- run was scanned: some of it entered across the other axis, then met)
      while region[order[at]][MARK] >= pass do at = at + 1 end
      self._crowd_at = at
    else
      local best, best_axis = region[order[at]], axes[order[at]]
      local x, y, w, h = self._leg_x, self._leg_y, self._w, self._h
      local dx, dy = self._leg_dx, self._leg_dy
      for j = at + 1, last do
        local i = order[j]
        local record, axis = region[i], axes[i]
        if record[MARK] < pass then
          if comes_before(record, best, t, axis, best_axis, x, y, w, h, dx, dy) then
            best, best_axis = record, axis
          end
        end
      end
      return best, t, best_axis
    end
  end
  return region[order[at]], t, axes[order[at]]
end

-- Fills col for meeting `record` at leg time t (see leg_candidates) on the leg from (x, y)
-- toward (goal_x, goal_y).
local function fill_col(col, item, record, kind, t, axis, x, y, w, h, goal_x, goal_y)
  local rx, ry, rw, rh = record[1], record[2], record[3], record[4]
  col.item, col.other, col.type = item, record[7], kind
  if BRANCH_FREE then -- (rawset: no call of COL_META's __newindex for an absent field)
    rawset(col, "slide", nil)
    rawset(col, "bounce", nil)
  else -- (Lua 5.x: rawset is a call into C; a present field is written as it is)
    if col.slide ~= nil then col.slide = nil end
    if col.bounce ~= nil then col.bounce = nil end
  end
  if t < 0 then
    detect_into(col, x, y, w, h, rx, ry, rw, rh, goal_x, goal_y)
    return col
  end
  local dx, dy = goal_x - x, goal_y - y
  local m, normal, touch, ir, orr = col.move, col.normal, col.touch, col.itemRect,
    col.otherRect
  col.overlaps, col.ti = false, t
  m.x, m.y = dx, dy
  -- exactly on the face it touches, never an ulp into it (sweep.before: (rx - w) + w can
  -- round past rx, and the next move would start inside and be let out through it)
  if axis == 1 then
    normal.y, touch.y = 0, y + dy * t
    if dx > 0 then normal.x, touch.x = -1, before(rx, w, x) else normal.x, touch.x = 1, rx + rw end
  else
    normal.x, touch.x = 0, x + dx * t
    if dy > 0 then normal.y, touch.y = -1, before(ry, h, y) else normal.y, touch.y = 1, ry + rh end
  end
  ir.x, ir.y, ir.w, ir.h = x, y, w, h
  orr.x, orr.y, orr.w, orr.h = rx, ry, rw, rh
  return col
end

-- The game's custom response to `col`: the goal it returns, and where the next leg starts
-- (where the collisions it returns were projected from; with none, the move ends at the
-- goal, as in bump).
local function custom_response(self, name, col, w, h, goal_x, goal_y)
  -- (bump gives a response the position the move began at)
  local new_x, new_y, cols, len = self.responses[name](self, col, self._x0, self._y0, w, h,
    goal_x, goal_y, self._visited_filter)
  local range = self._world.range
  if not (is_finite(new_x) and is_finite(new_y)) or new_x < -range or new_x > range
    or new_x + w > range or new_y < -range or new_y > range or new_y + h > range then
    error(format("response %s must return the new goal (two finite numbers keeping the "
      .. "item within the world's range, -%s to %s), got %s, %s", describe(name),
      describe(range), describe(range), describe(new_x), describe(new_y)), game_level())
  end
  local rect = type(len) == "number" and len > 0 and type(cols) == "table"
    and type(cols[1]) == "table" and cols[1].itemRect
  if type(rect) == "table" and is_finite(rect.x) and is_finite(rect.y) and rect.x >= -range
    and rect.x - 0.0 + w <= range and rect.y >= -range and rect.y - 0.0 + h <= range then
    return new_x, new_y, rect.x, rect.y
  end
  return new_x, new_y, new_x, new_y
end

-- At a stop after the leg's start: the touch in `col`, placed on the face of the record
-- met across `axis` at leg time t (its other coordinate x + dx * t or y + dy * t), moved
-- back onto the face of each record not met yet that the leg enters at the same t across
-- the other axis and that the stop lies inside. Those times round to one t with the
-- faces apart, and the other coordinate could lie an ulp inside such a record, which the
-- next leg would then start in and be let out of, through it (a review found a slide
-- through a ceiling 25 px thick). At every stop, not only after a tie nearest saw (the
-- _cross_tie flag, 2026-12-06 to 12-07): a slab passed at its corner at that time is not
-- a candidate nearest offers, and with no tie seen a slide went through it (a review,
-- 2026-12-07: 28 of 22547 corner cases built for it, every tree before); and a tie seen
-- before a nearer item set the flag in nearest's scan but not in the crowd's sort, so the
-- two paths differed. Only one the stop is inside: clamping onto a record the leg passes
-- above moved the stop an ulp for nothing. At a stop only, not at a col the leg crosses
-- (its touch is where the leg reaches its face, as computed): a scan of the region for
-- each crossed col cost k^2 again through a crowd crossed (de54c36: 1024 items crossed,
-- 8x the instructions of the same items ignored; bump_spec counts them). Cost
-- (`bench/world.lua --way bump_boxes --count 1000`, LuaJIT, 7 fresh runs each,
-- interleaved with a88667e, 2026-12-07): 975 against 1027 ns per move, and in a second
-- set 1599 against 1413, ranges overlapping; Lua 5.4 60175 -> 60369 instructions per
-- move (the flag's tests gone, this scan added).
local function clamp_tie(self, col, t, axis)
  local x, y, w, h = self._leg_x, self._leg_y, self._w, self._h
  local dx, dy = self._leg_dx, self._leg_dy
  local touch, region, pass = col.touch, self._region, self._pass
  for i = 1, self._region_n do
    local record = region[i]
    local rx, ry = record[1], record[2]
    if rx < self._leg_right and self._leg_left < rx + record[3] and ry < self._leg_bottom
      and self._leg_top < ry + record[4] and record[MARK] < pass
      and touch.x < rx + record[3] and rx < touch.x + w and touch.y < ry + record[4]
      and ry < touch.y + h then -- (the stop is inside it: see above)
      local near_x, far_x, near_y, far_y = leg_times(self, record)
      local enter_x, enter_y = min(near_x, far_x), min(near_y, far_y)
      if max(enter_x, enter_y) + 0 == t and (enter_x > enter_y and 1 or 2) ~= axis then
        if axis == 1 then -- entered across y
          if dy > 0 then touch.y = min(touch.y, before(ry, h, y))
          else touch.y = max(touch.y, ry + record[4]) end
        elseif dx > 0 then touch.x = min(touch.x, before(rx, w, x))
        else touch.x = max(touch.x, rx + record[3]) end
      end
    end
  end
end

-- The move meets candidate k of its leg from (x, y) toward the goal: the filter's answer
-- and its collision. Returns true and the next leg (its start and goal) when it stops
-- there; nil when the leg goes on.
local function meet(self, other, t, axis, x, y, goal_x, goal_y)
  local item, filter = self._item, self._filter
  local answer = "slide"
  if filter ~= nil then answer = filter(item, other[7]) end
  if not answer then
    other[MARK] = self._pass -- ignored: passed over for the rest of this leg
    return nil
  end
  local response = response_of(self, answer, other[7])
  other[MARK] = self._stamp + MET
  local n = self._n + 1
  self._n = n
  local col = fill_col(col_at(self._out, self._out_pool, n), item, other, answer, t,
    axis, x, y, self._w, self._h, goal_x, goal_y)
  if t < 0 or response == "cross" then -- crossed, or let out of it: the leg goes on
    if answer == "slide" then
      local s = col._slide
      s.x, s.y = goal_x, goal_y
      rawset(col, "slide", s) -- (rawset: see COL_META)
    elseif answer == "bounce" then
      local b = col._bounce
      b.x, b.y = goal_x, goal_y
      rawset(col, "bounce", b)
    end
    return nil
  end
  if t > 0 then clamp_tie(self, col, t, axis) end -- (at every stop: see clamp_tie)
  local touch = col.touch
  if response == "touch" then return true, touch.x, touch.y, touch.x, touch.y end
  if response == "slide" then
    local s = col._slide
    s.x, s.y = slide_goal(col, goal_x, goal_y)
    rawset(col, "slide", s)
    return true, touch.x, touch.y, s.x, s.y
  end
  if response == "bounce" then
    local b = col._bounce
    b.x, b.y = bounce_goal(col, goal_x, goal_y)
    rawset(col, "bounce", b)
    return true, touch.x, touch.y, b.x, b.y
  end
  local new_x, new_y, from_x, from_y = custom_response(self, answer, col, self._w, self._h,
    goal_x, goal_y)
  return true, from_x, from_y, new_x, new_y
end

-- One leg from (x, y) toward the goal: true and the next leg when something stops it,
-- false and the goal when nothing does.
local function run_leg(self, x, y, goal_x, goal_y)
  -- LuaJIT shaping: min and max, no branch on the direction (each branch between the
  -- move's loops is a side trace with its own copy of the code up to the next loop)
  do -- (LuaJIT: none of these locals is live in the loop below, see nearest)
    local dx, dy = goal_x - x, goal_y - y
    local w, h = self._w, self._h
    local left, top = min(x, goal_x), min(y, goal_y)
    local right, bottom = max(x, goal_x) + w, max(y, goal_y) + h
    cover(self, left, top, right, bottom)
    -- (nearest reads them from here)
    self._leg_x, self._leg_y, self._leg_dx, self._leg_dy = x, y, dx, dy
    self._leg_goal_x, self._leg_goal_y = goal_x, goal_y
    self._leg_x1, self._leg_y1 = x + w, y + h
    self._leg_left, self._leg_top, self._leg_right, self._leg_bottom = left, top, right, bottom
  end
  self._pass = self._pass + 1 -- (records this leg's filter ignores are marked with it)
  -- (the rounds before the sort, CROWD_WORK: a division, no call: on Lua 5.x math.floor is
  -- a call into C; the first round past it is the one within 1 of it)
  local crowd = self._crowd_work / self._region_n
  if crowd < 1 and crowd > 0 then crowd = 1 end -- (never a sort before the first search: a
  -- region of more than CROWD_WORK records sorted at each leg, though the first candidate
  -- most often stops it; 0, the specs' setting, sorts from the first)
  for round = 1, self._region_n do -- (each round meets one candidate: at most all of them)
    local other, t, axis
    if round > crowd then
      if round - 1 <= crowd then crowd_order(self) end
      other, t, axis = crowd_next(self)
    elseif BRANCH_FREE then other, t, axis = nearest(self)
    else other, t, axis = nearest_compared(self) end
    if other == nil then break end
    local stop, next_x, next_y, next_goal_x, next_goal_y = meet(self, other, t, axis, x, y,
      goal_x, goal_y)
    if stop then return true, next_x, next_y, next_goal_x, next_goal_y end
  end
  return false, goal_x, goal_y, goal_x, goal_y
end

-- LuaJIT shaping: called straight from world:move, never under pcall: traces cannot
-- return through a pcall frame ("NYI: return to lower frame"), and under one every path
-- after a loop of the move aborted (bench/world.lua --way bump_boxes: 15590 ns per move
-- against 3529). A callback's error leaves the world as it was (nothing is written
-- before the plan is done) and _running set, which enter() then finds stale.
---bump's move loop on budge's narrow phase: each leg goes from (x, y) toward the goal and
---asks the filter about what it meets, nearest first, until one answer stops it (touch,
---slide, bounce, a custom response): that one's response gives the next leg (from the
---touch; "cross", an ignored item and one the item starts inside go on along the leg, the
---last let out). What a move met is not met again. Writes the collisions into `list`.
---@param self budge.BumpWorld
---@param proxy table the item's proxy box
---@param goal_x number
---@param goal_y number
---@param filter? function
---@param list table[] the cols list to fill
---@param pool table[] its records
---@return number x, number y, integer n where the item ends, and how many cols
function plan_move(self, proxy, goal_x, goal_y, filter, list, pool)
  self._running = true
  local own = proxy._record
  self._own = own
  -- Marks: a move's marks begin at _stamp, a whole MARK_SPAN above the last move's; a
  -- leg skips a record whose mark is at least its own (_stamp + leg): one its filter
  -- ignored in this leg, and one the move met (_stamp + MET), the item itself too. One
  -- comparison in the narrow phase's loop.
  self._stamp = self._stamp + MARK_SPAN
  self._pass = self._stamp
  own[MARK] = self._stamp + MET
  self._item, self._w, self._h = proxy.item, proxy.width, proxy.height
  self._filter, self._out, self._out_pool = filter, list, pool
  self._n = 0
  self._region_right = -HUGE -- (no region yet: the first leg looks in the hash)
  local x, y = proxy.x, proxy.y
  self._x0, self._y0 = x, y
  -- LuaJIT shaping: the first two legs (all but a few moves) written out, not looped:
  -- inside a loop over legs, the narrow phase's values made LuaJIT abort its traces
  -- ("register coalescing too complex"). The first leg runs even for no motion: it
  -- reports what the item overlaps. Every leg after the first begins where one stopped,
  -- which the move then never meets again: there are at most as many legs as items.
  local stopped
  stopped, x, y, goal_x, goal_y = run_leg(self, x, y, goal_x, goal_y)
  if stopped and (goal_x ~= x or goal_y ~= y) then
    stopped, x, y, goal_x, goal_y = run_leg(self, x, y, goal_x, goal_y)
    while stopped and (goal_x ~= x or goal_y ~= y) do
      stopped, x, y, goal_x, goal_y = run_leg(self, x, y, goal_x, goal_y)
    end
  end
  local n = self._n
  cut(list, n, self._proxies)
  self._running = false
  return x, y, n
end

-- The errors of a move's or a check's goal (finite, and keeping the item within the
-- world's range) and filter, at the caller of world:move or world:check: called when
-- goal_ok fails.
local function check_goal(self, proxy, goal_x, goal_y, filter)
  check_finite(goal_x, "goalX", 4)
  check_finite(goal_y, "goalY", 4)
  check_span(self._world, goal_x, proxy.width, "goalX", "the item", 4)
  check_span(self._world, goal_y, proxy.height, "goalY", "the item", 4)
  -- (false as nil; a callable table as it is. In brackets: not a tail call, which would
  -- take this frame off the stack and the error's level past the caller)
  return (check_bump_filter(filter, 3))
end

-- True when a move's goal is two numbers keeping the item within the world's range (then
-- finite: a NaN or an infinity fails a comparison) and its filter is nil or a function:
-- check_goal's tests in one expression, for it runs on every move. Through check_goal's
-- calls, `lua5.4 bench/world.lua --way bump_boxes --count 1000 --frames 60` spent 6.5% of
-- its time in them (a sampling profile, 2026-12-06).
local function goal_ok(self, proxy, goal_x, goal_y, filter)
  local range = self._world.range
  return type(goal_x) == "number" and type(goal_y) == "number" and goal_x >= -range
    and goal_x <= range and goal_x + proxy.width <= range and goal_y >= -range
    and goal_y <= range and goal_y + proxy.height <= range -- (<= range: see check_span)
    and (filter == nil or type(filter) == "function")
end

---world:check(item, goalX, goalY, filter): where the item would end moving toward the
---goal, and its collisions, without moving it. The list and its records belong to the
---world and are reused by its next check.
---@param item any
---@param goal_x number
---@param goal_y number
---@param filter? fun(item: any, other: any): string|false|nil
---@return number x, number y, table[] cols, integer len
function World:check(item, goal_x, goal_y, filter)
  enter(self, "check")
  local proxy = find_proxy(self, item)
  if not goal_ok(self, proxy, goal_x, goal_y, filter) then
    filter = check_goal(self, proxy, goal_x, goal_y, filter)
  end
  local x, y, n = plan_move(self, proxy, goal_x, goal_y, filter, self._check_cols,
    self._check_pool)
  return x, y, self._check_cols, n
end

---world:move(item, goalX, goalY, filter): moves the item toward the goal, against every
---other item as the filter chooses (default: "slide" on everything); returns where it
---ended and its collisions. The list and its records belong to the world and are reused
---by its next move.
---@param item any
---@param goal_x number
---@param goal_y number
---@param filter? fun(item: any, other: any): string|false|nil
---@return number x, number y, table[] cols, integer len
function World:move(item, goal_x, goal_y, filter)
  enter(self, "move")
  local proxy = find_proxy(self, item)
  if not goal_ok(self, proxy, goal_x, goal_y, filter) then
    filter = check_goal(self, proxy, goal_x, goal_y, filter)
  end
  local x, y, n = plan_move(self, proxy, goal_x, goal_y, filter, self._move_cols,
    self._move_pool)
  if x ~= proxy.x or y ~= proxy.y then
    proxy.x, proxy.y = x, y
    local record = proxy._record
    record[1], record[2] = x, y
    -- Loose cells: a moved item is registered in the cells of its box grown by a quarter
    -- cell each way, and registered again only when its box leaves them (a hash lookup
    -- finds it wherever its box is). Items that stay near where they are, or press on a
    -- wall, cost nothing. About as fast on the world bench's scene (luajit bench/world.lua
    -- --way bump_boxes --count 1000, 5 fresh runs each, interleaved, 2026-12-01: 1282 ns
    -- per move against 1308 with exact cells, 1424 with half a cell).
    local hash = self._world._actors
    local w, h = proxy.width, proxy.height
    local cx0, cy0, cx1, cy1 = hash:cells_of(x, y, w, h)
    -- (the store's last column and row, [12] and [13], not the cells' [10] and [11]: a
    -- box that reaches a cell only by its far side has no entry there, see hash.lua)
    if cx0 < record[8] or cy0 < record[9] or cx1 > record[12] or cy1 > record[13] then
      local margin = self._margin
      hash:remove(record)
      hash:insert(record, x - margin, y - margin, w + 2 * margin, h + 2 * margin)
    end
    hash:repack(record, x, y, x + w, y + h) -- (its own box, in the cells of the loose one)
  end
  return x, y, self._move_cols, n
end

-- Inserts col (at n of list) into place by ti; at the same ti (not an overlap), the one
-- whose face is nearer along the move when both are entered across the same face (a
-- move's tie rule, comes_before); then by the distance between the item's and the
-- other's centres (bump's order), then the order they came in (query order: the order
-- items were added). Stable.
local function col_before(a, b)
  if a.ti ~= b.ti then return a.ti < b.ti end
  local ir, ar, br = a.itemRect, a.otherRect, b.otherRect
  local an, bn = a.normal, b.normal
  if a.ti >= 0 and an.x == bn.x and an.y == bn.y then
    -- (the normal faces the move: -1 for a move forward on its axis)
    local axis, d = an.x ~= 0 and 1 or 2, -(an.x + an.y)
    local fa = near_face(axis, d, ar.x, ar.y, ar.w, ar.h)
    local fb = near_face(axis, d, br.x, br.y, br.w, br.h)
    if fa ~= fb then return fa > fb end
  end
  return square_distance(ir.x, ir.y, ir.w, ir.h, ar.x, ar.y, ar.w, ar.h)
    < square_distance(ir.x, ir.y, ir.w, ir.h, br.x, br.y, br.w, br.h)
end

-- project sorts its cols by col_before, stable, by insertion alone up to COL_RUN and past
-- that in runs of COL_RUN merged (hits.sort_runs). By insertion alone (until 2026-12-07),
-- project through k items piled in its way cost k^2: 1024 piled items, 367 collisions,
-- 98x the interpreter instructions of 64 (Lua 5.4), now 30x (bump_spec). The same order,
-- but where col_before goes round in a circle (faces an ulp apart whose times round to
-- one ti, against a col entered across the other axis at that ti: by face, then by
-- distance), which the insertion and the merge can break in other places.
local COL_RUN = 16

---world:project(item, x, y, w, h, goalX, goalY, filter): every collision the rectangle
---would have moving in a straight line to the goal (default: it stays), sorted by ti,
---with the filter's response as each one's type; nothing moves and no response runs.
---`item` need not be in the world (it is left out when it is). The list and its records
---belong to the world and are reused by its next project.
---@param item any
---@param x number
---@param y number
---@param w number
---@param h number
---@param goal_x? number
---@param goal_y? number
---@param filter? fun(item: any, other: any): string|false|nil
---@return table[] cols, integer len
function World:project(item, x, y, w, h, goal_x, goal_y, filter)
  enter(self, "project")
  check_rect(self, x, y, w, h)
  if goal_x == nil then goal_x = x end
  if goal_y == nil then goal_y = y end
  check_finite(goal_x, "goalX", 3)
  check_finite(goal_y, "goalY", 3)
  check_span(self._world, goal_x, w, "goalX", "the rectangle", 3)
  check_span(self._world, goal_y, h, "goalY", "the rectangle", 3)
  filter = check_bump_filter(filter, 2) or default_filter
  local left, top = min(x, goal_x), min(y, goal_y)
  local right, bottom = max(x, goal_x) + w, max(y, goal_y) + h
  -- (query_rect's far sides are left + width and top + height, which can round below
  -- right and bottom: widened until they do not; the rectangle test below is exact)
  local width, height = right - left, bottom - top
  while left + width < right do width = width + max(abs(left), abs(right)) * 2 ^ -52 end
  while top + height < bottom do height = height + max(abs(top), abs(bottom)) * 2 ^ -52 end
  local found, count = self._world:query_rect(left, top, width, height, self._found)
  -- The collisions first, the filter asked after: a filter may query the world (which
  -- reuses the scratch `found`) or project again (which gets lists of its own).
  local list, pool = self._project_cols, self._project_pool
  local nested = self._projecting and on_stack(self, World.project)
  if nested then list, pool = {}, {} end
  self._projecting = true
  local own = self._proxies[item]
  local n = 0
  for i = 1, count do
    local other = found[i]
    found[i] = nil
    -- (the same rectangle test as a move's legs, so both agree at rounding edges)
    if other ~= own and other.x < right and left < other.x + other.width and other.y < bottom
      and top < other.y + other.height and detect_into(col_at(list, pool, n + 1), x, y, w, h,
      other.x, other.y, other.width, other.height, goal_x, goal_y) then
      n = n + 1
      local col = list[n]
      col.item, col.other, col.type = item, other.item, nil
      rawset(col, "slide", nil) -- (rawset: see COL_META)
      rawset(col, "bounce", nil)
    end
  end
  -- (past n, the last project's records as the pool holds them: its sort left the list in
  -- another order, and cut, below, would have taken the item and other out of a record
  -- this call returns, when the game's item is not in the world or the filter removed
  -- the other; a review, 2026-12-07)
  for i = n + 1, #list do list[i] = pool[i] end
  local kept = 0
  for i = 1, n do
    local col = list[i]
    local answer = filter(item, col.other)
    if answer then
      kept = kept + 1
      col.type = answer
      list[i], list[kept] = list[kept], col -- (what was at kept was left out)
    end
  end
  if kept > 1 then sort_runs(list, kept, COL_RUN, col_before, nil, self._sort_scratch) end
  cut(list, kept, self._proxies)
  self._projecting = nested
  return list, kept
end

-- queries --------------------------------------------------------------------------

-- The items of the proxies in found 1..count that `filter` (if any) accepts, in a new list
-- (copied before the filter is asked: it may query the world, which reuses `found`).
local function items_of(found, count, filter)
  local items = {}
  for i = 1, count do
    items[i] = found[i].item
    found[i] = nil
  end
  if filter == nil then return items, count end
  local n = 0
  for i = 1, count do
    local item = items[i]
    items[i] = nil
    if filter(item) then
      n = n + 1
      items[n] = item
    end
  end
  return items, n
end

---world:queryPoint(x, y, filter): the items strictly containing the point (an edge is
---outside), in the order they were added; a new list.
---@param x number
---@param y number
---@param filter? fun(item: any): any
---@return any[] items, integer len
function World:queryPoint(x, y, filter)
  enter(self, "queryPoint")
  check_finite(x, "x", 3)
  check_finite(y, "y", 3)
  check_span(self._world, x, 0, "x", "the point", 3)
  check_span(self._world, y, 0, "y", "the point", 3)
  filter = check_bump_filter(filter, 2)
  local found, count = self._world:query_point(x, y, self._found)
  return items_of(found, count, filter)
end

---world:queryRect(x, y, w, h, filter): the items overlapping the rectangle (strictly),
---in the order they were added; a new list.
---@param x number
---@param y number
---@param w number
---@param h number
---@param filter? fun(item: any): any
---@return any[] items, integer len
function World:queryRect(x, y, w, h, filter)
  enter(self, "queryRect")
  check_rect(self, x, y, w, h)
  filter = check_bump_filter(filter, 2)
  local found, count = self._world:query_rect(x, y, w, h, self._found)
  return items_of(found, count, filter)
end

-- The proxies the segment passes through (strictly), nearest first, with where it enters
-- and leaves each (fractions of it, within 0 and 1), into the world's scratch.
local function segment_hits(self, x1, y1, x2, y2)
  check_finite(x1, "x1", 4)
  check_finite(y1, "y1", 4)
  check_finite(x2, "x2", 4)
  check_finite(y2, "y2", 4)
  local w = self._world
  check_span(w, x1, 0, "x1", "the segment", 4)
  check_span(w, y1, 0, "y1", "the segment", 4)
  check_span(w, x2, 0, "x2", "the segment", 4)
  check_span(w, y2, 0, "y2", "the segment", 4)
  local found, count, entered = w:query_segment(x1, y1, x2, y2, self._found, self._found_t)
  -- The items entered at 0 (the segment starts inside them, or on a near face), here in
  -- the order they were added, in bump's order: by where the infinite line through the
  -- segment enters each (before the start for those it starts inside), then (as near) in
  -- the order added. Past them, budge's order is bump's.
  local run = 0
  while run < count and entered[run + 1] == 0 do run = run + 1 end
  if run > 1 then
    local keys = self._found_key
    for i = 1, run do
      local proxy = found[i]
      local near, far = segment_indices(proxy.x, proxy.y, proxy.width, proxy.height, x1, y1,
        x2, y2, -HUGE, HUGE)
      keys[i] = near and min(near, far) or 0 -- (nil: never, it passes through it)
    end
    for i = 2, run do -- (insertion: stable)
      local proxy, key = found[i], keys[i]
      local j = i - 1
      while j >= 1 and keys[j] > key do
        found[j + 1], keys[j + 1] = found[j], keys[j]
        j = j - 1
      end
      found[j + 1], keys[j + 1] = proxy, key
    end
  end
  return found, count
end

---world:querySegment(x1, y1, x2, y2, filter): the items the segment passes through
---(strictly: touching an edge or a corner is not), in the order it meets them (then in
---the order they were added); a new list.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param filter? fun(item: any): any
---@return any[] items, integer len
function World:querySegment(x1, y1, x2, y2, filter)
  enter(self, "querySegment")
  filter = check_bump_filter(filter, 2)
  local found, count = segment_hits(self, x1, y1, x2, y2)
  return items_of(found, count, filter)
end

---world:querySegmentWithCoords(x1, y1, x2, y2, filter): querySegment's items, each as
---{item =, ti1 =, ti2 =, x1 =, y1 =, x2 =, y2 =}: the fractions of the segment where it
---enters and leaves the item's rectangle (within 0 and 1), and those points; a new list.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param filter? fun(item: any): any
---@return table[] infos, integer len
function World:querySegmentWithCoords(x1, y1, x2, y2, filter)
  enter(self, "querySegmentWithCoords")
  filter = check_bump_filter(filter, 2)
  local found, count = segment_hits(self, x1, y1, x2, y2)
  local infos, n = {}, 0
  local dx, dy = x2 - x1, y2 - y1
  for i = 1, count do -- (all of them first: the filter may query the world, reusing found)
    local proxy = found[i]
    found[i] = nil
    local ti1, ti2 = segment_indices(proxy.x, proxy.y, proxy.width, proxy.height, x1, y1,
      x2, y2, 0, 1)
    if ti1 then -- (always: the segment passes through it)
      n = n + 1
      infos[n] = {item = proxy.item, ti1 = ti1, ti2 = ti2, x1 = x1 + dx * ti1,
        y1 = y1 + dy * ti1, x2 = x1 + dx * ti2, y2 = y1 + dy * ti2}
    end
  end
  if filter == nil then return infos, n end
  local kept = 0
  for i = 1, n do
    local info = infos[i]
    infos[i] = nil
    if filter(info.item) then
      kept = kept + 1
      infos[kept] = info
    end
  end
  return infos, kept
end

-- the rest of bump's API ---------------------------------------------------------------

---world:hasItem(item): true when the value is an item of this world (any value: nil
---and nan are never items).
---@param item any
---@return boolean
function World:hasItem(item)
  if item == nil or item ~= item then return false end
  return self._proxies[item] ~= nil
end

-- Records in the order their items were added.
local function added_before(a, b)
  return a.id < b.id
end

---world:getItems(): a new list of the items, in the order they were added, and its length.
---@return any[] items, integer len
function World:getItems()
  enter(self, "getItems")
  local list, records = self._list, self._world._records
  local sorted = {}
  for i = 1, #list do sorted[i] = records[list[i]] end
  table.sort(sorted, added_before)
  for i = 1, #sorted do sorted[i] = sorted[i][7] end
  return sorted, #sorted
end

---world:countItems(): how many items.
---@return integer
function World:countItems()
  return #self._list
end

---world:getRect(item): its x, y, w, h.
---@param item any
---@return number x, number y, number w, number h
function World:getRect(item)
  enter(self, "getRect")
  local proxy = find_proxy(self, item)
  return proxy.x, proxy.y, proxy.width, proxy.height
end

---world:toWorld(cx, cy): the top left corner of the cell (1, 1 is the one at 0, 0).
---@param cx integer
---@param cy integer
---@return number x, number y
function World:toWorld(cx, cy)
  local size = self.cellSize
  return (cx - 1) * size, (cy - 1) * size
end

---world:toCell(x, y): the cell holding the point.
---@param x number
---@param y number
---@return integer cx, integer cy
function World:toCell(x, y)
  local size = self.cellSize
  return floor(x / size) + 1, floor(y / size) + 1
end

---world:countCells(): how many cells of cellSize hold at least one item, counted now
---(bump counts an emptied cell until the garbage collector runs).
---@return integer
function World:countCells()
  enter(self, "countCells")
  local size, rows, count = self.cellSize, {}, 0
  local list = self._list
  for i = 1, #list do
    local proxy = list[i]
    local left, top = floor(proxy.x / size) + 1, floor(proxy.y / size) + 1
    local right = ceil((proxy.x + proxy.width) / size)
    local bottom = ceil((proxy.y + proxy.height) / size)
    for cy = top, bottom do
      local row = rows[cy]
      if row == nil then
        row = {}
        rows[cy] = row
      end
      for cx = left, right do
        if not row[cx] then
          row[cx] = true
          count = count + 1
        end
      end
    end
  end
  return count
end

return bump
