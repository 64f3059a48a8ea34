-- budge.advise: which method is enough for a scene, and why, in plain words.
--
-- The ladder is DESIGN.md's, cheapest model first: "wall_type" (the article's method
-- with the walls typed as given), "fat_cross" (blocks hit from both sides get a cross),
-- "min_axis" (every wall solid on all sides, the shortest way out), then "axis_sweep",
-- which is safe at any speed. A rung is enough when every mover stays inside its
-- envelope against every solid it can reach, with the bounds that spec/stability_spec.lua
-- pins (S = the mover's size and T = the wall's thickness along the push):
--
-- * a typed wall pushes right while speed < (S + T) / 2, and only if it is not open on
--   the sides its type does not push toward ("horizontal" open on its left: a mover
--   walking into it is lifted on top);
-- * a fat cross stops side hits while speed <= its inset, which must stay below half the
--   block's smaller side; top and bottom as a typed wall;
-- * the shortest way out needs speed < (S + T) / 2 on each open axis, and no seam in a
--   wall (two boxes stacked along one open vertical face): sliding down it, the mover is
--   pushed down a pixel at every seam;
-- * a oneway platform catches a falling mover while speed < S + T.
--
-- A face is open when the other solids do not cover all of it and it looks into
-- `scene.bounds` (the area the movers stay in, when given). Inside a world the answer
-- is always axis_sweep: `make bench` measures it cheaper than every discrete method there.
-- Meant for setup time: faces are checked against their neighbours in a spatial hash.

local here = (...):match("^(.*)%.[^%.]+$")
local box = require(here .. ".box")
local fatcross = require(here .. ".fatcross")
local hash = require(here .. ".hash")
local world_module = require(here .. ".world")

local check_box, check_wall_type = box.check_box, box.check_wall_type
local describe, is_finite = box.describe, box.is_finite
local format, error, type, sort = string.format, error, type, table.sort

local advise = {}

---@class budge.Scene
---@field solids? budge.Box[] the walls (or a world, not both)
---@field world? table a budge world
---@field movers {width: number, height: number, max_speed: number}[] max_speed: px per step
---@field bounds? budge.Box the area the movers stay in

local num = describe -- numbers in reasons read as in error messages

local function where(solid)
  return format("the %sx%s block at (%s, %s)", num(solid.width), num(solid.height),
    num(solid.x), num(solid.y))
end

-- The walls in a spatial hash, so that the faces of thousands of merged boxes are
-- checked against their neighbours only.
local INDEX_CELL = 64

local function new_index(walls)
  local index = {hash = hash.new(INDEX_CELL), found = {}}
  for i = 1, #walls do
    local wall = walls[i]
    index.hash:insert({item = wall, order = i, _stamp = 0}, wall.x, wall.y, wall.width,
      wall.height)
  end
  return index
end

local function by_order(a, b) return a.order < b.order end

-- The walls whose boxes touch the rectangle (edges included), in the order given.
local function walls_near(index, x, y, width, height)
  local found = index.found
  local n = index.hash:collect(x, y, width, height, found, 0)
  for i = n + 1, #found do found[i] = nil end
  sort(found, by_order)
  local walls = {}
  for i = 1, n do walls[i] = found[i].item end
  return walls
end

-- How much of one face of `rect` the other walls leave uncovered: returns
-- open_somewhere, open_everywhere. `axis` "x" means the left (side -1) or right (side 1)
-- face. A face that looks out of `bounds` (the area movers stay in) is closed.
local function face_open(rect, index, axis, side, bounds)
  local line, low, high
  local intervals = {}
  if axis == "x" then
    line = side < 0 and rect.x or rect.x + rect.width
    low, high = rect.y, rect.y + rect.height
  else
    line = side < 0 and rect.y or rect.y + rect.height
    low, high = rect.x, rect.x + rect.width
  end
  if bounds then
    local edge = bounds[axis .. (side < 0 and "_min" or "_max")]
    if (side < 0 and line <= edge) or (side > 0 and line >= edge) then return false, false end
  end
  local others
  if axis == "x" then others = walls_near(index, line, low, 0, high - low)
  else others = walls_near(index, low, line, high - low, 0) end
  for i = 1, #others do
    local other = others[i]
    local near, far, from, to
    if axis == "x" then
      near, far, from, to = other.x, other.x + other.width, other.y, other.y + other.height
    else
      near, far, from, to = other.y, other.y + other.height, other.x, other.x + other.width
    end
    -- it must reach across the face line to the outside of this face
    local across
    if side < 0 then across = near < line and far >= line else across = near <= line and far > line end
    if across and from < high and to > low then
      intervals[#intervals + 1] = {from > low and from or low, to < high and to or high}
    end
  end
  if #intervals == 0 then return true, true end
  sort(intervals, function(a, b) return a[1] < b[1] end)
  local reached = low
  for i = 1, #intervals do
    if intervals[i][1] > reached then return true, false end
    if intervals[i][2] > reached then reached = intervals[i][2] end
  end
  return reached < high, false
end

local function check_scene(scene)
  if type(scene) ~= "table" then
    error(format("scene must be a table {solids = {...} or world = w, movers = {...}}, got %s",
      describe(scene)), 3)
  end
  local solids, world = scene.solids, scene.world
  if (solids == nil) == (world == nil) then
    error("scene must have exactly one of solids (an array of boxes) and world (a budge world)",
      3)
  end
  if world ~= nil and not world_module.is_world(world) then
    error(format("scene.world must be a budge world (budge.new_world()), got %s",
      describe(world)), 3)
  end
  if solids ~= nil then
    if type(solids) ~= "table" then
      error(format("scene.solids must be an array of boxes, got %s", describe(solids)), 3)
    end
    for i = 1, #solids do
      local name = format("scene.solids[%d]", i)
      check_box(solids[i], name, 3)
      check_wall_type(solids[i], name, 3)
      if solids[i].tall ~= nil then
        check_box(solids[i].tall, name .. ".tall", 3)
        check_box(solids[i].wide, name .. ".wide", 3)
      end
    end
  end
  if scene.bounds ~= nil then check_box(scene.bounds, "scene.bounds", 3) end
  local movers = scene.movers
  if type(movers) ~= "table" or #movers == 0 then
    error(format("scene.movers must be a non-empty array of {width, height, max_speed}, got %s",
      describe(movers)), 3)
  end
  for i = 1, #movers do
    local mover = movers[i]
    if type(mover) ~= "table" then
      error(format("scene.movers[%d] must be a table {width, height, max_speed}, got %s", i,
        describe(mover)), 3)
    end
    for _, field in ipairs({"width", "height"}) do
      if not is_finite(mover[field]) or mover[field] <= 0 then
        error(format("scene.movers[%d].%s must be a finite number > 0, got %s", i, field,
          describe(mover[field])), 3)
      end
    end
    if not is_finite(mover.max_speed) or mover.max_speed < 0 then
      error(format("scene.movers[%d].max_speed must be a finite number >= 0 (px per step), "
        .. "got %s", i, describe(mover.max_speed)), 3)
    end
  end
end

-- The faces of each solid that movers can reach: {left, right, top, bottom} booleans.
-- Also returns the walls (the solids but oneway platforms), the bounds for face_open and
-- the walls' index.
local function open_faces(solids, area)
  local walls, faces = {}, {}
  local bounds
  if area then
    bounds = {x_min = area.x, y_min = area.y, x_max = area.x + area.width,
      y_max = area.y + area.height}
  end
  for i = 1, #solids do
    if solids[i].wall_type ~= "oneway" then walls[#walls + 1] = solids[i] end
  end
  local index = new_index(walls)
  for i = 1, #walls do
    local solid = walls[i]
    faces[solid] = {
      left = face_open(solid, index, "x", -1, bounds),
      right = face_open(solid, index, "x", 1, bounds),
      top = face_open(solid, index, "y", -1, bounds),
      bottom = face_open(solid, index, "y", 1, bounds),
    }
  end
  return walls, faces, bounds, index
end

-- How a rung resolves a solid: "oneway", "cross", "horizontal", "vertical" or
-- "shortest" (solid on all sides, the shortest way out).
local function treatment(rung, solid, face)
  if solid.wall_type == "oneway" then return "oneway" end
  if rung == "min_axis" then return "shortest" end
  local open_both = (face.left or face.right) and (face.top or face.bottom)
  if rung == "fat_cross" and open_both then return "cross" end
  if solid.tall ~= nil then return "shortest" end -- a cross only serves the fat_cross rung
  return solid.wall_type or "shortest"
end

-- True when a mover can slide along the face (`side` -1 left, 1 right) across the
-- junction of `a` above `b`: the face is open for a pixel (or less, on thin boxes) on
-- both sides of the junction.
local function open_across(a, b, side, index, bounds)
  local reach = math.min(1, a.height, b.height)
  local x = side < 0 and a.x or a.x + a.width
  local above = {x = side < 0 and x or x - 1, y = b.y - reach, width = 1, height = reach}
  local below = {x = above.x, y = b.y, width = 1, height = reach}
  local _, above_open = face_open(above, index, "x", side, bounds)
  local _, below_open = face_open(below, index, "x", side, bounds)
  return above_open and below_open
end

-- The first seam in a wall: two solids resolved by the shortest way out, one on top of
-- the other, flush on a vertical face a mover can slide along. Returns the two, or nil.
local function find_seam(rung, walls, faces, bounds, index)
  for i = 1, #walls do
    local a = walls[i]
    if treatment(rung, a, faces[a]) == "shortest" then
      local below = walls_near(index, a.x, a.y + a.height, a.width, 0)
      for j = 1, #below do
        local b = below[j]
        -- (rawequal: == on two of the game's boxes runs their __eq, which may say anything)
        if not rawequal(b, a) and treatment(rung, b, faces[b]) == "shortest"
          and b.y == a.y + a.height then
          if (a.x == b.x and open_across(a, b, -1, index, bounds))
            or (a.x + a.width == b.x + b.width and open_across(a, b, 1, index, bounds)) then
            return a, b
          end
        end
      end
    end
  end
  return nil
end

local function fastest(movers)
  local top = 0
  for i = 1, #movers do
    if movers[i].max_speed > top then top = movers[i].max_speed end
  end
  return top
end

-- The smallest mover size along an axis ("width" or "height") among movers at `speed`
-- or faster: the worst case for a (S + T) / 2 bound.
local function too_fast(movers, size_field, thickness, bound)
  for i = 1, #movers do
    local mover = movers[i]
    local limit = bound(mover[size_field], thickness)
    if mover.max_speed >= limit then return mover, limit end
  end
  return nil
end

local function half_sum(size, thickness) return (size + thickness) / 2 end
local function full_sum(size, thickness) return size + thickness end

local function speed_problem(solid, movers, axis)
  local size_field, thickness = "height", solid.height
  if axis == "x" then size_field, thickness = "width", solid.width end
  local mover, limit = too_fast(movers, size_field, thickness, half_sum)
  if mover then
    return format("a %sx%s mover at %s px per step passes the middle of %s (it needs less "
      .. "than %s on %s)", num(mover.width), num(mover.height), num(mover.max_speed),
      where(solid), num(limit), axis)
  end
  return nil
end

-- Problems for one rung ("wall_type", "fat_cross" or "min_axis"): a list of sentences.
local function problems_of(rung, solids, walls, faces, bounds, index, movers)
  local problems = {}
  local speed = fastest(movers)
  for i = 1, #solids do
    local solid = solids[i]
    if solid.wall_type == "oneway" then
      local mover, limit = too_fast(movers, "height", solid.height, full_sum)
      if mover then
        problems[#problems + 1] = format("a %sx%s mover at %s px per step falls through the "
          .. "oneway platform at (%s, %s) (it needs less than %s)", num(mover.width),
          num(mover.height), num(mover.max_speed), num(solid.x), num(solid.y), num(limit))
      end
    end
  end
  for i = 1, #walls do
    local solid = walls[i]
    local face = faces[solid]
    local open_x, open_y = face.left or face.right, face.top or face.bottom
    local how = treatment(rung, solid, face)
    local problem
    if how == "cross" then
      local inset = solid.tall and solid.tall.x - solid.x or speed
      local limit = fatcross.speed_limit(solid.width, solid.height)
      if solid.tall and inset < speed then
        problem = format("%s has a cross with an inset of %s, less than the %s px per step "
          .. "of the fastest mover", where(solid), num(inset), num(speed))
      elseif not solid.tall and speed >= limit then
        problem = format("%s is hit from the side and from %s, and is too small for a cross "
          .. "at %s px per step (it serves speeds below %s)", where(solid),
          face.top and "above" or "below", num(speed), num(limit))
      else
        problem = speed_problem(solid, movers, "y")
      end
    elseif how == "horizontal" then
      if open_x then
        problem = format("%s is typed horizontal but is open on its %s side: a mover that "
          .. "walks into it there is lifted onto it", where(solid), face.left and "left" or "right")
      elseif open_y then
        problem = speed_problem(solid, movers, "y")
      end
    elseif how == "vertical" then
      if open_y then
        problem = format("%s is typed vertical but is open on its %s: a mover that lands on "
          .. "it is pushed off sideways", where(solid), face.top and "top" or "bottom")
      elseif open_x then
        problem = speed_problem(solid, movers, "x")
      end
    elseif rung == "wall_type" and open_x and open_y then
      problem = format("%s is hit from the side and from %s, and no wall_type is right for "
        .. "both", where(solid), face.top and "above" or "below")
    else -- the shortest way out on each open axis
      problem = (open_x and speed_problem(solid, movers, "x"))
        or (open_y and speed_problem(solid, movers, "y")) or nil
    end
    if problem then problems[#problems + 1] = problem end
  end
  local a, b = find_seam(rung, walls, faces, bounds, index)
  if a then
    problems[#problems + 1] = format("%s and %s make a seam in a wall: the shortest way out "
      .. "drags a mover sliding down it a pixel further at the seam", where(a),
      (where(b):gsub("^the ", "")))
  end
  return problems
end

local LADDER = {"wall_type", "fat_cross", "min_axis"}

local ENOUGH = {
  wall_type = "wall_type is enough: every wall is typed for the sides it is hit from, and "
    .. "the fastest mover (%s px per step) stays under half of mover plus wall thickness",
  fat_cross = "fat_cross is enough: the fastest mover moves %s px per step and every "
    .. "crossed block has an inset of at least %s (a mover may overlap a crossed block's "
    .. "corner by up to the inset for a step: the corner notches)",
  min_axis = "min_axis is enough: the fastest mover (%s px per step) stays under half of "
    .. "mover plus wall thickness on every open side, and no wall has a seam",
}

---Returns the cheapest method whose envelope covers the scene, and the reasons, in plain
---words: one "X is not enough: ..." for each cheaper rung (its first problem, and how many
---more), then "X is enough: ...". `scene.solids` is an array of boxes (those from
---budge.tiles.merge keep their crosses) or `scene.world` a world; `scene.movers` lists
---`{width, height, max_speed}` with max_speed in px per step on each axis. The optional
---`scene.bounds` box is the area movers stay in: faces that look out of it (a level's
---outer walls) are never hit.
---@param scene budge.Scene
---@return string method "wall_type", "fat_cross", "min_axis" or "axis_sweep"
---@return string[] reasons
function advise.advise(scene)
  check_scene(scene)
  local movers, reasons = scene.movers, {}
  if scene.world then
    reasons[1] = "axis_sweep: inside a world it is both the cheapest method and right in "
      .. "every catalogue case (make bench: 368 ns per move on LuaJIT against 670 to 737 for "
      .. "the discrete methods), so world:move's \"auto\" is axis_sweep"
    return "axis_sweep", reasons
  end
  local solids = scene.solids
  local walls, faces, bounds, index = open_faces(solids, scene.bounds)
  local speed = fastest(movers)
  for _, rung in ipairs(LADDER) do
    local problems = problems_of(rung, solids, walls, faces, bounds, index, movers)
    if #problems == 0 then
      reasons[#reasons + 1] = format(ENOUGH[rung], num(speed), num(speed))
      return rung, reasons
    end
    local more = #problems > 1 and format(" (and %d more)", #problems - 1) or ""
    reasons[#reasons + 1] = format("%s is not enough: %s%s", rung, problems[1], more)
  end
  reasons[#reasons + 1] = "axis_sweep is enough at any speed: it moves x, then y, and stops "
    .. "at the first face (put the solids in a world); swept follows the exact diagonal "
    .. "at about 2.5 times the cost"
  return "axis_sweep", reasons
end

return advise
