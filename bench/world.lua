-- bench/world.lua: world:move on a tile map, three ways, against a hand-written reference.
--
--   lua bench/world.lua [--actors 100,1000,10000] [--frames 600] [--runs 3]
--
-- The scene: a 200x200 map of 16 px tiles, border walls and 20% random solid tiles; N
-- actors of 12x12 in free cells, each moving 1..8 px per frame in a fixed direction and
-- sliding, for F frames. Ways: (a) the map as a tile layer, (b) every solid tile as its
-- own 16x16 solid box in the spatial hash, (m) the solid tiles merged into rectangles by
-- budge.tiles.merge, in the hash, (c) a reference with no library that moves x then y
-- against the tile array (the speed limit for this scene). Reports ns per actor
-- per frame (median of the runs), the ratios a/c and b/c, and KB allocated per frame
-- (GC stopped, after a warm-up). Positions after the run must agree across a, b and c.
if ... ~= "bench.world" then -- run as a program; bench/run.lua requires it as a module
  package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
end
local budge = require("budge")
local common = require("bench.common")
local new_random = require("fixtures.random").new
local garbage = require("fixtures.garbage")

local scene = require("fixtures.scene")
local MAP, TILE, SIZE = scene.MAP, scene.TILE, scene.SIZE
local make_scene, make_actors = scene.make_scene, scene.make_actors

-- (c) the reference: exact faces, strict overlap, x then y, straight against the array.
local floor = math.floor
local function reference_move(grid, actor, dx, dy)
  local x, y = actor.x, actor.y
  if dx ~= 0 then
    local row0, row1 = floor(y / TILE) + 1, floor((y + SIZE - 1e-9) / TILE) + 1
    if dx > 0 then
      local target = x + dx
      local col = floor((x + SIZE) / TILE) + 1
      local last = floor((target + SIZE - 1e-9) / TILE) + 1
      while col <= last do
        local line_hit = false
        for row = row0, row1 do if grid[row][col] then line_hit = true break end end
        if line_hit then target = (col - 1) * TILE - SIZE break end
        col = col + 1
      end
      x = target
    else
      local target = x + dx
      local col = floor(x / TILE)
      local last = floor(target / TILE) + 1
      while col >= last do
        local line_hit = false
        for row = row0, row1 do if grid[row][col] then line_hit = true break end end
        if line_hit then target = col * TILE break end
        col = col - 1
      end
      x = target
    end
  end
  if dy ~= 0 then
    local col0, col1 = floor(x / TILE) + 1, floor((x + SIZE - 1e-9) / TILE) + 1
    if dy > 0 then
      local target = y + dy
      local row = floor((y + SIZE) / TILE) + 1
      local last = floor((target + SIZE - 1e-9) / TILE) + 1
      while row <= last do
        local line = grid[row]
        local line_hit = false
        for col = col0, col1 do if line[col] then line_hit = true break end end
        if line_hit then target = (row - 1) * TILE - SIZE break end
        row = row + 1
      end
      y = target
    else
      local target = y + dy
      local row = floor(y / TILE)
      local last = floor(target / TILE) + 1
      while row >= last do
        local line = grid[row]
        local line_hit = false
        for col = col0, col1 do if line[col] then line_hit = true break end end
        if line_hit then target = row * TILE break end
        row = row - 1
      end
      y = target
    end
  end
  actor.x, actor.y = x, y
end

local function setup(way, grid, starts, method)
  local actors = {}
  for i = 1, #starts do
    actors[i] = {x = starts[i].x, y = starts[i].y, width = SIZE, height = SIZE,
      dx = starts[i].dx, dy = starts[i].dy}
  end
  local step
  if way == "reference" then
    step = function()
      for i = 1, #actors do
        local actor = actors[i]
        reference_move(grid, actor, actor.dx, actor.dy)
      end
    end
  elseif way == "bump" then
    local bump = require("bump")
    local world = bump.newWorld(64)
    for row = 1, MAP do
      for col = 1, MAP do
        if grid[row][col] then
          world:add({}, (col - 1) * TILE, (row - 1) * TILE, TILE, TILE)
        end
      end
    end
    for i = 1, #actors do
      local actor = actors[i]
      world:add(actor, actor.x, actor.y, SIZE, SIZE)
    end
    local function slide() return "slide" end
    step = function()
      for i = 1, #actors do
        local actor = actors[i]
        actor.x, actor.y = world:move(actor, actor.x + actor.dx, actor.y + actor.dy, slide)
      end
    end
  else
    local world = budge.new_world()
    if way == "tiles" then
      world:add_tiles(grid, TILE, TILE)
    elseif way == "merged" then
      for _, solid in ipairs(budge.tiles.merge(grid, TILE, TILE)) do world:add_solid(solid) end
    else
      for row = 1, MAP do
        for col = 1, MAP do
          if grid[row][col] then
            world:add_solid({x = (col - 1) * TILE, y = (row - 1) * TILE, width = TILE, height = TILE})
          end
        end
      end
    end
    for i = 1, #actors do world:add_actor(actors[i]) end
    local move = world.move
    step = function()
      for i = 1, #actors do
        local actor = actors[i]
        move(world, actor, actor.dx, actor.dy, method)
      end
    end
  end
  return actors, step
end

-- One timed run: warm-up frames, then `frames` frames with the GC stopped.
local function run(way, grid, starts, frames, method)
  local actors, step = setup(way, grid, starts, method)
  local bytes, elapsed = garbage.measure(step, frames,
    {warm = function() for _ = 1, 20 do step() end end})
  collectgarbage("collect")
  return elapsed * 1e9 / (frames * #actors), bytes / 1024 / frames, actors
end

if ... == "bench.world" then -- required by bench/run.lua: export the timing, run nothing
  return {run = run, make_scene = make_scene, make_actors = make_actors}
end

local options = common.options(arg, {actors = "100,1000,10000", frames = 600, runs = 3,
  seed = 12345, csv = "", profile = ""})
local grid = make_scene(options.seed)
local has_bump = pcall(require, "bump")
local ways = {"tiles", "boxes", "merged", "reference"}
if has_bump then ways[#ways + 1] = "bump" end
if options.profile ~= "" then -- one way alone, for luajit -jp
  local starts = make_actors(grid, new_random(options.seed + 1000), 1000)
  print(options.profile, ("%.0f ns per move"):format(run(options.profile, grid, starts, options.frames)))
  return
end

print(("budge %s world bench on %s, %s"):format(budge._VERSION, common.interpreter(),
  common.machine()))
print(("map %dx%d tiles of %d px, 20%% solid; actors %dx%d moving 1..8 px per frame; %d frames; "
  .. "median of %d runs"):format(MAP, MAP, TILE, SIZE, SIZE, options.frames, options.runs))
if not has_bump then print("bump.lua: not installed, skipped (a user's own `require(\"bump\")` enables it)") end
print(("%8s %12s %12s %12s %12s %7s %7s %7s %9s %9s %s"):format("actors", "a tiles ns",
  "b boxes ns", "m merged ns", "c ref ns", "a/c", "b/c", "m/c", "a KB/fr", "b KB/fr",
  has_bump and "bump/c" or ""))
local csv = {"interpreter,actors,frames,runs,tiles_ns,boxes_ns,merged_ns,reference_ns,"
  .. "tiles_kb_per_frame,boxes_kb_per_frame,bump_ns"}
for count in tostring(options.actors):gmatch("%d+") do
  count = tonumber(count)
  local starts = make_actors(grid, new_random(options.seed + count), count)
  local times, memory, finals = {}, {}, {}
  for _, way in ipairs(ways) do times[way] = {}; memory[way] = 0 end
  for _ = 1, options.runs do
    for _, way in ipairs(ways) do
      local ns, kb, actors = run(way, grid, starts, options.frames)
      times[way][#times[way] + 1] = ns
      if kb > memory[way] then memory[way] = kb end
      finals[way] = actors
    end
  end
  for i = 1, count do
    local c = finals.reference[i]
    for _, way in ipairs({"tiles", "boxes", "merged"}) do
      local a = finals[way][i]
      if a.x ~= c.x or a.y ~= c.y then
        error(("actor %d ends at %.17g,%.17g (%s) but at %.17g,%.17g (reference)")
          :format(i, a.x, a.y, way, c.x, c.y))
      end
    end
  end
  local a, b, c = common.median(times.tiles), common.median(times.boxes), common.median(times.reference)
  local m = common.median(times.merged)
  local bump_ns = has_bump and common.median(times.bump) or nil
  print(("%8d %12.0f %12.0f %12.0f %12.0f %7.2f %7.2f %7.2f %9.3f %9.3f %s"):format(count, a, b, m,
    c, a / c, b / c, m / c, memory.tiles, memory.boxes,
    bump_ns and ("%.2f"):format(bump_ns / c) or ""))
  csv[#csv + 1] = ("%s,%d,%d,%d,%.1f,%.1f,%.1f,%.1f,%.4f,%.4f,%s"):format(common.interpreter(),
    count, options.frames, options.runs, a, b, m, c, memory.tiles, memory.boxes,
    bump_ns and ("%.1f"):format(bump_ns) or "")
end
print("every way ends every actor at the same position")
if options.csv ~= "" then
  local file = assert(io.open(options.csv, "w"))
  file:write(table.concat(csv, "\n"), "\n")
  file:close()
end
