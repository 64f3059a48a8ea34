local budge = require("budge")
local levels = require("fixtures.levels")
local scene = require("fixtures.scene")
local new_random = require("fixtures.random").new

local merge = budge.tiles.merge

local function from_strings(lines)
  local rows = {}
  for row, line in ipairs(lines) do
    rows[row] = {}
    for col = 1, #line do rows[row][col] = line:sub(col, col) == "#" and 1 or 0 end
  end
  return rows
end

-- Every solid tile covered by exactly one box, no free tile covered, boxes on the tile
-- lattice. Returns the number of tiles covered.
local function assert_exact_cover(rows, boxes, tile_width, tile_height, is_oneway)
  local cover = {}
  for index, item in ipairs(boxes) do
    assert.are.equal((item.col - 1) * tile_width, item.x)
    assert.are.equal((item.row - 1) * tile_height, item.y)
    assert.are.equal(item.cols * tile_width, item.width)
    assert.are.equal(item.rows * tile_height, item.height)
    for row = item.row, item.row + item.rows - 1 do
      for col = item.col, item.col + item.cols - 1 do
        local key = row * 100000 + col
        assert.is_nil(cover[key], ("tile %d,%d covered twice"):format(col, row))
        cover[key] = index
        local id = rows[row][col]
        assert.is_true(id ~= 0, ("free tile %d,%d covered"):format(col, row))
        assert.are.equal(is_oneway and is_oneway(id) and "oneway" or "solid",
          item.wall_type == "oneway" and "oneway" or "solid")
      end
    end
  end
  local count = 0
  for row = 1, #rows do
    for col = 1, #rows[row] do
      if rows[row][col] ~= 0 then
        count = count + 1
        assert.is_not_nil(cover[row * 100000 + col], ("tile %d,%d not covered"):format(col, row))
      end
    end
  end
  for i = 1, #boxes do
    for j = i + 1, #boxes do
      assert.is_false(budge.detect_collision(boxes[i], boxes[j]), ("boxes %d and %d overlap"):format(i, j))
    end
  end
  return count
end

local function count_kinds(boxes)
  local counts = {horizontal = 0, vertical = 0, cross = 0, untyped = 0, oneway = 0}
  for _, item in ipairs(boxes) do
    local kind = item.tall and "cross" or item.wall_type or "untyped"
    counts[kind] = counts[kind] + 1
  end
  return counts
end

describe("budge.tiles.merge", function()
  it("covers random maps exactly: every solid tile once, no free tile, no overlaps", function()
    local random = new_random(20261124)
    for _ = 1, 40 do
      local cols, rows_count = random(1, 24), random(1, 18)
      local density = random()
      local rows = {}
      for row = 1, rows_count do
        rows[row] = {}
        for col = 1, cols do
          local roll = random()
          rows[row][col] = roll < density * 0.8 and 1 or roll < density and 2 or 0
        end
      end
      local boxes = merge(rows, 8, 12, {is_oneway = function(id) return id == 2 end,
        max_speed = 2})
      assert_exact_cover(rows, boxes, 8, 12, function(id) return id == 2 end)
    end
  end)

  it("merges the platformer level and the bench map into few boxes (pinned counts)", function()
    local rows = levels.grid("platformer")
    local boxes = merge(rows, 16, 16, {is_oneway = levels.is_oneway, max_speed = 6})
    assert.are.equal(325, assert_exact_cover(rows, boxes, 16, 16, levels.is_oneway))
    assert.are.equal(42, #boxes)
    assert.are.same({horizontal = 7, vertical = 6, cross = 24, untyped = 0, oneway = 5},
      count_kinds(boxes))

    local map = scene.make_scene(12345) -- 200x200, border and 20% random tiles
    local solid_tiles = 0
    for row = 1, #map do for col = 1, #map do if map[row][col] then solid_tiles = solid_tiles + 1 end end end
    local merged = merge(map, 16, 16, {max_speed = 6})
    assert.are.same({8736, 5586}, {solid_tiles, #merged})
    assert.are.same({horizontal = 41, vertical = 3, cross = 5542, untyped = 0, oneway = 0},
      count_kinds(merged))
  end)

  it("types each box by its open faces: floors horizontal, walls vertical, blocks crossed", function()
    local rows = from_strings({
      "##########",
      "#........#",
      "#..##....#",
      "#..##....#",
      "#........#",
      "##########",
    })
    local boxes = merge(rows, 16, 16, {max_speed = 6})
    local shapes = {}
    for i, item in ipairs(boxes) do
      shapes[i] = ("%d,%d %dx%d %s"):format(item.col, item.row, item.cols, item.rows,
        item.tall and "cross" or tostring(item.wall_type))
    end
    assert.are.same({"1,1 10x1 horizontal", "1,2 1x5 vertical", "10,2 1x5 vertical",
      "4,3 2x2 cross", "2,6 8x1 horizontal"}, shapes)
    local tall, wide = budge.fat_cross(boxes[4], 6)
    assert.are.same(tall, boxes[4].tall)
    assert.are.same(wide, boxes[4].wide)
    assert.is_nil(boxes[4].wall_type)
  end)

  it("leaves a block hit from both sides untyped when it is too small for max_speed, or none is given", function()
    local rows = from_strings({"...", ".#.", "..."})
    assert.is_nil(merge(rows, 16, 16)[1].tall)
    assert.is_nil(merge(rows, 16, 16, {max_speed = 8})[1].tall) -- a 16 px block serves < 8
    assert.are.equal(2, merge(rows, 16, 16, {max_speed = 7.5})[1].tall.x - 16 - 5.5)
    assert.is_nil(merge(rows, 16, 16, {max_speed = 8})[1].wall_type)
  end)

  it("takes the map's edges as closed unless opts.open_edges", function()
    local rows = from_strings({"###", "...", "..."})
    assert.are.equal("horizontal", merge(rows, 16, 16, {max_speed = 4})[1].wall_type)
    local open = merge(rows, 16, 16, {max_speed = 4, open_edges = true})[1]
    assert.is_nil(open.wall_type)
    assert.is_table(open.tall)
  end)

  it("reads a 2D grid, a flat array with opts.width and a Tiled layer alike", function()
    local rows = levels.grid("platformer")
    local flat = {}
    for row = 1, #rows do for col = 1, #rows[1] do flat[#flat + 1] = rows[row][col] end end
    local opts = {is_oneway = levels.is_oneway, max_speed = 6}
    local from_rows = merge(rows, 16, 16, opts)
    opts.width = #rows[1]
    assert.are.same(from_rows, merge(flat, 16, 16, opts))
    opts.width = nil
    assert.are.same(from_rows, merge({width = #rows[1], height = #rows, data = flat}, 16, 16, opts))
  end)

  it("takes 0, nil and false as free by default, and opts.is_solid otherwise", function()
    assert.are.equal(1, #merge({{0, 7, false}}, 16, 16))
    assert.are.equal(0, #merge({{0, 7, false}}, 16, 16, {is_solid = function(id) return id == 3 end}))
    assert.are.equal(2, #merge({{3, 0, 3}}, 16, 16, {is_solid = function(id) return id == 3 end}))
    assert.are.same({}, merge({}, 16, 16))
  end)

  it("places boxes at opts.x, opts.y with the tile size given", function()
    local boxes = merge({{1, 1}}, 10, 20, {x = 100, y = -40})
    assert.are.same({100, -40, 20, 20}, {boxes[1].x, boxes[1].y, boxes[1].width, boxes[1].height})
  end)

  it("rejects bad input with messages that name the argument and the value", function()
    assert.has_error(function() merge(nil, 16, 16) end, "grid must be a table (grid[row][col], "
      .. "a flat array with opts.width, or a Tiled layer {width =, data =}), got nil")
    assert.has_error(function() merge({{1}, {1, 1}}, 16, 16) end,
      "grid[2] has 2 tiles but grid[1] has 1: every row must have the same length")
    assert.has_error(function() merge({1, 0, 1}, 16, 16) end,
      "opts.width must be a whole number >= 1 for a flat grid (tiles per row), got nil")
    assert.has_error(function() merge({1, 0, 1}, 16, 16, {width = 2}) end,
      "grid has 3 tiles, which is not a whole number of rows of 2")
    assert.has_error(function() merge({data = {1}, width = 0}, 16, 16) end,
      "grid.width must be a whole number >= 1 (tiles per row of the Tiled layer), got 0")
    assert.has_error(function() merge({{1}}, 0, 16) end,
      "tile_width must be a finite number > 0, got 0")
    assert.has_error(function() merge({{1}}, 16, 0 / 0) end,
      "tile_height must be a finite number > 0, got nan")
    assert.has_error(function() merge({{1}}, 1e-309, 16) end,
      "tile_width must be > 2^-1024 (its inverse must be finite), got 1e-309")
    assert.has_error(function() merge({{1}}, 16, 16, {max_speed = -1}) end,
      "opts.max_speed must be a finite number > 0 or nil, got -1")
    assert.has_error(function() merge({{1}}, 16, 16, {is_solid = 1}) end,
      "opts.is_solid must be a function or nil, got 1")
    assert.has_error(function() merge({{1}}, 16, 16, "fast") end,
      'opts must be a table or nil, got "fast"')
  end)
end)

-- The article's method in a loop of its own: move, then resolve against every box
-- (a crossed block through its two hitboxes).
local function article_step(mover, boxes, dx, dy)
  mover.x, mover.y = mover.x + dx, mover.y + dy
  for _, item in ipairs(boxes) do
    if item.tall then
      budge.resolve_fat_cross(mover, item.tall, item.wide)
    else
      budge.resolve_collision(mover, item)
    end
  end
end

local function raw_tiles(rows, wall_type)
  local boxes = {}
  for row = 1, #rows do
    for col = 1, #rows[row] do
      if rows[row][col] ~= 0 then
        boxes[#boxes + 1] = {x = (col - 1) * 16, y = (row - 1) * 16, width = 16, height = 16,
          wall_type = wall_type}
      end
    end
  end
  return boxes
end

describe("the article's method on merged tiles", function()
  -- a wall of 12 tiles on the left, a floor slab with an open end on the right
  local rows = from_strings({
    "#...........",
    "#...........",
    "#...........",
    "#...........",
    "#...........",
    "#...........",
    "#...........",
    "#...........",
    "#.....######",
    "#...........",
    "#...........",
    "############",
  })

  local function slide_down_wall(boxes)
    local mover = {x = 16, y = 4, width = 12, height = 12}
    for _ = 1, 100 do article_step(mover, boxes, -1, 1) end
    return mover.x, mover.y
  end

  local function walk_into_slab_end(boxes)
    local mover = {x = 60, y = 130, width = 12, height = 12} -- level with the slab
    for _ = 1, 10 do article_step(mover, boxes, 3, 0) end
    return mover.x, mover.y
  end

  it("slides down a wall without being dragged at the seams (raw untyped tiles are)", function()
    -- pressed 1 px into the wall while falling 1 px per step: 100 steps from y = 4
    assert.are.same({16, 104}, {slide_down_wall(merge(rows, 16, 16, {max_speed = 3}))})
    -- on raw tiles both ways out are 1 px at each of the 6 seams passed; the tie goes
    -- vertical and pushes the mover down a pixel more
    assert.are.same({16, 110}, {slide_down_wall(raw_tiles(rows, nil))})
  end)

  it("stops at the end of a slab (raw tiles typed as a floor lift the mover on top)", function()
    assert.are.same({84, 130}, {walk_into_slab_end(merge(rows, 16, 16, {max_speed = 3}))})
    local _, y = walk_into_slab_end(raw_tiles(rows, "horizontal"))
    assert.are.equal(128 - 12, y) -- teleported onto the slab
  end)
end)
