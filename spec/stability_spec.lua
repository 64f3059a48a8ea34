-- Where each method fails, in the world: the envelopes pinned at their edges, and the
-- whole scenario catalogue (fixtures/scenarios.lua) replayed with its failures counted.
-- The counts are pinned: a change in any method's behaviour moves them.
local scenarios = require("fixtures.scenarios")

local EDGE = 1 / 64

describe("stability: each discrete method's envelope in the world", function()
  -- The bounds the README documents under "Choosing a method", at S = 4, 12 and 32.
  for _, envelope in ipairs(scenarios.ENVELOPES) do
    for _, T in ipairs(scenarios.THICKNESS) do
      it(("%s from the %s, wall %d px: holds %s the bound, fails past it"):format(
        envelope.method, envelope.side, T, envelope.inclusive and "at" or "just inside"), function()
        for _, S in ipairs({4, 12, 32}) do
          local bound = envelope.bound(S, T)
          local inside = envelope.inclusive and bound or bound - EDGE
          local outside = envelope.inclusive and bound + EDGE or bound
          local label = ("S=%d T=%d speed %%s"):format(S, T)
          assert.is_true(scenarios.holds(envelope.method, envelope.side, envelope.typed, T, S,
            inside), label:format(inside))
          assert.is_false(scenarios.holds(envelope.method, envelope.side, envelope.typed, T, S,
            outside), label:format(outside))
        end
      end)
    end
  end

  it("the analytic bounds are the ones in the README", function()
    local S, T = 12, 16
    local by_method = {}
    for _, envelope in ipairs(scenarios.ENVELOPES) do by_method[envelope.method] = envelope end
    assert.are.equal(8, by_method.seed.bound(S, T))
    assert.are.equal(14, by_method.wall_type.bound(S, T))
    assert.are.equal(14, by_method.min_axis.bound(S, T))
    assert.are.equal(6, by_method.fat_cross.bound(S, T))
    assert.is_true(by_method.seed.inclusive and by_method.fat_cross.inclusive)
    assert.is_false(by_method.wall_type.inclusive or by_method.min_axis.inclusive)
  end)

  -- (the bounds above are for walls long across the move; a review's cases, as the README
  -- gives them: a 4x4 mover flush against the left face of a 64x16 block, mid-height)
  it("a block short across the move fails sooner: the fat cross's cap, min_axis's way out", function()
    local budge = require("budge")
    local function ends(method, speed)
      local world = budge.new_world()
      world:add_solid({x = 100, y = 0, width = 64, height = 16})
      local mover = world:add_actor({x = 96, y = 6, width = 4, height = 4})
      local x, y = world:move(mover, speed, 0, method)
      return {x, y}
    end
    assert.same({96, 6}, ends("fat_cross", 6)) -- 3/8 of 16
    assert.same({103, -4}, ends("fat_cross", 7)) -- lifted onto the top
    assert.same({96, 6}, ends("min_axis", 9))
    assert.same({106, -4}, ends("min_axis", 10)) -- 10 px out the top: a tie, y wins
  end)

  it("past S + T every discrete method tunnels", function()
    for _, envelope in ipairs(scenarios.ENVELOPES) do
      for _, speed in ipairs({28, 40, 512}) do
        assert.is_false(scenarios.holds(envelope.method, envelope.side, envelope.typed, 16, 12,
          speed), envelope.method .. " at " .. speed)
      end
    end
  end)
end)

-- Failures by kind over the whole catalogue (13233 cases per method), in KINDS order:
-- tunnelled, wrong side, residual overlap, snagged, teleported, jitter, order-dependent.
local PINNED = {
  seed = {passed = 6745, kinds = {4051, 512, 0, 153, 1717, 55, 0}},
  wall_type = {passed = 6771, kinds = {4108, 424, 0, 146, 1718, 66, 0}},
  fat_cross = {passed = 7009, kinds = {4166, 266, 449, 25, 1169, 149, 0}},
  min_axis = {passed = 7839, kinds = {4172, 424, 0, 278, 454, 66, 0}},
  axis_sweep = {passed = 13233, kinds = {0, 0, 0, 0, 0, 0, 0}},
  swept = {passed = 13233, kinds = {0, 0, 0, 0, 0, 0, 0}},
  auto = {passed = 13233, kinds = {0, 0, 0, 0, 0, 0, 0}},
}

local function failure_list(result)
  local lines = {}
  for i, failure in ipairs(result.failures) do lines[i] = scenarios.describe(failure) end
  return lines
end

describe("stability: the scenario catalogue", function()
  local results = {}
  local function result_of(method)
    results[method] = results[method] or scenarios.score(method, "full")
    return results[method]
  end

  it("has every scene the catalogue promises, each with cases", function()
    local names, counts = {}, {}
    for _, scene in ipairs(scenarios.SCENES) do names[#names + 1] = scene.name end
    assert.are.same({"thin wall, each side", "horizontal wall hit from the side",
      "vertical wall landed on", "block side hit", "seams", "corners", "resting", "squeezed",
      "order of solids", "oneway from below", "riding a moving platform"}, names)
    scenarios.each_case("full", function(scene) counts[scene.name] = (counts[scene.name] or 0) + 1 end)
    for _, name in ipairs(names) do assert.is_true((counts[name] or 0) > 0, name) end
    assert.are.equal(13233, result_of("swept").total)
  end)

  for _, method in ipairs({"axis_sweep", "swept", "auto"}) do
    it(method .. " gets every case right", function()
      local result = result_of(method)
      local first = result.failures[1]
      assert.are.equal(result.total, result.passed,
        first and scenarios.describe(first) or "no failure recorded")
    end)
  end

  for _, method in ipairs({"seed", "wall_type", "fat_cross", "min_axis"}) do
    it(method .. " fails the pinned cases, by kind", function()
      local result = result_of(method)
      local kinds = {}
      for i, kind in ipairs(scenarios.KINDS) do kinds[i] = result.by_kind[kind] end
      assert.are.same(PINNED[method].kinds, kinds)
      assert.are.equal(PINNED[method].passed, result.passed)
    end)
  end

  it("the discrete methods fail where the article says they do", function()
    -- each discrete method has at least one tunnel through the 1 px wall at 512 px/step
    -- and the article's method teleports onto a horizontal wall hit from its end
    for _, method in ipairs({"seed", "wall_type", "fat_cross", "min_axis"}) do
      local tunnels, teleports = 0, 0
      for _, failure in ipairs(result_of(method).failures) do
        if failure.scene == "thin wall, each side" and failure.kind == "tunnelled"
          and failure.case.thickness == 1 and failure.case.speed == 512 then
          tunnels = tunnels + 1
        end
        if failure.scene == "horizontal wall hit from the side" and failure.kind == "teleported" then
          teleports = teleports + 1
        end
      end
      assert.is_true(tunnels > 0, method .. " tunnels")
      if method ~= "min_axis" and method ~= "fat_cross" then
        assert.is_true(teleports > 0, method .. " teleports")
      end
    end
  end)

  it("the README's table shows the pinned counts", function()
    local readme = require("spec.support.files").read("README.md")
    for method, pinned in pairs(PINNED) do
      local row = readme:match("\n| `" .. method .. "` | ([^\n]+)")
      assert.is_string(row, method)
      local cells = {}
      for cell in row:gmatch("([^|]+)|") do cells[#cells + 1] = cell:match("^%s*(.-)%s*$") end
      assert.are.equal(pinned.passed, tonumber(cells[1]:match("^(%d+)")), method)
      for i = 1, 6 do assert.are.equal(pinned.kinds[i], tonumber(cells[i + 1]), method) end
    end
  end)

  local jit = rawget(_G, "jit")
  if jit and jit.status() then
    it("gives identical results with LuaJIT's compiler on and off", function()
      for _, method in ipairs({"seed", "fat_cross", "min_axis", "swept"}) do
        jit.off()
        jit.flush()
        local off = failure_list(scenarios.score(method, "spec"))
        jit.on()
        local on = failure_list(scenarios.score(method, "spec"))
        assert.are.same(off, on)
      end
    end)
  end
end)
