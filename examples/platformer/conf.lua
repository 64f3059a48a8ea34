-- The budge platformer. Scripted runs (--frames N) turn vsync off so they run as fast as
-- they can.
function love.conf(t)
  local scripted = false
  for _, value in ipairs(arg or {}) do
    if value == "--frames" or value == "--script" then scripted = true end
  end
  t.identity = "budge-platformer"
  t.version = "11.4"
  t.window.title = "budge platformer"
  t.window.width = 800
  t.window.height = 400
  t.window.vsync = scripted and 0 or 1
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
