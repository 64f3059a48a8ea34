local budge = require("budge")
local levels = require("fixtures.levels")

local box = require("fixtures.box")

local AXIS_SWEEP = "axis_sweep is enough at any speed: it moves x, then y, and stops at the "
  .. "first face (put the solids in a world); swept follows the exact diagonal at about 2.5 "
  .. "times the cost"

describe("budge.advise", function()
  -- a closed room: a floor typed horizontal, two walls typed vertical
  local function room()
    return {box(0, 200, 320, 16, "horizontal"), box(-16, 0, 16, 216, "vertical"),
      box(320, 0, 16, 216, "vertical")}
  end
  local ROOM_BOUNDS = {x = 0, y = 0, width = 320, height = 200}

  it("answers wall_type for typed walls hit only where their type pushes, inside the envelope", function()
    local method, reasons = budge.advise({solids = room(), bounds = ROOM_BOUNDS,
      movers = {{width = 12, height = 12, max_speed = 4}}})
    assert.are.equal("wall_type", method)
    assert.are.same({"wall_type is enough: every wall is typed for the sides it is hit from, "
      .. "and the fastest mover (4 px per step) stays under half of mover plus wall thickness"},
      reasons)
  end)

  it("finds the speed at which wall_type stops being enough: (S + T) / 2", function()
    local scene = {solids = room(), bounds = ROOM_BOUNDS,
      movers = {{width = 12, height = 12, max_speed = 13.9}}}
    assert.are.equal("wall_type", (budge.advise(scene)))
    scene.movers[1].max_speed = 14 -- (12 + 16) / 2
    local method, reasons = budge.advise(scene)
    assert.are.equal("axis_sweep", method)
    assert.are.equal("wall_type is not enough: a 12x12 mover at 14 px per step passes the "
      .. "middle of the 320x16 block at (0, 200) (it needs less than 14 on y) (and 2 more)",
      reasons[1])
  end)

  it("says which typed wall is hit from a side its type does not push toward", function()
    -- without bounds the walls' tops and the floor's ends are open
    local method, reasons = budge.advise({solids = {box(0, 200, 320, 16, "horizontal")},
      movers = {{width = 12, height = 12, max_speed = 4}}})
    assert.are.equal("fat_cross", method)
    assert.are.same({"wall_type is not enough: the 320x16 block at (0, 200) is typed "
      .. "horizontal but is open on its left side: a mover that walks into it there is lifted "
      .. "onto it", "fat_cross is enough: the fastest mover moves 4 px per step and every "
      .. "crossed block has an inset of at least 4 (a mover may overlap a crossed block's "
      .. "corner by up to the inset for a step: the corner notches)"}, reasons)
  end)

  it("answers fat_cross for the merged platformer level at the speed its crosses were sized for", function()
    local rows = levels.grid("platformer")
    local merged = budge.tiles.merge(rows, 16, 16, {is_oneway = levels.is_oneway, max_speed = 6})
    local scene = {solids = merged, bounds = {x = 0, y = 0, width = 800, height = 480},
      movers = {{width = 12, height = 14, max_speed = 6}}}
    local method, reasons = budge.advise(scene)
    assert.are.equal("fat_cross", method)
    assert.are.equal("wall_type is not enough: the 64x16 block at (672, 48) is hit from the side "
      .. "and from above, and no wall_type is right for both (and 24 more)", reasons[1])
    -- one px per step faster than the crosses' inset: no discrete method is safe
    scene.movers[1].max_speed = 7
    method, reasons = budge.advise(scene)
    assert.are.equal("axis_sweep", method)
    assert.are.equal("fat_cross is not enough: the 64x16 block at (672, 48) has a cross with an "
      .. "inset of 6, less than the 7 px per step of the fastest mover (and 23 more)", reasons[2])
  end)

  it("answers min_axis when blocks are too small for a cross but movers stay inside (S + T) / 2", function()
    local solids = {box(0, 200, 320, 16), box(100, 120, 16, 16)}
    local method, reasons = budge.advise({solids = solids,
      bounds = {x = 0, y = 0, width = 320, height = 200},
      movers = {{width = 12, height = 12, max_speed = 9}}})
    assert.are.equal("min_axis", method)
    assert.are.same({
      "wall_type is not enough: the 16x16 block at (100, 120) is hit from the side and from "
        .. "above, and no wall_type is right for both",
      "fat_cross is not enough: the 16x16 block at (100, 120) is hit from the side and from "
        .. "above, and is too small for a cross at 9 px per step (it serves speeds below 8)",
      "min_axis is enough: the fastest mover (9 px per step) stays under half of mover plus "
        .. "wall thickness on every open side, and no wall has a seam",
    }, reasons)
  end)

  it("finds seams in walls of raw tiles, which the shortest way out drags on", function()
    local solids = {}
    for row = 0, 5 do solids[#solids + 1] = box(0, row * 16, 16, 16) end
    local method, reasons = budge.advise({solids = solids, movers = {{width = 12, height = 12,
      max_speed = 2}}})
    assert.are.equal("axis_sweep", method)
    assert.are.equal("min_axis is not enough: the 16x16 block at (0, 0) and 16x16 block at "
      .. "(0, 16) make a seam in a wall: the shortest way out drags a mover sliding down it a "
      .. "pixel further at the seam", reasons[3])
    -- typed vertical, the same wall is fine for wall_type
    for _, solid in ipairs(solids) do solid.wall_type = "vertical" end
    assert.are.equal("wall_type", (budge.advise({solids = solids,
      bounds = {x = 16, y = 0, width = 100, height = 96},
      movers = {{width = 12, height = 12, max_speed = 2}}})))
  end)

  it("answers axis_sweep when only a continuous method is safe, and says why for each rung", function()
    local method, reasons = budge.advise({solids = {box(0, 200, 320, 16, "horizontal")},
      bounds = {x = 0, y = 0, width = 320, height = 200},
      movers = {{width = 12, height = 12, max_speed = 4}, {width = 4, height = 4, max_speed = 40}}})
    assert.are.equal("axis_sweep", method)
    assert.are.same({
      "wall_type is not enough: a 4x4 mover at 40 px per step passes the middle of the 320x16 "
        .. "block at (0, 200) (it needs less than 10 on y)",
      "fat_cross is not enough: a 4x4 mover at 40 px per step passes the middle of the 320x16 "
        .. "block at (0, 200) (it needs less than 10 on y)",
      "min_axis is not enough: a 4x4 mover at 40 px per step passes the middle of the 320x16 "
        .. "block at (0, 200) (it needs less than 10 on y)",
      AXIS_SWEEP,
    }, reasons)
  end)

  it("checks oneway platforms against falling through: speed < S + T", function()
    local solids = {box(0, 100, 64, 4, "oneway")}
    assert.are.equal("wall_type", (budge.advise({solids = solids,
      movers = {{width = 12, height = 12, max_speed = 15.5}}})))
    local method, reasons = budge.advise({solids = solids,
      movers = {{width = 12, height = 12, max_speed = 16}}})
    assert.are.equal("axis_sweep", method)
    assert.are.equal("wall_type is not enough: a 12x12 mover at 16 px per step falls through "
      .. "the oneway platform at (0, 100) (it needs less than 16)", reasons[1])
  end)

  it("handles the 5586 merged boxes of the bench map, each face against its neighbours", function()
    local map = require("fixtures.scene").make_scene(12345)
    local merged = budge.tiles.merge(map, 16, 16, {max_speed = 6})
    local method, reasons = budge.advise({solids = merged,
      bounds = {x = 0, y = 0, width = 3200, height = 3200},
      movers = {{width = 12, height = 12, max_speed = 6}}})
    assert.are.equal("fat_cross", method)
    assert.are.same({"wall_type is not enough: the 32x16 block at (0, 16) is hit from the side "
      .. "and from below, and no wall_type is right for both (and 5542 more)",
      "fat_cross is enough: the fastest mover moves 6 px per step and every crossed block has "
      .. "an inset of at least 6 (a mover may overlap a crossed block's corner by up to the "
      .. "inset for a step: the corner notches)"}, reasons)
  end)

  it("answers axis_sweep for a world, where it is measured cheapest, as auto does", function()
    local method, reasons = budge.advise({world = budge.new_world(),
      movers = {{width = 12, height = 12, max_speed = 1}}})
    assert.are.equal("axis_sweep", method)
    assert.are.equal(1, #reasons)
    assert.matches("inside a world it is both the cheapest method and right in every "
      .. "catalogue case", reasons[1], 1, true)
  end)

  it("tells the game's boxes apart by identity, whatever their __eq says", function()
    -- (a game's class may compare by id, always yes, or raise: found by an audit)
    local function scene(eq)
      local class = {__eq = eq}
      local function block(x, y) return setmetatable(box(x, y, 16, 16), class) end
      return {solids = {block(0, 0), block(0, 16)}, -- a seam in a wall
        movers = {{width = 8, height = 8, max_speed = 9}}}
    end
    local method, reasons = budge.advise(scene(nil))
    assert.are.equal("axis_sweep", method)
    assert.truthy(reasons[3]:find("make a seam in a wall", 1, true))
    for _, eq in ipairs({function() return true end, function() error("__eq ran", 0) end}) do
      local other_method, other_reasons = budge.advise(scene(eq))
      assert.are.same({method, reasons}, {other_method, other_reasons})
    end
    local base = {__eq = function() return true end} -- a class whose instances say yes
    local entity = setmetatable({}, setmetatable({}, base))
    getmetatable(entity).__eq = base.__eq
    assert.has_error(function() budge.advise({world = entity, movers = scene().movers}) end,
      "scene.world must be a budge world (budge.new_world()), got a table")
  end)

  it("rejects bad scenes with messages that name the field and the value", function()
    local movers = {{width = 12, height = 12, max_speed = 1}}
    assert.has_error(function() budge.advise(nil) end,
      "scene must be a table {solids = {...} or world = w, movers = {...}}, got nil")
    assert.has_error(function() budge.advise({movers = movers}) end,
      "scene must have exactly one of solids (an array of boxes) and world (a budge world)")
    assert.has_error(function() budge.advise({solids = {}, world = budge.new_world(), movers = movers}) end,
      "scene must have exactly one of solids (an array of boxes) and world (a budge world)")
    assert.has_error(function() budge.advise({world = {}, movers = movers}) end,
      "scene.world must be a budge world (budge.new_world()), got a table")
    assert.has_error(function() budge.advise({solids = {box(0, 0, -1, 1)}, movers = movers}) end,
      "scene.solids[1].width must be a finite number >= 0, got -1")
    assert.has_error(function() budge.advise({solids = {box(0, 0, 1, 1, "up")}, movers = movers}) end,
      'scene.solids[1].wall_type must be "horizontal", "vertical", "oneway" or nil, got "up"')
    assert.has_error(function() budge.advise({solids = {}, movers = {}}) end,
      "scene.movers must be a non-empty array of {width, height, max_speed}, got a table")
    assert.has_error(function() budge.advise({solids = {}, movers = {{width = 1, height = 1}}}) end,
      "scene.movers[1].max_speed must be a finite number >= 0 (px per step), got nil")
    assert.has_error(function() budge.advise({solids = {}, movers = {{width = 0, height = 1, max_speed = 1}}}) end,
      "scene.movers[1].width must be a finite number > 0, got 0")
    assert.has_error(function() budge.advise({solids = {}, bounds = 3, movers = movers}) end,
      "scene.bounds must be a box table {x, y, width, height}, got 3")
  end)
end)
