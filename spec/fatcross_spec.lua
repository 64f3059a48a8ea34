local budge = require("budge")
local sim = require("spec.support.sim")

local EPS = 1 / 64

describe("budge.fat_cross", function()
  it("returns a tall horizontal box inset on x and a wide vertical box inset on y", function()
    local block = {x = 10, y = 20, width = 32, height = 48}
    local tall, wide = budge.fat_cross(block, 6)
    assert.same({x = 16, y = 20, width = 20, height = 48, wall_type = "horizontal"}, tall)
    assert.same({x = 10, y = 26, width = 32, height = 36, wall_type = "vertical"}, wide)
    assert.same({x = 10, y = 20, width = 32, height = 48}, block)
  end)

  it("names the largest speed a box can serve when it is too small", function()
    local block = {x = 0, y = 0, width = 16, height = 40}
    assert.has_error(function() budge.fat_cross(block, 8) end,
      "box is too small for max_speed 8: a 16x40 box serves speeds below 8 (half its smaller side)")
    assert.has_no_error(function() budge.fat_cross(block, 8 - EPS) end)
  end)

  it("rejects a speed that is not a positive finite number", function()
    local block = {x = 0, y = 0, width = 16, height = 16}
    assert.has_error(function() budge.fat_cross(block, 0) end,
      "max_speed must be a finite number > 0, got 0")
    assert.has_error(function() budge.fat_cross(block, 0 / 0) end,
      "max_speed must be a finite number > 0, got nan")
    assert.has_error(function() budge.fat_cross(block) end,
      "max_speed must be a finite number > 0, got nil")
    assert.has_error(function() budge.fat_cross({x = 0, y = 0, width = 16}, 2) end,
      "box.height must be a finite number >= 0, got nil")
  end)
end)

describe("budge.resolve_fat_cross", function()
  local block = {x = 100, y = 100, width = 32, height = 32}
  local tall, wide = budge.fat_cross(block, 6)

  it("stops a side hit at the face when the speed is within the inset", function()
    local mover = {x = 100 - 12 + 6, y = 110, width = 12, height = 12}
    assert.same({-6, 0}, {budge.resolve_fat_cross(mover, tall, wide)})
    assert.same({88, 110}, {mover.x, mover.y})
  end)

  it("lands a fast faller on top even though it overlaps both boxes", function()
    -- 10 px into the top: deeper than the inset, so it overlaps tall and wide;
    -- tall goes first, so the mover lands instead of being thrown off the side.
    local mover = {x = 102, y = 100 - 12 + 10, width = 12, height = 12}
    assert.is_true(budge.detect_collision(mover, wide))
    assert.same({0, -10}, {budge.resolve_fat_cross(mover, tall, wide)})
    assert.same({102, 88}, {mover.x, mover.y})
  end)

  it("lifts a side hit faster than the inset onto the top (its known failure)", function()
    local mover = {x = 100 - 12 + 7, y = 100, width = 12, height = 12}
    assert.same({0, -12}, {budge.resolve_fat_cross(mover, tall, wide)})
    assert.same({95, 88}, {mover.x, mover.y})
  end)

  it("leaves a mover in the corner notch untouched (its other known failure)", function()
    -- 4 px into the block on both axes: inside the block, outside both hitboxes.
    local mover = {x = 100 - 12 + 4, y = 100 - 12 + 4, width = 12, height = 12}
    assert.is_true(budge.detect_collision(mover, block))
    assert.same({0, 0}, {budge.resolve_fat_cross(mover, tall, wide)})
  end)

  it("holds side hits exactly while the speed is at most the inset", function()
    for _, from in ipairs({"left", "right"}) do
      local wall = {x = 100, y = 0, width = 16, height = 64}
      assert.equal("correct", sim.hit("fat_cross", from, 6, wall, 12, 6))
      assert.equal("teleported", sim.hit("fat_cross", from, 6 + EPS, wall, 12, 6))
    end
  end)

  it("rejects boxes that are not the pair fat_cross returned", function()
    local mover = {x = 0, y = 0, width = 1, height = 1}
    assert.has_error(function() budge.resolve_fat_cross(mover, wide, tall) end,
      'tall.wall_type must be "horizontal" (the first box budge.fat_cross returns), got "vertical"')
    assert.has_error(function() budge.resolve_fat_cross(mover, tall, block) end,
      'wide.wall_type must be "vertical" (the second box budge.fat_cross returns), got nil')
    assert.has_error(function() budge.resolve_fat_cross({}, tall, wide) end,
      "mover.x must be a finite number, got nil")
  end)
end)
