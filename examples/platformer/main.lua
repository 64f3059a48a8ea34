-- examples/platformer/main.lua: the platformer under LÖVE.
--
--   love examples/platformer                      play: arrows or A/D run, Z/Space/Up jump,
--                                                 Down drops through a platform, X shoots,
--                                                 R restarts, Esc quits
--   love examples/platformer --script S [--frames N] [--screenshot out.png]
--                                                 plays scripts/S.lua at a fixed 1/60 s,
--                                                 writes the PNG, prints the verdict and
--                                                 exits 1 on a wrong outcome
--
-- budge is found beside this folder's parent's src/ (the repository), or in a budge/
-- folder copied next to this file.
local source = love.filesystem.getSource()
package.path = source .. "/?.lua;" .. source .. "/?/init.lua;" .. source .. "/../../src/?.lua;"
  .. source .. "/../../src/?/init.lua;" .. package.path

local game = require("game")
local draw = require("draw")
local outcome = require("outcome")

local DT = 1 / 60
local options = {}
local run, script, scripted_input, keys_input
local frame, accumulator, finishing = 0, 0, false

local function new_run()
  run = game.new(dofile(source .. "/level.lua"))
  frame = 0
end

function love.load(args)
  local i = 1
  while args[i] do
    local key = args[i]:match("^%-%-(%a+)$")
    if not key or args[i + 1] == nil then
      io.stderr:write("usage: love examples/platformer [--script S] [--frames N] "
        .. "[--screenshot out.png]\n")
      os.exit(2)
    end
    options[key] = tonumber(args[i + 1]) or args[i + 1]
    i = i + 2
  end
  if options.script then
    script = outcome.load_script(source, options.script)
    scripted_input = game.player_input(script.input)
    options.frames = options.frames or script.frames
  end
  keys_input = {}
  new_run()
end

local function keyboard()
  local down = love.keyboard.isDown
  keys_input.left = down("left", "a")
  keys_input.right = down("right", "d")
  keys_input.jump = down("z", "space", "up", "w")
  keys_input.down = down("down", "s")
  keys_input.shoot = down("x", "lctrl")
  return keys_input
end

function love.keypressed(key)
  if key == "escape" then love.event.quit(0) end
  if key == "r" and not script then new_run() end
end

local function finish()
  love.graphics.captureScreenshot(function(image)
    local ok, why = outcome.check(run, script.expect)
    if options.screenshot then
      local file = io.open(options.screenshot, "wb")
      if not file then
        io.stderr:write("budge platformer: cannot write " .. options.screenshot .. "\n")
        os.exit(1)
      end
      file:write(image:encode("png"):getString())
      file:close()
    end
    print(("%s: %s %s"):format(options.script, run:verdict(), ok and "OK" or ("WRONG: " .. why)))
    io.stdout:flush()
    os.exit(ok and 0 or 1)
  end)
end

function love.update(dt)
  if script then -- a fixed step per frame, whatever the clock says
    if finishing then return end
    frame = frame + 1
    run:update(scripted_input(frame))
    if frame >= options.frames then finishing = true; finish() end
    return
  end
  accumulator = math.min(accumulator + dt, 0.25)
  while accumulator >= DT do
    accumulator = accumulator - DT
    frame = frame + 1
    run:update(keyboard())
  end
end

function love.draw()
  draw.frame(love.graphics, run, 800, 400)
end
