-- budge.resolve: discrete push-out, the rungs of the ladder that look only at where the
-- mover is now: "seed", "wall_type" and "min_axis".
--
-- Each rule moves `a` out of `b` along ONE axis and returns the push it applied. Positions
-- are written exactly (a.y = b.y - a.height), never accumulated, so a box pushed onto a
-- floor rests with its bottom equal to the floor's top and no gap.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")

local overlaps = box.overlaps
local penetration = box.penetration
local check_box, check_wall_type = box.check_box, box.check_wall_type
local describe = box.describe
local format, error = string.format, error

local resolve = {}

-- Pushes `a` to just above (up = true) or just below `b`; returns the push.
local function push_vertical(a, b, up)
  local old = a.y
  if up then a.y = b.y - a.height else a.y = b.y + b.height end
  return 0, a.y - old
end

-- Pushes `a` to just left of (left = true) or just right of `b`; returns the push.
local function push_horizontal(a, b, left)
  local old = a.x
  if left then a.x = b.x - a.width else a.x = b.x + b.width end
  return a.x - old, 0
end

-- The shortest way out: the axis with less penetration, ties going vertical so that a
-- mover hitting a corner exactly diagonally lands on it (or bumps its head) instead of
-- being thrown sideways; on that axis, the side of a's centre, ties going up / left.
local function shortest(a, b)
  local push_x, push_y = penetration(a, b)
  local abs_x = push_x < 0 and -push_x or push_x
  local abs_y = push_y < 0 and -push_y or push_y
  if abs_x < abs_y then
    return push_horizontal(a, b, push_x < 0)
  end
  return push_vertical(a, b, push_y < 0)
end

-- "wall_type": the article's idea with the side chosen centre to centre (ties up / left).
-- A wall with no wall_type is solid on all sides: it pushes the shortest way out.
local function by_wall_type(a, b)
  local wall_type = b.wall_type
  if wall_type == "horizontal" then
    return push_vertical(a, b, a.y + a.height - b.y <= b.y + b.height - a.y)
  elseif wall_type == "vertical" then
    return push_horizontal(a, b, a.x + a.width - b.x <= b.x + b.width - a.x)
  end
  return shortest(a, b)
end

-- "seed": the article's published rule, a's top-left corner against b's centre, with its
-- strict "<" (a corner level with the centre goes below / right). A wall with no
-- wall_type (which the article's code ignores) gets the shortest axis and the same rule.
local function by_seed(a, b)
  local wall_type = b.wall_type
  if wall_type == nil then
    local push_x, push_y = penetration(a, b)
    if (push_x < 0 and -push_x or push_x) < (push_y < 0 and -push_y or push_y) then
      wall_type = "vertical"
    else
      wall_type = "horizontal"
    end
  end
  if wall_type == "horizontal" then
    return push_vertical(a, b, a.y < b.y + b.height / 2)
  end
  return push_horizontal(a, b, a.x < b.x + b.width / 2)
end

-- "min_axis": the shortest way out, whatever b.wall_type says.
local function by_min_axis(a, b)
  return shortest(a, b)
end

---The discrete rules by name: each `rule(a, b)` assumes `a` overlaps `b`, that b is not
---oneway, and that both are valid; it moves `a` and returns dx, dy.
resolve.RULES = {
  wall_type = by_wall_type,
  seed = by_seed,
  min_axis = by_min_axis,
}

---A oneway wall pushes only up, and only a box whose bottom was at or above the wall's
---top before this step (`prev_y` is a's y then). Returns the push, or 0, 0.
---@param a budge.Box the mover
---@param b budge.Box the oneway wall
---@param prev_y number a's y before this step
---@return number dx, number dy
function resolve.oneway(a, b, prev_y)
  if prev_y + a.height <= b.y then
    return push_vertical(a, b, true)
  end
  return 0, 0
end
local oneway = resolve.oneway

local METHOD_NAMES = '"wall_type", "seed" or "min_axis"'

---Looks up a discrete rule by name for a public entry; errors at `level` if unknown.
---@param method any
---@param level integer
---@return fun(a: budge.Box, b: budge.Box): number, number rule
function resolve.rule(method, level)
  local rule = resolve.RULES[method]
  if not rule then
    error(format("method must be %s, got %s", METHOD_NAMES, describe(method)), level + 1)
  end
  return rule
end

---Moves `a` out of `b` in place, along one axis, and returns the push it applied.
---`b` never moves. Returns 0, 0 when the boxes do not overlap (touching is not overlap).
---
---`method` is "wall_type" (the default), "seed" or "min_axis". Whatever the method, a
---`b.wall_type == "oneway"` platform pushes only up, and only when `a.prev_y` (a's y
---before this step, which the caller sets) put a's bottom at or above b's top.
---@param a budge.Box the mover
---@param b budge.Box the wall
---@param method? "wall_type"|"seed"|"min_axis"
---@return number dx, number dy
function resolve.resolve_collision(a, b, method)
  check_box(a, "a", 2)
  check_box(b, "b", 2)
  check_wall_type(b, "b", 2)
  local rule = resolve.rule(method or "wall_type", 2)
  if b.wall_type == "oneway" then
    local prev_y = a.prev_y
    if not box.is_finite(prev_y) then
      error(format("a.prev_y must be a finite number (a's y before this step) to resolve "
        .. "against a oneway wall, got %s", describe(prev_y)), 2)
    end
    if not overlaps(a, b) then return 0, 0 end
    return oneway(a, b, prev_y)
  end
  if not overlaps(a, b) then return 0, 0 end
  return rule(a, b)
end

return resolve
