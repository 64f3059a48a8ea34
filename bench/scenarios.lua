-- bench/scenarios.lua: the scenario catalogue. Named scenes, each a generator of cases
-- over parameters (speed, wall thickness, mover size) and a judge that says whether a
-- method got the case right and, if not, what kind of failure it was and why.
--
-- Every case is replayed under a time-step schedule: speeds are in px per 1/60 s frame,
-- and a step of dt seconds moves speed * dt * 60 px. Cases start the mover half its
-- planned travel away from what it should meet, so every schedule reaches the contact.
package.path = "./src/?.lua;./src/?/init.lua;./?.lua;" .. package.path
local budge = require("budge")

local scenarios = {}

scenarios.METHODS = {"seed", "wall_type", "fat_cross", "min_axis", "axis_sweep", "swept", "auto"}
scenarios.KINDS = {"tunnelled", "wrong side", "residual overlap", "snagged", "teleported",
  "jitter", "order-dependent"}

local FRAME = 1 / 60

-- Time-step schedules: dt of step i (1-based) out of `count`.
scenarios.SCHEDULES = {
  {name = "fixed", dt = function() return FRAME end},
  {name = "jittered", dt = function(i) return FRAME * (1 + 0.5 * math.sin(i * 1.7)) end},
  {name = "alternating", dt = function(i) return i % 2 == 1 and 0 or FRAME end},
  {name = "hitch", dt = function(i, count) return i == math.ceil(count / 2) and 0.25 or FRAME end},
  {name = "tiny", dt = function() return 1e-5 end},
}

local function displacements(schedule, count, speed)
  local steps, total = {}, 0
  for i = 1, count do
    steps[i] = speed * schedule.dt(i, count) * 60
    total = total + steps[i]
  end
  return steps, total
end

local function overlaps(a, b)
  return a.x < b.x + b.width and b.x < a.x + a.width and a.y < b.y + b.height
    and b.y < a.y + a.height
end

local function box(x, y, width, height, wall_type)
  return {x = x, y = y, width = width, height = height, wall_type = wall_type}
end

-- Direction of travel for each side a mover comes from.
local APPROACH = {left = {1, 0}, right = {-1, 0}, top = {0, 1}, bottom = {0, -1}}

-- A mover of size S comes from `side` toward a wall of thickness T (64 long), centred
-- on it. Judged on every step: inside it is a residual overlap, out through the far face
-- is the wrong side (pushed there) or a tunnel (passed), moved across its path is a
-- teleport.
local function wall_case(method, p, schedule, wall_type_of)
  local direction = APPROACH[p.side]
  local horizontal = direction[1] ~= 0
  local S, T = p.size, p.thickness
  local wall = horizontal and box(200, 100, T, 64) or box(100, 200, 64, T)
  wall.wall_type = wall_type_of and wall_type_of(horizontal) or nil
  local steps, total = displacements(schedule, p.steps or 8, p.speed)
  local gap = total / 2
  local mover = box(0, 0, S, S)
  if horizontal then
    mover.y = wall.y + (wall.height - S) / 2
    mover.x = direction[1] > 0 and wall.x - S - gap or wall.x + T + gap
  else
    mover.x = wall.x + (wall.width - S) / 2
    mover.y = direction[2] > 0 and wall.y - S - gap or wall.y + T + gap
  end
  local world = budge.new_world()
  world:add_solid(wall)
  world:add_actor(mover)
  local cross = horizontal and mover.y or mover.x
  for i = 1, #steps do
    world:move(mover, direction[1] * steps[i], direction[2] * steps[i], method)
    if overlaps(mover, wall) then return "residual overlap", "inside the wall after step " .. i end
    if (horizontal and mover.y or mover.x) ~= cross then
      return "teleported", "moved across its path at step " .. i
    end
    local beyond
    if direction[1] > 0 then beyond = mover.x >= wall.x + T and mover.x - (wall.x + T)
    elseif direction[1] < 0 then beyond = mover.x + S <= wall.x and wall.x - (mover.x + S)
    elseif direction[2] > 0 then beyond = mover.y >= wall.y + T and mover.y - (wall.y + T)
    else beyond = mover.y + S <= wall.y and wall.y - (mover.y + S) end
    if beyond then
      if beyond == 0 then return "wrong side", "pushed out through the far face at step " .. i end
      return "tunnelled", "passed through the wall at step " .. i
    end
  end
  return nil
end

local function typed_wall(horizontal) return horizontal and "vertical" or "horizontal" end

local SPEEDS = {0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512}
local THICKNESS = {1, 2, 4, 8, 16, 32, 64}
local SIZES = {4, 12, 32}

-- Parameter grids: "full" for make bench, "spec" for the stability spec.
local GRIDS = {
  full = {speeds = SPEEDS, thickness = THICKNESS, sizes = SIZES},
  spec = {speeds = {1, 8, 64, 512}, thickness = {1, 16}, sizes = {12}},
}

local function each(grid, fn)
  for _, speed in ipairs(grid.speeds) do
    for _, thickness in ipairs(grid.thickness) do
      for _, size in ipairs(grid.sizes) do fn(speed, thickness, size) end
    end
  end
end

-- One case per speed, thickness and size of the grid.
local function grid_cases(grid)
  local list = {}
  each(grid, function(speed, thickness, size)
    list[#list + 1] = {speed = speed, thickness = thickness, size = size}
  end)
  return list
end

-- One case per speed and size: for scenes whose walls do not vary.
local function speed_size_cases(grid)
  local list = {}
  for _, speed in ipairs(grid.speeds) do
    for _, size in ipairs(grid.sizes) do list[#list + 1] = {speed = speed, size = size} end
  end
  return list
end

scenarios.SCENES = {
  {
    name = "thin wall, each side",
    about = "tunnelling through a wall, or resolving to the wrong side after deep penetration",
    cases = function(grid)
      local list = {}
      each(grid, function(speed, thickness, size)
        for _, side in ipairs({"left", "right", "top", "bottom"}) do
          list[#list + 1] = {speed = speed, thickness = thickness, size = size, side = side}
        end
      end)
      return list
    end,
    run = function(method, p, schedule) return wall_case(method, p, schedule, typed_wall) end,
  },
  {
    name = "horizontal wall hit from the side",
    about = "a slab typed horizontal, met end-on",
    cases = grid_cases,
    run = function(method, p, schedule)
      local S, T = p.size, p.thickness
      local slab = box(200, 100, 64, T, "horizontal")
      local steps, total = displacements(schedule, 8, p.speed)
      local mover = box(200 - S - total / 2, 100 + (T - S) / 2, S, S)
      local world = budge.new_world()
      world:add_solid(slab)
      world:add_actor(mover)
      local y = mover.y
      for i = 1, #steps do
        world:move(mover, steps[i], 0, method)
        if mover.y ~= y then return "teleported", "lifted off its path at step " .. i end
        if overlaps(mover, slab) then return "residual overlap", "inside the slab at step " .. i end
        if mover.x >= 264 then return "tunnelled", "passed through the slab at step " .. i end
      end
      return nil
    end,
  },
  {
    name = "vertical wall landed on",
    about = "a pillar typed vertical, met from above",
    cases = grid_cases,
    run = function(method, p, schedule)
      local S, T = p.size, p.thickness
      local pillar = box(100, 200, T, 64, "vertical")
      local steps, total = displacements(schedule, 8, p.speed)
      local mover = box(100 + (T - S) / 2, 200 - S - total / 2, S, S)
      local world = budge.new_world()
      world:add_solid(pillar)
      world:add_actor(mover)
      local x = mover.x
      for i = 1, #steps do
        world:move(mover, 0, steps[i], method)
        if mover.x ~= x then return "teleported", "thrown sideways at step " .. i end
        if overlaps(mover, pillar) then return "residual overlap", "inside the pillar at step " .. i end
        if mover.y >= 264 then return "tunnelled", "passed through the pillar at step " .. i end
      end
      return nil
    end,
  },
  {
    name = "block side hit",
    about = "an untyped square block met on its side (the fat cross's side hits)",
    cases = function(grid)
      local list = {}
      each(grid, function(speed, thickness, size)
        if thickness >= 2 then
          list[#list + 1] = {speed = speed, thickness = thickness, size = size, side = "left"}
        end
      end)
      return list
    end,
    run = function(method, p, schedule)
      local S, T = p.size, p.thickness
      local block = box(200, 100, T, T)
      local steps, total = displacements(schedule, 8, p.speed)
      local mover = box(200 - S - total / 2, 100 + (T - S) / 2, S, S)
      local world = budge.new_world()
      world:add_solid(block)
      world:add_actor(mover)
      local y = mover.y
      for i = 1, #steps do
        world:move(mover, steps[i], 0, method)
        if overlaps(mover, block) then return "residual overlap", "inside the block at step " .. i end
        if mover.y ~= y then return "teleported", "pushed off its path at step " .. i end
        if mover.x >= 200 + T then
          if mover.x == 200 + T then return "wrong side", "pushed out the far side at step " .. i end
          return "tunnelled", "passed through the block at step " .. i
        end
      end
      return nil
    end,
  },
  {
    name = "seams",
    about = "sliding along floors, walls and ceilings made of separate 16 px boxes",
    cases = function(grid)
      local list = {}
      for _, speed in ipairs(grid.speeds) do
        for _, size in ipairs(grid.sizes) do
          for _, surface in ipairs({"floor", "wall", "ceiling"}) do
            list[#list + 1] = {speed = speed, size = size, surface = surface}
          end
        end
      end
      return list
    end,
    run = function(method, p, schedule)
      local S = p.size
      local count = math.max(3, math.min(30, math.floor(640 / p.speed)))
      local steps, total = displacements(schedule, count, p.speed)
      local presses = displacements(schedule, count, 1)
      local tiles = math.ceil((total + 3 * S) / 16) + 2
      local world = budge.new_world()
      local mover
      for i = 0, tiles - 1 do
        if p.surface == "floor" then world:add_solid(box(i * 16, 100, 16, 16, "horizontal"))
        elseif p.surface == "ceiling" then world:add_solid(box(i * 16, 100, 16, 16, "horizontal"))
        else world:add_solid(box(100, i * 16, 16, 16, "vertical")) end
      end
      if p.surface == "floor" then mover = box(16.25, 100 - S, S, S)
      elseif p.surface == "ceiling" then mover = box(16.25, 116, S, S)
      else mover = box(100 - S, 16.25, S, S) end
      world:add_actor(mover)
      -- the expected position is summed the way a move sums it, step by step
      local rest_x, rest_y = mover.x, mover.y
      local expect_x, expect_y = rest_x, rest_y
      for i = 1, count do
        if p.surface == "wall" then expect_y = expect_y + steps[i] else expect_x = expect_x + steps[i] end
        if p.surface == "floor" then
          world:move(mover, steps[i], presses[i], method)
          if mover.y ~= rest_y then return "jitter", ("rose or sank to y=%g at step %d"):format(mover.y, i) end
          if mover.x ~= expect_x then return "snagged", "lost travel at step " .. i end
        elseif p.surface == "ceiling" then
          world:move(mover, steps[i], -presses[i], method)
          if mover.y ~= rest_y then return "jitter", ("moved off the ceiling at step %d"):format(i) end
          if mover.x ~= expect_x then return "snagged", "lost travel at step " .. i end
        else
          world:move(mover, presses[i], steps[i], method)
          if mover.x ~= rest_x then return "jitter", ("moved off the wall at step %d"):format(i) end
          if mover.y ~= expect_y then return "snagged", "lost or gained travel at step " .. i end
        end
      end
      return nil
    end,
  },
  {
    name = "corners",
    about = "exact and near corner hits at 30, 45 and 60 degrees",
    cases = function(grid)
      local list = {}
      for _, speed in ipairs(grid.speeds) do
        for _, size in ipairs(grid.sizes) do
          for _, angle in ipairs({30, 45, 60}) do
            for _, offset in ipairs({-1, 0, 1}) do
              list[#list + 1] = {speed = speed, size = size, angle = angle, offset = offset}
            end
          end
        end
      end
      return list
    end,
    -- The exact answer at a corner is the continuous model's: the straight path
    -- ("swept") or x first ("axis_sweep", the documented tie-free rule). A method passes
    -- when it never overlaps the block, is never pushed back past its start, and ends
    -- where one of the two ends.
    run = function(method, p, schedule)
      local S = p.size
      local steps, total = displacements(schedule, 8, p.speed)
      local ux, uy = math.cos(math.rad(p.angle)), math.sin(math.rad(p.angle))
      local function play(with, judge)
        local block = box(200, 200, 32, 32)
        -- the mover's bottom-right corner passes (200, 200 + offset) halfway through
        local mover = box(200 - S - ux * total / 2, 200 + p.offset - S - uy * total / 2, S, S)
        local world = budge.new_world()
        world:add_solid(block)
        world:add_actor(mover)
        local start_x, start_y = mover.x, mover.y
        for i = 1, #steps do
          world:move(mover, ux * steps[i], uy * steps[i], with)
          if judge and overlaps(mover, block) then
            return nil, nil, "residual overlap", "inside the block at step " .. i
          end
          if judge and (mover.x < start_x - 1e-9 or mover.y < start_y - 1e-9) then
            return nil, nil, "teleported", "pushed back past its start at step " .. i
          end
        end
        return mover.x, mover.y
      end
      local x, y, kind, why = play(method, true)
      if kind then return kind, why end
      for _, reference in ipairs({"swept", "axis_sweep"}) do
        local rx, ry = play(reference, false)
        if math.abs(x - rx) <= 1e-6 and math.abs(y - ry) <= 1e-6 then return nil end
      end
      if x + S / 2 > 216 and y + S / 2 > 216 then
        return "tunnelled", ("ended past the block at %.4g,%.4g"):format(x, y)
      end
      return "snagged", ("ended at %.4g,%.4g, not where the path stops"):format(x, y)
    end,
  },
  {
    name = "resting",
    about = "resting on a floor under gravity, without jitter",
    cases = grid_cases,
    run = function(method, p, schedule)
      local S, T = p.size, p.thickness
      local floor = box(0, 100.5, 200, T)
      local mover = box(50, 100.5 - S, S, S)
      local world = budge.new_world()
      world:add_solid(floor)
      world:add_actor(mover)
      local steps = displacements(schedule, 20, p.speed)
      for i = 1, #steps do
        world:move(mover, 0, steps[i], method)
        if mover.y ~= 100.5 - S then
          if mover.y >= 100.5 + T then return "tunnelled", "fell through at step " .. i end
          if overlaps(mover, floor) then return "residual overlap", "sank into the floor at step " .. i end
          return "jitter", ("moved to y=%.17g at step %d"):format(mover.y, i)
        end
      end
      return nil
    end,
  },
  {
    name = "squeezed",
    about = "an actor put 2 px into the right of two walls whose gap is 2 px too narrow",
    cases = speed_size_cases,
    run = function(method, p, schedule)
      local S = p.size
      local left, right = box(0, 0, 100, 200), box(100 + S - 2, 0, 100, 200)
      local mover = box(100, 50, S, S)
      local world = budge.new_world()
      world:add_solid(left)
      world:add_solid(right)
      world:add_actor(mover)
      local steps = displacements(schedule, 8, p.speed)
      for i = 1, #steps do
        world:move(mover, (i % 2 == 0 and 1 or -1) * steps[i], 0, method)
        if mover.x + S <= 100 or mover.x >= right.x then
          return "teleported", "ejected into a wall's far side at step " .. i
        end
      end
      return nil
    end,
  },
  {
    name = "order of solids",
    about = "the same scene with its solids added in reverse order must end the same",
    cases = speed_size_cases,
    run = function(method, p, schedule)
      local function play(reverse)
        local solids = {}
        for i = 0, 11 do
          solids[#solids + 1] = box(60 + (i % 4) * 16, 100 + math.floor(i / 4) * 16, 16, 16)
        end
        solids[#solids + 1] = box(0, 148, 200, 16)
        local world = budge.new_world()
        local first, last, step = 1, #solids, 1
        if reverse then first, last, step = last, 1, -1 end
        for i = first, last, step do world:add_solid(solids[i]) end
        local mover = world:add_actor(box(20, 60, p.size, p.size))
        local steps = displacements(schedule, 8, p.speed)
        for i = 1, #steps do world:move(mover, steps[i], steps[i] * 0.75, method) end
        return mover.x, mover.y
      end
      local x1, y1 = play(false)
      local x2, y2 = play(true)
      if x1 ~= x2 or y1 ~= y2 then
        return "order-dependent", ("ends at %.17g,%.17g or %.17g,%.17g"):format(x1, y1, x2, y2)
      end
      return nil
    end,
  },
  {
    name = "oneway from below",
    about = "jumping up through a oneway platform, then landing on it",
    long = true, -- needs travel: not replayed with 1e-5 s steps
    cases = grid_cases,
    run = function(method, p, schedule)
      local S, T = p.size, p.thickness
      local platform = box(0, 100, 200, T, "oneway")
      local mover = box(50, 100 + T + 4, S, S)
      local world = budge.new_world()
      world:add_solid(platform)
      world:add_actor(mover)
      local i = 0
      while mover.y + S > 100 do
        i = i + 1
        if i > 4000 then return "snagged", "never got above the platform" end
        local before = mover.y
        world:move(mover, 0, -p.speed * schedule.dt(i, 4000) * 60, method)
        if mover.y > before then return "snagged", "pushed down by the platform at step " .. i end
      end
      for k = 1, 4000 do
        world:move(mover, 0, p.speed * schedule.dt(k, 4000) * 60, method)
        if mover.y >= 100 + T then return "tunnelled", "fell through at step " .. k end
        if mover.y + S == 100 and k > 1 then return nil end
        if mover.y + S > 100 then return "residual overlap", "sank into it at step " .. k end
      end
      return "snagged", "never landed"
    end,
  },
  {
    name = "riding a moving platform",
    about = "standing on a platform that moves up, down and sideways",
    long = true,
    cases = grid_cases,
    run = function(method, p, schedule)
      local S, T = p.size, p.thickness
      local platform = box(0, 300, 64, T)
      local world = budge.new_world()
      world:add_solid(platform)
      local mover = world:add_actor(box(20, 300 - S, S, S))
      for i = 1, 24 do
        local d = p.speed * schedule.dt(i, 24) * 60
        local phase = math.floor((i - 1) / 6) % 4
        local dx, dy = 0, 0
        if phase == 0 then dy = -d elseif phase == 1 then dx = d
        elseif phase == 2 then dy = d else dx = -d end
        world:move_solid(platform, dx, dy)
        world:move(mover, 0, 1, method) -- gravity pressing it down
        if mover.y ~= platform.y - S then
          if mover.y >= platform.y + T then return "tunnelled", "fell through at frame " .. i end
          return "jitter", ("off the top by %.3g at frame %d"):format(platform.y - S - mover.y, i)
        end
      end
      return nil
    end,
  },
}

---Runs `fn(scene, case, schedule)` for every case of the catalogue at `level` ("full" or
---"spec"), in a fixed order.
function scenarios.each_case(level, fn)
  local grid = GRIDS[level]
  for _, scene in ipairs(scenarios.SCENES) do
    local cases = scene.cases(grid)
    for _, schedule in ipairs(scenarios.SCHEDULES) do
      if not (scene.long and schedule.name == "tiny") then
        if level == "full" or schedule.name ~= "jittered" then
          for _, case in ipairs(cases) do fn(scene, case, schedule) end
        end
      end
    end
  end
end

---Runs one method over the catalogue. Returns {total, passed, by_kind = {kind = n},
---failures = {{scene, case, schedule, kind, why}...}}.
function scenarios.score(method, level)
  local result = {method = method, total = 0, passed = 0, by_kind = {}, failures = {}}
  for _, kind in ipairs(scenarios.KINDS) do result.by_kind[kind] = 0 end
  scenarios.each_case(level, function(scene, case, schedule)
    result.total = result.total + 1
    local kind, why = scene.run(method, case, schedule)
    if kind == nil then
      result.passed = result.passed + 1
    else
      result.by_kind[kind] = result.by_kind[kind] + 1
      result.failures[#result.failures + 1] = {scene = scene.name, case = case,
        schedule = schedule.name, kind = kind, why = why}
    end
  end)
  return result
end

-- Envelopes: the largest speed (px per step) at which a discrete method still stops a
-- 12 px mover that starts flush against a wall of thickness T (256 long, so the other
-- axis never offers a shorter way out) and moves into it in one step, from its worst
-- side. The analytic bound beside it, derived in the README; `inclusive` says whether the
-- bound itself is safe.
scenarios.ENVELOPES = {
  {method = "seed", side = "right", typed = true,
    bound = function(_, T) return T / 2 end, inclusive = true},
  {method = "wall_type", side = "right", typed = true,
    bound = function(S, T) return (S + T) / 2 end, inclusive = false},
  {method = "min_axis", side = "right", typed = false,
    bound = function(S, T) return (S + T) / 2 end, inclusive = false},
  {method = "fat_cross", side = "left", typed = false,
    bound = function(_, T) return 0.375 * T end, inclusive = true},
}

---True when `method` stops the mover (size S) flush at a wall of thickness T after one
---step of `speed` from `side`.
function scenarios.holds(method, side, typed, T, S, speed)
  local horizontal = side == "left" or side == "right"
  local wall = horizontal and box(200, 0, T, 256) or box(0, 200, 256, T)
  if typed then wall.wall_type = horizontal and "vertical" or "horizontal" end
  local direction = APPROACH[side]
  local mover = box(0, 0, S, S)
  if horizontal then
    mover.y = 128 - S / 2
    mover.x = direction[1] > 0 and 200 - S or 200 + T
  else
    mover.x = 128 - S / 2
    mover.y = direction[2] > 0 and 200 - S or 200 + T
  end
  local x, y = mover.x, mover.y
  local world = budge.new_world()
  world:add_solid(wall)
  world:add_actor(mover)
  world:move(mover, direction[1] * speed, direction[2] * speed, method)
  return mover.x == x and mover.y == y
end

---The largest speed, on a 1/64 px grid, up to which every speed holds.
function scenarios.safe_speed(envelope, T, S)
  local step = 1 / 64
  local speed = step
  while speed <= S + T + 1 and scenarios.holds(envelope.method, envelope.side, envelope.typed,
    T, S, speed) do
    speed = speed + step
  end
  return speed - step
end

scenarios.THICKNESS = THICKNESS

---A one-line description of a case, for failure messages.
function scenarios.describe(failure)
  local parts = {}
  for _, key in ipairs({"side", "surface", "speed", "thickness", "size", "angle", "offset"}) do
    if failure.case[key] ~= nil then parts[#parts + 1] = key .. "=" .. tostring(failure.case[key]) end
  end
  return ("%s [%s] %s: %s (%s)"):format(failure.scene, failure.schedule, table.concat(parts, " "),
    failure.kind, failure.why)
end

return scenarios
