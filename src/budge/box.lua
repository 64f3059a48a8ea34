-- budge.box: AABB primitives and the input checks every public entry uses.
--
-- A box is the caller's own table {x =, y =, width =, height =} with the origin at
-- the top-left corner and y growing downward. Touching edges are not a collision:
-- every comparison here is strict.

local box = {}

local HUGE = math.huge
local floor = math.floor
local format = string.format
local tostring, type, error = tostring, type, error

---@class budge.Box
---@field x number left edge
---@field y number top edge (y grows downward)
---@field width number >= 0
---@field height number >= 0
---@field wall_type? "horizontal"|"vertical"|"oneway" nil means solid on all sides
---@field prev_y? number the box's y before this step (read for oneway walls)

---Describes a value for an error message the same way on every interpreter
---(tostring(0/0) is "nan" on some platforms and "-nan" on others; 5.3 prints 3.0).
---@param value any
---@return string
function box.describe(value)
  local kind = type(value)
  if kind == "number" then
    if value ~= value then return "nan" end
    if value == HUGE then return "inf" end
    if value == -HUGE then return "-inf" end
    if value == floor(value) and value > -2 ^ 53 and value < 2 ^ 53 then
      return format("%d", value)
    end
    return format("%.14g", value)
  elseif kind == "string" then
    return format("%q", value)
  elseif kind == "nil" or kind == "boolean" then
    return tostring(value)
  end
  return "a " .. kind
end
local describe = box.describe

---True when `value` is a number that is neither NaN nor infinite.
---@param value any
---@return boolean
function box.is_finite(value)
  return type(value) == "number" and value == value and value ~= HUGE and value ~= -HUGE
end
local is_finite = box.is_finite

---Raises "<name> must be a finite number, got <value>" at `level` (1 = the caller of
---the function that calls check_number).
---@param value any
---@param name string the argument's name in the message
---@param level integer
function box.check_number(value, name, level)
  if not is_finite(value) then
    error(format("%s must be a finite number, got %s", name, describe(value)), level + 1)
  end
end

---Raises "filter must be a function or nil, got <value>" at `level` (1 = the caller of
---the function that calls check_filter) unless `filter` is a function or nil.
---@param filter any
---@param level integer
function box.check_filter(filter, level)
  if filter ~= nil and type(filter) ~= "function" then
    error(format("filter must be a function or nil, got %s", describe(filter)), level + 1)
  end
end

---Checks that `b` is a box: a table whose x, y, width and height are finite numbers,
---width and height >= 0. `name` names the argument in the message.
---@param b any
---@param name string
---@param level integer
function box.check_box(b, name, level)
  if type(b) ~= "table" then
    error(format("%s must be a box table {x, y, width, height}, got %s", name, describe(b)),
      level + 1)
  end
  local value = b.x
  if not is_finite(value) then
    error(format("%s.x must be a finite number, got %s", name, describe(value)), level + 1)
  end
  value = b.y
  if not is_finite(value) then
    error(format("%s.y must be a finite number, got %s", name, describe(value)), level + 1)
  end
  value = b.width
  if not is_finite(value) or value < 0 then
    error(format("%s.width must be a finite number >= 0, got %s", name, describe(value)),
      level + 1)
  end
  value = b.height
  if not is_finite(value) or value < 0 then
    error(format("%s.height must be a finite number >= 0, got %s", name, describe(value)),
      level + 1)
  end
end

local WALL_TYPES = {horizontal = true, vertical = true, oneway = true}

---Checks `b.wall_type`: "horizontal", "vertical", "oneway" or nil.
---@param b table a box whose other fields are checked
---@param name string
---@param level integer
function box.check_wall_type(b, name, level)
  local wall_type = b.wall_type
  if wall_type ~= nil and not WALL_TYPES[wall_type] then
    error(format('%s.wall_type must be "horizontal", "vertical", "oneway" or nil, got %s',
      name, describe(wall_type)), level + 1)
  end
end

---The overlap test without checks, for inner loops: strict, so touching is not a hit.
---@param a budge.Box
---@param b budge.Box
---@return boolean
function box.overlaps(a, b)
  return a.x < b.x + b.width and b.x < a.x + a.width
    and a.y < b.y + b.height and b.y < a.y + a.height
end
local overlaps = box.overlaps

---True when boxes `a` and `b` overlap; touching edges are not a collision.
---This is the seed article's AABB test with its typo fixed: the article compares
---`box_a.y + box_b.height`, budge compares `a.y + a.height`.
---@param a budge.Box
---@param b budge.Box
---@return boolean
function box.detect_collision(a, b)
  box.check_box(a, "a", 2)
  box.check_box(b, "b", 2)
  return overlaps(a, b)
end

---The shortest way out of `b` on each axis, for overlapping boxes (unchecked).
---Returns the x push (negative = left) and the y push (negative = up). On each axis the
---side is the one with less penetration, which is the side of a's centre; when the
---centres are level the push goes toward negative coordinates (left, up).
---@param a budge.Box
---@param b budge.Box
---@return number push_x, number push_y
function box.penetration(a, b)
  local to_left = a.x + a.width - b.x        -- distance to move left to clear b
  local to_right = b.x + b.width - a.x       -- distance to move right to clear b
  local to_top = a.y + a.height - b.y
  local to_bottom = b.y + b.height - a.y
  local push_x = to_left <= to_right and -to_left or to_right
  local push_y = to_top <= to_bottom and -to_top or to_bottom
  return push_x, push_y
end

return box
