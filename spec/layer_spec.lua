-- budge.layer's axis scans (tile_face, read from the reach tables by tile_line and
-- list_line, as LuaJIT's moves in a world of one layer read them; tile_face_scan, the line
-- scan a world with hashed solids uses on LuaJIT; and tile_stop, Lua 5.x's form of
-- tile_face, with the hits it writes) against a brute force over every tile of the layer,
-- and the reach tables kept up to date by world:update.
local layer = require("budge.layer")
local sweep = require("budge.sweep")
local random_source = require("fixtures.random")
local scale = require("spec.support.scale")

local SOLID_ID, ONEWAY_ID = 1, 5
local function is_oneway(id) return id == ONEWAY_ID end

-- The face tile_face must find, by looking at every tile: the nearest face of a tile
-- that stops the box, among the tiles strictly across from it, with the tiles on it in
-- the order across. Forward: a tile's low face counts when it is past the box's trailing
-- edge (or at it, for a box of size 0: a face inside the box counts, the box overlaps
-- that tile) and before the move's reach; a oneway tile only for a move down, from the
-- box's bottom edge on. Backward likewise with the high face.
local function brute(grid, cols, rows, opts, tile_w, tile_h, p)
  local best, list = nil, {}
  for row = 1, rows do
    for col = 1, cols do
      local id = grid[row][col]
      local kind = id == ONEWAY_ID and "oneway" or (id ~= 0 and "solid" or nil)
      if kind then
        local x0, y0 = opts.x + (col - 1) * tile_w, opts.y + (row - 1) * tile_h
        local x1, y1 = opts.x + col * tile_w, opts.y + row * tile_h
        local low, high, lo, hi
        if p.is_x then low, high, lo, hi = x0, x1, y0, y1 else low, high, lo, hi = y0, y1, x0, x1 end
        if lo < p.cross_end and p.cross < hi then
          local face
          if p.forward then
            if (low > p.pos or low >= p.edge) and low < p.reach and (kind == "solid"
              or (p.blocks_oneway and low >= p.edge)) then face = low end
          elseif (high < p.edge or high <= p.pos) and high > p.reach and kind == "solid" then
            face = high
          end
          if face and (best == nil or (p.forward and face < best)
            or (not p.forward and face > best)) then
            best, list = face, {}
          end
          if face and face == best then list[#list + 1] = {col, row, p.is_x and row or col} end
        end
      end
    end
  end
  table.sort(list, function(a, b) return a[3] < b[3] end)
  return best, list
end

local function probe_for(is_x, forward, pos, size, delta, cross, cross_size)
  local p = sweep.new_probe()
  p.is_x, p.forward, p.delta, p.pos, p.size, p.edge = is_x, forward, delta, pos, size, pos + size
  p.reach = forward and pos + size + delta or pos + delta
  p.cross, p.cross_end = cross, cross + cross_size
  p.blocks_oneway = not is_x and forward
  return p
end

local SIDES = {[true] = {[true] = "right -1 0", [false] = "left 1 0"},
  [false] = {[true] = "floor 0 -1", [false] = "ceiling 0 1"}}

-- tile_stop's answer for probe p as tile_face's (face, count, p.cols and p.rows), from the
-- hits it writes into a world of its own (after the 2 hits already there: into the spare
-- record past them, which held another contact, then new ones), its stop checked against the axis rules' (sweep's)
-- for that face and each hit's side, normal, time and response.
local function tile_stop_answer(tiles, p, case)
  local old = {other = false, side = "left", col = 0, row = 0, response = "touch", t = 1,
    nx = 9, ny = 9}
  local world = {_hits = {{}, {}, old}, _n_hits = 2, _records = {[tiles] = {id = 7}},
    _round = 1}
  local path = 2 * math.abs(p.delta) -- (done: half of it, before this phase)
  local stop, face = layer.tile_stop(world, tiles, p.is_x, p.pos, p.cross, p.cross_end,
    p.size, p.delta, path / 2, path)
  local where = ", case " .. case
  if stop == nil then
    assert.are.equal(2, world._n_hits, "tile_stop" .. where)
    return nil, 0
  end
  local want = p.forward and sweep.stop_forward(face, p.pos, p.edge, p.reach, p.size, false,
    true) or sweep.stop_backward(face, p.pos, p.edge, p.reach, false, true)
  assert.are.equal(want, stop, "tile_stop's stop" .. where)
  local count = world._n_hits - 2
  local t = (path / 2 + math.abs(stop - p.pos)) / path
  for i = 1, count do
    local hit = world._hits[2 + i]
    p.cols[i], p.rows[i] = hit.col, hit.row
    assert.are.same({tiles, SIDES[p.is_x][p.forward], "slide", t},
      {hit.other, ("%s %d %d"):format(hit.side, hit.nx, hit.ny), hit.response, hit.t},
      "tile_stop's hit " .. i .. where)
  end
  return face, count
end

-- The three scans' answers for probe p, each against the brute force's; returns the face.
local function compare(grid, cols, rows, opts, tile_w, tile_h, tiles, p, case)
  local want, list = brute(grid, cols, rows, opts, tile_w, tile_h, p)
  local face
  for _, scan in ipairs({"tile_face", "tile_face_scan", "tile_stop"}) do
    local count
    if scan == "tile_stop" then -- (from the probe's inputs, into its own lists)
      p.cols, p.rows = {}, {}
      face, count = tile_stop_answer(tiles, p, case)
    else
      face, count = layer[scan](tiles, p)
    end
    assert.are.equal(want, face, scan .. ", case " .. case)
    assert.are.equal(#list, count, scan .. ", case " .. case)
    for i = 1, count do
      assert.are.same({list[i][1], list[i][2]}, {p.cols[i], p.rows[i]}, scan .. ", case " .. case)
    end
  end
  return face
end

describe("budge.layer's axis scan", function()
  it("all three find the face and the tiles on it that a brute force over every tile finds, in "
    .. scale(40000) .. " random layers and moves (dyadic and non-dyadic origins, oneway tiles, moves "
    .. "short and long, boxes of size 0 to several tiles)", function()
    local rng = random_source.new(20261202)
    local found, checked = 0, 0
    local cases = scale(40000)
    for case = 1, cases do
      local cols, rows = rng(1, 12), rng(1, 12)
      local grid = {}
      for row = 1, rows do
        grid[row] = {}
        for col = 1, cols do
          grid[row][col] = rng(1, 4) == 1 and (rng(1, 5) == 1 and ONEWAY_ID or SOLID_ID) or 0
        end
      end
      local opts = {x = rng(-20, 20) / 4, y = rng(-20, 20) / 4, is_oneway = is_oneway}
      if case % 5 == 0 then opts.x, opts.y = opts.x + 0.3, opts.y - 0.1 end
      if case % 3 == 0 then opts.x, opts.y = 0, 0 end
      local tile_w, tile_h = rng(1, 5) * 4, rng(1, 5) * 4
      if case % 7 == 0 then tile_w, tile_h = tile_w / 3, tile_h * 0.7 end
      local tiles = layer.new(grid, tile_w, tile_h, opts, 1)
      local is_x, forward = rng(1, 2) == 1, rng(1, 2) == 1
      local pos, size = rng(-40, 240) / 4, rng(0, 80) / 4
      if case % 11 == 0 then pos = (is_x and opts.x or opts.y) + rng(0, 12) * (is_x and tile_w or tile_h) end
      local delta = (forward and 1 or -1) * rng(1, 200) / 4
      local p = probe_for(is_x, forward, pos, size, delta, rng(-40, 240) / 4, rng(0, 80) / 4)
      local face = compare(grid, cols, rows, opts, tile_w, tile_h, tiles, p, case)
      checked = checked + 1
      if face then found = found + 1 end
    end
    assert.are.equal(cases, checked)
    assert.is_true(found > cases / 4 and found < cases * 3 / 4, "found " .. found) -- (both kinds of case)
  end)

  it("all three agree with the brute force next to 0 and on tile edges: coordinates that "
    .. "underflow when divided by a side, sides whose multiples divide back below the count, "
    .. "and 1 and an ulp below it, where an exact layer (origin 0, sides powers of two) "
    .. "begins to skip the corrections,",
    function()
    local zero = 0.0 -- (-0 written as a literal is +0 on Lua 5.x: made at run time)
    local tiny = {0, -zero, 2 ^ -1074, -2 ^ -1074, 2 ^ -1060, -2 ^ -1060, 2 ^ -1020, -2 ^ -1020,
      2 ^ -1000, 1, -1, 16, -16, 1 - 2 ^ -53, 2 ^ 50 + 0.5}
    local grid = {{1, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 1}, {1, ONEWAY_ID, 1, 0, 0, 1, 0, 0},
      {0, 0, 0, 1, 0, 0, 0, 1}, {0, 1, 0, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 0},
      {1, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 1, 0, 0, 1, 0, 0}}
    local found, checked = 0, 0
    -- (3 * 0.7 / 0.7 rounds below 3; 10 and 12 are whole but not powers of two, where a
    -- face an ulp past the box divides onto the tile beyond: a review's case, 30 - ulp)
    for _, side in ipairs({16, 2 ^ 40, 0.25, 0.7, 10, 12}) do
      tiny[16], tiny[17], tiny[18] = 3 * side, 6 * side, 3 * side * (1 - 2 ^ -53)
      for _, origin in ipairs({0, -side}) do
        local opts = {x = origin, y = origin, is_oneway = is_oneway}
        local tiles = layer.new(grid, side, side, opts, 1)
        for _, pos in ipairs(tiny) do
          for _, cross in ipairs(tiny) do
            for _, size in ipairs({0, side / 2, side}) do
              for _, is_x in ipairs({true, false}) do
                for _, delta in ipairs({side, -side, 2 * side, -2 * side}) do
                  local p = probe_for(is_x, delta > 0, pos, size, delta, cross, size)
                  if compare(grid, 8, 8, opts, side, side, tiles, p, checked) then
                    found = found + 1
                  end
                  checked = checked + 1
                end
              end
            end
          end
        end
      end
    end
    assert.are.equal(6 * 2 * 18 * 18 * 3 * 2 * 4, checked)
    assert.is_true(found > checked / 4 and found < checked * 3 / 4, "found " .. found)
  end)

  it("tiles narrower than the rounding at their coordinate: a move gets the same answer on "
    .. "every interpreter, with a solid in the world (the line scan) and without (the reach "
    .. "tables, which disagree with it there)", function()
    local budge = require("budge")
    local function run(grid, width, dx, with_solid)
      local world = budge.new_world({cell_size = 2 ^ 16})
      world:add_tiles(grid, 2 ^ -20, 1, {x = -2 ^ 35 + 0.1, y = 0})
      if with_solid then world:add_solid({x = 0, y = 0, width = 1, height = 1}) end
      local actor = world:add_actor({x = -2 ^ 35 + 0.1, y = 0, width = width, height = 1})
      local x, _, n, hits = world:move(actor, dx, 0)
      local out = {("%.17g"):format(x), n}
      for i = 1, n do
        out[#out + 1] = ("%s %d %.17g"):format(hits[i].side, hits[i].col, hits[i].t)
      end
      return out
    end
    local one, row = {{0, 1}}, {{1, 0, 1, 0, 1, 1, 0, 1}}
    assert.are.same({"-34359738357.900002", 0}, run(one, 1, 10, true))
    assert.are.same({"-34359738367.900002", 1, "right 2 0"}, run(one, 1, 10, false))
    assert.are.same({"-34359738367.900002", 1, "right 5 0"}, run(row, 2 ^ -16, 0.5, true))
    assert.are.same({"-34359738367.900002", 1, "right 3 0"}, run(row, 2 ^ -16, 0.5, false))
  end)

  it("reads the grid again at world:update: a solid tile and a oneway tile stop moves "
    .. "once added, and not once gone", function()
    local budge = require("budge")
    local world = budge.new_world()
    local grid = {}
    for row = 1, 4 do grid[row] = {0, 0, 0, 0, 0, 0, 0, 0} end
    local handle = world:add_tiles(grid, 16, 16, {is_oneway = is_oneway})
    local actor = world:add_actor({x = 2, y = 2, width = 12, height = 12})
    local function move(dx, dy)
      local x, y = world:move(actor, dx, dy)
      return {x, y}
    end
    assert.are.same({98, 2}, move(96, 0))
    grid[1][8] = SOLID_ID
    world:update(handle)
    assert.are.same({2, 2}, move(-96, 0))
    assert.are.same({100, 2}, move(100, 0)) -- (the tile's face at x = 112)
    grid[3][7] = ONEWAY_ID
    world:update(handle)
    assert.are.same({100, 20}, move(0, 30)) -- (onto the oneway's top at y = 32)
    assert.are.same({100, 2}, move(0, -18)) -- (up through nothing)
    grid[1][8], grid[3][7] = 0, 0
    world:update(handle)
    assert.are.same({116, 32}, move(16, 30))
    -- (in place: with is_oneway given, spare arrays to read into, see the next spec; the
    -- default test raises nothing and keeps none, a second copy of a big map's tiles)
    local plain = world:add_tiles(grid, 16, 16, {y = 1000})
    world:update(plain)
    world:update(plain)
    assert.are.same({nil, nil, "table"}, {plain._spare_kinds, plain._spare_ids,
      type(handle._spare_kinds)})
  end)

  it("is left as it was by an is_solid that raises part-way through world:update; the "
    .. "next update reads the grid, with no garbage after the first", function()
    -- (read in place, the kinds read before the error were new and the reach table old:
    -- a fall went through the new block in a world of tiles alone and stopped on it with
    -- a solid box elsewhere, and a query found it; found by review, 2026-12-06)
    local budge = require("budge")
    local garbage = require("fixtures.garbage")
    for _, boxed in ipairs({false, true}) do
      local world = budge.new_world()
      local grid = {{0, 0, 0, 0}, {0, 0, 0, 0}, {1, 1, 1, 1}}
      local level = world:add_tiles(grid, 16, 16, {is_solid = function(id)
        if type(id) ~= "number" then error("unknown tile id " .. tostring(id), 0) end
        return id >= 1
      end})
      if boxed then world:add_solid({x = 1000, y = 1000, width = 1, height = 1}) end
      local player = world:add_actor({x = 0, y = 0, width = 8, height = 8})
      local out = {}
      local function fall()
        player.x, player.y = 0, 0
        world:update(player)
        local _, y = world:move(player, 0, 40)
        local _, above = world:query_point(4, 20, out)
        local _, floor = world:query_point(4, 40, out)
        return {y, above, floor}
      end
      grid[2][1], grid[2][4] = 1, "door" -- a new block under the player, a bad id after it
      assert.are.same({false, "unknown tile id door"}, {pcall(world.update, world, level)})
      assert.are.same({24, 0, 1}, fall()) -- the old grid: onto the floor
      grid[2][4] = 0
      world:update(level)
      assert.are.same({8, 1, 1}, fall()) -- onto the new block
      local function flip(i)
        grid[2][1] = i % 2
        world:update(level)
      end
      local bytes = garbage.measure(flip, 20,
        {jit_off = true, warm = function() for i = 1, 3 do flip(i) end end})
      assert.are.equal(0, bytes)
      -- with the default test, a grid that raises itself (a row's __index for a hole):
      -- what was read before the error stands, with its reach table, so that a move and
      -- a query agree (a review, 2026-12-07)
      local plain = world:add_tiles({{0, 0, 0, 0}, {0, 0, 0, 0}, {1, 1, 1, 1}}, 16, 16,
        {x = 0, y = 0})
      world:remove(level)
      setmetatable(plain.grid[2], {__index = function(_, k) error("no tile at " .. k, 0) end})
      plain.grid[2][1], plain.grid[2][3] = 1, nil
      assert.are.same({false, "no tile at 3"}, {pcall(world.update, world, plain)})
      assert.are.same({8, 1, 1}, fall()) -- (column 1 read: the move and the query see it)
    end
  end)
end)
