-- 100000 random operations on one world (a quarter of them on the secondary runs:
-- spec/support/scale.lua), checked after every step against brute force.
local budge = require("budge")
local scale = require("spec.support.scale")

local SEED = 20261124
local OPERATIONS = scale(100000)

-- Park-Miller, shared with the benches: the same sequence on every interpreter
-- (math.random is not).
local new_random = require("fixtures.random").new

local METHODS = {"axis_sweep", "swept", "seed", "wall_type", "min_axis", "fat_cross", "auto"}
local CONTINUOUS = {axis_sweep = true, swept = true, auto = true}
local TILE = 16

describe("a world under " .. OPERATIONS .. " random operations", function()
  it("never lets a continuous move or a moving solid leave an actor inside a solid unreported, "
    .. "finds every box, keeps its counts", function()
    local random = new_random(SEED)
    local world = budge.new_world({cell_size = 48})
    local grid = {}
    for row = 1, 20 do
      grid[row] = {}
      for col = 1, 20 do
        local roll = random()
        grid[row][col] = roll < 0.12 and 1 or (roll < 0.15 and 2 or 0)
      end
    end
    world:add_tiles(grid, TILE, TILE, {
      x = 40, y = 40,
      is_solid = function(id) return id ~= 0 end,
      is_oneway = function(id) return id == 2 end,
    })
    local solids, actors = {}, {}

    local function coordinate()
      local roll = random()
      if roll < 0.4 then return random(-20, 400) end
      if roll < 0.7 then return random(-80, 1600) / 4 end
      return random() * 420 - 20
    end

    local function overlaps(a, b)
      return a.x < b.x + b.width and b.x < a.x + a.width and a.y < b.y + b.height
        and b.y < a.y + a.height
    end

    -- does `a` overlap anything solid? (brute force; oneway solids and tiles count only
    -- when `with_oneway`)
    local function inside_solid(a, with_oneway)
      for i = 1, #solids do
        local solid = solids[i]
        if (with_oneway or solid.wall_type ~= "oneway") and overlaps(a, solid) then
          return solid
        end
      end
      for row = 1, 20 do
        for col = 1, 20 do
          local id = grid[row][col]
          if id == 1 or (id == 2 and with_oneway) then
            local tile = {x = 40 + (col - 1) * TILE, y = 40 + (row - 1) * TILE, width = TILE,
              height = TILE}
            if overlaps(a, tile) then return tile end
          end
        end
      end
      return nil
    end

    local function contains(list, item, n)
      for i = 1, n do if list[i] == item then return true end end
      return false
    end

    local out = {}
    local function check_found(item, step)
      if item.width > 0 and item.height > 0 then
        local cx, cy = item.x + item.width / 2, item.y + item.height / 2
        local _, n = world:query_point(cx, cy, out)
        if not contains(out, item, n) then
          error(("seed %d, step %d: box at %.17g,%.17g not found at its centre"):format(
            SEED, step, item.x, item.y))
        end
      end
      local _, n = world:query_rect(item.x - 60, item.y, 59.5, item.height, out)
      if contains(out, item, n) then
        error(("seed %d, step %d: box at %.17g,%.17g found where it is not"):format(
          SEED, step, item.x, item.y))
      end
    end

    local clean = {} -- actor -> it overlapped nothing solid after its last move or add
    local moved, huge, moved_solids = 0, 0, 0
    for step = 1, OPERATIONS do
      local roll = random()
      local touched
      if roll < 0.02 and #solids < 40 then
        local solid = {x = coordinate(), y = coordinate(), width = random(1, 40),
          height = random(1, 40), wall_type = random() < 0.15 and "oneway" or nil}
        world:add_solid(solid)
        solids[#solids + 1] = solid
        touched = solid
        for i = 1, #actors do clean[actors[i]] = not inside_solid(actors[i], false) end
      elseif roll < 0.035 and #solids > 0 then
        local index = random(1, #solids)
        world:remove(solids[index])
        table.remove(solids, index)
      elseif roll < 0.05 and #actors < 30 then
        local actor = {x = coordinate(), y = coordinate(), width = random(1, 24),
          height = random(1, 24)}
        world:add_actor(actor)
        actors[#actors + 1] = actor
        clean[actor] = not inside_solid(actor, false)
        touched = actor
      elseif roll < 0.06 and #actors > 0 then
        local index = random(1, #actors)
        clean[actors[index]] = nil
        world:remove(actors[index])
        table.remove(actors, index)
      elseif roll < 0.07 and #solids > 0 then
        local solid = solids[random(1, #solids)]
        solid.x, solid.y = coordinate(), coordinate()
        world:update(solid)
        touched = solid
        for i = 1, #actors do clean[actors[i]] = not inside_solid(actors[i], false) end
      elseif roll < 0.08 and #actors > 0 then
        local actor = actors[random(1, #actors)]
        actor.x, actor.y = coordinate(), coordinate()
        world:update(actor)
        clean[actor] = not inside_solid(actor, false)
        touched = actor
      elseif roll < 0.15 and #solids > 0 then
        local solid = solids[random(1, #solids)]
        local dx, dy = random(-48, 48) / 4, random(-48, 48) / 4
        if random() < 0.05 then dx, dy = random(-3000, 3000), random(-3000, 3000) end
        if random() < 0.5 then dx = 0 elseif random() < 0.5 then dy = 0 end
        local was_clean = {}
        for i = 1, #actors do was_clean[i] = clean[actors[i]] and not inside_solid(actors[i], false) end
        local n, crushed = world:move_solid(solid, dx, dy)
        local is_crushed = {}
        for i = 1, n do is_crushed[crushed[i]] = true end
        for i = 1, #actors do
          local actor = actors[i]
          local hit = inside_solid(actor, false)
          if was_clean[i] and hit and not is_crushed[actor] then
            error(("seed %d, step %d: move_solid by %.17g,%.17g left an actor inside a solid "
              .. "unreported: actor %.17g,%.17g %gx%g, solid %.17g,%.17g %gx%g"):format(SEED, step,
              dx, dy, actor.x, actor.y, actor.width, actor.height, hit.x, hit.y, hit.width, hit.height))
          end
          clean[actor] = not hit
          check_found(actor, step)
        end
        touched = solid
        moved_solids = moved_solids + 1
      elseif roll < 0.95 and #actors > 0 then
        local actor = actors[random(1, #actors)]
        local method = METHODS[random(1, #METHODS)]
        local dx, dy = random(-160, 160) / 8, random(-160, 160) / 8
        if random() < 0.02 then dx, dy = random(-100000, 100000), random(-100000, 100000); huge = huge + 1 end
        if random() < 0.1 then dx, dy = dx + random() - 0.5, dy + random() - 0.5 end
        local was_clean = clean[actor] and not inside_solid(actor, false)
        local x, y = world:move(actor, dx, dy, method)
        assert(x == actor.x and y == actor.y)
        if CONTINUOUS[method] then
          moved = moved + 1
          local hit = inside_solid(actor, false)
          if was_clean and hit then
            error(("seed %d, step %d: %s moved an actor by %.17g,%.17g into a solid: actor "
              .. "%.17g,%.17g %gx%g, solid %.17g,%.17g %gx%g"):format(SEED, step, method, dx, dy,
              actor.x, actor.y, actor.width, actor.height, hit.x, hit.y, hit.width, hit.height))
          end
          clean[actor] = was_clean
        else
          clean[actor] = not inside_solid(actor, false)
        end
        touched = actor
      else
        local x, y = coordinate(), coordinate()
        world:query_segment(x, y, coordinate(), coordinate(), out)
      end
      if touched then check_found(touched, step) end
      local solid_count, actor_count, layer_count = world:count()
      if solid_count ~= #solids or actor_count ~= #actors or layer_count ~= 1 then
        error(("seed %d, step %d: counts drifted: %d/%d solids, %d/%d actors"):format(
          SEED, step, solid_count, #solids, actor_count, #actors))
      end
      if step % 10000 == 0 then
        for i = 1, #solids do check_found(solids[i], step) end
        for i = 1, #actors do check_found(actors[i], step) end
      end
    end
    assert.is_true(moved > OPERATIONS / 5)
    assert.is_true(huge > OPERATIONS / 200)
    assert.is_true(moved_solids > OPERATIONS / 20)
  end)
end)
