-- examples/platformer/outcome.lua: input scripts and the verdicts they expect, shared by
-- headless.lua and main.lua.
local outcome = {}

---Loads a script by name (scripts/NAME.lua beside the game) or path.
---@param here string the game's folder
---@param name string
---@return table script {frames =, input = {{first, last, "keys"}, ...}, expect = {...}}
function outcome.load_script(here, name)
  local path = name:find("[/\\]") and name or (here .. "/scripts/" .. name .. ".lua")
  return dofile(path)
end

---Whether a finished run is what the script expects; returns false and why when not.
---@param run table the game
---@param expect table {coins =, kills =, deaths =, goal =, causes =, respawn =, and minimums
---of drops (frames dropping through a ledge), coyote and buffered jumps}
---@return boolean ok, string? why
function outcome.check(run, expect)
  if run.inside > 0 then return false, "an actor ended a frame inside a solid" end
  if expect.coins == "all" and run.coins ~= run.total_coins then return false, "coins" end
  if expect.kills == "all" and run.kills ~= run.total_enemies then return false, "kills" end
  if expect.deaths and run.deaths ~= expect.deaths then return false, "deaths" end
  if expect.goal ~= nil and run.goal ~= expect.goal then return false, "goal" end
  if expect.causes and table.concat(run.causes, ",") ~= expect.causes then
    return false, "causes of death"
  end
  if expect.respawn and run.respawn_x ~= expect.respawn then return false, "respawn point" end
  if (expect.drops or 0) > run.drops then return false, "drop-through" end
  if (expect.coyote or 0) > run.coyote_jumps then return false, "coyote jumps" end
  if (expect.buffered or 0) > run.buffered_jumps then return false, "buffered jumps" end
  return true
end

return outcome
