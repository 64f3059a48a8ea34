-- bench/levels.lua: hand-made levels shared by the specs, the benches and the demo.
-- "#" is a solid tile, "=" a oneway platform, "P" the player's start, "." free.
local levels = {}

levels.TILE = 16

-- A platformer level of 50x30 tiles: floors with steps, walls to slide down, floating
-- blocks to land on and bump into, ledges with corners, oneway platforms, a pit.
levels.platformer = {
  "##################################################",
  "#................................................#",
  "#................................................#",
  "#.........................................####...#",
  "#....######..............................#.......#",
  "#.........#.....................====.....#.......#",
  "#.........#..............................#.......#",
  "#.........#.........##...................#...##..#",
  "#.........#.........##...........................#",
  "#.........#...................................####",
  "#..................................###...........#",
  "#........................====....................#",
  "#...###..........................................#",
  "#............#####...............................#",
  "#................#.........................=====.#",
  "#................#...........##..................#",
  "#................#...........##..................#",
  "#......====......#...............................#",
  "#................#.......................###.....#",
  "#......................####..............#.......#",
  "#.....................##.................#.......#",
  "#.......##...........###.................#.......#",
  "#.......##..........####....====.........#.......#",
  "#..................#####.................#.......#",
  "#...P.............######.................#.......#",
  "###########....##########.....############.......#",
  "#.........#....#........#.....#..........#.......#",
  "#.........#....#........#.....#..........#.......#",
  "#.........######........#######..........#########",
  "##################################################",
}

---The level as a 2D grid of ids: 1 solid, 2 oneway, 0 free; and the player's start
---(top-left corner of its tile, in px).
function levels.grid(name)
  local rows, start_x, start_y = {}, 0, 0
  for row, line in ipairs(levels[name]) do
    local ids = {}
    for col = 1, #line do
      local char = line:sub(col, col)
      ids[col] = char == "#" and 1 or char == "=" and 2 or 0
      if char == "P" then start_x, start_y = (col - 1) * levels.TILE, (row - 1) * levels.TILE end
    end
    rows[row] = ids
  end
  return rows, start_x, start_y
end

function levels.is_oneway(id) return id == 2 end

-- Runners: the platformer's movers, shared by the lab (examples/demo) and bench/jit.lua.
local GRAVITY, MAX_FALL, RUN, JUMP = 0.45, 10, 2.5, -7.5
levels.MAX_FALL = MAX_FALL

function levels.new_runner(x, y, direction, jump_every)
  return {x = x, y = y, width = 12, height = 14, vx = 0, vy = 0, on_ground = false,
    direction = direction, jump_every = jump_every, stuck = 0, last_x = x}
end

---A runner's scripted input for `frame`: run one way, jump every few frames, turn after
---20 frames stuck. Returns left, right, jump.
function levels.runner_input(runner, frame)
  if math.abs(runner.x - runner.last_x) < 0.01 then runner.stuck = runner.stuck + 1 else runner.stuck = 0 end
  runner.last_x = runner.x
  if runner.stuck > 20 then runner.direction, runner.stuck = -runner.direction, 0 end
  return runner.direction < 0, runner.direction > 0, frame % runner.jump_every == 0
end

---One frame of a runner: run, jump from the ground, fall, and land or bump its head on
---the contacts `move(owner, runner, dx, dy)` reports (world.move with its world, or the
---lab's move). Returns the contacts: n, hits.
function levels.step_runner(runner, left, right, jump, move, owner)
  runner.vx = (right and RUN or 0) - (left and RUN or 0)
  if jump and runner.on_ground then runner.vy = JUMP end
  runner.vy = math.min(runner.vy + GRAVITY, MAX_FALL)
  local _, _, n, hits = move(owner, runner, runner.vx, runner.vy)
  runner.on_ground = false
  for i = 1, n do
    local side = hits[i].side
    if side == "floor" then runner.on_ground = true; runner.vy = 0 end
    if side == "ceiling" and runner.vy < 0 then runner.vy = 0 end
  end
  return n, hits
end

return levels
