-- The lab's scenes. Each scene builds itself into a Lab (lab.lua), steps once per frame
-- at a fixed 1/60 s, draws itself, and says whether the run showed what it should:
-- the continuous methods never fail anywhere; the discrete ones fail where the README's
-- envelopes say they do.
local levels = require("fixtures.levels")
local bench_scene = require("fixtures.scene")
local Lab = require("lab")
local runner_logic = require("runner")

local scenes = {}

local box = require("fixtures.box")

-- verdict helpers ---------------------------------------------------------------------
local function continuous_clean(lab)
  if lab.total_failures == 0 then return true, "no failure" end
  return false, "a continuous method failed: " .. lab:summary()
end

local function expect_failures(lab, what)
  if Lab.CONTINUOUS[lab.method] then return continuous_clean(lab) end
  if lab.total_failures > 0 then return true, what .. ": " .. lab:summary() end
  return false, lab.method .. " should fail here (" .. what .. ") but did not"
end

-- drawing helpers ---------------------------------------------------------------------
local SIDE_COLOR = {1, 0.95, 0.2}

local function draw_contacts(gfx, actor)
  local sides = actor.contacts
  if not sides then return end
  gfx.setColor(SIDE_COLOR)
  gfx.setLineWidth(3)
  local x, y, w, h = actor.x, actor.y, actor.width, actor.height
  if sides.floor then gfx.line(x, y + h, x + w, y + h) end
  if sides.ceiling then gfx.line(x, y, x + w, y) end
  if sides.left then gfx.line(x, y, x, y + h) end
  if sides.right then gfx.line(x + w, y, x + w, y + h) end
  gfx.setLineWidth(1)
end

local function remember_contacts(actor, n, hits)
  local sides = actor.contacts or {}
  sides.floor, sides.ceiling, sides.left, sides.right = nil, nil, nil, nil
  for i = 1, n do sides[hits[i].side] = true end
  actor.contacts = sides
end

-- The fat cross the world builds for a block at this speed (capped at 3/8 of its
-- smaller side), drawn as two outlines.
local function draw_cross(gfx, x, y, width, height, speed)
  local smaller = math.min(width, height)
  local inset = math.min(speed, smaller * 0.375)
  gfx.setColor(0.3, 0.8, 1, 0.8)
  gfx.rectangle("line", x + inset, y, width - 2 * inset, height)
  gfx.rectangle("line", x, y + inset, width, height - 2 * inset)
end

local function draw_tiles(gfx, rows, tile, lab, speed, crosses)
  for row = 1, #rows do
    local line = rows[row]
    for col = 1, #line do
      local id = line[col]
      if id ~= 0 and id ~= false then
        local x, y = (col - 1) * tile, (row - 1) * tile
        if levels.is_oneway(id) then
          gfx.setColor(0.75, 0.55, 0.3)
          gfx.rectangle("fill", x, y, tile, 4)
        else
          gfx.setColor(0.35, 0.38, 0.45)
          gfx.rectangle("fill", x, y, tile, tile)
          if lab.method == "fat_cross" and crosses then draw_cross(gfx, x, y, tile, tile, speed) end
        end
      end
    end
  end
end

local function draw_solid(gfx, solid, lab, speed, color)
  if solid.wall_type == "oneway" then
    gfx.setColor(0.75, 0.55, 0.3)
    gfx.rectangle("fill", solid.x, solid.y, solid.width, 4)
  else
    gfx.setColor(color or {0.35, 0.38, 0.45})
    gfx.rectangle("fill", solid.x, solid.y, solid.width, solid.height)
    if lab.method == "fat_cross" then
      draw_cross(gfx, solid.x, solid.y, solid.width, solid.height, speed)
    end
  end
end

local function draw_actor(gfx, actor, color)
  gfx.setColor(color or {0.4, 0.9, 0.5})
  gfx.rectangle("fill", actor.x, actor.y, actor.width, actor.height)
  draw_contacts(gfx, actor)
end

-- 1. the platformer -------------------------------------------------------------------
local MAX_FALL = runner_logic.MAX_FALL

scenes[1] = {
  name = "platformer",
  title = "Platformer: a tile level with seams, corners, oneway and moving platforms",
  view = {12, 52, 1.25},
  load = function(lab)
    local rows, start_x, start_y = levels.grid("platformer")
    local state = {rows = rows, tile = levels.TILE, frame = 0, platforms = {}}
    lab:add_tiles(rows, levels.TILE, {is_oneway = levels.is_oneway})
    -- two moving platforms: one across the pit, one lift
    state.platforms[1] = {solid = lab:add_solid(box(176, 400, 48, 8)), dx = 1, range = {176, 240}}
    state.platforms[2] = {solid = lab:add_solid(box(704, 240, 48, 8)), dy = -1, range = {160, 400}}
    state.player = lab:add_actor(runner_logic.new_runner(start_x + 2, start_y + 2, 1, 37))
    state.runners = {state.player}
    local starts = {{100, 40, 1, 29}, {300, 100, -1, 41}, {520, 100, 1, 53}, {680, 300, -1, 31},
      {420, 300, 1, 47}, {60, 200, 1, 23}}
    for _, s in ipairs(starts) do
      state.runners[#state.runners + 1] = lab:add_actor(runner_logic.new_runner(s[1], s[2], s[3], s[4]))
    end
    return state
  end,
  update = function(state, lab, input, scripted)
    state.frame = state.frame + 1
    for _, platform in ipairs(state.platforms) do
      local solid = platform.solid
      if platform.dx then
        if solid.x <= platform.range[1] then platform.dx = 1 end
        if solid.x >= platform.range[2] then platform.dx = -1 end
        lab.world:move_solid(solid, platform.dx, 0)
      else
        if solid.y <= platform.range[1] then platform.dy = 1 end
        if solid.y >= platform.range[2] then platform.dy = -1 end
        lab.world:move_solid(solid, 0, platform.dy)
      end
    end
    for i, runner in ipairs(state.runners) do
      local left, right, jump
      if i == 1 and not scripted then
        left, right, jump = input.left, input.right, input.jump
      else
        left, right, jump = runner_logic.runner_input(runner, state.frame)
      end
      remember_contacts(runner, runner_logic.step_runner(runner, left, right, jump, lab.move, lab))
    end
  end,
  draw = function(state, lab, gfx)
    draw_tiles(gfx, state.rows, state.tile, lab, MAX_FALL, true)
    for _, platform in ipairs(state.platforms) do
      draw_solid(gfx, platform.solid, lab, MAX_FALL, {0.2, 0.75, 0.7})
    end
    for i, runner in ipairs(state.runners) do
      draw_actor(gfx, runner, i == 1 and {0.3, 1, 0.45} or {0.55, 0.75, 1})
    end
  end,
  verdict = function(state, lab)
    local inside = 0
    for _, runner in ipairs(state.runners) do
      if runner.y > #state.rows * state.tile or runner.y < -100 then inside = inside + 1 end
    end
    if Lab.CONTINUOUS[lab.method] then
      if inside > 0 then return false, inside .. " runners left the level" end
      return continuous_clean(lab)
    end
    return expect_failures(lab, "runners snag or teleport on the tiles")
  end,
}

-- 2. the corner gallery ---------------------------------------------------------------
local ANGLES = {30, 45, 60}
local OFFSETS = {-3, 0, 3}

scenes[2] = {
  name = "corners",
  title = "Corner gallery: movers aimed at block corners at 30, 45 and 60 degrees",
  load = function(lab)
    local state = {shots = {}, blocks = {}, frame = 0}
    state.floor = lab:add_solid(box(0, 740, 1024, 28, "horizontal"))
    for i, angle in ipairs(ANGLES) do
      for j, offset in ipairs(OFFSETS) do
        local bx, by = 110 + (j - 1) * 300, 120 + (i - 1) * 220
        local block = lab:add_solid(box(bx, by, 48, 48))
        state.blocks[#state.blocks + 1] = block
        local radians = math.rad(angle)
        local speed = 7
        local vx, vy = math.cos(radians) * speed, math.sin(radians) * speed
        -- aimed so that its bottom-right corner meets the block's top-left corner (+offset)
        local travel = 80
        local shot = {x = bx - 10 - vx / speed * travel + offset, y = by - 10 - vy / speed * travel,
          width = 10, height = 10, vx = vx, vy = vy, age = 0}
        shot.start_x, shot.start_y = shot.x, shot.y
        state.shots[#state.shots + 1] = lab:add_actor(shot)
      end
    end
    return state
  end,
  update = function(state, lab)
    state.frame = state.frame + 1
    for _, shot in ipairs(state.shots) do
      shot.age = shot.age + 1
      if shot.age > 40 then
        shot.x, shot.y, shot.age = shot.start_x, shot.start_y, 0
        lab.world:update(shot)
      else
        local _, _, n, hits = lab:move(shot, shot.vx, shot.vy)
        remember_contacts(shot, n, hits)
      end
    end
  end,
  draw = function(state, lab, gfx)
    for _, block in ipairs(state.blocks) do draw_solid(gfx, block, lab, 7) end
    draw_solid(gfx, state.floor, lab, 7)
    for _, shot in ipairs(state.shots) do
      gfx.setColor(1, 1, 1, 0.25)
      gfx.line(shot.start_x + 10, shot.start_y + 10, shot.start_x + 10 + shot.vx * 40,
        shot.start_y + 10 + shot.vy * 40)
      draw_actor(gfx, shot, {1, 0.6, 0.2})
    end
  end,
  verdict = function(_, lab) return expect_failures(lab, "corner hits go wrong") end,
}

-- 3. the speed range ------------------------------------------------------------------
local SPEEDS = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512}
local THICKNESS = {1, 4, 16}
local WALL_X, BULLET_X = 640, 200

scenes[3] = {
  name = "speed",
  title = "Speed range: bullets at 1 to 512 px per frame against walls 1, 4 and 16 px thick",
  load = function(lab)
    local state = {lanes = {}, passed = 0}
    local lane_height = 22
    for t, thickness in ipairs(THICKNESS) do
      for s, speed in ipairs(SPEEDS) do
        local y = 60 + ((t - 1) * #SPEEDS + (s - 1)) * lane_height
        local wall = lab:add_solid(box(WALL_X, y, thickness, lane_height - 4))
        local bullet = lab:add_actor(box(BULLET_X, y + 6, 6, 6))
        state.lanes[#state.lanes + 1] = {wall = wall, bullet = bullet, speed = speed,
          thickness = thickness, y = y, passed = 0, rest = 0}
      end
    end
    return state
  end,
  update = function(state, lab)
    for _, lane in ipairs(state.lanes) do
      local bullet = lane.bullet
      if lane.rest > 0 then
        lane.rest = lane.rest - 1
        if lane.rest == 0 then bullet.x = BULLET_X; lab.world:update(bullet) end
      else
        local before = bullet.x
        local _, _, n, hits = lab:move(bullet, lane.speed, 0)
        remember_contacts(bullet, n, hits)
        if bullet.x >= lane.wall.x + lane.thickness then
          lane.passed, state.passed = lane.passed + 1, state.passed + 1
          lane.rest = 20
        elseif bullet.x == before then
          lane.rest = 20 -- stopped at the wall
        end
      end
    end
  end,
  draw = function(state, lab, gfx)
    for _, lane in ipairs(state.lanes) do
      draw_solid(gfx, lane.wall, lab, lane.speed)
      gfx.setColor(0.8, 0.8, 0.8)
      gfx.print(("%3d px/frame, wall %2d px"):format(lane.speed, lane.thickness), 12, lane.y + 2)
      if lane.passed > 0 then
        gfx.setColor(1, 0.3, 0.3)
        gfx.print(("passed %d"):format(lane.passed), 900, lane.y + 2)
      end
      draw_actor(gfx, lane.bullet, {1, 0.85, 0.3})
    end
  end,
  verdict = function(state, lab)
    if Lab.CONTINUOUS[lab.method] then
      if state.passed > 0 then return false, state.passed .. " bullets passed a wall" end
      return continuous_clean(lab)
    end
    if state.passed > 0 then return true, state.passed .. " bullets passed a wall" end
    return false, lab.method .. " should let fast bullets through but did not"
  end,
}

-- 4. the fat-cross blocks -------------------------------------------------------------
local CROSS_SPEEDS = {4, 8, 12, 16, 20, 24}

scenes[4] = {
  name = "fatcross",
  title = "Fat cross: 32 px blocks hit from the side and from above at 4 to 24 px per frame",
  view = {40, 50, 2},
  load = function(lab)
    local state = {pairs = {}}
    for i, speed in ipairs(CROSS_SPEEDS) do
      local bx, by = 110 + ((i - 1) % 3) * 150, 110 + math.floor((i - 1) / 3) * 170
      local block = lab:add_solid(box(bx, by, 32, 32))
      -- a whole number of steps from flush, so the hit goes exactly `speed` deep: the
      -- worst case the envelopes are about
      local back = speed * math.ceil(80 / speed)
      local side = lab:add_actor(box(bx - 12 - back, by + 10, 12, 12))
      local top = lab:add_actor(box(bx + 10, by - 12 - back, 12, 12))
      state.pairs[i] = {block = block, side = side, top = top, speed = speed,
        side_start = side.x, side_y = side.y, top_start = top.y, age = 0}
    end
    return state
  end,
  update = function(state, lab)
    for _, pair in ipairs(state.pairs) do
      pair.age = pair.age + 1
      if pair.age > 30 then
        pair.age = 0
        pair.side.x, pair.side.y = pair.side_start, pair.side_y
        pair.top.x, pair.top.y = pair.block.x + 10, pair.top_start
        lab.world:update(pair.side)
        lab.world:update(pair.top)
      else
        local _, _, n, hits = lab:move(pair.side, pair.speed, 0)
        remember_contacts(pair.side, n, hits)
        _, _, n, hits = lab:move(pair.top, 0, pair.speed)
        remember_contacts(pair.top, n, hits)
      end
    end
  end,
  draw = function(state, lab, gfx)
    for _, pair in ipairs(state.pairs) do
      draw_solid(gfx, pair.block, lab, pair.speed)
      if lab.method ~= "fat_cross" then
        draw_cross(gfx, pair.block.x, pair.block.y, 32, 32, pair.speed)
      end
      gfx.setColor(0.8, 0.8, 0.8)
      gfx.print(("%d px/frame, inset %g"):format(pair.speed, math.min(pair.speed, 12)),
        pair.block.x - 30, pair.block.y + 40, 0, 0.5)
      draw_actor(gfx, pair.side, {1, 0.6, 0.2})
      draw_actor(gfx, pair.top, {0.6, 0.8, 1})
    end
  end,
  verdict = function(_, lab)
    -- the README's bounds for a 12 px mover and a 32 px block: seed < S + T/2 = 28 from
    -- the left and the top; the shortest way out < (S + T)/2 = 22; the cross <= 12
    local bound = ({seed = {28, "of 28 and more"}, wall_type = {22, "of 22 and more"},
      min_axis = {22, "of 22 and more"}, fat_cross = {12, "above 12"}})[lab.method]
    if not bound then return continuous_clean(lab) end
    local fastest = CROSS_SPEEDS[#CROSS_SPEEDS]
    if fastest > bound[1] or (fastest == bound[1] and lab.method ~= "fat_cross") then
      return expect_failures(lab, ("hits at speeds %s px per frame fail"):format(bound[2]))
    end
    if lab.total_failures == 0 then return true, "every speed is inside the envelope: no failure" end
    return false, "failed inside its envelope: " .. lab:summary()
  end,
}

-- 5. the crowd ------------------------------------------------------------------------
local CROWD_SCALE = 0.22

scenes[5] = {
  name = "crowd",
  title = "Crowd: 1000 actors sliding around the world bench's 200x200 tile map",
  load = function(lab)
    local grid = bench_scene.make_scene(12345)
    local rows = {}
    for r = 1, #grid do
      rows[r] = {}
      for c = 1, #grid[r] do rows[r][c] = grid[r][c] and 1 or 0 end
    end
    local starts = bench_scene.make_actors(grid, require("fixtures.random").new(13345), 1000)
    local state = {rows = rows, actors = {}}
    lab:add_tiles(rows, bench_scene.TILE)
    for i, s in ipairs(starts) do
      state.actors[i] = lab:add_actor({x = s.x, y = s.y, width = bench_scene.SIZE,
        height = bench_scene.SIZE, dx = s.dx, dy = s.dy})
    end
    return state
  end,
  update = function(state, lab)
    for _, actor in ipairs(state.actors) do lab:move(actor, actor.dx, actor.dy) end
  end,
  view = {160, 46, CROWD_SCALE},
  draw = function(state, lab, gfx)
    draw_tiles(gfx, state.rows, bench_scene.TILE, lab, 8, false)
    gfx.setColor(0.4, 0.9, 0.5)
    for _, actor in ipairs(state.actors) do
      gfx.rectangle("fill", actor.x, actor.y, actor.width, actor.height)
    end
  end,
  verdict = function(_, lab)
    return expect_failures(lab, "diagonal movers snag on tile corners")
  end,
}

function scenes.find(key)
  local number = tonumber(key)
  if number and scenes[number] then return number end
  for i, scene in ipairs(scenes) do
    if scene.name == key then return i end
  end
  return nil
end

return scenes
