-- The continuous methods, axis_sweep and swept, in a world: seams, corners, speed, rest.
local budge = require("budge")

local CONTINUOUS = {"axis_sweep", "swept"}

local function tile_row_world(as_tiles, horizontal, count)
  -- a straight surface of 16x16 tiles starting at 0: a floor at y = 100 (horizontal)
  -- or a wall at x = 100
  local world = budge.new_world()
  if as_tiles then
    local grid = {}
    if horizontal then
      grid[1] = {}
      for col = 1, count do grid[1][col] = 1 end
      world:add_tiles(grid, 16, 16, {x = 0, y = 100})
    else
      for row = 1, count do grid[row] = {1} end
      world:add_tiles(grid, 16, 16, {x = 100, y = 0})
    end
  else
    for i = 0, count - 1 do
      if horizontal then
        world:add_solid({x = i * 16, y = 100, width = 16, height = 16})
      else
        world:add_solid({x = 100, y = i * 16, width = 16, height = 16})
      end
    end
  end
  return world
end

describe("sliding with a continuous method", function()
  for _, method in ipairs(CONTINUOUS) do
    for _, as_tiles in ipairs({true, false}) do
      local kind = as_tiles and "a tile layer" or "separate boxes"
      it(method .. " slides along a floor of " .. kind .. " without stopping at a seam", function()
        local world = tile_row_world(as_tiles, true, 45)
        local actor = world:add_actor({x = 0, y = 88, width = 12, height = 12})
        for step = 1, 200 do
          local x, y, n, hits = world:move(actor, 3, 1, method)
          assert.equal(3 * step, x)
          assert.equal(88, y)
          assert.is_true(n >= 1)
          for i = 1, n do assert.equal("floor", hits[i].side) end
        end
      end)

      it(method .. " slides along a ceiling of " .. kind .. " without stopping at a seam", function()
        local world = tile_row_world(as_tiles, true, 45)
        local actor = world:add_actor({x = 0, y = 116, width = 12, height = 12})
        for step = 1, 200 do
          local x, y, n, hits = world:move(actor, 3, -1, method)
          assert.same({3 * step, 116}, {x, y})
          assert.equal("ceiling", n > 0 and hits[1].side)
        end
      end)

      it(method .. " slides down a wall of " .. kind .. " without stopping at a seam", function()
        local world = tile_row_world(as_tiles, false, 45)
        local actor = world:add_actor({x = 88, y = 0, width = 12, height = 12})
        for step = 1, 200 do
          local x, y, n, hits = world:move(actor, 1, 3, method)
          assert.same({88, 3 * step}, {x, y})
          assert.equal("right", n > 0 and hits[1].side)
        end
      end)
    end
  end
end)

-- A 32x32 block at (100, 100) and a 12x12 actor 20 px away, moving 40 px in one step
-- toward it from eight directions (diagonals aimed exactly at a corner).
describe("corners at eight approach angles", function()
  local APPROACHES = {
    -- name, start x, start y, dx, dy, expected x, y, side
    {"north", 110, 60, 0, 40, 110, 88, "floor"},
    {"south", 110, 160, 0, -40, 110, 132, "ceiling"},
    {"west", 60, 110, 40, 0, 88, 110, "right"},
    {"east", 160, 110, -40, 0, 132, 110, "left"},
    {"north-west", 68, 68, 40, 40, 108, 88, "floor"},
    {"north-east", 152, 68, -40, 40, 112, 88, "floor"},
    {"south-west", 68, 152, 40, -40, 108, 132, "ceiling"},
    {"south-east", 152, 152, -40, -40, 112, 132, "ceiling"},
  }
  for _, method in ipairs(CONTINUOUS) do
    for _, case in ipairs(APPROACHES) do
      it(("%s from the %s ends flush on the expected face"):format(method, case[1]), function()
        local world = budge.new_world()
        local block = world:add_solid({x = 100, y = 100, width = 32, height = 32})
        local actor = world:add_actor({x = case[2], y = case[3], width = 12, height = 12})
        local x, y, n, hits = world:move(actor, case[4], case[5], method)
        assert.same({case[6], case[7]}, {x, y})
        assert.equal(1, n)
        assert.equal(block, hits[1].other)
        assert.equal(case[8], hits[1].side)
      end)
    end
  end

  it("differ 1 px below an exact corner hit: axis_sweep goes x first, swept follows the path",
    function()
      local world = budge.new_world()
      world:add_solid({x = 100, y = 100, width = 32, height = 32})
      local actor = world:add_actor({x = 68, y = 69, width = 12, height = 12})
      local function move(method)
        local x, y = world:move(actor, 40, 40, method)
        return {x, y}
      end
      assert.same({108, 88}, move("axis_sweep"))
      actor.x, actor.y = 68, 69
      assert.same({88, 109}, move("swept"))
      actor.x, actor.y = 68, 67
      assert.same({108, 88}, move("swept"))
    end)

  -- A swept move longer than a cell goes in steps whose ends are the line's points
  -- rounded; a step's line could tilt by an ulp and turn a corner the path only touches
  -- into an overlap an ulp of time long (found by a review: 20% of exact grazes snagged
  -- when the move spanned more than one cell).
  it("swept passes a corner its path only touches, whatever the cell size", function()
    local function ends(cell, wall, box, dx, dy)
      local world = budge.new_world({cell_size = cell})
      world:add_solid(wall)
      local actor = world:add_actor(box)
      local x, y, n = world:move(actor, dx, dy, "swept")
      return ("%.17g %.17g %d"):format(x, y, n)
    end
    -- the actor's top-left corner passes through (32, 80), the wall's bottom-right, at 1/4
    local wall = {x = 16, y = 76, width = 16, height = 4}
    for _, cell in ipairs({64, 256, 8}) do
      assert.equal("-100 128 0", ends(cell, wall, {x = 76, y = 64, width = 44, height = 28},
        -176, 64))
    end
    -- exact grazes of random walls, corners and times: as with one step (a cell larger
    -- than the move), and never stopped
    local random = require("fixtures.random").new(7)
    local cases, snags = 0, 0
    while cases < 400 do
      local wx, wy, ww, wh = random(-20, 20), random(-20, 20), random(1, 16), random(1, 16)
      local aw, ah, dx, dy = random(1, 16), random(1, 16), random(-60, 60), random(-60, 60)
      if dx ~= 0 and dy ~= 0 then
        cases = cases + 1
        local t = random(1, 3) / 4
        -- the actor's corner facing the wall across x, away from it across y
        local ax = (dx < 0 and wx + ww or wx) - dx * t - (dx < 0 and 0 or aw)
        local ay = (dy > 0 and wy + wh or wy) - dy * t - (dy > 0 and 0 or ah)
        local w = {x = wx, y = wy, width = ww, height = wh}
        local one = ends(1e6, w, {x = ax, y = ay, width = aw, height = ah}, dx, dy)
        if not one:match(" 0$") then snags = snags + 1 end
        for _, cell in ipairs({4, 16, 64}) do
          assert.equal(one, ends(cell, w, {x = ax, y = ay, width = aw, height = ah}, dx, dy))
        end
      end
    end
    assert.equal(0, snags)
  end)
end)

describe("speed", function()
  local SPEEDS = {0.01, 0.5, 1, 7.99, 8, 8.01, 100, 1000, 100000}
  for _, method in ipairs(CONTINUOUS) do
    for _, as_tiles in ipairs({false, true}) do
      it(method .. " never tunnels through a 1 px wall of " .. (as_tiles and "tiles" or "a box")
        .. " from 0.01 to 100000 px per step", function()
          for _, speed in ipairs(SPEEDS) do
            for _, direction in ipairs({1, -1}) do
              local world = budge.new_world()
              if as_tiles then
                local row = {}
                for col = 1, 200 do row[col] = col == 101 end
                world:add_tiles({row}, 1, 64)
              else
                world:add_solid({x = 100, y = 0, width = 1, height = 64})
              end
              local start = direction > 0 and 80 or 109
              local actor = world:add_actor({x = start, y = 20, width = 12, height = 12})
              local x = world:move(actor, direction * speed, direction * speed / 1000, method)
              if direction > 0 then
                assert.equal(speed >= 8 and 88 or 80 + speed, x)
              else
                assert.equal(speed >= 8 and 101 or 109 - speed, x)
              end
            end
          end
        end)
    end
  end
end)

describe("resting", function()
  for _, method in ipairs(CONTINUOUS) do
    it(method .. " rests on a floor for 10000 frames without a sub-pixel change", function()
      for _, top in ipairs({100, 100.1, -33.3}) do
        local world = budge.new_world()
        world:add_solid({x = -50, y = top, width = 200, height = 16})
        local actor = world:add_actor({x = 10, y = top - 40, width = 12, height = 12})
        local _, rest_y = world:move(actor, 0, 1000, method)
        assert.is_true(rest_y + 12 <= top)
        assert.is_true(rest_y + 12 > top - 1e-9)
        if top == 100 then assert.equal(88, rest_y) end
        for _ = 1, 10000 do
          local x, y, n = world:move(actor, 0, 0.35, method)
          if y ~= rest_y or x ~= 10 or n ~= 1 then
            assert.same({10, rest_y, 1}, {x, y, n})
          end
        end
      end
    end)
  end
end)
