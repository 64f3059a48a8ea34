-- bench/contacts.lua: moves with interactions and frame contacts on the world bench map.
--
--   lua bench/contacts.lua [--runs 5] [--frames 300]
--
-- The scene: the world bench map (fixtures/scene.lua: 200x200 tiles of 16 px, 20% solid)
-- as a tile layer; 1000 walkers of 12x12 (no filter: they slide on tiles and cross coins),
-- 200 coin sensors of 6x6, and 100 bullets of 4x4 flying at 40 px per frame whose filter
-- stops them at walls and crosses walkers; a bullet that hits a wall is fired again from
-- a free cell. Each frame moves every walker and bullet, then calls world:contacts.
-- Reports ns per actor per frame for the moves and for contacts, the contacts found per
-- frame, and KB allocated per frame (GC stopped, after a warm-up).
--
-- When `require("bump")` finds bump.lua (BUMP_PATH=dir adds dir to package.path), the same
-- scene runs on it: every solid tile an item, coins items its filters cross, bullets
-- crossing walkers with bump's "cross" (it has no frame contacts: its figure is the moves).
--
-- `--budget large` raises LuaJIT's compiled-code budget (maxtrace=4000, maxmcode=4096) in
-- the measured processes, to tell the cost of the code from the cost of running out.
-- Each way and run is its own fresh process (what one compiles on LuaJIT changes the
-- others' figures), interleaved; the medians of the runs are printed.
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
if os.getenv("BUMP_PATH") then
  package.path = os.getenv("BUMP_PATH") .. "/?.lua;" .. package.path
end
local common = require("bench.common")
local scene = require("fixtures.scene")
local MAP, TILE = scene.MAP, scene.TILE

local options = common.options(arg, {runs = 5, frames = 300, way = "", seed = 12345,
  walkers = 1000, coins = 200, bullets = 100, budget = "default", readme = ""})
local jit = rawget(_G, "jit")
if jit and options.way ~= "" and options.budget == "large" then
  jit.opt.start("maxtrace=4000", "maxmcode=4096") -- a budget this scene never runs out of
end
local clock = os.clock

-- Free cells, in a fixed order, for coins and bullets.
local function free_cells(grid, random, count)
  local cells = {}
  while #cells < count do
    local col, row = random(2, MAP - 1), random(2, MAP - 1)
    if not grid[row][col] then cells[#cells + 1] = {(col - 1) * TILE, (row - 1) * TILE} end
  end
  return cells
end

-- Runs frame() 30 times to warm up, then reset() and the measured frames with the
-- collector stopped; returns the KB allocated per measured frame.
local function measure(frame, reset)
  for _ = 1, 30 do frame() end
  reset()
  collectgarbage("collect")
  collectgarbage("stop")
  local before = collectgarbage("count")
  for _ = 1, options.frames do frame() end
  local kb = (collectgarbage("count") - before) / options.frames
  collectgarbage("restart")
  return kb
end

local DIRECTIONS = {{40, 0}, {0, 40}, {-40, 0}, {0, -40}, {28, 28}, {-28, 28}, {28, -28},
  {-28, -28}}

local function run_budge()
  local budge = require("budge")
  local grid, random = scene.make_scene(options.seed)
  local starts = scene.make_actors(grid, random, options.walkers)
  local world = budge.new_world()
  world:add_tiles(grid, TILE, TILE)
  local walkers = {}
  for i = 1, #starts do
    local s = starts[i]
    local walker = world:add_actor({x = s.x, y = s.y, width = 12, height = 12})
    walker.vx, walker.vy, walker.walker = s.dx, s.dy, true
    walkers[i] = walker
  end
  for _, cell in ipairs(free_cells(grid, random, options.coins)) do
    world:add_sensor({x = cell[1] + 5, y = cell[2] + 5, width = 6, height = 6})
  end
  local cells = free_cells(grid, random, 997)
  local function bullet_filter(_, other)
    if other.walker then return "cross" end
    if other.width == 6 then return nil end -- coins
    return "slide"
  end
  local bullets, next_cell = {}, 0
  local function fire(bullet)
    next_cell = next_cell % #cells + 1
    local cell = cells[next_cell]
    bullet.x, bullet.y = cell[1] + 6, cell[2] + 6
    local direction = DIRECTIONS[next_cell % #DIRECTIONS + 1]
    bullet.vx, bullet.vy = direction[1], direction[2]
  end
  for i = 1, options.bullets do
    local bullet = {x = 0, y = 0, width = 4, height = 4, filter = bullet_filter}
    fire(bullet)
    bullets[i] = world:add_actor(bullet)
  end
  local out = {}
  local move_time, contact_time, found = 0, 0, 0
  local function frame()
    local started = clock()
    for i = 1, #walkers do
      local walker = walkers[i]
      world:move(walker, walker.vx, walker.vy)
    end
    for i = 1, #bullets do
      local bullet = bullets[i]
      local _, _, n, hits = world:move(bullet, bullet.vx, bullet.vy)
      for k = 1, n do
        if hits[k].response == "slide" then
          fire(bullet)
          world:update(bullet)
          break
        end
      end
    end
    local moved = clock()
    local _, n = world:contacts(out)
    contact_time = contact_time + (clock() - moved)
    move_time = move_time + (moved - started)
    found = found + n
  end
  local kb = measure(frame, function() move_time, contact_time, found = 0, 0, 0 end)
  local per = 1e9 / (options.frames * (#walkers + #bullets))
  return move_time * per, contact_time * per, found / options.frames, kb
end

local function run_bump()
  local ok, bump = pcall(require, "bump")
  if not ok then return nil end
  local grid, random = scene.make_scene(options.seed)
  local starts = scene.make_actors(grid, random, options.walkers)
  local world = bump.newWorld(64)
  for row = 1, MAP do
    for col = 1, MAP do
      if grid[row][col] then
        world:add({tile = true}, (col - 1) * TILE, (row - 1) * TILE, TILE, TILE)
      end
    end
  end
  local walkers = {}
  local function walker_filter(_, other)
    if other.tile then return "slide" end
    if other.coin then return "cross" end
    return nil
  end
  for i = 1, #starts do
    local s = starts[i]
    local walker = {vx = s.dx, vy = s.dy, walker = true}
    world:add(walker, s.x, s.y, 12, 12)
    walkers[i] = walker
  end
  for _, cell in ipairs(free_cells(grid, random, options.coins)) do
    world:add({coin = true}, cell[1] + 5, cell[2] + 5, 6, 6)
  end
  local cells = free_cells(grid, random, 997)
  local function bullet_filter(_, other)
    if other.walker then return "cross" end
    if other.tile then return "slide" end
    return nil
  end
  local bullets, next_cell = {}, 0
  local function fire(bullet)
    next_cell = next_cell % #cells + 1
    local cell = cells[next_cell]
    local direction = DIRECTIONS[next_cell % #DIRECTIONS + 1]
    bullet.vx, bullet.vy = direction[1], direction[2]
    return cell[1] + 6, cell[2] + 6
  end
  for i = 1, options.bullets do
    local bullet = {}
    local x, y = fire(bullet)
    world:add(bullet, x, y, 4, 4)
    bullets[i] = bullet
  end
  local move_time, found = 0, 0
  local function frame()
    local started = clock()
    for i = 1, #walkers do
      local walker = walkers[i]
      local x, y = world:getRect(walker)
      world:move(walker, x + walker.vx, y + walker.vy, walker_filter)
    end
    for i = 1, #bullets do
      local bullet = bullets[i]
      local x, y = world:getRect(bullet)
      local _, _, cols, n = world:move(bullet, x + bullet.vx, y + bullet.vy, bullet_filter)
      for k = 1, n do
        if cols[k].type == "cross" then found = found + 1 end
      end
      for k = 1, n do
        if cols[k].type == "slide" then
          world:update(bullet, fire(bullet))
          break
        end
      end
    end
    move_time = move_time + (clock() - started)
  end
  local kb = measure(frame, function() move_time, found = 0, 0 end)
  return move_time * 1e9 / (options.frames * (#walkers + #bullets)), 0, found / options.frames, kb
end

if options.way ~= "" then -- one run of one way: print its figures on one line
  local moves, contacts, found, kb
  if options.way == "budge" then moves, contacts, found, kb = run_budge()
  else moves, contacts, found, kb = run_bump() end
  if moves then print(("%.1f %.1f %.2f %.3f"):format(moves, contacts, found, kb)) end
  os.exit(0)
end

-- The driver: fresh processes, interleaved, medians.
local interpreter = arg[-1] or "lua"
local has_bump = pcall(require, "bump")
local ways = has_bump and {"budge", "bump"} or {"budge"}
local results = common.fresh_runs(ways, options.runs, 4, function(way)
  return ("%s bench/contacts.lua --way %s --frames %d --seed %d --walkers %d --coins %d "
    .. "--bullets %d --budget %s"):format(interpreter, way, options.frames, options.seed,
    options.walkers, options.coins, options.bullets, options.budget)
end)
print(("bench/contacts.lua on %s (%s JIT budget), %s: %d walkers, %d coin sensors, %d "
  .. "bullets at 40 px/frame, %d frames, median of %d fresh processes"):format(
  common.interpreter(), options.budget, common.machine(), options.walkers, options.coins,
  options.bullets, options.frames, options.runs))
print(("%-24s %14s %16s %16s %10s"):format("way", "moves ns/actor", "contacts ns/actor",
  "contacts/frame", "KB/frame"))
local lines = {("`%s bench/contacts.lua --runs %d --frames %d --budget %s`, %s, on %s, %s: ns "
  .. "per actor per frame, median of %d fresh processes (the ways interleaved)."):format(
  interpreter, options.runs, options.frames, options.budget, os.date("!%Y-%m-%d"),
  common.interpreter(), common.machine(), options.runs), "",
  "| way | moves | `contacts` | contacts per frame | KB/frame |", "|---|---|---|---|---|"}
for _, way in ipairs(ways) do
  local r = results[way]
  local name = way == "budge" and "budge" or "bump.lua 3.1.7 (cross)"
  local contacts = way == "budge" and ("%.0f"):format(common.median(r[2])) or "-"
  print(("%-24s %14.0f %16s %16.1f %10.2f"):format(name, common.median(r[1]), contacts,
    common.median(r[3]), common.median(r[4])))
  lines[#lines + 1] = ("| %s | %.0f | %s | %.1f | %.2f |"):format(name, common.median(r[1]),
    contacts, common.median(r[3]), common.median(r[4]))
end
if options.readme ~= "" then
  common.write_readme(options.readme, ("bench/contacts.lua %s %s"):format(common.key(),
    options.budget), lines)
end
