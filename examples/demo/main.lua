-- The budge lab: the same scene under each collision method, with every failure marked
-- where it happens and counted.
--
--   love examples/demo                      interactive (keys on screen)
--   love examples/demo --scene speed --method seed --frames 240 --screenshot out.png
--                                           scripted: fixed dt, scripted input, a PNG,
--                                           a one-line verdict, exit 1 on a wrong outcome
--   ... --keys 20:m,60:3                    presses keys at those frames (the verdict
--                                           is the last scene's, under the last method)
--
-- The library is loaded from the repository's src/, never copied here.
local source = love.filesystem.getSource()
local root = source .. "/../.."
package.path = root .. "/src/?.lua;" .. root .. "/src/?/init.lua;" .. root .. "/?.lua;"
  .. source .. "/?.lua;" .. package.path

-- The lab runs every move twice (the method, and the exact sweep it is judged against)
-- plus its checks: more compiled code than LuaJIT's defaults hold (1000 traces, 512 KB
-- of machine code), and LuaJIT would throw it all away and recompile over and over.
if jit then jit.opt.start("maxtrace=4000", "maxmcode=4096") end

local budge = require("budge")
local Lab = require("lab")
local scenes = require("scenes")

local DT = 1 / 60
local KIND_COLORS = {
  tunnelled = {1, 0.2, 0.2}, ["wrong side"] = {1, 0.2, 0.8}, ["residual overlap"] = {1, 0.5, 0},
  snagged = {1, 1, 0.2}, teleported = {0.7, 0.3, 1},
}

local options = {scene = "1", method = "axis_sweep"}
local scripted = false
local current = {scene = 1, method = "axis_sweep"}
local lab, state
local frame = 0 -- frames since the scene (re)started
local total_frames = 0 -- frames since the lab started
local show_help = true
local input = {left = false, right = false, jump = false}
local fonts = {}

local function fail_fast(message)
  io.stderr:write(("budge lab: %s\n"):format(message))
  os.exit(2)
end

local function parse_args(args)
  local i = 1
  while i <= #args do
    local key, value = args[i], args[i + 1]
    if key == "--scene" or key == "--method" or key == "--frames" or key == "--screenshot"
        or key == "--keys" then
      if value == nil then fail_fast(key .. " needs a value") end
      options[key:sub(3)] = value
      i = i + 2
    else
      i = i + 1 -- LÖVE's own arguments
    end
  end
  options.presses = {}
  for at, key in (options.keys or ""):gmatch("(%d+):([%w]+)") do
    options.presses[#options.presses + 1] = {frame = tonumber(at), key = key}
  end
  if options.frames then
    scripted = true
    options.frames = tonumber(options.frames)
    if not options.frames or options.frames < 1 then fail_fast("--frames must be a number >= 1") end
  end
end

local function start(scene_index, method)
  current.scene, current.method = scene_index, method
  lab = Lab.new(method)
  state = scenes[scene_index].load(lab)
  frame = 0
end

local function method_index(method)
  for i, name in ipairs(Lab.METHODS) do if name == method then return i end end
  return nil
end

function love.load(args)
  parse_args(args or {})
  local scene_index = scenes.find(options.scene)
  if not scene_index then fail_fast("unknown --scene " .. tostring(options.scene)) end
  if not method_index(options.method) then
    fail_fast("unknown --method " .. tostring(options.method) .. " (one of "
      .. table.concat(Lab.METHODS, ", ") .. ")")
  end
  if scripted then
    -- an error must end the run with a message, not wait for a key
    love.errorhandler = function(message)
      io.stderr:write(debug.traceback("budge lab error: " .. tostring(message), 2), "\n")
      os.exit(1)
    end
  end
  fonts.hud = love.graphics.newFont(14)
  fonts.small = love.graphics.newFont(12)
  love.graphics.setFont(fonts.small)
  start(scene_index, options.method)
end

local WARMUP_FRAMES = 120 -- LuaJIT compiles first; moves are timed after this

local function step()
  frame = frame + 1
  total_frames = total_frames + 1
  for _, press in ipairs(options.presses) do -- scripted key presses (--keys 20:m,40:3)
    if press.frame == total_frames then love.keypressed(press.key) end
  end
  lab.timing = frame > WARMUP_FRAMES
  scenes[current.scene].update(state, lab, input, scripted)
  lab:tick()
  input.jump = false
end

local accumulator = 0
function love.update(dt)
  if scripted then
    if total_frames < options.frames then step() end
    return
  end
  accumulator = math.min(accumulator + dt, 0.25)
  while accumulator >= DT do
    input.left = love.keyboard.isDown("left", "a")
    input.right = love.keyboard.isDown("right", "d")
    step()
    accumulator = accumulator - DT
  end
end

function love.keypressed(key)
  if key == "escape" then love.event.quit(0) end
  if key == "space" or key == "up" or key == "w" then input.jump = true end
  local number = tonumber(key)
  if number and scenes[number] then start(number, current.method) end
  if key == "m" or key == "tab" then
    local direction = love.keyboard.isDown("lshift", "rshift") and -1 or 1
    local i = (method_index(current.method) - 1 + direction) % #Lab.METHODS + 1
    start(current.scene, Lab.METHODS[i])
  end
  if key == "r" then start(current.scene, current.method) end
  if key == "h" then show_help = not show_help end
end

-- Failures are drawn in the scene's coordinates, over it, each with its kind.
local function draw_marks(gfx, scale)
  gfx.setLineWidth(2 / scale)
  local grow = (scale < 1 and 6 or 3) / scale
  for _, mark in ipairs(lab.marks) do
    local color = KIND_COLORS[mark.kind]
    gfx.setColor(color[1], color[2], color[3], math.min(1, mark.ttl / 30))
    gfx.rectangle("line", mark.x - grow, mark.y - grow, mark.width + 2 * grow, mark.height + 2 * grow)
    if scale >= 1 then gfx.print(mark.kind, mark.x + mark.width + 4, mark.y - 12, 0, 1 / scale) end
  end
  gfx.setLineWidth(1)
end

local function draw_hud(gfx)
  local scene = scenes[current.scene]
  gfx.setFont(fonts.hud)
  gfx.setColor(0, 0, 0, 0.75)
  gfx.rectangle("fill", 0, 0, 1024, 44)
  gfx.setColor(1, 1, 1)
  gfx.print(("%d  %s"):format(current.scene, scene.title), 8, 4)
  local line = ("method: %s%s   %s per move   frame %d   failures:"):format(current.method,
    Lab.CONTINUOUS[current.method] and " (continuous)" or " (discrete)", lab:speed_text(), frame)
  gfx.print(line, 8, 24)
  local x = 8 + fonts.hud:getWidth(line) + 10
  if lab.total_failures == 0 then
    gfx.setColor(0.5, 1, 0.5)
    gfx.print("none", x, 24)
  else
    for _, kind in ipairs(Lab.KINDS) do
      local count = lab.failures[kind]
      if count then
        gfx.setColor(KIND_COLORS[kind])
        local text = ("%s %d"):format(kind, count)
        gfx.print(text, x, 24)
        x = x + fonts.hud:getWidth(text) + 16
      end
    end
  end
  gfx.setFont(fonts.small)
  if show_help then
    gfx.setColor(0, 0, 0, 0.75)
    gfx.rectangle("fill", 0, 748, 1024, 20)
    gfx.setColor(0.85, 0.85, 0.85)
    gfx.print("1-5 scene   M / Tab next method (Shift: previous)   R restart   arrows or A/D run, "
      .. "Space jump (platformer)   H help   Esc quit      budge " .. budge._VERSION, 8, 751)
  end
end

local function finish()
  love.graphics.captureScreenshot(function(image)
    local ok, verdict = scenes[current.scene].verdict(state, lab)
    if options.screenshot then
      local file = io.open(options.screenshot, "wb")
      if not file then
        io.stderr:write("budge lab: cannot write " .. options.screenshot .. "\n")
        os.exit(1)
      end
      file:write(image:encode("png"):getString())
      file:close()
    end
    print(("%s scene %s, method %s, %d frames, %s per move: %s"):format(
      ok and "PASS" or "FAIL", scenes[current.scene].name, current.method, frame,
      lab:speed_text(), verdict))
    io.stdout:flush()
    os.exit(ok and 0 or 1)
  end)
end

local finishing = false
function love.draw()
  local gfx = love.graphics
  gfx.clear(0.08, 0.09, 0.12)
  local view = scenes[current.scene].view or {0, 0, 1}
  gfx.push()
  gfx.translate(view[1], view[2])
  gfx.scale(view[3])
  scenes[current.scene].draw(state, lab, gfx)
  draw_marks(gfx, view[3])
  gfx.pop()
  draw_hud(gfx)
  if scripted and total_frames >= options.frames and not finishing then
    finishing = true
    finish()
  end
end
