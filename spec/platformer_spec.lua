-- The example game's mechanics one at a time (its input scripts check whole runs in
-- make test): each would pass a broken game if the scripts alone were the check.
package.path = "./examples/platformer/?.lua;" .. package.path
local game = require("game")

local LEVEL = dofile("examples/platformer/level.lua")
local NOTHING = {}

local function frames(run, count, input)
  local worst = 0
  for _ = 1, count do
    local before = run.deaths
    run:update(input or NOTHING)
    if run.deaths - before > worst then worst = run.deaths - before end
  end
  return worst
end

local function place(run, item, x, y)
  item.x, item.y = x, y
  run.world:update(item)
end

describe("the example platformer", function()
  it("kills an enemy a bullet crosses on its way into a wall", function()
    local run = game.new(LEVEL)
    local enemy = run.enemies[1]
    place(run, enemy, 620, 272) -- just before the wall at x = 640
    enemy.direction = 1
    place(run, run.player, 560, 274)
    run.player.facing = 1
    frames(run, 1, {shoot = true})
    frames(run, 3)
    assert.are.same({1, 0}, {run.kills, #run.bullets})
  end)

  it("stops a bullet at a wall", function()
    local run = game.new(LEVEL)
    place(run, run.player, 500, 274)
    run.player.facing = 1
    frames(run, 1, {shoot = true})
    local bullet = run.bullets[1]
    assert.are.equal(548, bullet.x) -- fired at 512, one move of 36 px
    frames(run, 3)
    assert.are.same({0, 634}, {#run.bullets, bullet.x}) -- stopped with its front on the wall
  end)

  it("lets an enemy kill the player it walks into, once a frame", function()
    local run = game.new(LEVEL)
    local enemy = run.enemies[1]
    place(run, enemy, 420, 272)
    enemy.direction = -1
    place(run, run.player, 380, 274)
    local worst = frames(run, 40)
    assert.are.same({1, "enemy"}, {worst, run.causes[1]})
  end)

  it("keeps its enemies on their floor for 3000 frames, even where two meet at a ledge", function()
    local run = game.new(LEVEL)
    frames(run, 3000)
    for _, enemy in ipairs(run.enemies) do assert.are.equal(272, enemy.y) end
    assert.are.equal(0, run.inside)
  end)

  it("drops the player through a oneway ledge only while Down is held", function()
    local run = game.new(LEVEL)
    place(run, run.player, 1130, 240 - 14) -- standing on the ledge at cols 71-73
    frames(run, 30)
    assert.are.equal(226, run.player.y)
    frames(run, 30, {down = true})
    assert.are.equal(274, run.player.y)
  end)

  it("replays a script to the same verdict", function()
    local function replay(name)
      local script = dofile("examples/platformer/scripts/" .. name .. ".lua")
      local run = game.new(LEVEL)
      local input = game.player_input(script.input)
      local worst = 0
      for frame = 1, script.frames do
        local before = run.deaths
        run:update(input(frame))
        if run.deaths - before > worst then worst = run.deaths - before end
      end
      assert.is_true(worst <= 1, name .. ": two deaths in one frame")
      return run:verdict()
    end
    for _, name in ipairs({"playthrough", "deaths", "checkpoint"}) do
      assert.are.equal(replay(name), replay(name))
    end
  end)
end)
