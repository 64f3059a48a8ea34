-- budge.bump: bump.lua 3.1.7's API on budge's engine, so that a game written for bump
-- switches with one line: `local bump = require("budge.bump")`. README.md, "Coming from
-- bump.lua", lists what differs from bump and why.
--
-- Every bump item is an actor of a budge world, standing for itself through a proxy box
-- the front end owns (the game's own values are keys, never written to), so every item
-- can block every other, as in bump. world:move is budge's "swept" method (the straight
-- line to the goal, then a slide along what it met), asked through the game's filter;
-- the collision records are bump's, filled from budge's contacts. world:project and
-- bump.rect.detectCollision answer with the same rules: the exact-corner tie lands on
-- the top or bottom face, and a box that starts inside another is let out, never backed
-- out along its move.
--
-- A move allocates nothing once the world is warm: the `cols` list it returns, and the
-- records in it, belong to the world and are reused by its next move (world:check and
-- world:project have lists of their own). Queries return new lists, as in bump.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local sweep = require(here .. ".sweep")
local hits = require(here .. ".hits")
local actors = require(here .. ".actors")
local entry = require(here .. ".entry")
local move = require(here .. ".move")
local world_module = require(here .. ".world")

local describe, is_finite = box.describe, box.is_finite
local box_enter = sweep.box_enter
local guarded, abandon_move, check_span = entry.guarded, entry.abandon_move, entry.check_span
local BadResponse = hits.BadResponse
local SWEPT = move.BY_NAME.swept
local format, error, type, setmetatable = string.format, error, type, setmetatable
local floor, ceil, abs, min, max = math.floor, math.ceil, math.abs, math.min, math.max

local bump = {
  _VERSION = "0.1.0", -- budge's version (a spec ties them); the API is bump.lua 3.1.7's
  _DESCRIPTION = "bump.lua 3.1.7's API on budge's engine",
  _LICENSE = "MIT",
}

-- A custom response's leg (world:addResponse) ends where the next begins; a move takes at
-- most this many (each excludes what the legs before it met, as bump does).
local MAX_LEGS = 64

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

-- Fills `col` (a record with the tables move, normal, touch, itemRect and otherRect) with
-- what the rectangle (x1, y1, w1, h1) moving to (goal_x, goal_y) meets of (x2, y2, w2,
-- h2), by budge's rules; returns col, or nil when it meets nothing.
-- * Moving into it from outside: `ti` is the fraction of the move where it touches, and
--   the normal is the face's; aimed exactly at a corner, the top or bottom face (budge's
--   corner rule: it lands on it).
-- * Overlapping it at the start: `overlaps` is true and `ti` is minus the overlap's area
--   (so the deepest sorts first). Standing still, `touch` is the nearest place outside
--   (the minimum displacement, on y when x and y are as near), with its normal; moving,
--   the box is let out: `touch` is where it starts and the normal that displacement's.
local function detect_into(col, x1, y1, w1, h1, x2, y2, w2, h2, goal_x, goal_y)
  local dx, dy = goal_x - x1, goal_y - y1
  local ti, nx, ny, tx, ty
  local overlaps = is_intersecting(x1, y1, w1, h1, x2, y2, w2, h2)
  if overlaps then
    local x, y, w, h = rect_diff(x1, y1, w1, h1, x2, y2, w2, h2)
    local px, py = nearest_corner(x, y, w, h, 0, 0)
    ti = -min(w1, abs(px)) * min(h1, abs(py))
    if abs(px) < abs(py) then py = 0 else px = 0 end
    nx, ny = sign(px), sign(py)
    if dx == 0 and dy == 0 then tx, ty = x1 + px, y1 + py else tx, ty = x1, y1 end
  else
    local axis
    ti, axis = box_enter(x1, y1, w1, h1, dx, dy, x2, y2, w2, h2)
    if ti == nil then return nil end
    if axis == 1 then nx, ny = dx > 0 and -1 or 1, 0 else nx, ny = 0, dy > 0 and -1 or 1 end
    tx, ty = x1 + dx * ti, y1 + dy * ti
    -- exactly on the face it touches
    if axis == 1 then tx = dx > 0 and x2 - w1 or x2 + w2 else ty = dy > 0 and y2 - h1 or y2 + h2 end
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

local function new_col()
  return {overlaps = false, ti = 0, move = {x = 0, y = 0}, normal = {x = 0, y = 0},
    touch = {x = 0, y = 0}, itemRect = {x = 0, y = 0, w = 0, h = 0},
    otherRect = {x = 0, y = 0, w = 0, h = 0}, _slide = {x = 0, y = 0},
    _bounce = {x = 0, y = 0}}
end

---bump.rect.detectCollision: a new collision record, or nil (see detect_into).
local function detect_collision(x1, y1, w1, h1, x2, y2, w2, h2, goal_x, goal_y)
  local col = detect_into(new_col(), x1, y1, w1, h1, x2, y2, w2, h2, goal_x or x1,
    goal_y or y1)
  if col then col._slide, col._bounce = nil, nil end
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
---@field package _engine table<string, string> response name -> the engine's response,
---or "custom" for one the front end runs itself (the engine stops there: "touch")
---@field package _filter function the running move's filter (the default: "slide")
---@field package _translate function the filter budge's engine asks (made once per world)
---@field package _custom table<table, string> proxy -> the custom response chosen for it
---@field package _custom_list table[] those proxies, to clear after the leg
---@field package _n_custom integer
---@field package _visited table<table, boolean> what the legs before a custom one met
---@field package _visited_list table[]
---@field package _n_visited integer
---@field package _move_cols table[] world:move's list (reused), its records from _move_pool
---@field package _move_pool table[]
---@field package _check_cols table[] world:check's
---@field package _check_pool table[]
---@field package _project_cols table[] world:project's
---@field package _project_pool table[]
---@field package _found table[] the budge world's query output (scratch)
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

local function check_filter(filter)
  if filter ~= nil and type(filter) ~= "function" then
    error(format("filter must be a function or nil, got %s", describe(filter)), 3)
  end
end

-- The start of every method: called with a colon, and not from inside a move's filter.
local function enter(self, call)
  if getmetatable(self) ~= World then
    error(format("call it as world:%s(...), with a colon, got %s for the world", call,
      describe(self)), 3)
  end
  if self._world._busy then
    error(format("world:%s was called from inside a move's filter: a filter may not move, "
      .. "add, update, remove or query the world it is called from", call), 3)
  end
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
  local self = setmetatable({
    cellSize = cell_size,
    responses = {},
    _world = world_module.new_world({cell_size = cell_size}),
    _proxies = {},
    _list = {},
    _engine = {},
    _filter = default_filter, -- the move's filter (the translator below reads it)
    _custom = {}, -- proxy -> the custom response name its filter chose, during a move
    _custom_list = {}, -- those proxies, to clear
    _n_custom = 0,
    _visited = {}, -- proxy -> true: what earlier legs of this move met (custom responses)
    _visited_list = {},
    _n_visited = 0,
    _move_cols = {}, _move_pool = {},
    _check_cols = {}, _check_pool = {},
    _project_cols = {}, _project_pool = {},
    _found = {},
  }, World)
  -- The filter budge's engine asks during a move: the game's filter, asked about the
  -- other item, its answer turned into the engine's response.
  local proxies_custom, visited, engine = self._custom, self._visited, self._engine
  self._translate = function(proxy, other)
    if self._n_visited > 0 and visited[other] then return nil end
    local answer = self._filter(proxy.item, other.item)
    if answer == nil or answer == false then return nil end
    local response = engine[answer]
    if response == nil then
      error(setmetatable({message = format("filter must return the name of a response "
        .. "(\"touch\", \"cross\", \"slide\", \"bounce\" or one given to world:addResponse), "
        .. "or false/nil, got %s for %s", describe(answer), describe(other.item))},
        BadResponse))
    end
    if response == "custom" then
      if proxies_custom[other] == nil then
        local n = self._n_custom + 1
        self._n_custom = n
        self._custom_list[n] = other
      end
      proxies_custom[other] = answer
      return "touch"
    end
    return response
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
  if type(name) ~= "string" then
    error(format("name must be a string, got %s", describe(name)), 2)
  end
  if type(response) ~= "function" then
    error(format("response must be a function, got %s", describe(response)), 2)
  end
  self.responses[name] = response
  self._engine[name] = ENGINE[response] or "custom"
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
  proxy._id = self._world._records[proxy].id
  self._proxies[item] = proxy
  return item
end

---world:remove(item).
---@param item any
function World:remove(item)
  enter(self, "remove")
  local proxy = find_proxy(self, item)
  self._world:remove(proxy)
  self._proxies[item] = nil
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
  end
  list[n] = col
  return col
end

-- Ends `list` at n (so #list and ipairs see n records).
local function cut(list, n)
  for i = n + 1, #list do list[i] = nil end
end

-- Appends to `list` (from index n + 1) the collision records of the engine leg just made
-- by `proxy` from (x, y) toward (goal_x, goal_y): one per contact, in the order they
-- happened. Returns n, the goal of its last slide and the last record's type.
local function collect_cols(self, list, pool, n, proxy, x, y, goal_x, goal_y)
  local w = self._world
  local found, custom = w._hits, self._custom
  local width, height = proxy.width, proxy.height
  local slide = 1 -- the slide of the engine's move this leg of it belongs to
  local t0 = 0 -- the time it began, x, y where, goal_x, goal_y its goal
  local last_type
  local blocked_x, blocked_y, next_x, next_y, t_next, bounced = false, false, x, y, 0, false
  for i = 1, w._n_hits do
    local hit = found[i]
    local other = hit.other
    local round = floor((hit._round + 1) / 2)
    if round > slide then -- the engine slid (or bounced) on from what stopped it last
      slide = round
      if bounced then
        if blocked_x then goal_x = 2 * next_x - goal_x end
        if blocked_y then goal_y = 2 * next_y - goal_y end
      else
        if blocked_x then goal_x = next_x end
        if blocked_y then goal_y = next_y end
      end
      x, y, t0 = next_x, next_y, t_next
      blocked_x, blocked_y, bounced = false, false, false
    end
    n = n + 1
    local col = col_at(list, pool, n)
    local kind = custom[other] or hit.response
    col.item, col.other, col.type = proxy.item, other.item, kind
    if hit.side == nil then -- it was inside already: let out
      detect_into(col, x, y, width, height, other.x, other.y, other.width, other.height,
        goal_x, goal_y)
    else
      local m, normal, touch, ir, orr = col.move, col.normal, col.touch, col.itemRect,
        col.otherRect
      col.overlaps = false
      col.ti = t0 < 1 and (hit.t - t0) / (1 - t0) or 0
      m.x, m.y = goal_x - x, goal_y - y
      normal.x, normal.y = hit.nx, hit.ny
      touch.x, touch.y = hit._x, hit._y
      ir.x, ir.y, ir.w, ir.h = x, y, width, height
      orr.x, orr.y, orr.w, orr.h = other.x, other.y, other.width, other.height
      if kind ~= "cross" then
        if normal.x ~= 0 then blocked_x = true else blocked_y = true end
        if hit.response == "bounce" then bounced = true end
        next_x, next_y, t_next = hit._x, hit._y, hit.t
      end
    end
    col.slide, col.bounce = nil, nil
    if kind == "slide" then
      local s = col._slide
      s.x, s.y = slide_goal(col, goal_x, goal_y)
      col.slide = s
    elseif kind == "bounce" then
      local b = col._bounce
      b.x, b.y = bounce_goal(col, goal_x, goal_y)
      col.bounce = b
    end
    last_type = kind
  end
  return n, goal_x, goal_y, last_type
end

-- What a filter's error leaves (entry.guarded): the item where its move began, the leg's
-- contacts gone.
local function abandon_leg(w, proxy)
  abandon_move(w)
  proxy.x, proxy.y = proxy._x0, proxy._y0
end

-- One leg: the engine moves the proxy toward the goal, asking the game's filter through
-- the translator. An axis on which nothing stopped it ends exactly at the goal (x + (goal
-- - x) can round off it).
local function engine_leg(self, proxy, goal_x, goal_y)
  local w = self._world
  local x, y = proxy.x, proxy.y
  local dx, dy = goal_x - x, goal_y - y
  w._n_hits = 0
  -- (level 4: the game's line, through run_move and world:move or world:check)
  guarded(w, "a move's filter", 4, SWEPT.move, abandon_leg, proxy, dx, dy, self._translate,
    SWEPT)
  hits.sort(w)
  if proxy.x == x + dx then proxy.x = goal_x end
  if proxy.y == y + dy then proxy.y = goal_y end
end

-- Empties a set kept as a table and a list of its keys; returns 0, its new count.
local function forget(set, list, n)
  for i = 1, n do
    set[list[i]] = nil
    list[i] = nil
  end
  return 0
end

-- Adds the others of `list` 1..n to the move's visited set: the legs after a custom
-- response leave them out, as bump's do.
local function visit(self, list, n)
  local visited, proxies = self._visited, self._proxies
  for i = 1, n do
    local other = proxies[list[i].other]
    if other and not visited[other] then
      local k = self._n_visited + 1
      self._n_visited = k
      self._visited_list[k] = other
      visited[other] = true
    end
  end
end

-- Where the game's custom response to `col` says to go on to from the touch. Its error
-- leaves the item where the move began.
local function custom_goal(self, name, col, proxy, goal_x, goal_y, filter)
  local touch = col.touch
  local ok, new_x, new_y = pcall(self.responses[name], self, col, touch.x, touch.y,
    proxy.width, proxy.height, goal_x, goal_y, filter)
  if not ok or not (is_finite(new_x) and is_finite(new_y)) then
    proxy.x, proxy.y = proxy._x0, proxy._y0
    if not ok then error(new_x, 0) end
    error(format("response %s must return the new goal (two finite numbers), got %s, %s",
      describe(name), describe(new_x), describe(new_y)), 4)
  end
  return new_x, new_y
end

-- Where `proxy` ends moving toward (goal_x, goal_y), its collisions written into `list`;
-- leaves the proxy there (the callers put it back or keep it). Returns how many.
local function run_move(self, proxy, goal_x, goal_y, filter, list, pool)
  -- (what an error in an earlier move left in the sets goes now)
  self._n_custom = forget(self._custom, self._custom_list, self._n_custom)
  self._n_visited = forget(self._visited, self._visited_list, self._n_visited)
  self._filter = filter or default_filter
  proxy._x0, proxy._y0 = proxy.x, proxy.y
  local n = 0
  for _ = 1, MAX_LEGS do
    local x, y = proxy.x, proxy.y
    engine_leg(self, proxy, goal_x, goal_y)
    local last_type
    n, goal_x, goal_y, last_type = collect_cols(self, list, pool, n, proxy, x, y, goal_x,
      goal_y)
    self._n_custom = forget(self._custom, self._custom_list, self._n_custom)
    if last_type == nil or self._engine[last_type] ~= "custom" then break end
    visit(self, list, n)
    goal_x, goal_y = custom_goal(self, last_type, list[n], proxy, goal_x, goal_y, filter)
  end
  self._n_visited = forget(self._visited, self._visited_list, self._n_visited)
  cut(list, n)
  return n
end

-- The goal of a move or a check: finite, and keeping the item within the world's range.
local function check_goal(self, proxy, goal_x, goal_y)
  check_finite(goal_x, "goalX", 4)
  check_finite(goal_y, "goalY", 4)
  check_span(self._world, goal_x, proxy.width, "goalX", "the item", 4)
  check_span(self._world, goal_y, proxy.height, "goalY", "the item", 4)
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
  check_goal(self, proxy, goal_x, goal_y)
  check_filter(filter)
  local x, y = proxy.x, proxy.y
  local n = run_move(self, proxy, goal_x, goal_y, filter, self._check_cols, self._check_pool)
  local to_x, to_y = proxy.x, proxy.y
  proxy.x, proxy.y = x, y
  return to_x, to_y, self._check_cols, n
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
  check_goal(self, proxy, goal_x, goal_y)
  check_filter(filter)
  local n = run_move(self, proxy, goal_x, goal_y, filter, self._move_cols, self._move_pool)
  local record = self._world._records[proxy]
  record.x, record.y = proxy.x, proxy.y
  actors.moved(self._world, record)
  return proxy.x, proxy.y, self._move_cols, n
end

-- Inserts col (at n of list) into place by ti, then by the distance between the item's
-- and the other's centres (bump's order), then the order they came in (query order:
-- the order items were added). Stable.
local function col_before(a, b)
  if a.ti ~= b.ti then return a.ti < b.ti end
  local ir, ar, br = a.itemRect, a.otherRect, b.otherRect
  return square_distance(ir.x, ir.y, ir.w, ir.h, ar.x, ar.y, ar.w, ar.h)
    < square_distance(ir.x, ir.y, ir.w, ir.h, br.x, br.y, br.w, br.h)
end

local function insert_sorted(list, n)
  local col = list[n]
  local j = n - 1
  while j >= 1 and col_before(col, list[j]) do
    list[j + 1] = list[j]
    j = j - 1
  end
  list[j + 1] = col
end

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
  check_filter(filter)
  filter = filter or default_filter
  local left, top = min(x, goal_x), min(y, goal_y)
  local found, count = self._world:query_rect(left, top, max(x, goal_x) + w - left,
    max(y, goal_y) + h - top, self._found)
  local list, pool = self._project_cols, self._project_pool
  local own = self._proxies[item]
  local n = 0
  for i = 1, count do
    local other = found[i]
    if other ~= own then
      local answer = filter(item, other.item)
      if answer then
        local col = detect_into(col_at(list, pool, n + 1), x, y, w, h, other.x, other.y,
          other.width, other.height, goal_x, goal_y)
        if col then
          n = n + 1
          col.item, col.other, col.type = item, other.item, answer
          col.slide, col.bounce = nil, nil
          insert_sorted(list, n)
        end
      end
    end
    found[i] = nil
  end
  cut(list, n)
  return list, n
end

-- queries --------------------------------------------------------------------------

-- The items of the proxies in found 1..count that `filter` (if any) accepts, in a new list.
local function items_of(found, count, filter)
  local items, n = {}, 0
  for i = 1, count do
    local item = found[i].item
    found[i] = nil
    if filter == nil or filter(item) then
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
  check_filter(filter)
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
  check_filter(filter)
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
  local found, count = w:query_segment(x1, y1, x2, y2, self._found)
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
  check_filter(filter)
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
  check_filter(filter)
  local found, count = segment_hits(self, x1, y1, x2, y2)
  local infos, n = {}, 0
  local dx, dy = x2 - x1, y2 - y1
  for i = 1, count do
    local proxy = found[i]
    found[i] = nil
    local item = proxy.item
    if filter == nil or filter(item) then
      local ti1, ti2 = segment_indices(proxy.x, proxy.y, proxy.width, proxy.height, x1, y1,
        x2, y2, 0, 1)
      if ti1 then -- (always: the segment passes through it)
        n = n + 1
        infos[n] = {item = item, ti1 = ti1, ti2 = ti2, x1 = x1 + dx * ti1, y1 = y1 + dy * ti1,
          x2 = x1 + dx * ti2, y2 = y1 + dy * ti2}
      end
    end
  end
  return infos, n
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

-- Proxies in the order their items were added.
local function added_before(a, b)
  return a._id < b._id
end

---world:getItems(): a new list of the items, in the order they were added, and its length.
---@return any[] items, integer len
function World:getItems()
  enter(self, "getItems")
  local list = self._list
  local sorted = {}
  for i = 1, #list do sorted[i] = list[i] end
  table.sort(sorted, added_before)
  for i = 1, #sorted do sorted[i] = sorted[i].item end
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
