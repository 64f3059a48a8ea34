-- What a game's moving things touch: filter responses, hit records, sensors, actors that
-- meet actors, frame contacts, dry runs and swept queries. Oracles where one exists:
-- brute force over the two straight motions, the same move without a filter, a world
-- without the dry runs, exact reflections of dyadic speeds.
local budge = require("budge")
local box = require("fixtures.box")
local garbage = require("fixtures.garbage")
local random_source = require("fixtures.random")
local scale = require("spec.support.scale")
local instructions = require("spec.support.instructions")

local function trace(x, y, n, hits)
  local parts = {string.format("%.17g %.17g %d", x, y, n)}
  for i = 1, n do
    local hit = hits[i]
    parts[#parts + 1] = string.format("%s/%s/%s/%s/%s/%.17g/%d/%d", tostring(hit.other.name or
      hit.other.x), tostring(hit.side), tostring(hit.col), tostring(hit.row), hit.response,
      hit.t, hit.nx, hit.ny)
  end
  return table.concat(parts, " ")
end

local function always(response) return function() return response end end
local function xy(x, y) return {x, y} end

describe("responses", function()
  it("slide (and true) is exactly the move without a filter, in " .. scale(3000) .. " random scenes with "
    .. "sensors, for axis_sweep and swept; a sensor far away changes nothing", function()
    local rng = random_source.new(20261201)
    local checked = 0
    local cases = scale(3000)
    for case = 1, cases do
      local grid = {}
      for r = 1, 12 do
        grid[r] = {}
        for c = 1, 12 do grid[r][c] = rng(1, 4) == 1 and rng(1, 5) or 0 end
      end
      local boxes, sensors = {}, {}
      for i = 1, 6 do
        boxes[i] = {x = rng(0, 180), y = rng(0, 180), width = rng(1, 40),
          height = rng(1, 40), wall_type = rng(1, 5) == 1 and "oneway" or nil}
        sensors[i] = {x = rng(0, 180), y = rng(0, 180), width = rng(0, 30), height = rng(0, 30)}
      end
      local ax, ay = rng(0, 720) / 4, rng(0, 720) / 4
      local aw, ah = rng(1, 20), rng(1, 20)
      local dx, dy = rng(-400, 400) / 4, rng(-400, 400) / 4
      local method = case % 2 == 0 and "swept" or "axis_sweep"
      local results, clear = {}, true
      for k = 1, 4 do
        local world = budge.new_world({cell_size = 32})
        local solid = {}
        solid[world:add_tiles(grid, 16, 16, {is_oneway = function(id) return id == 5 end})] = true
        for i = 1, #boxes do
          local b = boxes[i]
          solid[world:add_solid({x = b.x, y = b.y, width = b.width, height = b.height,
            wall_type = b.wall_type})] = true
          if k ~= 4 then world:add_sensor(box(sensors[i].x, sensors[i].y, sensors[i].width,
            sensors[i].height)) end
        end
        if k == 4 then world:add_sensor(box(5000, 5000, 10, 10)) end
        local _, inside = world:query_rect(ax, ay, aw, ah, nil,
          function(item) return solid[item] end) -- (inside a sensor is fine)
        if inside > 0 then clear = false end
        local actor = world:add_actor(box(ax, ay, aw, ah))
        if k == 2 then actor.filter = always("slide") elseif k == 3 then actor.filter = always(true) end
        results[k] = trace(world:move(actor, dx, dy, method))
        if k == 4 then -- no sensor on the way: the same place, the blocking hits only
          local blocking = {}
          for part in results[1]:gmatch("%S+") do
            if not part:find("/cross/", 1, true) then blocking[#blocking + 1] = part end
          end
          local with_cross = results[1]:match("^%S+ %S+ (%d+)")
          local n = 0
          for _ in results[1]:gmatch("/cross/") do n = n + 1 end
          blocking[3] = tostring(tonumber(with_cross) - n)
          results[4] = results[4] == table.concat(blocking, " ")
        end
      end
      -- (an actor that starts inside tiles lists, with a filter, every tile that holds it
      -- where it is; without one, the first line of them: README, "Responses")
      if clear then
        checked = checked + 1
        assert.are.equal(results[1], results[2], method)
        assert.are.equal(results[1], results[3], method)
        assert.is_true(results[4], method)
      end
    end
    assert.is_true(checked > cases / 3, "checked " .. checked)
  end)

  it("slide (and true) is exactly the move without a filter in " .. scale(3000) .. " random worlds "
    .. "of solids and actors alone (LuaJIT's lean phase), several solids met at once", function()
    local rng = random_source.new(20261207)
    local checked, several = 0, 0
    local cases = scale(3000)
    for case = 1, cases do
      local boxes = {}
      for i = 1, rng(1, 60) do -- (on a grid of 8 px three times in four: faces that tie)
        local on_grid = rng(1, 4) > 1
        boxes[i] = {x = on_grid and rng(0, 24) * 8 or rng(0, 760) / 4,
          y = on_grid and rng(0, 24) * 8 or rng(0, 760) / 4,
          width = on_grid and 8 * rng(1, 3) or rng(0, 160) / 4,
          height = on_grid and 8 * rng(1, 3) or rng(0, 160) / 4,
          wall_type = rng(1, 6) == 1 and "oneway" or nil, name = "s" .. i}
      end
      local ax, ay = rng(0, 24) * 8 + rng(0, 1) * rng(0, 7) / 2, rng(0, 24) * 8
      local aw, ah = rng(1, 6) * 4, rng(1, 6) * 4
      local dx, dy = rng(-160, 160) / 4, rng(-160, 160) / 4
      local results, clear = {}, true
      for k = 1, 3 do
        local world = budge.new_world({cell_size = ({16, 64, 50})[case % 3 + 1]})
        for i = 1, #boxes do
          local b = boxes[i]
          world:add_solid({x = b.x, y = b.y, width = b.width, height = b.height,
            wall_type = b.wall_type, name = b.name})
        end
        local _, inside = world:query_rect(ax, ay, aw, ah)
        if inside > 0 then clear = false end
        local actor = world:add_actor(box(ax, ay, aw, ah))
        if k == 2 then actor.filter = always("slide") elseif k == 3 then actor.filter = always(true) end
        local x, y, n, hits = world:move(actor, dx, dy)
        results[k] = trace(x, y, n, hits)
        if k == 1 then -- (a phase that met several solids: the move sorts its hits)
          for i = 2, n do
            if hits[i].side == hits[i - 1].side then several = several + 1 break end
          end
        end
      end
      if clear then
        checked = checked + 1
        assert.are.equal(results[1], results[2])
        assert.are.equal(results[1], results[3])
      end
    end
    assert.is_true(checked > cases / 3, "checked " .. checked)
    assert.is_true(several > cases / 20, "several " .. several .. " of " .. checked)
  end)

  it("slide is exactly the move without a filter where the far side of the band it looks "
    .. "at rounds short (wide actors across 0, faces between the two roundings)", function()
    -- The band a filtered phase looks at ends at its reach, high = (pos + delta) + size
    -- (the far side where the box ends); low + (high - low)
    -- can round below it when the band straddles 0 and is wide. A box whose near face lies
    -- between the two was left out (the solids' bounds clipped the band short of it): the
    -- move without a filter met it, the filtered one went into it. Each case puts the face
    -- there, on x or on y, as a solid, another actor or a sensor (crossed by both moves).
    local rng = random_source.new(20261203)
    local between, kinds = 0, {solid = 0, actor = 0, sensor = 0}
    for case = 1, 2500 do
      local size = 300 + rng(0, 2500000) / 1000 -- (non-dyadic: the roundings happen)
      local delta = 1 + rng(0, 60000) / 1009
      -- (the band's end near 0, its start far below: the widest gaps between the roundings)
      local pos = rng(-50000, 50000) / 1013 - size - delta
      local high = pos + delta + size
      local far = pos + (high - pos)
      local face = far + (high - far) / 2 -- (strictly between, when there is a value there)
      local is_x = case % 4 < 2
      local kind = ({"solid", "actor", "sensor"})[case % 3 + 1]
      local results = {"", ""}
      if far < face and face < high then between = between + 1 end
      for k = 1, (far < face and face < high) and 2 or 0 do
        local world = budge.new_world({cell_size = 64})
        local other = is_x and box(face, 0, 10, 10) or box(0, face, 10, 10)
        if kind == "solid" then world:add_solid(other)
        elseif kind == "sensor" then world:add_sensor(other)
        else world:add_actor(other) end
        local actor = world:add_actor(is_x and box(pos, 0, size, 10) or box(0, pos, 10, size))
        -- (k = 1: with no filter the actor passes other actors: give both a filter that
        -- answers for each kind what the move without one does)
        if k == 2 or kind == "actor" then
          actor.filter = function(_, item)
            if kind == "actor" and k == 1 then return item == other and "slide" or nil end
            return "slide"
          end
        end
        if kind == "actor" and k == 1 then -- the reference: the other actor as a solid
          world = budge.new_world({cell_size = 64})
          world:add_solid(other)
          actor = world:add_actor(is_x and box(pos, 0, size, 10) or box(0, pos, 10, size))
        end
        local dx, dy = 0, 0
        if is_x then dx = delta else dy = delta end
        local x, y, n, hits = world:move(actor, dx, dy)
        results[k] = string.format("%.17g %.17g %d %s", x, y, n, tostring(n > 0
          and hits[1].side))
      end
      if far < face and face < high then kinds[kind] = kinds[kind] + 1 end
      assert.are.equal(results[1], results[2], kind .. (is_x and " on x" or " on y"))
    end
    -- not vacuous: many cases have a face between the roundings, of each kind
    assert.is_true(between > 25, "between " .. between)
    -- (few: with the reach (pos + delta) + size on the same grid as pos, high - pos is
    -- mostly exact; spec "ends no move overlapping ..." puts faces at the reach's roundings)
    for kind, count in pairs(kinds) do assert.is_true(count > 5, kind .. " " .. count) end
  end)

  it("ends no move overlapping what would stop it: the far side where a box ends is the "
    .. "one its stops and crossings compare with, with a filter or without", function()
    -- A box at pos (of size) moving forward by delta ends at pos + delta, its far side
    -- then at (pos + delta) + size, which can round above (pos + size) + delta: a face
    -- between the two stopped nothing when the stops compared with the second, and the
    -- box ended inside the solid, tile or actor by a rounding, with no hit. Each case
    -- puts the face of a solid, a tile layer's tile, a blocking actor or a sensor at one
    -- of the two roundings or between them, on x or y, with game-sized values and with
    -- wide boxes across 0, and checks the move against that oracle: the box overlaps
    -- the thing where it ends exactly when the face lies below its far side there, and
    -- then it stopped with a hit on it, or crossed it (a sensor). With and without a
    -- filter, the same. Then a moving solid pushes an actor whose face is there.
    local rng = random_source.new(20261204)
    local kinds = {"solid", "tiles", "actor", "sensor"}
    local overlapped, checked, pushed, at_edge = 0, 0, 0, 0
    for case = 1, 3000 do
      local size, pos, delta
      if case % 2 == 0 then -- game-sized, non-dyadic
        size = 8 + rng(0, 56000) / 1000
        pos = rng(-1000000, 1000000) / 997
        delta = rng(100, 8000) / 1009
      else -- wide, across 0
        size = 300 + rng(0, 2500000) / 1000
        delta = 1 + rng(0, 60000) / 1009
        pos = rng(-50000, 50000) / 1013 - size - delta
      end
      local old_reach, far = (pos + size) + delta, (pos + delta) + size
      local face = ({old_reach, far, old_reach + (far - old_reach) / 2})[case % 3 + 1]
      local is_x = case % 4 < 2
      local kind = kinds[math.floor(case / 4) % 4 + 1]
      if old_reach <= face and face < far then at_edge = at_edge + 1 end
      local results = {}
      for k = 1, 2 do -- k = 2: with a filter ("slide" on everything: a sensor is crossed)
        local world = budge.new_world({cell_size = 64})
        local other
        if kind == "tiles" then -- one 16 px tile whose near face is at `face`
          local origin = is_x and {x = face, y = -3} or {x = -3, y = face}
          local handle = world:add_tiles({{1}}, 16, 16, origin)
          other = is_x and box(face, -3, 16, 16) or box(-3, face, 16, 16)
          other.handle = handle
        else
          other = is_x and box(face, 0, 10, 10) or box(0, face, 10, 10)
          if kind == "solid" then world:add_solid(other)
          elseif kind == "actor" then world:add_actor(other)
          else world:add_sensor(other) end
        end
        local actor = world:add_actor(is_x and box(pos, 0, size, 10) or box(0, pos, 10, size))
        -- (without a filter an actor passes other actors: the reference answers "slide"
        -- for it alone, the filtered move for everything)
        if k == 2 or kind == "actor" then actor.filter = always("slide") end
        local x, y, n, hits = world:move(actor, is_x and delta or 0, is_x and 0 or delta)
        local lead, near = is_x and x + size or y + size, is_x and other.x or other.y
        local met = 0
        for i = 1, n do
          if hits[i].other == other or hits[i].other == other.handle then met = met + 1 end
        end
        if far > near then -- the box would end overlapping it
          overlapped = overlapped + (k == 1 and 1 or 0)
          assert.are.equal(1, met, kind)
          if kind == "sensor" then
            assert.are.equal("cross", hits[1].response)
            assert.are.equal(is_x and pos + delta or pos + delta, is_x and x or y)
          else
            assert.is_true(lead <= near, kind .. " overlapped") -- stopped, touching it
          end
        else
          assert.are.same({0, pos + delta}, {n, is_x and x or y}, kind)
        end
        results[k] = string.format("%.17g %.17g %d", x, y, n)
        checked = checked + 1
      end
      assert.are.equal(results[1], results[2], kind)
      -- a solid moving by delta pushes an actor whose near face is where the solid's
      -- far side ends: the actor is left touching the solid's new box, never inside it
      local world = budge.new_world({cell_size = 64})
      local solid = world:add_solid(is_x and box(pos, 0, size, 10) or box(0, pos, 10, size))
      local actor = world:add_actor(is_x and box(face, 0, 10, 10) or box(0, face, 10, 10))
      world:move_solid(solid, is_x and delta or 0, is_x and 0 or delta)
      local solid_far = is_x and solid.x + solid.width or solid.y + solid.height
      local actor_near = is_x and actor.x or actor.y
      if solid_far > face then
        pushed = pushed + 1
        assert.are.equal(solid_far, actor_near) -- pushed to the solid's far side, exactly
      else
        assert.are.equal(face, actor_near)
      end
    end
    -- not vacuous: many boxes would end overlapping, many pushes, and many of those with
    -- the face at or above the old reach (where the box ended inside the thing)
    assert.is_true(overlapped > 400, "overlapped " .. overlapped)
    assert.is_true(pushed > 400, "pushed " .. pushed)
    assert.is_true(at_edge > 400, "at the edge " .. at_edge)
    assert.are.equal(6000, checked)
  end)

  it("crosses no sensor between where a blocked box stops and the face that stops it, "
    .. "with a filter or without", function()
    -- A box stopped by a face at `wall` ends at the largest position whose far side is at
    -- most the wall; with non-dyadic values that far side can fall short of it. A sensor
    -- whose face lies in the gap is never entered by the box. The move with a filter
    -- compared its distance with the wall's (both rounded) and reported it crossed.
    local rng = random_source.new(20261205)
    local in_gap = 0
    for case = 1, 12000 do
      local size = 8 + rng(0, 56000) / 1000
      local pos = rng(-1000000, 1000000) / 997
      local delta = rng(100, 8000) / 1009
      local is_x = case % 2 == 0
      local wall = pos + size + delta * rng(1, 999) / 1000
      local function place(b) -- (on y: the box turned over the diagonal)
        if not is_x then b.x, b.y, b.width, b.height = b.y, b.x, b.height, b.width end
        return b
      end
      local reference = budge.new_world({cell_size = 64})
      reference:add_solid(place(box(wall, 0, 10, 10)))
      local x, y = reference:move(reference:add_actor(place(box(pos, 0, size, 10))),
        is_x and delta or 0, is_x and 0 or delta)
      local lead = (is_x and x or y) + size
      local face = lead + (wall - lead) / 2
      if lead < face and face < wall then
        in_gap = in_gap + 1
        for k = 1, 2 do
          local world = budge.new_world({cell_size = 64})
          local solid = world:add_solid(place(box(wall, 0, 10, 10)))
          world:add_sensor(place(box(face, 0, 10, 10)))
          local actor = world:add_actor(place(box(pos, 0, size, 10)))
          if k == 2 then actor.filter = always("slide") end
          local x2, y2, n, hits = world:move(actor, is_x and delta or 0, is_x and 0 or delta)
          assert.are.same({x, y, 1, solid}, {x2, y2, n, hits[1].other}) -- the wall alone
        end
      end
    end
    assert.is_true(in_gap > 100, "in the gap " .. in_gap) -- not vacuous
  end)

  it("with a filter, ends where it ends without one against a tile layer whose origin and "
    .. "tile size are not whole numbers, never inside a tile", function()
    -- A filtered move took a tile's far side as (origin + (col - 1) * tile) + tile, which
    -- can round below the layer's own edge origin + col * tile (what its scans and queries
    -- use): moving back onto it, the box stopped an ulp inside the tile.
    local rng = random_source.new(20261206)
    local differs, checked = 0, 0
    for case = 1, 1500 do
      local tile = rng(1000, 40000) / 997
      local origin = rng(-400000, 400000) / 991
      local is_x, back = case % 2 == 0, case % 4 < 2
      local row = {}
      for col = 1, 12 do row[col] = rng(0, 3) == 0 and 1 or 0 end
      local grid = {}
      if is_x then grid[1] = row else for k = 1, 12 do grid[k] = {row[k]} end end
      local opts = is_x and {x = origin, y = 0} or {x = 0, y = origin}
      local size = rng(100, 3000) / 101
      local pos = origin + rng(0, 12000) / 1000 * tile
      local delta = (back and -1 or 1) * rng(10, 3000) / 103
      for col = 1, 12 do
        if (origin + (col - 1) * tile) + tile ~= origin + col * tile then differs = differs + 1 end
      end
      local results = {}
      for k = 1, 2 do
        local world = budge.new_world({cell_size = 64})
        local layer = world:add_tiles(grid, is_x and tile or 8, is_x and 8 or tile, opts)
        local actor = world:add_actor(is_x and box(pos, 1, size, 6) or box(1, pos, 6, size))
        if k == 2 then actor.filter = always("slide") end
        local _, n = world:query_rect(actor.x, actor.y, actor.width, actor.height, nil,
          function(item) return item == layer end)
        if n == 0 then -- (not starting inside a tile)
          local x, y = world:move(actor, is_x and delta or 0, is_x and 0 or delta)
          local _, inside = world:query_rect(x, y, actor.width, actor.height, nil,
            function(item) return item == layer end)
          assert.are.equal(0, inside)
          results[k] = string.format("%.17g %.17g", x, y)
          checked = checked + 1
        end
      end
      assert.are.equal(results[1], results[2])
    end
    assert.is_true(differs > 2000 and checked > 1500, differs .. " " .. checked)
  end)

  it("touch ends the whole move at the contact", function()
    local world = budge.new_world()
    local wall = world:add_solid(box(20, -100, 10, 200))
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = always("touch")
    local x, y, n, hits = world:move(actor, 20, 30)
    assert.are.same({10, 0, 1}, {x, y, n})
    assert.are.same({wall, "right", "touch", 10 / 50, -1, 0},
      {hits[1].other, hits[1].side, hits[1].response, hits[1].t, hits[1].nx, hits[1].ny})
    actor.filter = always("slide")
    world:update(actor)
    assert.are.same({10, 30}, xy(world:move(actor, 20, 30)))
  end)

  it("bounce reflects what is left of the move off the face, exactly", function()
    local world = budge.new_world()
    world:add_solid(box(20, -100, 10, 200))
    local floor = world:add_solid(box(-100, 20, 300, 10))
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = always("bounce")
    local x, y, n, hits = world:move(actor, 16, 14)
    -- x: 10 px to the wall, 6 back; y: 10 px to the floor, 4 back
    assert.are.same({4, 6, 2}, {x, y, n})
    assert.are.same({"right", -1, 0, 10 / 30}, {hits[1].side, hits[1].nx, hits[1].ny, hits[1].t})
    assert.are.same({floor, "floor", 0, -1, (16 + 10) / 30},
      {hits[2].other, hits[2].side, hits[2].nx, hits[2].ny, hits[2].t})
  end)

  it("bounce in the swept method reflects the blocked part of the diagonal", function()
    local world = budge.new_world()
    world:add_solid(box(20, -100, 10, 200))
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = always("bounce")
    local x, y, n, hits = world:move(actor, 20, 8, "swept")
    assert.are.same({0, 8, 1}, {x, y, n})
    assert.are.same({"right", "bounce", 0.5}, {hits[1].side, hits[1].response, hits[1].t})
  end)

  it("cross passes through and reports what was crossed, with its side and t", function()
    local world = budge.new_world()
    local glass = world:add_solid(box(20, 0, 10, 10))
    local wall = world:add_solid(box(60, 0, 10, 10))
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = function(_, other) return other == glass and "cross" or "slide" end
    for _, method in ipairs({"axis_sweep", "swept"}) do
      actor.x = 0
      world:update(actor)
      local x, _, n, hits = world:move(actor, 100, 0, method)
      assert.are.same({50, 2}, {x, n}, method)
      assert.are.same({glass, "right", "cross", 0.1, -1}, {hits[1].other, hits[1].side,
        hits[1].response, hits[1].t, hits[1].nx}, method)
      assert.are.same({wall, "slide", 0.5}, {hits[2].other, hits[2].response, hits[2].t}, method)
    end
  end)

  it("a tile layer's filter gets col, row and the tile's id: drop through one oneway tile", function()
    local world = budge.new_world()
    local grid = {{0, 0, 0, 0}, {7, 7, 0, 0}, {0, 0, 0, 0}, {1, 1, 1, 1}}
    local tiles = world:add_tiles(grid, 16, 16, {is_oneway = function(id) return id == 7 end})
    local player = world:add_actor(box(4, 0, 8, 8))
    local asked = {}
    local holding_down = false
    player.filter = function(_, other, col, row, id)
      asked[#asked + 1] = string.format("%s %s %s %s", other == tiles and "tiles" or "?", col, row, id)
      if id == 7 and holding_down then return nil end
      return "slide"
    end
    local _, y, n, hits = world:move(player, 0, 40)
    assert.are.same({8, 1, 1, 2}, {y, n, hits[1].col, hits[1].row})
    assert.are.same({"tiles 1 2 7"}, asked)
    holding_down = true
    asked = {}
    _, y = world:move(player, 0, 40)
    assert.are.equal(40, y) -- dropped through onto the floor (its top at 48)
    assert.are.same({"tiles 1 2 7", "tiles 1 4 1"}, asked)
  end)

  it("is asked only about what the path meets, nearest first, up to the first stop", function()
    local world = budge.new_world({cell_size = 16})
    local near = world:add_solid(box(30, 0, 4, 10))
    local far = world:add_solid(box(60, 0, 4, 10))
    world:add_solid(box(40, 40, 4, 4)) -- beside the path: never asked
    local actor = world:add_actor(box(0, 0, 10, 10))
    local asked = {}
    actor.filter = function(_, other)
      asked[#asked + 1] = other.x
      return other == near and "cross" or "slide"
    end
    world:move(actor, 200, 0)
    assert.are.same({30, 60}, asked)
    assert.are.same({50, 0}, {actor.x, actor.y})
    assert.is_true(world:has(far))
  end)

  it("refuses any other return value with an error naming it, and moves nothing", function()
    local world = budge.new_world()
    world:add_solid(box(20, 0, 10, 10))
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = always("stick")
    local ok, message = pcall(world.move, world, actor, 30, 0)
    assert.is_false(ok)
    assert.are.equal('actor.filter must return "slide" (or true), "touch", "bounce", "cross", '
      .. 'or false/nil to ignore, got "stick" for a table', message:gsub("^[^:]+:%d+: ", ""))
    assert.are.same({0, 0}, {actor.x, actor.y})
    actor.filter = always(1)
    ok, message = pcall(world.move, world, actor, 30, 0)
    assert.is_false(ok)
    assert.truthy(message:find("got 1 for a table", 1, true), message)
    actor.filter = nil
    assert.are.same({10, 0}, xy(world:move(actor, 30, 0)))
  end)
end)

describe("hit records", function()
  it("carry the normal of each face, pointing from the other toward the actor", function()
    local world = budge.new_world()
    world:add_solid(box(-20, -20, 60, 10)) -- ceiling
    world:add_solid(box(-20, 30, 60, 10)) -- floor
    world:add_solid(box(-20, -10, 10, 40)) -- left wall
    world:add_solid(box(30, -10, 10, 40)) -- right wall
    local actor = world:add_actor(box(10, 10, 10, 10))
    local normals = {}
    for _, move in ipairs({{40, 0}, {-60, 0}, {0, 60}, {0, -60}}) do
      local _, _, n, hits = world:move(actor, move[1], move[2])
      assert.are.equal(1, n)
      normals[#normals + 1] = string.format("%s %d %d", hits[1].side, hits[1].nx, hits[1].ny)
    end
    assert.are.same({"right -1 0", "left 1 0", "floor 0 -1", "ceiling 0 1"}, normals)
  end)

  it("list every thing crossed once, in path order, even at 10^4 px per step", function()
    local world = budge.new_world()
    local coins = {}
    for i = 1, 100 do coins[i] = world:add_sensor(box(i * 97, 3, 4, 4)) end
    local grid = {}
    for col = 1, 700 do grid[col] = col % 7 == 0 and 9 or 0 end
    local water = world:add_tiles(grid, 16, 16, {width = 700, y = 0})
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = function(_, other) if other == water then return "cross" end return "cross" end
    local _, _, n, hits = world:move(actor, 10000, 0)
    assert.are.equal(100 + 89, n) -- 100 coins, and columns 7, 14, ... 623 before x = 10010
    local last, coin = -1, 0
    for i = 1, n do
      local hit = hits[i]
      assert.is_true(hit.t >= last, "in path order")
      last = hit.t
      if hit.other ~= water then
        coin = coin + 1
        assert.are.equal(coins[coin], hit.other)
        assert.is_true(math.abs((coin * 97 - 10) / 10000 - hit.t) < 1e-15)
      else
        assert.are.equal(0, hit.col % 7)
      end
    end
    assert.are.equal(100, coin)
  end)
end)

describe("sensors", function()
  local function coin_run(speed)
    local world = budge.new_world()
    world:add_tiles({{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
      1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}}, 16, 16, {y = 32})
    local coins = {}
    for i = 1, 20 do coins[i] = world:add_sensor(box(20 + i * 24, 20, 6, 6)) end
    local player = world:add_actor(box(0, 20, 10, 12))
    local got = {}
    for _ = 1, math.ceil(560 / speed) do
      local _, _, n, hits = world:move(player, speed, 4) -- walking on the floor, pressed down
      for i = 1, n do
        if hits[i].response == "cross" then got[#got + 1] = hits[i].other end
      end
      for i = 1, n do
        if hits[i].response == "cross" and world:has(hits[i].other) then world:remove(hits[i].other) end
      end
    end
    return got, coins, world
  end

  it("a player walking through 20 coins gets each exactly once, in path order", function()
    for _, speed in ipairs({3, 40}) do
      local got, coins, world = coin_run(speed)
      assert.are.same(coins, got, "speed " .. speed)
      assert.are.same({0, 1, 1, 0}, {world:count()})
    end
  end)

  it("are found by queries, counted, moved by update, and refused twice", function()
    local world = budge.new_world()
    local coin = world:add_sensor(box(10, 10, 4, 4))
    assert.are.same({0, 0, 0, 1}, {world:count()})
    assert.are.same({coin}, (world:query_point(12, 12)))
    coin.x = 100
    world:update(coin)
    assert.are.same({}, (world:query_point(12, 12)))
    assert.are.same({coin}, (world:query_rect(90, 0, 20, 20)))
    local ok, message = pcall(world.add_sensor, world, coin)
    assert.is_false(ok)
    assert.truthy(message:find("box is already in this world (as a sensor)", 1, true), message)
    local actor = world:add_actor(box(0, 10, 4, 4))
    local _, _, n, hits = world:move(actor, 200, 0)
    assert.are.same({1, coin, "cross", 96 / 200}, {n, hits[1].other, hits[1].response, hits[1].t})
    actor.filter = function() return false end
    actor.x = 0
    world:update(actor)
    local x, y
    x, y, n = world:move(actor, 200, 0)
    assert.are.same({200, 10, 0}, {x, y, n})
    world:remove(coin)
    assert.are.same({0, 1, 0, 0}, {world:count()})
  end)

  it("never block, and never stop a moving solid's push", function()
    local world = budge.new_world()
    world:add_sensor(box(0, 0, 100, 100))
    local platform = world:add_solid(box(0, 50, 40, 10))
    local rider = world:add_actor(box(10, 40, 10, 10))
    world:move_solid(platform, 30, -20)
    assert.are.same({40, 20}, {rider.x, rider.y})
  end)
end)

describe("actors that meet actors", function()
  it("ignore each other with no filter, and block where the other stands with one", function()
    local world = budge.new_world()
    local enemy = world:add_actor(box(30, 0, 10, 10))
    local player = world:add_actor(box(0, 0, 10, 10))
    assert.are.same({60, 0}, xy(world:move(player, 60, 0)))
    player.x = 0
    world:update(player)
    player.filter = function(_, other) if other == enemy then return "slide" end return "slide" end
    local x, _, n, hits = world:move(player, 60, 0)
    assert.are.same({20, 1, enemy, "right"}, {x, n, hits[1].other, hits[1].side})
  end)

  it("200 enemies that block each other in a closed room never overlap, in either order, "
    .. "and rerun bit for bit", function()
    local function run(reverse, frames, snapshot_at)
      local world = budge.new_world({cell_size = 32})
      world:add_solid(box(-10, -10, 420, 10))
      world:add_solid(box(-10, 400, 420, 10))
      world:add_solid(box(-10, 0, 10, 400))
      world:add_solid(box(400, 0, 10, 400))
      local rng = random_source.new(7)
      local enemies = {}
      local function filter(_, other) return other.enemy and "bounce" or "slide" end
      for row = 0, 9 do
        for col = 0, 19 do
          local enemy = world:add_actor(box(col * 20 + 2, row * 40 + 2, 12, 12))
          enemy.enemy, enemy.filter = true, filter
          enemy.vx, enemy.vy = rng(-8, 8) / 2, rng(-8, 8) / 2
          enemies[#enemies + 1] = enemy
        end
      end
      local count = #enemies
      local snapshot
      local function positions()
        local parts = {}
        for i = 1, count do parts[i] = string.format("%.17g,%.17g", enemies[i].x, enemies[i].y) end
        return table.concat(parts, ";")
      end
      for frame = 1, frames do
        for k = 1, count do
          local enemy = enemies[reverse and count + 1 - k or k]
          local _, _, n, hits = world:move(enemy, enemy.vx, enemy.vy)
          for i = 1, n do -- turn at walls and at each other
            if hits[i].nx ~= 0 then enemy.vx = hits[i].nx * math.abs(enemy.vx) end
            if hits[i].ny ~= 0 then enemy.vy = hits[i].ny * math.abs(enemy.vy) end
          end
        end
        if frame == snapshot_at then snapshot = positions() end
        if frame % 50 == 0 or frame == frames then
          for i = 1, count do
            local a = enemies[i]
            for j = i + 1, count do
              assert(not budge.detect_collision(a, enemies[j]), "overlap in frame " .. frame)
            end
            assert(a.x >= 0 and a.y >= 0 and a.x + 12 <= 400 and a.y + 12 <= 400)
          end
        end
      end
      return positions(), snapshot
    end
    local frames = scale(2000)
    local forward, at_quarter = run(false, frames, frames / 4)
    assert.are.equal(at_quarter, (run(false, frames / 4))) -- a rerun is bit-identical
    assert.are_not.equal(forward, (run(true, frames))) -- the order of moves decides, as in bump.lua
  end)
end)

-- The oracle of frame contacts: the two straight motions, brute force over the moments
-- where any edge of one passes an edge of the other (between two of them, overlap does
-- not change), evaluated with each box's own position at that moment.
local function oracle_contact(a0x, a0y, a1x, a1y, aw, ah, b0x, b0y, b1x, b1y, bw, bh)
  local function at(s)
    local ax, ay = a0x + (a1x - a0x) * s, a0y + (a1y - a0y) * s
    local bx, by = b0x + (b1x - b0x) * s, b0y + (b1y - b0y) * s
    return ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah
  end
  local times = {0, 1}
  local function edge(p, vp, q, vq) -- p + vp s = q + vq s
    if vp ~= vq then
      local s = (q - p) / (vp - vq)
      if s > 0 and s < 1 then times[#times + 1] = s end
    end
  end
  local avx, avy, bvx, bvy = a1x - a0x, a1y - a0y, b1x - b0x, b1y - b0y
  edge(a0x, avx, b0x + bw, bvx); edge(a0x + aw, avx, b0x, bvx)
  edge(a0y, avy, b0y + bh, bvy); edge(a0y + ah, avy, b0y, bvy)
  table.sort(times)
  if at(0) then return 0, false, not at(1) end
  for i = 1, #times - 1 do
    if times[i + 1] > times[i] and at((times[i] + times[i + 1]) / 2) then
      return times[i], true, not at(1)
    end
  end
  return nil
end

describe("frame contacts", function()
  it("find every bullet crossing a moving enemy, exactly as the brute-force oracle, in "
    .. scale(100000) .. " random frames moved in both orders", function()
    local world = budge.new_world({cell_size = 32})
    local bullet = world:add_actor(box(0, 0, 4, 4))
    local enemy = world:add_actor(box(0, 0, 16, 16))
    bullet.filter = function(_, other) return other == enemy and "cross" or nil end
    local rng = random_source.new(42)
    local out = {}
    local found, misses, false_reports, worst = 0, 0, 0, 0
    local cases = scale(100000)
    for case = 1, cases do
      local ex, ey = rng(-400, 400) / 8, rng(-400, 400) / 8
      local bx, by = ex + rng(-480, 480) / 8, ey + rng(-480, 480) / 8
      local speed, angle = rng(160, 480) / 8, rng(0, 15)
      local bdx = ({1, 1, 0, -1, -1, -1, 0, 1, 0.5, -0.5, 0.5, -0.5, 0.25, -0.75, 0.75, -0.25})[angle + 1]
      local bdy = ({0, 1, 1, 1, 0, -1, -1, -1, 0.75, 0.25, -1, 1, -0.5, 0.5, 0.25, -0.75})[angle + 1]
      bdx, bdy = bdx * speed, bdy * speed
      local edx, edy = rng(-240, 240) / 8, rng(-240, 240) / 8
      bullet.x, bullet.y, enemy.x, enemy.y = bx, by, ex, ey
      world:update(bullet)
      world:update(enemy)
      if case % 2 == 0 then
        world:move(bullet, bdx, bdy)
        world:move(enemy, edx, edy)
      else
        world:move(enemy, edx, edy)
        world:move(bullet, bdx, bdy)
      end
      local _, n = world:contacts(out)
      local t, began, ended = oracle_contact(bx, by, bx + bdx, by + bdy, 4, 4,
        ex, ey, ex + edx, ey + edy, 16, 16)
      if t then
        found = found + 1
        if n ~= 1 then
          misses = misses + 1
        else
          local record = out[1]
          assert(record.item == bullet and record.other == enemy)
          assert(record.began == began and record.ended == ended, "began/ended, case " .. case)
          local error_t = math.abs(record.t - t)
          if error_t > worst then worst = error_t end
        end
      elseif n ~= 0 then
        false_reports = false_reports + 1
      end
    end
    assert.are.same({0, 0}, {misses, false_reports})
    assert.is_true(worst <= 1e-9, "t off by " .. worst)
    assert.is_true(found > cases / 10, "found " .. found)
  end)

  it("match a brute force over every pair in " .. scale(240) .. " frames of worlds spread wide, "
    .. "tall, piled up and reshuffled, with sensors moved, resized, removed and added", function()
    -- Every pair of things in the world, through oracle_contact, with the rules of
    -- world:contacts: an actor and a sensor unless the actor's filter answers false/nil
    -- for it; two actors when the one added first answers "cross" for the other, else the
    -- other for it. The frame of each: from where it was at the last call, its add, or an
    -- actor's teleport (world:update), to where it is. The layouts switch the axis the
    -- broad phase prunes along, and a reshuffle moves everything at once (its order is
    -- sorted again by merging, not by insertion).
    local rng = random_source.new(20261206)
    local world = budge.new_world({cell_size = 32})
    local things, serial = {}, 0
    local answers = {"cross", "slide", "touch", false, "cross", "bounce"}
    local function filter(self, other)
      return answers[(self.serial * 7 + other.serial * 13) % (#answers + 1) + 1]
    end
    local layout = "wide"
    local function place()
      local across, along = rng(-320, 320) / 8, rng(-16000, 16000) / 8
      if layout == "wide" then return along, across end
      if layout == "tall" then return across, along end
      if layout == "pile" then return rng(-200, 200) / 8, rng(-200, 200) / 8 end
      return rng(-4000, 4000) / 8, rng(-4000, 4000) / 8
    end
    local function add(kind)
      serial = serial + 1
      local x, y = place()
      local size = rng(0, 6) == 0 and 0 or rng(4, 160) / 8
      local thing = {x = x, y = y, width = size, height = rng(0, 6) == 0 and 0 or rng(4, 160) / 8,
        serial = serial, kind = kind, fx = x, fy = y}
      if kind == "actor" then
        if rng(1, 3) > 1 then thing.filter = filter end
        world:add_actor(thing)
      else
        world:add_sensor(thing)
      end
      things[#things + 1] = thing
    end
    for _ = 1, 40 do add("actor") end
    for _ = 1, 30 do add("sensor") end
    local out, frames, reported = {}, scale(240), 0
    local period = math.floor(frames / 6)
    local seen = {began = 0, ended = 0, both = 0, pairs = 0, sensors = 0}
    for frame = 1, frames do
      -- six phases or more, each a layout, and each a crowd (more actors than sensors:
      -- all are swept together) or a few actors among many sensors (the sensors that stay
      -- put are found through the hash)
      local phase = math.floor((frame - 1) / period)
      layout = ({"wide", "tall", "pile", "square"})[phase % 4 + 1]
      local reshuffle = (frame - 1) % period == 0
      local crowd = phase % 2 == 0
      local count = {actor = 0, sensor = 0}
      for i = #things, 1, -1 do -- a few taken out; at a sparse phase's start, most actors
        local kind = things[i].kind
        local cut = reshuffle and not crowd and kind == "actor" and count.actor >= 5
        if cut or rng(1, 60) == 1 then
          world:remove(things[i])
          table.remove(things, i)
        else
          count[kind] = count[kind] + 1
        end
      end
      if rng(1, 3) == 1 then add(rng(1, 2) == 1 and "actor" or "sensor") end
      if reshuffle then
        for _ = count.actor + 1, crowd and 40 or 0 do add("actor") end
        for _ = count.sensor + 1, crowd and 0 or 60 do add("sensor") end
      end
      for _, thing in ipairs(things) do
        if thing.kind == "actor" then
          if reshuffle or rng(1, 20) == 1 then -- a teleport: its frame starts there
            thing.x, thing.y = place()
            world:update(thing)
            thing.fx, thing.fy = thing.x, thing.y
          end
          world:move(thing, rng(-96, 96) / 8, rng(-96, 96) / 8)
        elseif reshuffle or rng(1, 4) == 1 then -- a sensor moved: its frame sweeps there
          if reshuffle then thing.x, thing.y = place()
          else thing.x, thing.y = thing.x + rng(-64, 64) / 8, thing.y + rng(-64, 64) / 8 end
          if rng(1, 5) == 1 then thing.width = rng(0, 160) / 8 end
          world:update(thing)
        end
      end
      local expected = {}
      for i = 1, #things do
        for j = i + 1, #things do
          local a, b = things[i], things[j]
          if a.kind == "sensor" and b.kind == "actor" then a, b = b, a end
          local t, began, ended = oracle_contact(a.fx, a.fy, a.x, a.y, a.width, a.height,
            b.fx, b.fy, b.x, b.y, b.width, b.height)
          local item, other
          if t == nil or a.kind == "sensor" then -- (two sensors are never a pair)
            item = nil
          elseif b.kind == "sensor" then
            if a.filter == nil or a.filter(a, b) then item, other = a, b end
          elseif a.filter and a.filter(a, b) == "cross" then
            item, other = a, b
          elseif b.filter and b.filter(b, a) == "cross" then
            item, other = b, a
          end
          if item then
            expected[#expected + 1] = {item = item, other = other, t = t, began = began,
              ended = ended}
          end
        end
      end
      local _, n = world:contacts(out)
      assert.are.equal(#expected, n, "frame " .. frame)
      local index = {}
      for k = 1, n do
        local record = out[k]
        index[record.item.serial * 100000 + record.other.serial] = record
        if k > 1 then -- sorted by t, then the order item and other were added
          local before = out[k - 1]
          assert.is_true(before.t < record.t or before.t == record.t
            and (before.item.serial < record.item.serial or before.item.serial
            == record.item.serial and before.other.serial < record.other.serial))
        end
      end
      for _, want in ipairs(expected) do
        local record = index[want.item.serial * 100000 + want.other.serial]
        assert(record, ("frame %d: %d meets %d, not reported"):format(frame, want.item.serial,
          want.other.serial))
        assert.are.same({want.began, want.ended}, {record.began, record.ended})
        assert.is_true(math.abs(record.t - want.t) <= 1e-9)
        if want.began and want.ended then seen.both = seen.both + 1
        elseif want.began then seen.began = seen.began + 1
        elseif want.ended then seen.ended = seen.ended + 1 end
        if want.other.kind == "sensor" then seen.sensors = seen.sensors + 1
        else seen.pairs = seen.pairs + 1 end
      end
      reported = reported + n
      for _, thing in ipairs(things) do thing.fx, thing.fy = thing.x, thing.y end
    end
    -- every kind of contact came up, many times
    for _, key in ipairs({"began", "ended", "both", "pairs", "sensors"}) do
      assert.is_true(seen[key] > frames / 10, key .. ": " .. seen[key])
    end
    assert.is_true(reported > frames * 3, "reported " .. reported)
  end)

  it("cost what the actors near things need, not the square of what is in the world "
    .. "(virtual machine instructions, counted by a debug hook)", function()
    -- Each case builds a world of `size` things and counts the instructions of its third
    -- world:contacts call (the first two settle the orders and the axis); four times the
    -- things must cost less than `most` times as much. Measured on 2026-12-06, 400 -> 1600
    -- things, in hundreds of instructions on Lua 5.4: 288 -> 288, 1070 -> 4270, 450 ->
    -- 1787, 895 -> 3908; before that day's change, which made them linear, each was
    -- quadratic: 648 -> 5384, 1649 -> 21589, 88502 -> 1414002, 1004 -> 13088 (contacts
    -- pruned along x alone, walked every pair of sensors and of actors without filters,
    -- and sorted by insertion alone).
    local function contacts_cost(build)
      local world, frame = build()
      world:contacts()
      frame()
      world:contacts()
      frame()
      return instructions(function() world:contacts() end)
    end
    local cases = {
      {"coins up a tall level, few actors", 2, function(size)
        local world = budge.new_world()
        for i = 0, size - 1 do
          world:add_sensor(box((i % 20) * 16 + 5, math.floor(i / 20) * 16 + 5, 6, 6))
        end
        local actors = {}
        for i = 1, 20 do actors[i] = world:add_actor(box((i % 20) * 16 + 2, i * 12, 12, 12)) end
        return world, function() for i = 1, #actors do world:move(actors[i], 0, 3) end end
      end},
      {"a crowd up a tall level, a filter on each", 6, function(size)
        local world = budge.new_world()
        local actors = {}
        for i = 0, size - 1 do
          local actor = world:add_actor(box((i % 4) * 20, i * 16, 12, 12))
          actor.filter = always("cross")
          actors[#actors + 1] = actor
        end
        return world, function() for i = 1, #actors do world:move(actors[i], 1, 0) end end
      end},
      {"actors without filters piled up", 6, function(size)
        local world = budge.new_world()
        for i = 1, size do world:add_actor(box(100 + i % 3, 100 + i % 5, 12, 12)) end
        return world, function() end
      end},
      {"a tenth of the actors replaced each frame, anywhere", 6, function(size)
        local world = budge.new_world()
        local rng = random_source.new(5)
        local actors, next = {}, 0
        for i = 1, size do
          actors[i] = world:add_actor(box(rng(0, 64000) / 16, rng(0, 64000) / 16, 4, 4))
        end
        return world, function()
          for _ = 1, size / 10 do
            next = next % size + 1
            world:remove(actors[next])
            actors[next] = world:add_actor(box(rng(0, 64000) / 16, rng(0, 64000) / 16, 4, 4))
          end
        end
      end},
    }
    for _, case in ipairs(cases) do
      local name, most, build = case[1], case[2], case[3]
      local small = contacts_cost(function() return build(400) end)
      local large = contacts_cost(function() return build(1600) end)
      assert.is_true(large < most * small, ("%s: %d -> %d instructions (x100)"):format(name,
        small, large))
    end
  end)

  -- A filtered move meets what its path meets nearest first, then in the order added; it
  -- sorted them by insertion alone until 2026-12-07, k^2 through a pile of k actors its
  -- filter passes over. Interpreter instructions of four moves through 64 and 1024 8x8
  -- actors piled on a 48x48 spot, in hundreds, Lua 5.4: ignored 221 -> 14667 (66x) by
  -- insertion, 224 -> 4668 (21x) now; crossed 348 -> 18603 (53x), 352 -> 8605 (24x).
  it("ask a filter about a pile of actors nearest first, then in the order added, at "
    .. "about k log k (virtual machine instructions, counted by a debug hook)", function()
    local function pile(count, answer)
      local world = budge.new_world()
      local rng = random_source.new(20261207)
      local actors = {}
      for i = 1, count do actors[i] = world:add_actor(box(100 + rng(0, 40), 100 + rng(0, 40), 8, 8)) end
      local asked = {}
      local mover = world:add_actor(box(60, 110, 8, 8))
      mover.filter = function(_, other)
        asked[#asked + 1] = other
        return answer
      end
      return world, mover, actors, asked
    end
    -- the order asked, against the pile sorted by where the path meets each (its left
    -- side: all lie ahead), then the order added; those whose rows overlap the mover's
    local world, mover, actors, asked = pile(300, "cross")
    local _, _, n = world:move(mover, 80, 0)
    local expected = {}
    for i, actor in ipairs(actors) do
      if actor.y < 118 and actor.y + 8 > 110 then expected[#expected + 1] = {actor, i} end
    end
    table.sort(expected, function(a, b)
      if a[1].x ~= b[1].x then return a[1].x < b[1].x end
      return a[2] < b[2]
    end)
    for i = 1, #expected do expected[i] = expected[i][1] end
    assert.are.equal(113, #expected)
    assert.are.equal(#expected, n)
    assert.are.equal(#expected, #asked)
    for i = 1, #expected do -- (the same actors, not equal copies: several share a box)
      assert.is_true(rawequal(expected[i], asked[i]), "asked out of order at " .. i)
    end
    local function cost(count, answer)
      local pile_world, pile_mover, _, pile_asked = pile(count, answer)
      local function step() pile_world:move(pile_mover, pile_mover.x < 100 and 80 or -80, 0) end
      for _ = 1, 4 do step() end
      return instructions(function() for _ = 1, 4 do step() end end), #pile_asked
    end
    for _, answer in ipairs({false, "cross"}) do
      local few = cost(64, answer)
      local many, calls = cost(1024, answer)
      assert.are.equal(8 * 367, calls) -- (367 of the 1024 in the mover's rows, each move)
      assert.is_true(many < 40 * few, ("%s: 64 -> 1024 actors, %d -> %d instructions (x100)")
        :format(tostring(answer), few, many))
    end
  end)

  it("report an actor in water once as began, once as ended, never began while inside", function()
    local world = budge.new_world()
    local water = world:add_sensor(box(100, 0, 50, 50))
    local swimmer = world:add_actor(box(0, 10, 10, 10))
    local began, ended, frames_inside = 0, 0, 0
    local out = {}
    for _ = 1, 100 do
      world:move(swimmer, 3, 0)
      local _, n = world:contacts(out)
      for i = 1, n do
        assert.are.same({swimmer, water}, {out[i].item, out[i].other})
        if out[i].began then began = began + 1 end
        if out[i].ended then ended = ended + 1 end
        if not out[i].began and not out[i].ended then frames_inside = frames_inside + 1 end
      end
    end
    assert.are.same({1, 1}, {began, ended})
    assert.are.equal(math.floor((150 - 1) / 3) - math.floor(90 / 3) - 1, frames_inside)
  end)

  it("come sorted by t, then by the order added; a teleport starts its frame where it lands", function()
    local world = budge.new_world()
    local late = world:add_sensor(box(50, 0, 10, 10))
    local early = world:add_sensor(box(20, 0, 10, 10))
    local also = world:add_sensor(box(20, 20, 10, 10))
    local runner = world:add_actor(box(0, 0, 10, 30))
    world:move(runner, 100, 0)
    local out, n = world:contacts({})
    assert.are.equal(3, n)
    assert.are.same({early, also, late}, {out[1].other, out[2].other, out[3].other})
    assert.are.same({0.1, 0.1, 0.4}, {out[1].t, out[2].t, out[3].t})
    runner.x = 0
    world:update(runner) -- teleported back: this frame starts at x = 0
    out, n = world:contacts(out)
    assert.are.equal(0, n)
    assert.are.equal(nil, out[1])
  end)

  it("take a pair when either actor's filter crosses the other; refuse a bad out", function()
    local world = budge.new_world()
    local a = world:add_actor(box(0, 0, 10, 10))
    local b = world:add_actor(box(5, 0, 10, 10))
    assert.are.equal(0, select(2, world:contacts()))
    b.filter = function() return "cross" end
    local out, n = world:contacts()
    assert.are.same({1, b, a}, {n, out[1].item, out[1].other})
    a.filter = function() return "cross" end
    out = world:contacts()
    assert.are.same({a, b}, {out[1].item, out[1].other}) -- both: the one added first
    local ok, message = pcall(world.contacts, world, "list")
    assert.is_false(ok)
    assert.truthy(message:find('out must be a table or nil, got "list"', 1, true), message)
  end)
end)

describe("check", function()
  it("interleaved anywhere in a random script leaves every trace bit-identical", function()
    local function script(with_checks)
      local rng = random_source.new(99)
      local world = budge.new_world({cell_size = 32})
      local grid = {}
      for r = 1, 20 do
        grid[r] = {}
        for c = 1, 20 do grid[r][c] = (r == 1 or r == 20 or c == 1 or c == 20 or rng(1, 8) == 1) and 1 or 0 end
      end
      world:add_tiles(grid, 16, 16)
      local coin = world:add_sensor(box(100, 100, 8, 8))
      local actors = {}
      for i = 1, 8 do
        actors[i] = world:add_actor(box(20 + i * 30, 40, 10, 10))
        if i % 2 == 0 then
          actors[i].filter = function(_, other) return other == coin and "cross" or "slide" end
        end
      end
      local lines = {}
      for step = 1, 4000 do
        local actor = actors[rng(1, #actors)]
        local dx, dy = rng(-64, 64) / 4, rng(-64, 64) / 4
        local method = rng(1, 4) == 1 and "swept" or "axis_sweep"
        if with_checks and step % 3 == 0 then
          local probe = actors[(step % #actors) + 1]
          world:check(probe, dy, dx, method)
        end
        lines[#lines + 1] = trace(world:move(actor, dx, dy, method))
        if with_checks and step % 5 == 0 then world:check(actor, -dx, -dy) end
        if step % 10 == 0 then lines[#lines + 1] = tostring(select(2, world:contacts())) end
      end
      return table.concat(lines, "\n")
    end
    assert.are.equal(script(false), script(true))
  end)

  it("returns what move would, and keeps the last move's hits valid", function()
    local world = budge.new_world()
    local wall = world:add_solid(box(30, 0, 10, 20))
    local floor = world:add_solid(box(0, 20, 100, 10))
    local actor = world:add_actor(box(0, 0, 10, 10))
    local _, _, n, hits = world:move(actor, 5, 15)
    assert.are.same({1, floor, "floor"}, {n, hits[1].other, hits[1].side})
    local x, y, cn, chits = world:check(actor, 50, 0)
    assert.are.same({20, 10, 1, wall, "right"}, {x, y, cn, chits[1].other, chits[1].side})
    assert.are.same({5, 10}, {actor.x, actor.y})
    assert.are.same({floor, "floor"}, {hits[1].other, hits[1].side}) -- still the move's
    assert.are.same({20, 10}, xy(world:move(actor, 50, 0)))
  end)
end)

describe("query_sweep", function()
  it("equals a brute-force oracle on " .. scale(10000) .. " random cases, including tiles", function()
    local world = budge.new_world({cell_size = 32})
    local rng = random_source.new(5)
    local grid = {}
    for r = 1, 16 do
      grid[r] = {}
      for c = 1, 16 do grid[r][c] = rng(1, 6) == 1 and 1 or 0 end
    end
    local tiles = world:add_tiles(grid, 16, 16, {x = 40, y = 40})
    local items = {}
    for i = 1, 12 do items[i] = world:add_solid(box(rng(0, 300), rng(0, 300), rng(1, 40), rng(1, 40))) end
    for i = 13, 18 do items[i] = world:add_sensor(box(rng(0, 300), rng(0, 300), rng(1, 20), rng(1, 20))) end
    for i = 19, 24 do items[i] = world:add_actor(box(rng(0, 300), rng(0, 300), rng(1, 20), rng(1, 20))) end
    local function enter(x, y, w, h, dx, dy, bx, by, bw, bh)
      return oracle_contact(x, y, x + dx, y + dy, w, h, bx, by, bx, by, bw, bh)
    end
    local out, out_t = {}, {}
    for _ = 1, scale(10000) do
      local x, y = rng(-200, 1400) / 4, rng(-200, 1400) / 4
      local w, h = rng(0, 24), rng(0, 24)
      if w == 0 then h = 0 end
      local dx, dy = rng(-800, 800) / 4, rng(-800, 800) / 4
      local expected = {}
      for i = 1, #items do
        local item = items[i]
        local t = w > 0 and enter(x, y, w, h, dx, dy, item.x, item.y, item.width, item.height)
        if w == 0 then -- a segment: the point inside the open box at some moment
          t = enter(x, y, 1e-300, 1e-300, dx, dy, item.x, item.y, item.width, item.height)
        end
        if t then expected[#expected + 1] = {item, t, i} end
      end
      local first
      for r = 1, 16 do
        for c = 1, 16 do
          if grid[r][c] == 1 then
            local t = enter(x, y, w > 0 and w or 1e-300, w > 0 and h or 1e-300, dx, dy,
              40 + (c - 1) * 16, 40 + (r - 1) * 16, 16, 16)
            if t and (first == nil or t < first) then first = t end
          end
        end
      end
      if first then expected[#expected + 1] = {tiles, first, 0} end -- (added first)
      table.sort(expected, function(a, b)
        if a[2] ~= b[2] then return a[2] < b[2] end
        return a[3] < b[3]
      end)
      local _, n = world:query_sweep(x, y, w, h, dx, dy, out, out_t)
      local label = string.format("query_sweep(%.17g, %.17g, %g, %g, %.17g, %.17g)", x, y, w, h,
        dx, dy)
      assert(#expected == n, label .. " found " .. n .. ", the oracle " .. #expected)
      for i = 1, n do
        assert(expected[i][1] == out[i], label .. ": item " .. i)
        assert(math.abs(expected[i][2] - out_t[i]) <= 1e-9, label .. ": t " .. i)
      end
    end
  end)

  it("lists a box or a tile layer exactly when the box where the sweep ends overlaps it, at "
    .. "the roundings of a face", function()
    -- A sweep aimed within a few ulps of a box's near face (non-dyadic values: the entry
    -- time, from x + w, and the far side where it ends, (x + dx) + w, round apart) lists
    -- the box exactly when query_rect finds it overlapping the box where the sweep ends
    -- (it cannot pass through it: the sweep ends at its face). Before, with a solid box
    -- in every case, 35 of 4000 disagreed (8 boxes overlapped by an ulp left out, 27 only
    -- touched at the end listed); with a one-tile layer (its tile's far side the layer's
    -- edge), 145 of 4000 (overlapped by an ulp, left out).
    local rng = random_source.new(20261206)
    local aim = require("fixtures.aim")
    local out, listed = {}, 0
    for case = 1, 4000 do
      local is_x, forward = case % 2 == 0, rng(1, 2) == 1
      local size, delta = aim.size_and_delta(rng, forward)
      local depth, face = rng(1000, 40000) / 997, rng(-1000000, 1000000) / 997
      local world = budge.new_world({cell_size = 64})
      local thing
      if case % 4 < 2 then
        thing = world:add_solid(is_x and box(face, 0, depth, 10) or box(0, face, 10, depth))
      elseif is_x then thing = world:add_tiles({{1}}, depth, 16, {x = face, y = -3})
      else thing = world:add_tiles({{1}}, 16, depth, {x = -3, y = face}) end
      local pos = aim.start(rng, forward, size, delta, face, face + depth)
      local across = aim.across(rng)
      local x, y = is_x and pos or -across, is_x and -across or pos
      local w, h = is_x and size or 10, is_x and 10 or size
      local dx, dy = is_x and delta or across, is_x and across or delta
      local _, at_start = world:query_rect(x, y, w, h, out)
      if at_start == 0 then
        local _, at_end = world:query_rect(x + dx, y + dy, w, h, out)
        local _, n = world:query_sweep(x, y, w, h, dx, dy, out)
        assert.are.equal(at_end, n, ("case %d: %.17g, %.17g by %.17g, %.17g"):format(case, x, y,
          dx, dy))
        if n == 1 then assert.are.equal(thing, out[1]) end
        listed = listed + n
      end
    end
    assert.is_true(listed > 1000, "listed " .. listed)
  end)

  it("lists a box a point sweep ends inside by an ulp (a review's case)", function()
    local world = budge.new_world({cell_size = 64})
    local actor = world:add_actor(box(-17.571428571428573, 96, 25.213640922768306, 42))
    local x, y, dx, dy = -91.666666666666671, -35.799999999999997, 74.095238095238102,
      167.37142857142857
    assert.is_true(actor.x < x + dx) -- (the end point, an ulp inside it)
    assert.are.equal(1, select(2, world:query_point(x + dx, y + dy)))
    local out, n, out_t = world:query_sweep(x, y, 0, 0, dx, dy, {}, {})
    assert.are.same({1, actor}, {n, out[1]})
    assert.is_true(out_t[1] < 1)
    assert.are.equal(1, select(2, world:query_segment(x, y, x + dx, y + dy)))
  end)

  it("takes a filter, which may leave the probing actor out", function()
    local world = budge.new_world()
    local me = world:add_actor(box(0, 0, 10, 10))
    local wall = world:add_solid(box(40, 0, 10, 10))
    local out, n, out_t = world:query_sweep(0, 0, 10, 10, 100, 0, {}, {},
      function(item) return item ~= me end)
    assert.are.same({1, wall, 0.3}, {n, out[1], out_t[1]})
    out, n = world:query_rect(0, 0, 100, 10, out, function(item) return item == me end)
    assert.are.same({1, me}, {n, out[1]})
    local ok, message = pcall(world.query_point, world, 1, 1, out, function() world:add_solid(box(0, 0, 1, 1)) end)
    assert.is_false(ok)
    assert.truthy(message:find("world:add_solid was called from inside a query's filter", 1, true), message)
    assert.are.same({1, 1, 0, 0}, {world:count()})
  end)
end)

describe("a ball bouncing in a closed box", function()
  it("never leaves it in 10^5 frames, and with dyadic speeds every reflection is exact", function()
    local world = budge.new_world()
    world:add_solid(box(-16, -16, 288, 16))
    world:add_solid(box(-16, 256, 288, 16))
    world:add_solid(box(-16, 0, 16, 256))
    world:add_solid(box(256, 0, 16, 256))
    local ball = world:add_actor(box(100, 60, 8, 8))
    ball.filter = always("bounce")
    local vx, vy = 13.375, -7.625
    local ox, oy, ovx, ovy = 100, 60, vx, vy -- the oracle: each axis reflected in [0, 248]
    local function reflect(p, v)
      local q = p + v
      if q < 0 then return -q, -v elseif q > 248 then return 496 - q, -v end
      return q, v
    end
    local bounces = 0
    for frame = 1, 100000 do
      local _, _, n, hits = world:move(ball, vx, vy)
      for i = 1, n do
        if hits[i].nx ~= 0 then vx = hits[i].nx * math.abs(vx); bounces = bounces + 1 end
        if hits[i].ny ~= 0 then vy = hits[i].ny * math.abs(vy); bounces = bounces + 1 end
      end
      ox, ovx = reflect(ox, ovx)
      oy, ovy = reflect(oy, ovy)
      if ball.x ~= ox or ball.y ~= oy or vx ~= ovx or vy ~= ovy then
        error(("frame %d: ball at %.17g,%.17g moving %g,%g; reflected exactly: %.17g,%.17g")
          :format(frame, ball.x, ball.y, vx, vy, ox, oy))
      end
      assert(ball.x >= 0 and ball.x <= 248 and ball.y >= 0 and ball.y <= 248)
    end
    assert.is_true(bounces > 8000, "bounces " .. bounces)
  end)
end)

describe("what a hostile review found", function()
  it("a sensor the actor is inside is reported when the move is blocked at once", function()
    for _, filter in ipairs({false, true}) do
      local world = budge.new_world()
      local water = world:add_sensor(box(0, 0, 100, 100))
      local wall = world:add_solid(box(10, 0, 10, 100))
      local swimmer = world:add_actor(box(0, 10, 10, 10))
      if filter then swimmer.filter = always("slide") end
      local x, _, n, hits = world:move(swimmer, 5, 0)
      assert.are.same({0, 2, water, nil, 0, wall, "right"}, {x, n, hits[1].other, hits[1].side,
        hits[1].t, hits[2].other, hits[2].side})
    end
  end)

  it("a sensor crossed along y after a blocked x has the y phase's t, filter or not", function()
    for _, filter in ipairs({false, true}) do
      local world = budge.new_world()
      world:add_solid(box(-10, -50, 10, 200))
      local coin = world:add_sensor(box(0, 50, 10, 10))
      local actor = world:add_actor(box(0, 0, 10, 10))
      if filter then actor.filter = always("slide") end
      local _, y, n, hits = world:move(actor, -90, 100)
      assert.are.same({100, 2, coin, "floor"}, {y, n, hits[2].other, hits[2].side})
      assert.is_true(math.abs(hits[2].t - (90 + 40) / 190) < 1e-15, hits[2].t)
    end
  end)

  it("an actor with a filter never blocks a push of another", function()
    for _, filter in ipairs({false, true}) do
      local world = budge.new_world()
      local pusher = world:add_solid(box(0, 0, 10, 10))
      local pushed = world:add_actor(box(10, 0, 10, 10))
      world:add_actor(box(25, 0, 10, 10)) -- in the way
      if filter then pushed.filter = always("slide") end
      local n = world:move_solid(pusher, 20, 0)
      assert.are.same({0, 30}, {n, pushed.x})
    end
  end)

  it("bounce inside a solid stops after bouncing in place both ways", function()
    local world = budge.new_world()
    world:add_solid(box(4, 0, 2, 10))
    local actor = world:add_actor(box(0, 0, 10, 10))
    actor.filter = always("bounce")
    local x, _, n, hits = world:move(actor, 5, 0)
    assert.are.same({0, 2, "right", "left"}, {x, n, hits[1].side, hits[2].side})
  end)

  it("two extents of 0 on the axis never cross", function()
    local world = budge.new_world()
    world:add_sensor(box(10, 0, 0, 20))
    local actor = world:add_actor(box(0, 5, 0, 5))
    assert.are.equal(0, select(3, world:move(actor, 20, 0)))
    actor.x = 0
    world:update(actor)
    assert.are.equal(0, select(3, world:move(actor, 20, 0, "swept")))
  end)

  it("a sensor moved by update sweeps its frame: a moving hazard never tunnels", function()
    local world = budge.new_world()
    local saw = world:add_sensor(box(0, 0, 10, 10))
    local player = world:add_actor(box(50, 0, 10, 10))
    world:contacts()
    saw.x = 100
    world:update(saw)
    local out, n = world:contacts()
    assert.are.same({1, player, saw, 0.4}, {n, out[1].item, out[1].other, out[1].t})
  end)
end)

describe("garbage", function()
  it("allocates nothing for filtered moves, sensors, contacts, checks and swept queries", function()
    local world = budge.new_world()
    local grid = {}
    for row = 1, 30 do
      grid[row] = {}
      for col = 1, 30 do grid[row][col] = (row == 1 or row == 30 or col == 1 or col == 30) and 1 or 0 end
    end
    world:add_tiles(grid, 16, 16)
    for i = 1, 20 do world:add_sensor(box(40 + (i * 37) % 400, 40 + (i * 53) % 400, 8, 8)) end
    local actors = {}
    local function filter(_, other) return other.bullet and "cross" or "bounce" end
    for i = 1, 30 do
      local actor = world:add_actor(box(40 + i * 13, 40 + i * 11, 10, 10))
      if i % 3 == 0 then actor.filter = filter end
      if i % 5 == 0 then actor.bullet = true end
      actors[i] = actor
    end
    local out, out_t = {}, {}
    local function keep(item) return item.bullet == nil end
    local function frame(f)
      for i = 1, #actors do
        world:move(actors[i], ((i + f) % 17) - 8, ((i * 3 + f) % 17) - 8, i % 7 == 0 and "swept" or nil)
      end
      world:check(actors[1], 40, 40)
      world:query_sweep(30, 30, 10, 10, 300, 200, out, out_t, keep)
      world:contacts(out)
    end
    local function reset()
      for i = 1, #actors do actors[i].x, actors[i].y = 40 + i * 13, 40 + i * 11; world:update(actors[i]) end
    end
    local bytes = garbage.measure(frame, 200, {jit_off = true, reset = reset,
      warm = function() for _ = 1, 3 do reset(); for f = 1, 200 do frame(f) end end end})
    assert.equal(0, bytes)
  end)
end)

describe("frame contacts' broad phase", function()
  it("meets no more what a filter removed earlier in the call, as a move does", function()
    -- two players on one coin: the first asked collects it (removes it); the second does
    -- not get it too. The same with the coin found through the hash (5 sensors to an actor)
    for _, extra in ipairs({0, 12}) do
      local world = budge.new_world()
      local coin = world:add_sensor(box(20, 0, 6, 6))
      for i = 1, extra do world:add_sensor(box(5000 + 20 * i, 5000, 2, 2)) end
      local asked, collecting = 0, false
      local function collect(_, other) -- (during world:contacts: the moves ask it too)
        if other == coin and collecting then
          asked = asked + 1
          if world:has(coin) then world:remove(coin) end
        end
        return other == coin and "cross" or nil
      end
      local one = world:add_actor(box(0, 0, 10, 10))
      local two = world:add_actor(box(40, 0, 10, 10))
      one.filter, two.filter = collect, collect
      world:contacts()
      world:move(one, 16, 0)
      world:move(two, -16, 0)
      collecting = true
      local out, n = world:contacts()
      assert.are.same({1, 1}, {n, asked}, "with " .. extra .. " more sensors")
      assert.are.equal(coin, out[1].other)
      assert.is_false(world:has(coin))
    end
  end)

  it("reports no actor that ends only touching a sensor, swept with it or found in the "
    .. "hash", function()
    -- The frame's times are rounded: an actor whose right side ends exactly on a sensor's
    -- left side can come out entering it an ulp before the frame's end. The swept boxes'
    -- test comes first in both ways (a review's case: reported through the hash alone).
    local function contacts_of(extra, x, dx, width)
      local world = budge.new_world()
      local actor = world:add_actor(box(x, 0, width, 10))
      local sensor = world:add_sensor(box(x + dx + width, 0, 10, 10))
      for i = 1, extra do world:add_sensor(box(5000 + 20 * i, 5000, 1, 1)) end
      world:contacts()
      world:move(actor, dx, 0)
      return select(2, world:contacts()), actor.x + actor.width == sensor.x
    end
    assert.are.same({0, true}, {contacts_of(4, -47.186, 19.927783350050152, 20.385714285714286)})
    local rng = random_source.new(12345)
    local touching = 0
    for _ = 1, scale(4000) do
      local x, dx, width = rng(-50000, 50000) / 1000, rng(0, 100000) / 997, rng(1, 1000) / 7
      local swept_n, touch = contacts_of(0, x, dx, width)
      if touch then
        touching = touching + 1
        assert.are.same({0, 0}, {swept_n, (contacts_of(4, x, dx, width))})
      end
    end
    assert.is_true(touching > scale(4000) / 2, "touching " .. touching)
  end)

  it("grows no record of a thing added since the last call (their fields are made at "
    .. "the add)", function()
    local world = budge.new_world()
    local out = {}
    world:contacts(out)
    for i = 1, 1000 do
      world:add_actor(box(i * 20, 0, 4, 4))
      world:add_sensor(box(i * 20, 40, 4, 4))
    end
    collectgarbage("collect")
    collectgarbage("stop")
    local before = collectgarbage("count")
    world:contacts(out)
    local bytes = (collectgarbage("count") - before) * 1024
    collectgarbage("restart")
    -- (what is left: the world's frame orders growing to 2000 entries, once; with the
    -- fields made at the first call, 610 bytes a thing)
    assert.is_true(bytes < 64 * 1000, ("%.0f bytes for 1000 actors and 1000 sensors"):format(bytes))
  end)

  it("allocates nothing with sensors found through the hash, sensors moved, the axis "
    .. "turning and every actor teleported", function()
    local world = budge.new_world({cell_size = 32})
    local sensors, actors = {}, {}
    for i = 1, 300 do sensors[i] = world:add_sensor(box((i * 37) % 600, (i * 53) % 600, 8, 8)) end
    local function filter(_, other) return other.bullet and "cross" or nil end
    for i = 1, 40 do
      local actor = world:add_actor(box(i * 13, i * 11, 10, 10))
      if i % 2 == 0 then actor.filter = filter end
      if i % 3 == 0 then actor.bullet = true end
      actors[i] = actor
    end
    local out = {}
    local function frame(f)
      local tall = f % 40 < 20 -- (a column, then a row: the prune axis turns)
      for i = 1, #actors do
        local actor = actors[i]
        if f % 10 == 0 then -- everyone teleported: the order is sorted again by merging
          actor.x, actor.y = tall and (i * 7) % 30 or (i * 97) % 2000,
            tall and (i * 97) % 2000 or (i * 7) % 30
          world:update(actor)
        end
        world:move(actor, ((i + f) % 17) - 8, ((i * 3 + f) % 17) - 8)
      end
      for i = 1, 12 do -- a few sensors moved (swept apart from the others)
        local sensor = sensors[(f * 7 + i * 13) % #sensors + 1]
        sensor.x = sensor.x + ((f + i) % 2 == 0 and 3 or -3)
        world:update(sensor)
      end
      world:contacts(out)
    end
    local function reset() -- (the sensors too: drifting, they would enter new hash cells)
      for i = 1, #actors do actors[i].x, actors[i].y = i * 13, i * 11; world:update(actors[i]) end
      for i = 1, #sensors do
        sensors[i].x, sensors[i].y = (i * 37) % 600, (i * 53) % 600
        world:update(sensors[i])
      end
    end
    local found = 0
    for f = 1, 40 do frame(f); found = found + #out end
    assert.is_true(found > 40, "found " .. found)
    local bytes = garbage.measure(frame, 200, {jit_off = true, reset = reset,
      warm = function() for _ = 1, 3 do reset(); for f = 1, 200 do frame(f) end end end})
    assert.equal(0, bytes)
  end)
end)

describe("frame contacts' moved sensors", function()
  it("are not kept once removed, in a game that never calls world:contacts", function()
    -- world:update puts a moved sensor on a list that world:contacts empties; a game that
    -- never calls it, and adds, moves and removes sensors (bullets), must not grow it
    local world = budge.new_world()
    local keep = world:add_sensor(box(0, 0, 4, 4)) -- one that stays, moved every frame
    for frame = 1, 2000 do
      local shot = world:add_sensor(box(frame, 0, 2, 2))
      shot.x = shot.x + 5
      world:update(shot)
      keep.x = frame % 7
      world:update(keep)
      world:remove(shot)
    end
    local moved = world._moved_sensors -- (white box: the list itself)
    assert.is_true(#moved <= 4, "moved list of " .. #moved)
    assert.are.equal(keep, moved[1].item)
    -- and contacts still sweeps the one that stayed from where it began
    local runner = world:add_actor(box(-20, 0, 10, 4))
    world:move(runner, 30, 0)
    local out, n = world:contacts()
    assert.are.same({1, runner, keep}, {n, out[1] and out[1].item, out[1] and out[1].other})
  end)
end)

describe("what the packed solid cells and the sensor pre-check must not change", function()
  it("a solid's new wall_type (world:update) is what the next move meets", function()
    for _, count in ipairs({1, 20}) do -- (a hash of a few solids is scanned whole)
      local world = budge.new_world({cell_size = 16})
      for i = 1, count - 1 do world:add_solid(box(1000 + i * 40, 1000, 8, 8)) end
      local ledge = world:add_solid(box(0, 20, 32, 4))
      local actor = world:add_actor(box(4, 0, 8, 8))
      local ys = {}
      local _, y = world:move(actor, 0, 30) -- a wall: stops on it
      ys[1] = y
      ledge.wall_type = "oneway"
      world:update(ledge)
      actor.y = 24 -- under it now: up through a oneway, down onto it
      world:update(actor)
      _, y = world:move(actor, 0, -30)
      ys[2] = y
      _, y = world:move(actor, 0, 30)
      ys[3] = y
      ledge.wall_type = nil
      world:update(ledge)
      actor.y = 30
      world:update(actor)
      _, y = world:move(actor, 0, -30)
      ys[4] = y
      assert.are.same({12, -6, 12, 24}, ys)
    end
  end)

  it("a sensor more than 4096 cells wide is crossed by every kind of move", function()
    for _, method in ipairs({"axis_sweep", "swept", "wall_type"}) do
      for _, filtered in ipairs({false, true}) do
        local world = budge.new_world({cell_size = 16})
        local field = world:add_sensor(box(-2000, -2000, 4000, 4000))
        field.name = "field"
        local actor = world:add_actor(box(100, 100, 8, 8))
        if filtered then actor.filter = always("slide") end
        local _, _, n, hits = world:move(actor, 3, 0, method)
        assert.are.equal(1, n)
        assert.are.equal(field, hits[1].other)
        assert.are.equal("cross", hits[1].response)
      end
    end
  end)
end)
