-- Every public entry blames the caller's line for bad input: the message starts with
-- this file's name and the line of the call (error(msg, 2), never an inner line).
local budge = require("budge")

local box = require("fixtures.box")

-- Each case is a one-line function: its own line is the line the error must name. (No
-- `return f()`: a tail call leaves no caller line for error() to name.)
local world = budge.new_world()
local actor = world:add_actor(box(0, 0, 4, 4))
local solid = world:add_solid(box(50, 0, 4, 4))
local sensor = world:add_sensor(box(0, 40, 4, 4))
local picky = world:add_actor(box(40, 0, 4, 4))
picky.filter = function() return "bogus" end
local pusher = world:add_solid(box(10, 0, 4, 4))
local CASES = {
  {"detect_collision", function() local _ = budge.detect_collision(box(0, 0, 1, 1), nil) end},
  {"resolve_collision", function() local _ = budge.resolve_collision(box(0, 0, 1, 1), box(0, 0, 1, 1), "x") end},
  {"fat_cross", function() local _ = budge.fat_cross(box(0, 0, 16, 16), 8) end},
  {"resolve_fat_cross", function() local _ = budge.resolve_fat_cross(box(0, 0, 1, 1), nil, nil) end},
  {"new_world", function() local _ = budge.new_world({cell_size = -1}) end},
  {"add_solid", function() local _ = world:add_solid(box(0, 0, -1, 1)) end},
  {"add_actor", function() local _ = world:add_actor(actor) end},
  {"add_tiles ragged", function() local _ = world:add_tiles({{1}, {1, 1}}, 16, 16) end},
  {"add_tiles size", function() local _ = world:add_tiles({{1}}, 0, 16) end},
  {"remove", function() local _ = world:remove(box(0, 0, 1, 1)) end},
  {"update", function() local _ = world:update(42) end},
  {"move", function() local _ = world:move(actor, 0 / 0, 0) end},
  {"move method", function() local _ = world:move(actor, 1, 0, "fastest") end},
  {"move_solid", function() local _ = world:move_solid(solid, 1, math.huge) end},
  {"query_point", function() local _ = world:query_point(nil, 0) end},
  {"query_rect", function() local _ = world:query_rect(0, 0, -1, 1) end},
  {"query_segment", function() local _ = world:query_segment(0, 0, 1, 0 / 0) end},
  {"query_sweep", function() local _ = world:query_sweep(0, 0, 1, 1, 1, 0 / 0) end},
  {"query filter", function() local _ = world:query_rect(0, 0, 1, 1, {}, "self") end},
  {"add_sensor", function() local _ = world:add_sensor(sensor) end},
  {"check", function() local _ = world:check(actor, 1, 0, "fastest") end},
  {"contacts", function() local _ = world:contacts(7) end},
  {"filter response", function() local _ = world:move(picky, 20, 0) end},
  {"check response", function() local _ = world:check(picky, 20, 0) end},
  {"move_solid response", function() local _ = world:move_solid(pusher, 30, 0) end},
  {"tiles.merge", function() local _ = budge.tiles.merge({1, 1}, 16, 16) end},
  {"tiles.merge ragged", function() local _ = budge.tiles.merge({{1}, {}}, 16, 16) end},
  {"advise", function() local _ = budge.advise({solids = {}, movers = {{width = 1}}}) end},
}

describe("errors from every public entry", function()
  for _, case in ipairs(CASES) do
    it(case[1] .. " names the caller's line", function()
      local line = debug.getinfo(case[2], "S").linedefined
      local ok, message = pcall(case[2])
      assert.is_false(ok)
      assert.are.equal("string", type(message))
      assert.are.equal(tostring(line), message:match("errors_spec%.lua:(%d+): "), message)
    end)
  end

  it("changes nothing in the world when it refuses", function()
    assert.are.same({0, 0}, {actor.x, actor.y})
    assert.are.same({50, 0}, {solid.x, solid.y})
    assert.are.same({40, 0}, {picky.x, picky.y})
    assert.are.same({2, 2, 0, 1}, {world:count()})
  end)
end)
