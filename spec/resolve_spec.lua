local budge = require("budge")
local sim = require("spec.support.sim")

local EPS = 1 / 64 -- exact in binary, so "just outside" is one representable step

local box = require("fixtures.box")

local function push(a, b, method)
  local dx, dy = budge.resolve_collision(a, b, method)
  return {dx, dy, a.x, a.y}
end

describe("budge.resolve_collision", function()
  describe("with the default wall_type method", function()
    it("pushes out of a horizontal wall only along y, to the side of the centre", function()
      assert.same({0, -3, 5, 87}, push(box(5, 90, 12, 12), box(0, 99, 64, 16, "horizontal")))
      assert.same({0, 2, 5, 116}, push(box(5, 114, 12, 12), box(0, 100, 64, 16, "horizontal")))
    end)

    it("pushes out of a vertical wall only along x, to the side of the centre", function()
      assert.same({-4, 0, 88, 10}, push(box(92, 10, 12, 12), box(100, 0, 16, 64, "vertical")))
      assert.same({3, 0, 116, 10}, push(box(113, 10, 12, 12), box(100, 0, 16, 64, "vertical")))
    end)

    it("returns 0, 0 and moves nothing when the boxes only touch", function()
      local a = box(88, 10, 12, 12)
      assert.same({0, 0, 88, 10}, push(a, box(100, 0, 16, 64, "vertical")))
    end)

    it("pushes out of a wall without wall_type the shortest way (solid on all sides)", function()
      assert.same({-2, 0, 88, 30}, push(box(90, 30, 12, 12), box(100, 0, 16, 64)))
      assert.same({0, -1, 105, -12}, push(box(105, -11, 12, 12), box(100, 0, 16, 64)))
    end)

    it("never moves the wall", function()
      local wall = box(100, 0, 16, 64, "vertical")
      budge.resolve_collision(box(95, 5, 12, 12), wall)
      assert.same(box(100, 0, 16, 64, "vertical"), wall)
    end)

    it("sends a mover whose centre is level with the wall's up, or left (the tie rule)",
      function()
        assert.same({0, -14, 2, 88}, push(box(2, 102, 12, 12), box(0, 100, 16, 16, "horizontal")))
        assert.same({-14, 0, 88, 2}, push(box(102, 2, 12, 12), box(100, 0, 16, 16, "vertical")))
      end)

    it("lifts a mover that hits a horizontal wall from the side onto its top (the article's own limitation)",
      function()
        -- moving right into the end of a floor slab: 3 px into it, and it is teleported
        -- 14 px up instead of being stopped at the slab's left face
        local floor = box(100, 100, 64, 16, "horizontal")
        assert.same({0, -14, 91, 88}, push(box(91, 102, 12, 12), floor))
        assert.same({0, -3, 91, 88}, push(box(91, 91, 12, 12), floor))
      end)
  end)

  describe("with the seed method (the article as published)", function()
    it("chooses the side by the mover's top-left corner against the wall's centre", function()
      -- 11 px into the slab from below: the centres say "below" (wall_type pushes down
      -- 11), the top-left corner is above the slab's centre (seed lifts it 17 on top)
      local wall = box(0, 100, 64, 16, "horizontal")
      assert.same({0, 11, 5, 116}, push(box(5, 105, 12, 12), wall, "wall_type"))
      assert.same({0, -17, 5, 88}, push(box(5, 105, 12, 12), wall, "seed"))
      assert.same({0, -7, 5, 88}, push(box(5, 95, 12, 12), wall, "seed"))
    end)

    it("differs from wall_type only in where the side flips", function()
      local wall = box(100, 0, 16, 64, "vertical")
      -- 9 px into the wall from the right: wall_type keeps it right, seed throws it left
      assert.same({9, 0, 116, 5}, push(box(107, 5, 12, 12), wall, "wall_type"))
      assert.same({-19, 0, 88, 5}, push(box(107, 5, 12, 12), wall, "seed"))
    end)

    it("sends a top-left corner level with the centre below or right (its strict <)",
      function()
        assert.same({0, 8, 0, 116}, push(box(0, 108, 12, 12), box(0, 100, 64, 16, "horizontal"), "seed"))
        assert.same({8, 0, 116, 0}, push(box(108, 0, 12, 12), box(100, 0, 16, 64, "vertical"), "seed"))
      end)
  end)

  describe("with the min_axis method", function()
    it("ignores wall_type and pushes the shortest way out", function()
      -- a "horizontal" slab hit 3 px from the side: stopped at the face, not lifted
      assert.same({-3, 0, 88, 102}, push(box(91, 102, 12, 12), box(100, 100, 64, 16, "horizontal"), "min_axis"))
    end)

    it("pushes vertically when both ways out are equally short", function()
      assert.same({0, -4, 92, 88}, push(box(92, 92, 12, 12), box(100, 100, 16, 16), "min_axis"))
    end)

    it("measures the way out, not the overlap, for a mover wider than the wall", function()
      -- overlap on x is the post's 4 px width, but clearing it takes 10 px either way;
      -- the vertical way out is 6 px, so the push is vertical
      assert.same({0, -6, 0, 3}, push(box(0, 9, 16, 12), box(6, 15, 4, 20), "min_axis"))
    end)
  end)

  describe("with a oneway platform", function()
    local platform = box(0, 100, 64, 8, "oneway")

    it("lands a box that came from above", function()
      local a = {x = 5, y = 93, width = 12, height = 12, prev_y = 86}
      assert.same({0, -5, 5, 88}, push(a, platform))
    end)

    it("lands a box that was resting exactly on it", function()
      local a = {x = 5, y = 89, width = 12, height = 12, prev_y = 88}
      assert.same({0, -1, 5, 88}, push(a, platform, "seed"))
    end)

    it("lets a box pass that came from below or from the side", function()
      assert.same({0, 0, 5, 95}, push({x = 5, y = 95, width = 12, height = 12, prev_y = 104}, platform))
      assert.same({0, 0, 5, 89}, push({x = 5, y = 89, width = 12, height = 12, prev_y = 89}, platform, "min_axis"))
    end)

    it("needs the mover's prev_y", function()
      assert.has_error(function() budge.resolve_collision(box(5, 95, 12, 12), platform) end,
        "a.prev_y must be a finite number (a's y before this step) to resolve against a oneway wall, got nil")
    end)
  end)

  describe("with bad input", function()
    it("names the argument, the field and the value, and changes nothing", function()
      local a = box(90, 30, 12, 12)
      local wall = box(100, 0, 16, 64)
      assert.has_error(function() budge.resolve_collision(a, wall, "fast") end,
        'method must be "wall_type", "seed" or "min_axis", got "fast"')
      assert.has_error(function() budge.resolve_collision(a, box(100, 0, 16, 64, "diagonal")) end,
        'b.wall_type must be "horizontal", "vertical", "oneway" or nil, got "diagonal"')
      assert.has_error(function() budge.resolve_collision(a, box(100, 0, 16, 64, 3)) end,
        'b.wall_type must be "horizontal", "vertical", "oneway" or nil, got 3')
      assert.has_error(function() budge.resolve_collision(a, box(100, 0, 16, 0 / 0)) end,
        "b.height must be a finite number >= 0, got nan")
      assert.has_error(function() budge.resolve_collision(a, true) end,
        "b must be a box table {x, y, width, height}, got true")
      assert.has_error(function() budge.resolve_collision({x = 1, y = 2, width = {}}, wall) end,
        "a.width must be a finite number >= 0, got a table")
      assert.same(box(90, 30, 12, 12), a)
    end)

    it("blames the caller's line", function()
      local ok, message = pcall(function() budge.resolve_collision(box(0, 0, 1, 1), box(0, 0, 1, 1), 1) end)
      assert.is_false(ok)
      assert.matches("resolve_spec%.lua:%d+: method must be", message)
    end)
  end)
end)

-- Sliding: a 12x12 mover pressed 1 px per step into a surface of separate 16x16 tiles
-- while moving 3 px per step along it, for 200 steps. The mover must keep its full
-- travel along the surface and stay flush against it at every seam.
describe("sliding over separate tiles", function()
  local function slide(method, along_floor)
    local typed = (method == "wall_type" or method == "seed")
    local solids
    if along_floor then
      solids = sim.tiles(0, 100, 16, 45, true, typed and "horizontal" or nil)
    else
      solids = sim.tiles(100, 0, 16, 45, false, typed and "vertical" or nil)
    end
    if method == "fat_cross" then solids = sim.crossed(solids, 3) end
    local mover = along_floor and box(0, 88, 12, 12) or box(88, 0, 12, 12)
    local first_slip
    for step = 1, 200 do
      if along_floor then
        sim.step(mover, 3, 1, solids, method)
        if not first_slip and (mover.x ~= 3 * step or mover.y ~= 88) then
          first_slip = {step, mover.x, mover.y}
        end
      else
        sim.step(mover, 1, 3, solids, method)
        if not first_slip and (mover.x ~= 88 or mover.y ~= 3 * step) then
          first_slip = {step, mover.x, mover.y}
        end
      end
    end
    return mover, first_slip
  end

  for _, method in ipairs({"seed", "wall_type", "min_axis", "fat_cross"}) do
    it(method .. " slides along a floor of separate tiles without rising or sinking at a seam",
      function()
        local mover, first_slip = slide(method, true)
        assert.is_nil(first_slip)
        assert.same({600, 88}, {mover.x, mover.y})
      end)
  end

  for _, method in ipairs({"seed", "wall_type", "fat_cross"}) do
    it(method .. " slides down a wall of stacked tiles at full speed", function()
      local mover, first_slip = slide(method, false)
      assert.is_nil(first_slip)
      assert.same({88, 600}, {mover.x, mover.y})
    end)
  end

  it("min_axis is dragged down at wall seams (equal ways out go vertical)", function()
    -- at y = 15 the mover is 1 px into the wall and 1 px below the upper tile's
    -- bottom: both ways out are 1 px, the tie goes vertical, and it is pushed down
    local mover, first_slip = slide("min_axis", false)
    assert.same({5, 88, 16}, first_slip)
    assert.same({88, 640}, {mover.x, mover.y})
  end)
end)

-- Corners: a 12x12 mover moving (4, 4) per step at the top-left corner of a 16x16 block
-- at (32, 32), aimed exactly corner to corner, and 1 px above and below that line.
describe("hitting an outer corner diagonally", function()
  local function corner(method, offset, wall_type)
    local block = box(32, 32, 16, 16, wall_type)
    local solids = {block}
    if method == "fat_cross" then solids = sim.crossed(solids, 4) end
    local mover = box(12, 12 + offset, 12, 12)
    for _ = 1, 3 do sim.step(mover, 4, 4, solids, method) end
    return {mover.x, mover.y}
  end

  it("lands on top when aimed exactly at the corner (ties go vertical)", function()
    assert.same({24, 20}, corner("min_axis", 0))
    assert.same({24, 20}, corner("wall_type", 0))
    assert.same({24, 20}, corner("seed", 0))
  end)

  it("lands on top when aimed 1 px high and stops at the side when 1 px low", function()
    for _, method in ipairs({"min_axis", "wall_type", "seed"}) do
      assert.same({24, 20}, corner(method, -1))
      assert.same({20, 25}, corner(method, 1))
    end
  end)

  it("follows the wall's type, not the geometry, with wall_type", function()
    assert.same({24, 20}, corner("wall_type", 1, "horizontal"))
    assert.same({20, 23}, corner("wall_type", -1, "vertical"))
  end)

  it("lets the fat cross's notch swallow a corner hit within the inset", function()
    -- 4 px into the block on both axes is inside the notch: no hitbox is touched
    assert.same({24, 24}, corner("fat_cross", 0))
  end)
end)

-- Speed: a 12x12 mover hits a 16 px thick wall (64 px long) from each side, starting
-- flush against it and moving `speed` into it in one step. The largest speed that still
-- resolves to the correct side, with S = 12 (mover) and T = 16 (wall):
--   seed       from left/top:  speed < S + T/2 = 20   from right/bottom: speed <= T/2 = 8
--   wall_type  from left/top:  speed <= (S+T)/2 = 14  from right/bottom: speed < 14
--   min_axis   the same as wall_type while the wall's other way out is longer
--   fat_cross  sides: speed <= inset (6 here); top: <= 14; bottom: < 14
-- Past S + T = 28 there is no overlap left to resolve: every discrete method tunnels.
describe("the speed envelope of each discrete method", function()
  local function wall(from, wall_type)
    if from == "left" or from == "right" then
      return box(100, 0, 16, 64, wall_type and "vertical" or nil)
    end
    return box(0, 100, 64, 16, wall_type and "horizontal" or nil)
  end

  local function pin(method, typed, from, last_good, first_bad, failure)
    it(("%s from the %s holds up to %s px per step and fails at %s"):format(
      method, from, last_good, first_bad), function()
      assert.equal("correct", sim.hit(method, from, last_good, wall(from, typed), 12, 6))
      assert.equal(failure, sim.hit(method, from, first_bad, wall(from, typed), 12, 6))
    end)
  end

  for _, from in ipairs({"left", "top"}) do
    pin("seed", true, from, 20 - EPS, 20, "wrong side")
    pin("wall_type", true, from, 14, 14 + EPS, "wrong side")
    pin("min_axis", false, from, 14, 14 + EPS, "wrong side")
  end
  for _, from in ipairs({"right", "bottom"}) do
    pin("seed", true, from, 8, 8 + EPS, "wrong side")
    pin("wall_type", true, from, 14 - EPS, 14, "wrong side")
    pin("min_axis", false, from, 14 - EPS, 14, "wrong side")
  end
  pin("fat_cross", false, "left", 6, 6 + EPS, "teleported")
  pin("fat_cross", false, "right", 6, 6 + EPS, "teleported")
  pin("fat_cross", false, "top", 14, 14 + EPS, "wrong side")
  pin("fat_cross", false, "bottom", 14 - EPS, 14, "wrong side")

  it("tunnels with every discrete method once the step clears the wall", function()
    for _, method in ipairs({"seed", "wall_type", "min_axis", "fat_cross"}) do
      assert.equal("tunnelled", sim.hit(method, "left", 28, wall("left", true), 12, 6))
      assert.equal("wrong side", sim.hit(method, "left", 28 - EPS, wall("left", true), 12, 6))
    end
  end)
end)
