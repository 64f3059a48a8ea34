local budge = require("budge")

local box = require("fixtures.box")

-- The seed article's test, typo included, to show what the fix changes.
local function article_detect(box_a, box_b)
  return box_a.x + box_a.width > box_b.x and box_a.x < box_b.x + box_b.width
    and box_a.y + box_b.height > box_b.y and box_a.y < box_b.y + box_b.height
end

describe("budge.detect_collision", function()
  it("finds two overlapping boxes", function()
    assert.is_true(budge.detect_collision(box(0, 0, 10, 10), box(5, 5, 10, 10)))
    assert.is_true(budge.detect_collision(box(5, 5, 10, 10), box(0, 0, 10, 10)))
  end)

  it("finds a box entirely inside another", function()
    assert.is_true(budge.detect_collision(box(2, 2, 1, 1), box(0, 0, 10, 10)))
    assert.is_true(budge.detect_collision(box(0, 0, 10, 10), box(2, 2, 1, 1)))
  end)

  it("does not count touching edges or corners as a collision", function()
    assert.is_false(budge.detect_collision(box(0, 0, 10, 10), box(10, 0, 10, 10)))
    assert.is_false(budge.detect_collision(box(0, 0, 10, 10), box(0, 10, 10, 10)))
    assert.is_false(budge.detect_collision(box(0, 0, 10, 10), box(-10, 0, 10, 10)))
    assert.is_false(budge.detect_collision(box(0, 0, 10, 10), box(10, 10, 10, 10)))
  end)

  it("counts the smallest overlap as a collision", function()
    assert.is_true(budge.detect_collision(box(0, 0, 10, 10), box(9.999, 9.999, 10, 10)))
  end)

  it("says a 10x10 box does not hit a 10x50 box 10 px below it (the article says it does)",
    function()
      local a, b = box(0, 0, 10, 10), box(0, 20, 10, 50)
      assert.is_true(article_detect(a, b))
      assert.is_false(budge.detect_collision(a, b))
    end)

  it("says a 10x50 box hits a 10x10 box inside its lower half (the article says it does not)",
    function()
      local a, b = box(0, 0, 10, 50), box(0, 30, 10, 10)
      assert.is_false(article_detect(a, b))
      assert.is_true(budge.detect_collision(a, b))
    end)

  it("treats a zero-size box as a point: inside collides, on an edge does not", function()
    assert.is_true(budge.detect_collision(box(5, 5, 0, 0), box(0, 0, 10, 10)))
    assert.is_false(budge.detect_collision(box(10, 5, 0, 0), box(0, 0, 10, 10)))
    assert.is_false(budge.detect_collision(box(5, 0, 0, 0), box(0, 0, 10, 10)))
  end)

  it("rejects bad input with the argument, the field and the value", function()
    local good = box(0, 0, 1, 1)
    assert.has_error(function() budge.detect_collision(nil, good) end,
      "a must be a box table {x, y, width, height}, got nil")
    assert.has_error(function() budge.detect_collision(good, 7) end,
      "b must be a box table {x, y, width, height}, got 7")
    assert.has_error(function() budge.detect_collision({y = 0, width = 1, height = 1}, good) end,
      "a.x must be a finite number, got nil")
    assert.has_error(function() budge.detect_collision(box(0, "3", 1, 1), good) end,
      'a.y must be a finite number, got "3"')
    assert.has_error(function() budge.detect_collision(good, box(0 / 0, 0, 1, 1)) end,
      "b.x must be a finite number, got nan")
    assert.has_error(function() budge.detect_collision(good, box(0, -math.huge, 1, 1)) end,
      "b.y must be a finite number, got -inf")
    assert.has_error(function() budge.detect_collision(box(0, 0, -2, 1), good) end,
      "a.width must be a finite number >= 0, got -2")
    assert.has_error(function() budge.detect_collision(good, box(0, 0, 1, math.huge)) end,
      "b.height must be a finite number >= 0, got inf")
    assert.has_error(function() budge.detect_collision(good, box(0, 0, 1, 0.25 - 1)) end,
      "b.height must be a finite number >= 0, got -0.75")
  end)

  it("blames the caller's line, not budge's", function()
    local ok, message = pcall(function() budge.detect_collision(nil, nil) end)
    assert.is_false(ok)
    assert.matches("box_spec%.lua:%d+: a must be", message)
  end)
end)
