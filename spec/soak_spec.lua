-- The soak: random operations on one world against a brute-force oracle, with the
-- hostile parts of a game in the mix: zero-size actors, a tile layer at an origin not
-- exact in binary, filters that remove what they touch or raise errors (caught), and
-- on_crush callbacks that move and remove solids. After every operation: queries equal
-- the oracle, the counts are right, and no actor is inside a solid unless it started
-- inside, was reported crushed, or a caught error left it there.
--
--   BUDGE_SOAK=1000000 busted spec/soak_spec.lua     (10^5 operations by default, a
--   quarter of them on the secondary runs: spec/support/scale.lua)
local budge = require("budge")
local new_random = require("fixtures.random").new
local scale = require("spec.support.scale")

local SEED = tonumber(os.getenv("BUDGE_SOAK_SEED") or "") or 20261201
local OPERATIONS = tonumber(os.getenv("BUDGE_SOAK") or "") or scale(100000)
local TILE, ORIGIN_X, ORIGIN_Y, ROWS, COLS = 16, 0.3, 40.1, 16, 20

describe("a world soaked in random operations and hostile callbacks", function()
  it("agrees with a brute-force oracle after every one of them", function()
    local random = new_random(SEED)
    local world = budge.new_world({cell_size = 32})
    local grid = {}
    for row = 1, ROWS do
      grid[row] = {}
      for col = 1, COLS do
        local roll = random()
        grid[row][col] = roll < 0.1 and 1 or (roll < 0.13 and 2 or nil) -- nil: empty
      end
    end
    local layer = world:add_tiles(grid, TILE, TILE, {x = ORIGIN_X, y = ORIGIN_Y, width = COLS,
      is_oneway = function(id) return id == 2 end})

    -- the oracle's own view: every item in the order it was added
    local items = {}
    local function remember(item) items[#items + 1] = item end
    local function forget(item)
      for i = 1, #items do if items[i] == item then table.remove(items, i) return end end
    end
    remember(layer)
    local solids, actors = {}, {}
    local function drop(list, item)
      for i = 1, #list do if list[i] == item then table.remove(list, i) return true end end
      return false
    end

    local function strictly(ax, ay, aw, ah, b)
      return ax < b.x + b.width and b.x < ax + aw and ay < b.y + b.height and b.y < ay + ah
    end
    local function tile_box(row, col)
      return {x = ORIGIN_X + (col - 1) * TILE, y = ORIGIN_Y + (row - 1) * TILE, width = TILE,
        height = TILE}
    end
    -- (the rows and columns a rectangle can touch, widened by one: the oracle computes its
    -- tile boxes as the layer does, and tests each exactly)
    local function layer_overlaps(x, y, w, h, solid_only)
      local col0 = math.max(1, math.floor((x - ORIGIN_X) / TILE))
      local col1 = math.min(COLS, math.floor((x + w - ORIGIN_X) / TILE) + 2)
      local row0 = math.max(1, math.floor((y - ORIGIN_Y) / TILE))
      local row1 = math.min(ROWS, math.floor((y + h - ORIGIN_Y) / TILE) + 2)
      for row = row0, row1 do
        for col = col0, col1 do
          local id = grid[row][col]
          if (id == 1 or (id == 2 and not solid_only)) and strictly(x, y, w, h, tile_box(row, col)) then
            return true
          end
        end
      end
      return false
    end
    local function inside_solid(a)
      for i = 1, #solids do
        local s = solids[i]
        if s.wall_type ~= "oneway" and strictly(a.x, a.y, a.width, a.height, s) then return s end
      end
      if layer_overlaps(a.x, a.y, a.width, a.height, true) then return layer end
      return nil
    end
    local function oracle_rect(x, y, w, h)
      local list = {}
      for i = 1, #items do
        local item = items[i]
        if item == layer then
          if layer_overlaps(x, y, w, h, false) then list[#list + 1] = item end
        elseif strictly(x, y, w, h, item) then
          list[#list + 1] = item
        end
      end
      return list
    end

    local function coordinate() return random(-40, 1400) / 4 end
    local out = {}
    local excused = {} -- actor -> may be inside a solid (started inside, crushed, or an error)
    local caught, crushes, broken = 0, 0, 0

    local function fail(step, what)
      error(("seed %d, step %d: %s"):format(SEED, step, what), 0)
    end

    -- hostile callbacks, chosen per actor
    local function brick_breaker(_, other)
      if other ~= layer and world:has(other) and random() < 0.3 then
        world:remove(other); drop(solids, other); forget(other); broken = broken + 1
        return false
      end
      return true
    end
    local function buggy(_, other)
      if random() < 0.05 then error("filter bug", 0) end
      return other ~= nil
    end
    local function on_crush(actor)
      crushes = crushes + 1
      excused[actor] = true
      if #solids > 0 and random() < 0.5 then
        local solid = solids[random(1, #solids)]
        if random() < 0.5 then
          local _, crushed = world:move_solid(solid, random(-8, 8), random(-8, 8))
          for i = 1, #crushed do excused[crushed[i]] = true end
        else
          world:remove(solid); drop(solids, solid); forget(solid)
        end
      end
    end

    for step = 1, OPERATIONS do
      local roll = random()
      if roll < 0.03 and #solids < 30 then
        local solid = {x = coordinate(), y = coordinate(), width = random(1, 40),
          height = random(1, 40), wall_type = random() < 0.15 and "oneway" or nil}
        world:add_solid(solid); solids[#solids + 1] = solid; remember(solid)
        for i = 1, #actors do if inside_solid(actors[i]) then excused[actors[i]] = true end end
      elseif roll < 0.05 and #solids > 0 then
        local solid = solids[random(1, #solids)]
        world:remove(solid); drop(solids, solid); forget(solid)
      elseif roll < 0.08 and #actors < 30 then
        local actor = {x = coordinate(), y = coordinate(), width = random(0, 3) == 0 and 0 or random(1, 24),
          height = random(0, 3) == 0 and 0 or random(1, 24)}
        local kind = random(1, 4)
        actor.filter = kind == 1 and brick_breaker or (kind == 2 and buggy or nil)
        actor.on_crush = on_crush
        world:add_actor(actor); actors[#actors + 1] = actor; remember(actor)
        excused[actor] = inside_solid(actor) ~= nil
      elseif roll < 0.1 and #actors > 0 then
        local actor = actors[random(1, #actors)]
        world:remove(actor); drop(actors, actor); forget(actor)
      elseif roll < 0.12 and #actors > 0 then
        local actor = actors[random(1, #actors)]
        actor.x, actor.y = coordinate(), coordinate()
        world:update(actor)
        excused[actor] = inside_solid(actor) ~= nil
      elseif roll < 0.2 and #solids > 0 then
        local solid = solids[random(1, #solids)]
        local dx, dy = random(-48, 48) / 4, random(-48, 48) / 4
        if random() < 0.5 then dx = 0 elseif random() < 0.5 then dy = 0 end
        local ok, n, crushed = pcall(world.move_solid, world, solid, dx, dy)
        if ok then
          for i = 1, n do excused[crushed[i]] = true end
        else
          if n ~= "filter bug" then fail(step, "move_solid raised " .. tostring(n)) end
          caught = caught + 1
          for i = 1, #actors do if inside_solid(actors[i]) then excused[actors[i]] = true end end
        end
      elseif roll < 0.9 and #actors > 0 then
        local actor = actors[random(1, #actors)]
        local method = budge.METHODS[random(1, #budge.METHODS)]
        local dx, dy = random(-160, 160) / 8, random(-160, 160) / 8
        if random() < 0.1 then dx, dy = dx + random() - 0.5, dy + random() - 0.5 end
        local x0, y0 = actor.x, actor.y
        local ok, err = pcall(world.move, world, actor, dx, dy, method)
        if not ok then
          if err ~= "filter bug" then fail(step, "move raised " .. tostring(err)) end
          caught = caught + 1
          if actor.x ~= x0 or actor.y ~= y0 then fail(step, "a failed move moved its actor") end
        elseif not budge.CONTINUOUS[method] then
          excused[actor] = inside_solid(actor) ~= nil
        elseif excused[actor] then
          excused[actor] = inside_solid(actor) ~= nil -- it may have moved out
        elseif world:has(actor) then
          local hit = inside_solid(actor)
          if hit then
            fail(step, ("%s moved an actor by %g,%g into a solid: %.17g,%.17g %gx%g"):format(
              method, dx, dy, actor.x, actor.y, actor.width, actor.height))
          end
        end
      end
      -- the checks
      for i = #actors, 1, -1 do
        if not world:has(actors[i]) then forget(actors[i]); table.remove(actors, i) end
      end
      local solid_count, actor_count, layer_count = world:count()
      if solid_count ~= #solids or actor_count ~= #actors or layer_count ~= 1 then
        fail(step, ("counts %d, %d, %d; the oracle has %d, %d, 1"):format(solid_count,
          actor_count, layer_count, #solids, #actors))
      end
      local x, y = coordinate(), coordinate()
      local w, h = random(0, 120), random(0, 120)
      local _, n = world:query_rect(x, y, w, h, out)
      local expected = oracle_rect(x, y, w, h)
      local same = n == #expected
      for i = 1, n do if out[i] ~= expected[i] then same = false end end
      if not same then
        fail(step, ("query_rect(%g, %g, %g, %g) found %d items, the oracle %d"):format(x, y, w, h,
          n, #expected))
      end
      for i = 1, #actors, step % 10 == 0 and 1 or #actors + 1 do -- every actor, every 10 steps
        local actor = actors[i]
        if not excused[actor] and inside_solid(actor) then
          fail(step, ("an actor at %.17g,%.17g %gx%g is inside a solid"):format(actor.x, actor.y,
            actor.width, actor.height))
        end
      end
    end
    if os.getenv("SOAK_PRINT") then print("caught", caught, "crushes", crushes, "broken", broken) end
    assert.is_true(caught > OPERATIONS / 1000, "caught " .. caught)
    assert.is_true(crushes > OPERATIONS / 2000, "crushes " .. crushes)
    assert.is_true(broken > OPERATIONS / 1000, "broken " .. broken)
  end)
end)
