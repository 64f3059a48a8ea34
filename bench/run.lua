-- bench/run.lua: speed against accuracy for every method, on this interpreter.
--
--   lua bench/run.lua [--runs 5] [--frames 200] [--actors 1000] [--level full]
--
-- Accuracy: the share of the scenario catalogue (fixtures/scenarios.lua) each method gets
-- right, with its failures counted by kind. Cost: ns per move on the world bench scene
-- (bench/world.lua's tile map, 1000 actors) with that method, median of the runs.
-- Writes bench/results/<interpreter>.csv, bench/results/scenes-<interpreter>.csv and
-- bench/results/envelopes.csv; bench/chart.lua draws them.
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local budge = require("budge")
local common = require("bench.common")
local scenarios = require("fixtures.scenarios")
local world_bench = require("bench.world")

local options = common.options(arg, {runs = 5, frames = 200, actors = 1000, level = "full",
  seed = 12345})
local jit = rawget(_G, "jit")
local tag = jit and "luajit" or _VERSION:gsub("Lua ", "lua")
local interpreter, machine = common.interpreter(), common.machine()

print(("budge %s: speed against accuracy on %s, %s"):format(budge._VERSION, interpreter, machine))

-- accuracy, per method and per scene
local accuracy, per_scene = {}, {}
for _, method in ipairs(scenarios.METHODS) do
  local started = os.clock()
  accuracy[method] = scenarios.score(method, options.level)
  per_scene[method] = {}
  scenarios.each_case(options.level, function(scene) per_scene[method][scene.name] =
    per_scene[method][scene.name] or {cases = 0, failed = 0} end)
  for _, failure in ipairs(accuracy[method].failures) do
    local row = per_scene[method][failure.scene]
    row.failed = row.failed + 1
  end
  scenarios.each_case(options.level, function(scene)
    local row = per_scene[method][scene.name]
    row.cases = row.cases + 1
  end)
  print(("  %-10s %5d of %5d cases right (%.1f%%) in %.1f s"):format(method,
    accuracy[method].passed, accuracy[method].total,
    100 * accuracy[method].passed / accuracy[method].total, os.clock() - started))
end

-- cost, per method, on the world bench scene
local grid = world_bench.make_scene(options.seed)
local starts = world_bench.make_actors(grid, require("fixtures.random").new(options.seed + options.actors),
  options.actors)
local cost = {}
for _, method in ipairs(scenarios.METHODS) do cost[method] = {} end
for _ = 1, options.runs do
  for _, method in ipairs(scenarios.METHODS) do -- interleaved, so noise hits all alike
    local ns = world_bench.run("tiles", grid, starts, options.frames, method)
    local list = cost[method]
    list[#list + 1] = ns
  end
end

local header = {"interpreter", "machine", "method", "cases", "passed", "accuracy_percent"}
for _, kind in ipairs(scenarios.KINDS) do header[#header + 1] = kind:gsub("[ -]", "_") end
header[#header + 1] = "ns_per_move"
header[#header + 1] = "runs"
local lines = {table.concat(header, ",")}
print(("  %-10s %10s %9s   %s"):format("method", "ns/move", "accuracy", "failures by kind"))
for _, method in ipairs(scenarios.METHODS) do
  local result = accuracy[method]
  local ns = common.median(cost[method])
  local row = {('"' .. interpreter .. '"'), ('"' .. machine .. '"'), method, result.total,
    result.passed, ("%.2f"):format(100 * result.passed / result.total)}
  local kinds = {}
  for _, kind in ipairs(scenarios.KINDS) do
    row[#row + 1] = result.by_kind[kind]
    if result.by_kind[kind] > 0 then kinds[#kinds + 1] = kind .. " " .. result.by_kind[kind] end
  end
  row[#row + 1] = ("%.1f"):format(ns)
  row[#row + 1] = options.runs
  lines[#lines + 1] = table.concat(row, ",")
  print(("  %-10s %10.0f %8.1f%%   %s"):format(method, ns, 100 * result.passed / result.total,
    table.concat(kinds, ", ")))
end

local function write(path, text)
  local file = assert(io.open(path, "w"))
  file:write(text)
  file:close()
  print("wrote " .. path)
end
write(("bench/results/%s.csv"):format(tag), table.concat(lines, "\n") .. "\n")

local scene_lines = {"method,scene,cases,failed"}
for _, method in ipairs(scenarios.METHODS) do
  for _, scene in ipairs(scenarios.SCENES) do
    local row = per_scene[method][scene.name]
    if row then
      scene_lines[#scene_lines + 1] = ('%s,"%s",%d,%d'):format(method, scene.name, row.cases,
        row.failed)
    end
  end
end
write(("bench/results/scenes-%s.csv"):format(tag), table.concat(scene_lines, "\n") .. "\n")

local envelope_lines = {"method,side,mover_size,thickness,measured,analytic,analytic_inclusive"}
for _, envelope in ipairs(scenarios.ENVELOPES) do
  for _, thickness in ipairs(scenarios.THICKNESS) do
    envelope_lines[#envelope_lines + 1] = ("%s,%s,12,%d,%.6f,%.6f,%s"):format(envelope.method,
      envelope.side, thickness, scenarios.safe_speed(envelope, thickness, 12),
      envelope.bound(12, thickness), tostring(envelope.inclusive))
  end
end
write("bench/results/envelopes.csv", table.concat(envelope_lines, "\n") .. "\n")
