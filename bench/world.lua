-- bench/world.lua: world:move on a tile map, several ways, against a hand-written reference.
--
--   lua bench/world.lua [--actors 100,1000,10000] [--frames 600] [--runs 5] [--readme README.md]
--
-- The scene: a 200x200 map of 16 px tiles, border walls and 20% random solid tiles; N
-- actors of 12x12 in free cells, each moving 1..8 px per frame in a fixed direction and
-- sliding, for F frames. Ways:
--   reference  no library: moves x then y against the tile array (the speed limit);
--   tiles      the map as a budge tile layer;
--   boxes      every solid tile its own 16x16 solid box in budge's spatial hash;
--   merged     the solid tiles merged into rectangles by budge.tiles.merge, in the hash;
--   blocking   boxes, with every actor's filter answering "slide" to everything: the
--              actors block each other, as bump's items do (the native world's like
--              for the front end's ways below);
--   bump_boxes budge.bump (the bump.lua front end), every solid tile an item, as bump
--              games do (actors block each other there, as in bump);
--   bump_merged budge.bump with the merged rectangles as items;
--   bump       bump.lua itself, every tile an item, when require("bump") finds it
--              (BUMP_PATH=dir adds dir to package.path).
-- Each way and run is its own fresh process (on LuaJIT what one way compiles changes
-- another's figures, and a bare loop compiles two ways from run to run), the ways
-- interleaved round by round (counts too); the medians of the runs are printed, with the
-- median of each round's ratio to the reference's run of that round. bump.lua runs at
-- most 300000 moves a run (fewer frames at 10000 actors: it is slow), the others F frames
-- and at least 60000 moves (more frames at 100 actors). KB per frame are allocated with
-- the GC stopped, after a warm-up of 20 frames and at least 50000 moves. The budge ways
-- that move as the reference does (tiles, boxes, merged) must end every actor where it
-- does: the processes print a checksum of the final positions.
-- --readme FILE writes the table into FILE between the markers for this interpreter.
if ... ~= "bench.world" then -- run as a program; bench/run.lua requires it as a module
  package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
  if os.getenv("BUMP_PATH") then
    package.path = os.getenv("BUMP_PATH") .. "/?.lua;" .. package.path
  end
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
  elseif way == "bump" or way == "bump_boxes" or way == "bump_merged"
    or way == "bump_walls" then
    local bump = way == "bump" and require("bump") or require("budge.bump")
    local world = bump.newWorld(64)
    if way == "bump_merged" then
      for _, solid in ipairs(budge.tiles.merge(grid, TILE, TILE)) do
        world:add({}, solid.x, solid.y, solid.width, solid.height)
      end
    else
      for row = 1, MAP do
        for col = 1, MAP do
          if grid[row][col] then
            world:add({}, (col - 1) * TILE, (row - 1) * TILE, TILE, TILE)
          end
        end
      end
    end
    for i = 1, #actors do
      local actor = actors[i]
      world:add(actor, actor.x, actor.y, SIZE, SIZE)
    end
    local slide = function() return "slide" end
    if way == "bump_walls" then -- (--way alone: the movers pass through each other, a
      -- filter's nil for every mover, as bullets among bullets; the tiles are {} items)
      slide = function(_, other) if other.dx == nil then return "slide" end end
    end
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
    if way == "blocking" then
      local function slide() return "slide" end
      for i = 1, #actors do actors[i].filter = slide end
    end
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

-- One timed run: warm-up frames (20, and at least WARM_MOVES moves), then `frames` frames
-- with the GC stopped. The warm-up counts moves, not only frames: with 20 frames (2000
-- moves at 100 actors) LuaJIT was still compiling in the timed frames (0.2 KB a frame
-- of its own), and 100 actors' tile moves measured 106-181 ns, the reference 80-358;
-- after 50000 moves, 101-103 and 34-65, as with ten times the frames (`luajit
-- bench/world.lua --way W --count 100`, 3 runs each, 2026-12-03).
local WARM_MOVES = 50000
local function run(way, grid, starts, frames, method)
  local actors, step = setup(way, grid, starts, method)
  local warm_frames = math.max(20, math.ceil(WARM_MOVES / #actors))
  local bytes, elapsed = garbage.measure(step, frames,
    {warm = function() for _ = 1, warm_frames do step() end end})
  collectgarbage("collect")
  return elapsed * 1e9 / (frames * #actors), bytes / 1024 / frames, actors
end

if ... == "bench.world" then -- required by bench/run.lua: export the timing, run nothing
  return {run = run, make_scene = make_scene, make_actors = make_actors}
end

local options = common.options(arg, {actors = "100,1000,10000", frames = 600, runs = 5,
  seed = 12345, csv = "", profile = "", way = "", count = 0, readme = ""})
local grid = make_scene(options.seed)
if options.profile ~= "" then -- one way alone, for luajit -jp
  local starts = make_actors(grid, new_random(options.seed + 1000), 1000)
  print(options.profile, ("%.0f ns per move"):format(run(options.profile, grid, starts, options.frames)))
  return
end

-- How many frames a way runs with `count` actors: --frames, and for budge's ways and the
-- reference at least MIN_MOVES moves (a timed run of a few milliseconds measures the
-- machine more than the moves: Lua 5.4's 100 actors' tile moves took 2195-2367 ns a move
-- over 60 frames and 1473-1510 over 600, the same instructions per move, 2026-12-03).
local MIN_MOVES = 60000
local function frames_for(way, count)
  if way == "bump" then return math.min(options.frames, math.ceil(300000 / count)) end
  return math.max(options.frames, math.ceil(MIN_MOVES / count))
end

if options.way ~= "" then -- one run of one way in this process: ns, KB per frame, checksum
  local count = options.count
  local starts = make_actors(grid, new_random(options.seed + count), count)
  local ns, kb, actors = run(options.way, grid, starts, frames_for(options.way, count))
  local sum = 0
  for i = 1, #actors do sum = sum + actors[i].x * (i % 7 + 1) + actors[i].y * (i % 11 + 3) end
  print(("%.3f %.6f %.17g"):format(ns, kb, sum))
  os.exit(0)
end

local interpreter = arg[-1] or "lua"
local has_bump = pcall(require, "bump")
local ways = {"reference", "tiles", "boxes", "merged", "blocking", "bump_boxes",
  "bump_merged"}
if has_bump then ways[#ways + 1] = "bump" end
local NAMES = {reference = "(c) reference", tiles = "(a) tile layer", boxes = "(b) box per tile",
  merged = "(m) merged boxes", blocking = "(b) with actors blocking each other",
  bump_boxes = "budge.bump, box per tile",
  bump_merged = "budge.bump, merged", bump = "bump.lua 3.1.7"}
local lines = {}
local function say(line)
  print(line)
  lines[#lines + 1] = line
end
local date = os.date("!%Y-%m-%d")
say(("`%s bench/world.lua --frames %d --runs %d`, %s, on %s, %s: ns per actor per frame, "
  .. "median of %d fresh processes (ways and counts interleaved, one run of each a round); "
  .. "in brackets the median of each round's ratio to that round's reference; each run at "
  .. "least %d moves after a warm-up of %d%s."):format(
  interpreter, options.frames, options.runs, date,
  common.interpreter(), common.machine(), options.runs, MIN_MOVES, WARM_MOVES,
  has_bump and "; bump.lua at most 300000 moves a run" or "; bump.lua not found, skipped"))
say("")
local header, rule = "| way |", "|---|"
local counts = {}
for count in tostring(options.actors):gmatch("%d+") do
  counts[#counts + 1] = tonumber(count)
  header = header .. (" N = %s |"):format(count)
  rule = rule .. "---|"
end
-- Every (count, way) pair is a configuration of its own, and each round runs all of them
-- once, counts and ways interleaved: the machine's drift over the half hour of a run
-- falls on a way and the reference it is compared with alike, and on a way's 100 and
-- 10000 actors alike. The ratios printed are the medians of each round's ratio (the way's
-- run over the reference's run of that round), not ratios of the medians: on this shared
-- machine the medians of one set of rounds drifted by 20-40% from the next with the code
-- unchanged (2026-12-07), while each round's way and reference ran a few seconds apart.
local configs = {}
for _, count in ipairs(counts) do
  for _, way in ipairs(ways) do configs[#configs + 1] = way .. "@" .. count end
end
local results = common.fresh_runs(configs, options.runs, 3, function(config)
  local way, count = config:match("^(.-)@(%d+)$")
  return ("%s bench/world.lua --way %s --count %d --frames %d --seed %d"):format(
    interpreter, way, tonumber(count), options.frames, options.seed)
end)
local function runs_of(way, count) return results[way .. "@" .. count] end
local medians, ratios, memory = {}, {}, {}
for _, count in ipairs(counts) do
  local reference = runs_of("reference", count)
  for _, way in ipairs({"tiles", "boxes", "merged"}) do
    for run_index = 1, options.runs do
      if runs_of(way, count)[3][run_index] ~= reference[3][1] then
        error(("%s ends the %d actors elsewhere than the reference (checksum %.17g, not %.17g)")
          :format(way, count, runs_of(way, count)[3][run_index], reference[3][1]))
      end
    end
  end
  for _, way in ipairs(ways) do
    medians[way], ratios[way] = medians[way] or {}, ratios[way] or {}
    memory[way] = memory[way] or {}
    local runs = runs_of(way, count)
    medians[way][count] = common.median(runs[1])
    ratios[way][count] = common.paired_ratio(runs[1], reference[1])
    local worst = 0
    for _, value in ipairs(runs[2]) do worst = math.max(worst, value) end
    memory[way][count] = worst
  end
end
say(header)
say(rule)
for _, way in ipairs(ways) do
  local row = ("| %s |"):format(NAMES[way])
  for _, count in ipairs(counts) do
    local ns = medians[way][count]
    if way == "reference" then row = row .. (" %.0f |"):format(ns)
    else row = row .. (" %.0f (%.2fx) |"):format(ns, ratios[way][count]) end
  end
  say(row)
end
say("")
-- Per-mover cost from the fewest actors to the most, each round's run over its own
-- (the issue's flatness), and the ratios of the medians beside the paired ones.
local first, last = counts[1], counts[#counts]
local flat, plain = {}, {}
for _, way in ipairs(ways) do
  if #counts > 1 then
    flat[#flat + 1] = ("%s %.2f"):format(way,
      common.paired_ratio(runs_of(way, last)[1], runs_of(way, first)[1]))
  end
  if way ~= "reference" then
    local cells = {}
    for _, count in ipairs(counts) do
      cells[#cells + 1] = ("%.2f"):format(medians[way][count] / medians.reference[count])
    end
    plain[#plain + 1] = ("%s %s"):format(way, table.concat(cells, "/"))
  end
end
if #counts > 1 then
  say(("Per-mover cost at N = %d over N = %d (median of the rounds' ratios): %s.")
    :format(last, first, table.concat(flat, ", ")))
end
say(("The ratios of the medians instead (N = %s): %s."):format(table.concat(counts, "/"),
  table.concat(plain, ", ")))
local kb = {}
for _, way in ipairs(ways) do
  local worst = 0
  for _, count in ipairs(counts) do worst = math.max(worst, memory[way][count]) end
  kb[#kb + 1] = ("%s %.3f"):format(way, worst)
end
say("Most KB allocated per frame (GC stopped, after warm-up): " .. table.concat(kb, ", ")
  .. ". The tile layer, boxes and merged boxes end every actor where the reference does.")

if options.readme ~= "" then -- the table into the README, between this interpreter's markers
  common.write_readme(options.readme, "bench/world.lua " .. common.key(), lines)
end
