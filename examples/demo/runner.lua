-- examples/demo/runner.lua: the platformer's runners, game logic shared by the lab
-- (examples/demo) and bench/jit.lua: run, jump from the ground, fall, land.
local logic = {}

local GRAVITY, MAX_FALL, RUN, JUMP = 0.45, 10, 2.5, -7.5
logic.MAX_FALL = MAX_FALL

function logic.new_runner(x, y, direction, jump_every)
  return {x = x, y = y, width = 12, height = 14, vx = 0, vy = 0, on_ground = false,
    direction = direction, jump_every = jump_every, stuck = 0, last_x = x}
end

---A runner's scripted input for `frame`: run one way, jump every few frames, turn after
---20 frames stuck. Returns left, right, jump.
function logic.runner_input(runner, frame)
  if math.abs(runner.x - runner.last_x) < 0.01 then runner.stuck = runner.stuck + 1 else runner.stuck = 0 end
  runner.last_x = runner.x
  if runner.stuck > 20 then runner.direction, runner.stuck = -runner.direction, 0 end
  return runner.direction < 0, runner.direction > 0, frame % runner.jump_every == 0
end

---One frame of a runner: run, jump from the ground, fall, and land or bump its head on
---the contacts `move(owner, runner, dx, dy)` reports (world.move with its world, or the
---lab's move). Returns the contacts: n, hits.
function logic.step_runner(runner, left, right, jump, move, owner)
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

return logic
