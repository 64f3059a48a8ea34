-- The budge lab. Scripted runs (--frames N) turn vsync off so they run as fast as they can.
function love.conf(t)
  local scripted = false
  for _, value in ipairs(arg or {}) do
    if value == "--frames" then scripted = true end
  end
  t.identity = "budge-lab"
  t.version = "11.4"
  t.window.title = "budge lab: watch each collision method work and fail"
  t.window.width = 1024
  t.window.height = 768
  t.window.vsync = scripted and 0 or 1
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
  t.modules.physics = false
  t.modules.video = false
end
