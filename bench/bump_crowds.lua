-- bench/bump_crowds.lua: budge.bump against bump.lua 3.1.7 where a move passes through a
-- crowd, each item of which its filter ignores (nil: bullets among bullets) or crosses
-- ("cross": a player through a field of coins).
--
--   lua bench/bump_crowds.lua [--items 4,16,64,256] [--runs 5] [--moves 20000]
--
-- The scene: `items` 8x8 items piled at random on a 48x48 spot (a fixed seed), an 8x8
-- mover going 80 px through it and back along one row, one move at a time; ns per move
-- (os.clock) and the collisions per move. Each way, count and answer runs in its own
-- fresh process, the ways interleaved; medians of --runs. bump.lua is looked for in
-- BUMP_PATH (default ../shared/peers/bump.lua-3.1.7), and skipped when it is not there.
-- budge.bump meets a leg's candidates nearest first: until 2026-12-07 every one passed
-- over sent it over all of them again (k^2); now it sorts them past CROWD (bump.lua).
-- The way "world" is budge's own world, the items actors and the mover's filter on it
-- (move.lua's filtered phase: it sorted what a path meets by insertion until 2026-12-07).
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local bump_dir = os.getenv("BUMP_PATH") or "../shared/peers/bump.lua-3.1.7"
package.path = package.path .. ";" .. bump_dir .. "/?.lua"
local common = require("bench.common")

if arg[1] == "--one" then -- one run: --one WAY ITEMS ANSWER MOVES
  local way, count, answer, moves = arg[2], tonumber(arg[3]), arg[4], tonumber(arg[5])
  local random = require("fixtures.random").new(20261207)
  local said = answer ~= "nil" and answer or nil
  local function filter() return said end
  local total, step = 0
  if way == "world" then -- budge's own world: the items actors, the mover's filter on it
    local world = require("budge").new_world({cell_size = 64})
    for _ = 1, count do
      local x = 100 + random(0, 40)
      world:add_actor({x = x, y = 100 + random(0, 40), width = 8, height = 8})
    end
    local mover = world:add_actor({x = 60, y = 110, width = 8, height = 8, filter = filter})
    step = function()
      local _, _, n = world:move(mover, mover.x < 100 and 80 or -80, 0)
      total = total + n
    end
  else
    local bump = way == "bump" and require("bump") or require("budge.bump")
    local world = bump.newWorld(64)
    for i = 1, count do world:add({id = i}, 100 + random(0, 40), 100 + random(0, 40), 8, 8) end
    local mover = {}
    world:add(mover, 60, 110, 8, 8)
    local x = 60
    step = function()
      local len
      local _
      x, _, _, len = world:move(mover, x < 100 and 140 or 60, 110, filter)
      total = total + len
    end
  end
  for _ = 1, math.max(200, moves / 10) do step() end
  total = 0
  local started = os.clock()
  for _ = 1, moves do step() end
  print(("%.1f %.2f"):format((os.clock() - started) * 1e9 / moves, total / moves))
  os.exit(0)
end

local options = common.options(arg, {items = "4,16,64,256", runs = 5, moves = 20000})
local interpreter = arg[-1] or "lua"
local ways = {"budge.bump", "world"}
if loadfile(bump_dir .. "/bump.lua") then ways[3] = "bump" end
print(("`%s bench/bump_crowds.lua --runs %d --moves %d`, %s, on %s, %s: ns per move, "
  .. "median of %d fresh processes (interleaved)%s"):format(interpreter, options.runs,
  options.moves, os.date("!%Y-%m-%d"), common.interpreter(), common.machine(), options.runs,
  ways[3] and "" or "; bump.lua not found, skipped"))
print("")
print("| items piled | filter | budge.bump | budge world | bump.lua 3.1.7 | cols per move |")
print("|---|---|---|---|---|---|")
for count in options.items:gmatch("%d+") do
  for _, answer in ipairs({"nil", "cross"}) do
    -- (bump.lua's crosses cost it a project per col: fewer moves for it at 64 and more)
    local results = common.fresh_runs(ways, options.runs, 2, function(way)
      local moves = options.moves
      if way == "bump" and answer == "cross" then moves = math.max(200, moves * 4 / count) end
      return ("%s bench/bump_crowds.lua --one %s %s %s %d"):format(interpreter,
        way == "budge.bump" and "budge" or way, count, answer, moves)
    end)
    local ours = common.median(results["budge.bump"][1])
    local native = common.median(results.world[1])
    local theirs = results.bump and ("%.0f"):format(common.median(results.bump[1])) or "-"
    print(("| %s | %s | %.0f | %.0f | %s | %.1f |"):format(count, answer, ours, native, theirs,
      common.median(results["budge.bump"][2])))
  end
end
